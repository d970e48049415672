"""View words agree with the map's directions (play-test findings)."""

from ewa_mcp.envs.street.scene import compute_scene, describe


def _node_on(graph, *streets):
    return next(i for i in range(len(graph.ids)) if set(streets) <= set(graph.node_streets[i]))


def test_a_cross_street_that_changes_name_is_named_per_side(world):
    graph = world.city("philadelphia")
    corner = _node_on(graph, "Market Street", "North 11th Street", "South 11th Street")
    # one node west along Market, facing east towards 11th Street: north (North 11th) is on the left
    west = next(j for j, _, s, h in graph.adj[corner] if graph.streets[s] == "Market Street" and 225 < h < 315)
    heading = next(h for j, _, s, h in graph.adj[west] if j == corner)
    text = describe(compute_scene(world, graph, west, heading, "front"))
    assert "North 11th Street opens to the left and South 11th Street to the right" in text, text


def test_views_never_say_a_bare_on_the_left_or_right(world):
    # "On the right" meant the direction of sight while the map's "on your right" means the side of
    # the street: a view says which one it means.
    graph = world.city("manhattan")
    target = world.places["store-target-herald-square"] if "store-target-herald-square" in world.places else None
    seen_side = seen_sight = False
    for i in range(0, len(graph.ids), 7):
        for _, _, _, h in graph.adj[i][:2]:
            text = describe(compute_scene(world, graph, i, h, "front"))
            assert "On the right," not in text and "On the left," not in text, text
            seen_side |= "-hand side of" in text
            seen_sight |= "of straight ahead" in text
    assert seen_side and seen_sight and target is not None


def test_a_view_across_a_park_shows_the_park_not_building_fronts(world):
    graph = world.city("boston")
    common = world.places["poi-boston-boston-common"]
    # along Tremont and Boylston beside the Common, the side facing the park
    checked = 0
    for street in ("Tremont Street", "Boylston Street"):
        for i in range(len(graph.ids)):
            if graph.node_streets[i] != (street,):
                continue
            from ewa_mcp.geometry import bearing_deg, haversine_m
            if haversine_m(graph.lat[i], graph.lng[i], common.lat, common.lng) > 250:
                continue
            h = bearing_deg(graph.lat[i], graph.lng[i], common.lat, common.lng)
            scene = compute_scene(world, graph, i, h, "left")
            if scene.road_ahead:
                continue
            text = describe(scene)
            assert "building fronts" not in text and "open ground" in text, text
            checked += 1
    assert checked >= 2


def test_a_street_named_in_a_frontage_keeps_its_capitals(world):
    # play-test: "Ahead on the right-hand side of 6th avenue" — the sentence was capitalised as a whole
    import re

    graph = world.city("manhattan")
    streets = set(graph.streets)
    named = 0
    for i in range(0, len(graph.ids), 5):
        for _, _, _, h in graph.adj[i][:2]:
            text = describe(compute_scene(world, graph, i, h, "front"))
            for street in re.findall(r"-hand side of ([^,]+), \d+ m away", text):
                assert street in streets, (street, text)
                named += 1
    assert named > 0
