"""A run directory written by the real MCP server core is graded correctly.

The two environments below are minimal stand-ins that report a fixed kitchen final state and a
page counter; what is under test is the core's record format meeting the grader."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from mcp import Client

from ewa_mcp.core.environment import Environment, Observation
from ewa_mcp.graders import grade_run
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio

PLATE = "Plate|+0.00|+0.90|-1.00"


class FixedKitchen(Environment):
    side = "embodied"
    name = "kitchen"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        return None

    async def observe(self) -> Observation:
        return Observation(text="a kitchen")

    async def final_state(self) -> dict[str, Any]:
        on_plate = self.episode.task.id.endswith("good")
        return {"backend": "sim", "scene": "FloorPlan1", "held": None, "objects": [
            {"objectId": PLATE, "objectType": "Plate", "parentReceptacles": []},
            {"objectId": "Tomato|+1.00|+0.90|-1.00|TomatoSliced_0", "objectType": "TomatoSliced",
             "sourceType": "Tomato", "parentReceptacles": [PLATE] if on_plate else []},
        ]}


class Pages(Environment):
    side = "web"
    name = "browser"

    def __init__(self, episode: Any, services: Any):
        pass

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        return None

    async def observe(self) -> Observation:
        return Observation(text="a page")

    async def final_state(self) -> dict[str, Any]:
        return {"url": "recipes:/"}


def cooking_task(task_id: str) -> dict[str, Any]:
    return {"id": task_id, "domain": "cooking", "intent": "put tomato slices on a plate",
            "start": {"environment": "web", "web": {"start_url": "recipes:/"},
                      "embodied": {"kind": "kitchen", "scene": "FloorPlan1"}},
            "web_goals": [{"kind": "recipe_completed", "recipe_id": "r-1"}],
            "embodied_goals": [{"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate"}],
            "answer": {"kind": "text", "must_include": ["done"]}}


async def test_core_run_directory_is_graded(tmp_path: Path) -> None:
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "t.json").write_text(json.dumps([cooking_task("cook-good"), cooking_task("cook-bad")]))
    run = tmp_path / "run"
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=run,
                                              environments={"kitchen": FixedKitchen, "browser": Pages}))
    async with Client(mcp) as client:
        for task_id in ("cook-good", "cook-bad"):
            r = await client.call_tool("start_episode", {"task_id": task_id})
            episode_id = r.structured_content["episode_id"]
            episodes.emit_event(episode_id, {"site": "recipes", "type": "recipe_step", "recipe_id": "r-1",
                                             "step": 3, "of": 3})
            r = await client.call_tool("switch_environment", {"episode_id": episode_id, "target": "embodied",
                                                              "message": "cook"})
            assert not r.is_error
            r = await client.call_tool("finish_episode", {"episode_id": episode_id, "answer": "Done."})
            assert not r.is_error

    report = grade_run(run)
    by_task = {e.task_id: e for e in report.episodes}
    good, bad = by_task["cook-good"], by_task["cook-bad"]
    assert good.overall_success is True and good.problems == [] and good.status == "finished"
    assert (good.steps, good.switches) == (2, 1)  # the switch and the finish are steps; start is not
    assert good.wall_time_s is not None
    assert bad.web_success is True and bad.embodied_success is False and bad.completion == pytest.approx(2 / 3)
    assert report.domains["cooking"].overall_accuracy.successes == 1
