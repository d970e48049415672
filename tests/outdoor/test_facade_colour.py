"""Vision mode at a place's node: its front is drawn in the colour its description gives the material it is
built of, and no nameless front a step away is drawn in that colour (play-test round 12: at the U.S. Steel
Tower's stop the side view showed a grey glass grid, "clad in rust-brown weathering steel" being drawn in the
grey of bare steel, while the node a step before showed a brown front of no place, which the player took
for it). benchmarks/bench_facade_at_node.py prints the same over every place and every way of facing."""

from __future__ import annotations

import math

from ewa_mcp.envs.street.facades import DECOY_RGB
from ewa_mcp.envs.street.scene import OPEN_SPACE_KINDS, compute_scene, wall_colour_of
from ewa_mcp.envs.street.here_view import sidewalk_entrance
from ewa_mcp.envs.street.street_view import render_cues
from ewa_mcp.geometry import angle_diff

TOWER = "poi-pittsburgh-us-steel-tower"


def share_of(img, colour: tuple[int, int, int], within: float = 0.0) -> float:
    """The share of the picture drawn in ``colour`` (or within this RGB distance of it)."""
    n = sum(k for k, c in img.getcolors(maxcolors=1 << 18) or [] if math.dist(c, colour) <= within)
    return n / (img.width * img.height)


def test_the_stated_colour_is_that_of_the_material_named():
    assert wall_colour_of("A huge triangular tower, clad in rust-brown weathering steel.") == (140, 70, 40)
    assert wall_colour_of("A red-brick hall with white marble trim.") == (160, 56, 44)  # brick's, not marble's
    assert wall_colour_of("A plain steel frame.") == (140, 150, 160)  # no colour word: the material's own
    assert wall_colour_of("A big house of dark brown stone.") == (70, 46, 32)  # brown, darkened
    assert wall_colour_of("A tall tower with a green roof.") is None  # no material: the style's palette


def test_the_us_steel_tower_is_drawn_rust_brown_at_its_stop(world):
    """The player's arrival: walking south on Grant Street (191°), the left view (101°) faces the tower."""
    tower = world.place(TOWER)
    rust = wall_colour_of(tower.description_hint)
    assert rust[0] > rust[1] + 50 > rust[2] + 50, rust  # a rust-brown, not the grey of bare steel
    graph, i = world.locate(tower.node)
    img, cues = render_cues(compute_scene(world, graph, i, 101.0, "left"))
    assert f"here:{TOWER}" in cues
    assert share_of(img, rust) > 0.3, "the tower's front fills the view in its rust-brown"


def test_no_nameless_front_a_step_before_the_tower_passes_for_it(world):
    """At the node the player passed a step before (22 m north), the view east draws no front of the
    tower's, and no other front in a tone near its rust-brown."""
    tower = world.place(TOWER)
    rust = wall_colour_of(tower.description_hint)
    graph, i = world.locate("pg-ae0942248b")
    img, cues = render_cues(compute_scene(world, graph, i, 102.0, "left"))
    assert f"facade:{TOWER}" not in cues
    assert share_of(img, rust, within=DECOY_RGB) < 0.02


def test_every_place_is_drawn_in_its_stated_colour_at_its_node(world):
    """Every place whose description colours what it is built of, in every view facing it at its node
    (along each street there either way, and the compass views), is drawn in that colour."""
    problems = []
    for p in sorted(world.places.values(), key=lambda p: p.id):
        colour = wall_colour_of(p.description_hint)
        if colour is None or p.kind in OPEN_SPACE_KINDS or p.heading_from_node is None:
            continue
        graph, i = world.locate(p.node)
        faces = {0.0, 90.0, 180.0, 270.0} | {h % 360.0 for *_, h in graph.adj[i]} | {
            (h + 180.0) % 360.0 for *_, h in graph.adj[i]}
        for face in sorted(faces):
            view = min(((face + 90.0 * k) % 360.0 for k in range(4)),
                       key=lambda v: abs(angle_diff(p.heading_from_node, v)))
            scene = compute_scene(world, graph, i, view, "view")
            here = next((f for f in scene.here if f.place_id == p.id), None)
            if here is None:
                problems.append(f"{p.id}: not drawn facing {view:.0f}°")
                continue
            if sidewalk_entrance(here):
                continue
            img, _ = render_cues(scene)
            if share_of(img, colour) < 0.02:
                problems.append(f"{p.id}: facing {view:.0f}° its front is not in {colour}")
    assert not problems, problems[:8]
