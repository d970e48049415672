"""Where a place's address is: a task names a place by its address or corner and the walk is graded
at its node, so the two must be one spot (ewa_mcp/envs/street/README.md, "Address anchoring"). ``anchor_addresses``
runs once when the world loads."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ewa_mcp.geometry import bearing_deg, haversine_m
from .address import fold, normalize_street, parse_address

if TYPE_CHECKING:
    from .graph import CityGraph, Place

# A task names a place with its address ("Boston Common (Tremont St & Park St)"), and the walk is graded
# at the place's node: the two must be one spot. A place whose corner label names a corner away from its
# node is moved to that corner when the corner is near the place itself, else relabelled with its node's
# own corner; places sharing one address share one node.
ANCHOR_RADIUS_M = 25.0  # the default arrival radius of a street goal
ANCHOR_MAX_MOVE_M = 320.0  # a named corner farther than this from the place itself is not its corner
ANCHOR_MAX_MOVE_OTHER_M = 225.0  # the same for anything but a park (a park reaches its corners from far)
ANCHOR_KIND_ORDER = ["landmark", "park", "hotel", "museum", "church", "library", "theater", "market", "station"]


def label_streets(graph: CityGraph, label: str) -> tuple[list[set[int]], bool]:
    """The node sets of the streets a corner label names ("A & B", "X (A & B)", "A & B at C",
    "A between B & C"), and whether it names a block rather than a corner."""
    text = label.replace("(", ",").replace(")", ",").replace(" between ", " & ").replace(" at ", " & ")
    parts = [q.strip() for chunk in text.split(",") for q in chunk.replace(" and ", " & ").split("&") if q.strip()]
    found = [nodes for nodes in (graph.street_nodes(normalize_street(q, graph.aliases)) for q in parts) if nodes]
    return found, " between " in label


def label_corner(graph: CityGraph, label: str, lat: float, lng: float) -> int | None:
    """The corner a label names (the one nearest the place when streets meet twice); None if it names none."""
    streets, _ = label_streets(graph, label)
    corners = {i for a in range(len(streets)) for b in range(a + 1, len(streets)) for i in streets[a] & streets[b]}
    return graph.nearest(lat, lng, corners) if corners else None


def label_fits(graph: CityGraph, label: str, node: int) -> bool:
    """Whether a corner label describes this node: its corner within the arrival radius, or (a block
    label, "A between B & C") the node on A between the two corners."""
    streets, block = label_streets(graph, label)
    if not streets and graph.node_streets[node]:
        # A place inside a park is addressed by the park ("Point State Park"): its node is on the park's paths.
        return all(label in s and s != label for s in graph.node_streets[node])
    if block and len(streets) == 3:
        ends = [streets[0] & streets[k] for k in (1, 2)]
        if node not in streets[0] or not all(ends):
            return False
        e1, e2 = (min(e, key=lambda i: haversine_m(graph.lat[i], graph.lng[i], graph.lat[node], graph.lng[node]))
                  for e in ends)
        span = haversine_m(graph.lat[e1], graph.lng[e1], graph.lat[e2], graph.lng[e2])
        return (haversine_m(graph.lat[e1], graph.lng[e1], graph.lat[node], graph.lng[node]) +
                haversine_m(graph.lat[e2], graph.lng[e2], graph.lat[node], graph.lng[node])) <= span + ANCHOR_RADIUS_M
    corner = label_corner(graph, label, graph.lat[node], graph.lng[node])
    return corner is not None and haversine_m(graph.lat[corner], graph.lng[corner], graph.lat[node],
                                              graph.lng[node]) <= ANCHOR_RADIUS_M


def _attach(p: Place, graph: CityGraph, i: int) -> None:
    p.node = graph.ids[i]
    p.offset_m = round(haversine_m(graph.lat[i], graph.lng[i], p.lat, p.lng), 1)
    p.heading_from_node = round(bearing_deg(graph.lat[i], graph.lng[i], p.lat, p.lng), 1)


def node_label(graph: CityGraph, i: int) -> str:
    """A label derived from the node itself: its corner, or its street between the corners either side."""
    if len(graph.node_streets[i]) >= 2:
        return " & ".join(graph.node_streets[i])
    street = graph.node_streets[i][0] if graph.node_streets[i] else ""
    ends = []
    for j, _, _s, _ in graph.adj[i]:
        prev, cur = i, j
        for _ in range(50):
            if len(graph.node_streets[cur]) >= 2:
                ends.append(next(n for n in graph.node_streets[cur] if n != street))
                break
            nxt = [k for k, _, s2, _ in graph.adj[cur] if k != prev and graph.streets[s2] == street]
            if not nxt:
                break
            prev, cur = cur, nxt[0]
    ends = sorted(set(ends))
    return f"{street} between {ends[0]} & {ends[1]}" if len(ends) == 2 else street


def anchor_addresses(places: dict[str, Place], graphs: dict[str, CityGraph]) -> None:
    """Make every point of interest's address name the spot of its node (see ANCHOR_* above)."""
    for p in sorted(places.values(), key=lambda p: p.id):
        graph = graphs[p.city]
        if p.refers_to or p.kind in ("address", "intersection") or parse_address(p.address) is not None:
            continue
        i = graph.index[p.node]
        corner = None if label_streets(graph, p.address)[1] else label_corner(graph, p.address, p.lat, p.lng)
        reach = ANCHOR_MAX_MOVE_M if p.kind == "park" else ANCHOR_MAX_MOVE_OTHER_M
        if corner is not None and haversine_m(graph.lat[corner], graph.lng[corner], p.lat, p.lng) <= reach:
            if corner != i:
                _attach(p, graph, corner)  # at the corner itself: places named by one corner share its node
        elif not label_fits(graph, p.address, i):
            p.address = node_label(graph, i)
    groups: dict[tuple[str, str], list[Place]] = {}
    for p in places.values():
        if parse_address(p.address) is not None:
            groups.setdefault((p.city, fold(p.address)), []).append(p)
    for group in groups.values():
        if len({p.node for p in group}) > 1:  # one address, one spot: the main building's node
            rank = {k: n for n, k in enumerate(ANCHOR_KIND_ORDER)}
            main = min(group, key=lambda p: (rank.get(p.kind, len(rank)), p.id))
            graph = graphs[main.city]
            for p in group:
                if p.node != main.node:
                    _attach(p, graph, graph.index[main.node])
