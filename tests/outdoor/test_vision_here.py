"""Vision mode at a place's own node: what the text's "Right here:" names is drawn in the view facing it
(play-test: at a goal the images showed a generic doorway, no sign, no park, none of the described features)."""

from __future__ import annotations

import json
import random
from dataclasses import replace
from pathlib import Path

import pytest

from ewa_mcp.core.services import Services
from ewa_mcp.core.taskmodel import Task
from ewa_mcp.envs.street.env import StreetEnvironment
from ewa_mcp.envs.street.here_view import LAWN, POND, RAILING, STREET_SIGN
from ewa_mcp.envs.street.scene import compute_scene, describe, here_cues, places_here, sign_colour_of, text_cues
from ewa_mcp.envs.street.street_view import render_cues

TASKS = Path(__file__).resolve().parents[2] / "tasks"


def four_views(world, node_id: str, start: float):
    graph, i = world.locate(node_id)
    for k in range(4):
        heading = (start + 90.0 * k) % 360.0
        scene = compute_scene(world, graph, i, heading, "front")
        img, drawn = render_cues(scene)
        yield scene, img, drawn


def check_node(world, node_id: str, start: float) -> list[str]:
    """Problems at one node: a place the text names here that no view shows, or a cue not drawn."""
    problems, shown = [], set()
    for scene, _, drawn in four_views(world, node_id, start):
        missing = (text_cues(scene) | here_cues(scene)) - drawn
        # a far tower already hidden without the places here (a known gap of the skyline drawing, which
        # tests/outdoor/test_vision_only.py samples) is not theirs to show
        missing -= {c for c in render_cues(replace(scene, here=[]))[1] ^ text_cues(replace(scene, here=[]))
                    if c.startswith("skyline:")}
        if missing:
            problems.append(f"{node_id} at {scene.heading:.0f}°: not drawn {sorted(missing)}")
        shown |= {f.place_id for f in scene.here}
    for p in world.places_near(node_id):
        if p.id not in shown:
            problems.append(f"{node_id}: {p.id} is 'Right here' in the text but in no view")
    return problems


def test_every_place_is_drawn_at_its_own_node(world):
    """Every place, from its node, whichever way the agent faces: it lies in one of the four views and
    that view draws it (its sign, its park features, its material and described details)."""
    rng = random.Random(7)
    problems: list[str] = []
    for node_id in sorted({p.node for p in world.places.values()}):
        problems += check_node(world, node_id, rng.uniform(0, 360))
    assert not problems, problems[:8]


def goal_nodes(domain: str, count: int) -> list[str]:
    goals = []
    for path in sorted((TASKS / domain).glob("*.json")):
        for task in json.loads(path.read_text(encoding="utf-8")):
            goals += [g["node"] for g in task.get("embodied_goals", []) if g.get("node")]
    return random.Random(domain).sample(sorted(set(goals)), min(count, len(set(goals))))


def check_approach(world, node_id: str) -> list[str]:
    """From each neighbouring node, facing the goal: what the text names there (the goal's places among
    them, seen along the street) is drawn."""
    graph, i = world.locate(node_id)
    problems = []
    for j, _, _, _ in graph.adj[i]:
        back = next((h for k, _, _, h in graph.adj[j] if k == i), None)
        if back is None:
            continue
        scene = compute_scene(world, graph, j, back, "front")
        missing = text_cues(scene) - render_cues(scene)[1]
        missing -= {c for c in render_cues(replace(scene, here=[]))[1] ^ text_cues(replace(scene, here=[]))
                    if c.startswith("skyline:")}
        if missing:
            problems.append(f"{graph.ids[j]} towards {node_id}: not drawn {sorted(missing)}")
    return problems


@pytest.mark.parametrize("domain", ["navigation", "shopping", "traveling"])
def test_the_goal_of_a_sample_of_tasks_is_drawn_there_and_on_the_way_in(world, domain):
    nodes = goal_nodes(domain, 25)
    assert nodes
    problems = [p for node in nodes for p in check_node(world, node, 17.0) + check_approach(world, node)]
    assert not problems, problems[:8]


def pixels(img, colour: tuple[int, int, int]) -> int:
    return sum(n for n, c in img.getcolors(maxcolors=1 << 18) or [] if c == colour)


