"""A task names a place by its address or corner; the walk is graded at the place's node. Every label
must point at that node (play-test: "Boston Common (Tremont St & Park St)" was graded 270 m away)."""

from ewa_mcp.envs.street.address import parse_address
from ewa_mcp.geometry import haversine_m
from ewa_mcp.envs.street.address import fold
from ewa_mcp.envs.street.anchoring import ANCHOR_RADIUS_M, label_fits
from ewa_mcp.websites.map.places import WorldAdapter


def _pois(world):
    return sorted((p for p in world.places.values() if not p.id.startswith("address:")), key=lambda p: p.id)


def test_every_place_label_resolves_to_its_graded_node(world):
    resolver = WorldAdapter(world)
    wrong = []
    for p in _pois(world):
        node = world.node(p.node)
        if parse_address(p.address) is not None:
            found = resolver.resolve(p.address).place
            ok = found is not None and haversine_m(found.lat, found.lng, node.lat, node.lng) <= ANCHOR_RADIUS_M \
                or found is not None and found.node == p.node
        else:
            graph = world.city(p.city)
            ok = label_fits(graph, p.address, graph.index[p.node])
        if not ok:
            wrong.append(f"{p.id}: {p.address}")
    assert not wrong, wrong


def test_corner_labels_resolve_on_the_map_within_the_goal_radius(world):
    resolver = WorldAdapter(world)
    for p in _pois(world):
        parts = p.address.split(" & ")
        if len(parts) != 2 or any(c in p.address for c in "(),") or " at " in p.address or " between " in p.address:
            continue
        hit = next(h for h in resolver.search(p.address, p.city, 10) if h.kind == "intersection")
        node = world.node(p.node)
        assert haversine_m(hit.lat, hit.lng, node.lat, node.lng) <= ANCHOR_RADIUS_M, (p.id, p.address)


def test_one_label_one_spot(world):
    spots: dict[tuple[str, str], set[str]] = {}
    for p in _pois(world):
        spots.setdefault((p.city, fold(p.address)), set()).add(p.node)
    assert {k: v for k, v in spots.items() if len(v) > 1} == {}


def test_boston_common_is_at_tremont_and_park(world):
    common, station = world.places["poi-boston-boston-common"], world.places["poi-boston-park-street-station"]
    assert common.node == station.node
    assert {"Tremont Street", "Park Street"} <= set(world.node(common.node).streets)
