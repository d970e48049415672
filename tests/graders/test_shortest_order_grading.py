"""The grader on a shipped shortest-order task (navigation hard): a walk along the map's routes past the stops
in the best order passes; the greedy nearest-next order, which the task's draw made wrong, fails."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from grading_builders import EpisodeBuilder

from ewa_mcp.envs.street.taskgen.navigation import shortcut_orders
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.graders import grade_episode

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def task(task_id: str) -> dict[str, Any]:
    tasks = [t for p in sorted((TASKS_DIR / "navigation").glob("*.json")) for t in json.loads(p.read_text("utf-8"))]
    (found,) = [t for t in tasks if t["id"] == task_id]
    assert found["metadata"]["form"] == "shortest order"
    return found


def walked(tmp_path: Path, t: dict[str, Any], order: list[str]) -> Any:
    """Grade a walk from the start along the map's route to each stop of ``order`` in turn, stopped at the last."""
    world = get_world()
    origin = world.places.get(t["metadata"]["origin_id"]) or world.place(t["metadata"]["origin_id"])
    stops = [world.places[p] for p in order]
    legs = [world.directions(a.id, b.id).nodes for a, b in zip([origin, *stops], stops)]
    nodes = legs[0] + [n for lg in legs[1:] for n in lg[1:]]
    end = world.node(nodes[-1])
    state = {"name": "street", "city": t["start"]["embodied"]["city"], "node": end.id, "lat": end.lat,
             "lng": end.lng, "heading": 0.0, "stopped": True, "path": nodes,
             "path_points": [[world.node(n).lat, world.node(n).lng] for n in nodes], "distance_walked_m": 1000.0}
    ep = EpisodeBuilder(tmp_path, t).event(type="page_view", site="map", path="/directions")
    return grade_episode(ep.finish(embodied=state).directory)


def test_the_best_order_passes_and_the_greedy_order_fails(tmp_path: Path) -> None:
    t = task("navigation-via-boston-001")
    world = get_world()
    origin = world.places.get(t["metadata"]["origin_id"]) or world.place(t["metadata"]["origin_id"])
    stops = [world.places[p] for p in t["metadata"]["listed"]]
    greedy = shortcut_orders(world, lambda a, b: world.directions(a.id, b.id).distance_m, origin, stops,
                             stops)["greedy nearest-next"]
    assert greedy != t["metadata"]["stops"]

    best = walked(tmp_path, t, t["metadata"]["stops"])
    assert best.overall_success is True, [c.note for c in best.conditions if not c.met]

    wrong = walked(tmp_path, t, greedy)
    assert wrong.overall_success is False
    # the walk ends at a stop; what fails is a stop passed only before the one the best order puts first
    failed = [c for c in wrong.conditions if c.met is False]
    assert failed and all(c.kind in ("passed_place", "reached_place") for c in failed)