def facing_view(world, place_id: str):
    p = world.places[place_id]
    for scene, img, drawn in four_views(world, p.node, p.heading_from_node or 0.0):
        if any(f.place_id == place_id for f in scene.here):
            return scene, img, drawn
    raise AssertionError(f"{place_id} in no view")


def test_a_shop_shows_its_name_board_in_the_colour_its_description_gives(world):
    scene, img, drawn = facing_view(world, "store-cvs-midtown")
    assert "sign:CVS Pharmacy Grand Central" in drawn and "here:store-cvs-midtown" in drawn
    red = sign_colour_of(world.places["store-cvs-midtown"].description_hint)
    assert red is not None and pixels(img, red) >= 300  # a board a passer-by reads, not a sliver at the edge


def test_a_park_is_drawn_as_a_park_with_its_pond(world):
    scene, img, drawn = facing_view(world, "poi-boston-boston-common")
    assert {"park:poi-boston-boston-common:pond", "park:poi-boston-boston-common:paths"} <= drawn
    assert pixels(img, LAWN) >= 0.05 * img.width * img.height and pixels(img, POND) >= 100
    # the same node, looking away from the park: no lawn of this park is drawn there
    p = world.places["poi-boston-boston-common"]
    _, away, _ = next(four_views(world, p.node, (p.heading_from_node or 0.0) + 180.0))
    assert pixels(away, POND) == 0


def test_a_small_alley_has_its_street_sign_and_its_look(world):
    scene, img, drawn = facing_view(world, "poi-philadelphia-elfreths-alley")
    pid = "poi-philadelphia-elfreths-alley"
    assert {"sign:Elfreth's Alley", f"material:{pid}:brick", f"detail:{pid}:shutters", f"detail:{pid}:flowers"} <= drawn
    assert pixels(img, STREET_SIGN) >= 150


def test_a_subway_entrance_is_a_stairway_in_the_sidewalk_with_its_name_board(world):
    pid = "poi-manhattan-23-st-station-eighth-avenue"
    scene, img, drawn = facing_view(world, pid)
    assert {"sign:23 St station (Eighth Avenue)", f"detail:{pid}:lamps", f"here:{pid}"} <= drawn
    assert pixels(img, RAILING) >= 100
    graph, i = world.locate(world.places[pid].node)
    away = compute_scene(world, graph, i, scene.heading + 180.0, "back")
    assert pixels(render_cues(away)[0], RAILING) == 0  # the railings belong to the view facing it


def test_a_landmark_carries_no_name_only_its_look(world):
    scene, img, drawn = facing_view(world, "poi-manhattan-tudor-city")
    pid = "poi-manhattan-tudor-city"
    assert {f"detail:{pid}:gables", f"detail:{pid}:stained", f"detail:{pid}:neon", f"material:{pid}:brick"} <= drawn
    assert not any(c.startswith("sign:") and "Tudor" in c for c in drawn)


def test_the_text_mode_is_unchanged_by_the_drawn_places(world):
    """describe never reads Scene.here: the text mode's words stay what they were."""
    p = world.places["store-target-herald-square"]
    graph, i = world.locate(p.node)
    scene = compute_scene(world, graph, i, p.heading_from_node or 0.0, "front")
    assert scene.here and describe(scene) == describe(replace(scene, here=[]))


@pytest.mark.anyio
@pytest.mark.parametrize("place_id",
                         ["store-cvs-midtown", "poi-philadelphia-elfreths-alley", "poi-boston-boston-common"])
async def test_vision_observation_at_a_goal_carries_no_scene_text(world, place_id):
    p = world.places[place_id]
    task = Task.model_validate({
        "id": "nav-test", "domain": "navigation", "intent": "Walk.",
        "start": {"environment": "embodied",
                  "embodied": {"kind": "street", "city": p.city, "node": p.node, "heading": 10.0}}})
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": "vision"})
    graph, i = world.locate(p.node)
    assert places_here(world, graph, i, env.heading)  # the text mode would say "Right here:"
    obs = env.observation()
    everything = (obs.text + json.dumps(obs.data)).lower()
    assert len(obs.images) == 4
    for q in world.places_near(p.node):
        assert q.name.lower() not in everything
        assert q.description_hint.lower()[:30] not in everything
    assert "right here" not in everything and "sign reading" not in everything


@pytest.fixture
def anyio_backend():
    return "asyncio"
