"""Views: deterministic images and text descriptions derived from the same scene."""

import io

from PIL import Image

from ewa_mcp.envs.street.street_view import render_png
from ewa_mcp.envs.street.scene import compute_scene, describe


def _scene(world, place_id, heading):
    p = world.place(place_id)
    graph, i = world.locate(p.node)
    return compute_scene(world, graph, i, heading, "front")


def test_same_scene_renders_identical_pixels(world):
    a = render_png(_scene(world, "store-target-herald-square", 299.0))
    b = render_png(_scene(world, "store-target-herald-square", 299.0))
    assert a == b
    img = Image.open(io.BytesIO(a))
    assert img.size == (480, 330)
    assert len(img.convert("RGB").getcolors(maxcolors=4096) or []) > 10  # an actual picture, not a blank frame


def test_different_directions_give_different_views(world):
    views = {render_png(_scene(world, "poi-manhattan-flatiron-building", h)) for h in (29.0, 119.0, 209.0, 299.0)}
    assert len(views) == 4


def test_description_names_shop_signs_but_not_landmarks(world):
    # Facing along West 34th Street from Target's node: Target's own sign is in view.
    store = world.place("store-target-herald-square")
    graph, i = world.locate(store.node)
    texts = [describe(compute_scene(world, graph, i, h, "v")) for h in range(0, 360, 45)]
    assert any('"Target Herald Square"' in t for t in texts)
    fl = world.place("poi-manhattan-flatiron-building")
    graph, i = world.locate(fl.node)
    texts = [describe(compute_scene(world, graph, i, h, "v")) for h in range(0, 360, 30)]
    assert any("triangular" in t for t in texts)  # its look is described ...
    assert not any("Flatiron Building" in t for t in texts)  # ... its name is never painted


def test_street_ahead_and_cross_streets_follow_the_graph(world):
    node = world.search("5th Ave & W 23rd St")[0].node
    graph, i = world.locate(node)
    up = compute_scene(world, graph, i, 29.0, "front")
    assert up.road_ahead and up.ahead_street == "5th Avenue"
    assert [o.street for o in up.openings][:1] and all(o.distance_m > 0 for o in up.openings)
    sideways = compute_scene(world, graph, i, 29.0 + 45.0, "front")
    assert not sideways.road_ahead  # facing the buildings between two streets
    assert "5th Avenue" in up.street_signs


def test_the_details_a_description_names_are_drawn(world):
    # The library's description mentions two stone lions, steps, columns and arched entrances: standing at
    # its door and facing it, the lions are in the picture (and not in the same view of a plain building).
    from ewa_mcp.envs.street.facades import LION
    from ewa_mcp.envs.street.scene import details_of
    from ewa_mcp.envs.street.street_view import render

    library = world.place("poi-manhattan-new-york-public-library-stephen-a-schwarzman-building")
    assert {"lions", "steps", "columns", "arch"} <= details_of(library.description_hint)
    graph, i = world.locate(library.node)
    scene = compute_scene(world, graph, i, library.heading_from_node, "front")
    assert "lions" in describe(scene)
    lion_pixels = sum(n for n, colour in render(scene).getcolors(maxcolors=1 << 16) if colour == LION)
    assert lion_pixels > 400
    for f in scene.frontages + scene.here:  # the place drawn close up at its node reads the hint too
        f.hint = "a plain building"
    assert not any(colour == LION for _, colour in render(scene).getcolors(maxcolors=1 << 16))


def test_a_place_straight_ahead_on_a_street_that_goes_on_does_not_block_it(world):
    # oracle walk (shopping-pair-023), Broadway north at West 27th Street: the text says Broadway goes on
    # 250 m and the 28 St station is "straight ahead, 52 m away"; the picture drew the station as a
    # building front across the road at 52 m, as if the street ended there.
    from ewa_mcp.envs.street.facades import LANE, ROAD, STREET_CAMERA
    from ewa_mcp.envs.street.street_view import render

    graph = world.city("manhattan")
    checked = 0
    for node, heading in (("mn-f682acba60", 8.0), ("mn-289c60f1ba", 8.0), ("mn-45058621c3", 9.0)):
        scene = compute_scene(world, graph, graph.index[node], heading, "front")
        assert scene.road_ahead
        img = render(scene)
        for f in scene.frontages:
            # where the road itself shows 1 m above its surface at the place's depth (it runs on past 2.5x as far)
            if f.side != "ahead" or 2.5 * f.distance_m > scene.ahead_length_m:
                continue
            x, y = STREET_CAMERA.project(0.5, 1.0, f.distance_m)
            assert img.getpixel((int(x), int(y))) in (ROAD, LANE), (node, f.place_id, describe(scene))
            checked += 1
    assert checked >= 2


def test_a_place_described_as_tiny_or_low_is_drawn_low(world):
    # oracle walk (navigation-pittsburgh-034's park): "a tiny five-sided brick fort building" was drawn as a
    # 20-30 m block. A place of unknown height whose description makes it low is drawn two storeys high.
    from ewa_mcp.envs.street import here_view
    from ewa_mcp.envs.street.facades import STREET_CAMERA
    from ewa_mcp.envs.street.scene import LOW_HEIGHT_M, stated_low

    graph = world.city("pittsburgh")
    fort = world.places["poi-pittsburgh-fort-pitt-block-house"]
    scene = compute_scene(world, graph, graph.index[fort.node], fort.heading_from_node, "front")
    here = next(f for f in scene.here if f.place_id == fort.id)
    assert stated_low(here) and here_view._height(here, STREET_CAMERA, 10.0) == LOW_HEIGHT_M
    tower = next(p for p in world.places.values() if p.city == "pittsburgh" and (p.facts.get("height_m") or 0) > 100)
    tall = compute_scene(world, graph, graph.index[tower.node], tower.heading_from_node or 0.0, "front")
    assert not any(stated_low(f) for f in tall.here if f.place_id == tower.id)
