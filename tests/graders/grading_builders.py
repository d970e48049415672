"""Hand-built run directories for the grader tests.

Files are written with the core's own EpisodeRecorder, so the tests read exactly the format a
real run produces; the goals, states and trajectories are chosen per test with known outcomes.
"""

from __future__ import annotations

import json

import itertools
from pathlib import Path
from typing import Any

from ewa_mcp.core.records import EpisodeRecorder
from ewa_mcp.core.taskmodel import Task

_ids = itertools.count(1)

# Two real Manhattan points about 30 m apart on West 23rd Street, for street goals.
GOAL = {"lat": 40.74180, "lng": -73.98950}


def offset_north(lat: float, lng: float, metres: float) -> tuple[float, float]:
    """A point ``metres`` north of (lat, lng): 1 degree of latitude is ≈ 111,195 m on the mean sphere."""
    return lat + metres / 111_194.93, lng


def make_task(task_id: str = "t-1", domain: str = "cooking", **fields: Any) -> dict[str, Any]:
    """A task dict, validated by the real schema so tests cannot drift from it."""
    raw = {"id": task_id, "domain": domain, "intent": f"test task {task_id}", **fields}
    return Task.model_validate(raw).model_dump(mode="json")


def kitchen_task(task_id: str = "cook-1", embodied_goals: list[dict[str, Any]] | None = None,
                 web_goals: list[dict[str, Any]] | None = None, **fields: Any) -> dict[str, Any]:
    return make_task(task_id, "cooking", start={"environment": "web", "web": {"start_url": "recipes:/"},
                                                "embodied": {"kind": "kitchen", "scene": "FloorPlan1"}},
                     web_goals=web_goals or [], embodied_goals=embodied_goals or [], **fields)


def street_task(task_id: str = "nav-1", domain: str = "navigation", web_goals: list[dict[str, Any]] | None = None,
                radius_m: float = 25.0, metadata: dict[str, Any] | None = None, **goal_fields: Any) -> dict[str, Any]:
    goal = {"kind": "reached_place", "city": "manhattan", "node": "n-goal", **GOAL, "radius_m": radius_m,
            **goal_fields}
    return make_task(task_id, domain, start={"environment": "web", "web": {"start_url": "map:/"},
                                             "embodied": {"kind": "street", "city": "manhattan", "node": "n-start"}},
                     web_goals=web_goals or [], embodied_goals=[goal], metadata=metadata or {})


def obj(object_type: str, n: int = 0, parents: list[str] | None = None, source: str | None = None,
        **states: bool) -> dict[str, Any]:
    """An AI2-THOR-style object dict; ``n`` keeps ids of same-type objects distinct."""
    base = {"isSliced": False, "isCooked": False, "isBroken": False, "isToggled": False, "isOpen": False,
            "isPickedUp": False}
    object_id = f"{object_type}|+{n}.00|+0.90|-1.00"
    if source is not None:
        object_id = f"{source}|+{n}.00|+0.90|-1.00|{object_type}_{n}"
    out: dict[str, Any] = {"objectId": object_id, "objectType": object_type, "parentReceptacles": parents or [],
                           **base, **states}
    if source is not None:
        out["sourceType"] = source
    return out


def kitchen_state(objects: list[dict[str, Any]], held: str | None = None) -> dict[str, Any]:
    return {"name": "kitchen", "backend": "sim", "scene": "FloorPlan1", "objects": objects, "held": held}


def street_state(lat: float, lng: float, stopped: bool = True, node: str = "n-x", walked: float = 100.0,
                 city: str = "manhattan") -> dict[str, Any]:
    return {"name": "street", "city": city, "node": node, "lat": lat, "lng": lng, "heading": 0.0,
            "stopped": stopped, "path": ["n-start", node], "distance_walked_m": walked}


class EpisodeBuilder:
    """Writes one episode directory: task, trajectory calls, web events, final state."""

    def __init__(self, run_dir: Path, task: dict[str, Any] | None, episode_id: str | None = None):
        self.episode_id = episode_id or f"ep-{next(_ids):012d}"
        self.directory = run_dir / self.episode_id
        self.recorder = EpisodeRecorder(self.directory)
        self.task = task
        if task is not None:
            self.recorder.write_task(task)
        self.active = (task or {}).get("start", {}).get("environment", "web")
        self.calls = 0
        self.steps = 0
        self.switches = 0

    def call(self, tool: str, args: dict[str, Any] | None = None, *, ok: bool = True, error: str | None = None,
             observation: str | None = None, counted: bool = True) -> EpisodeBuilder:
        self.calls += 1
        self.steps += counted
        self.recorder.step(index=self.calls, tool=tool, args=args or {}, ok=ok, error=error, duration_ms=1.0,
                           environment=self.active, observation=observation or error or f"after {tool} #{self.calls}",
                           counted=counted)
        return self

    def switch(self, target: str) -> EpisodeBuilder:
        self.active = target
        self.switches += 1
        return self.call("switch_environment", {"target": target, "message": "go"}, observation=f"now in {target}")

    def event(self, **event: Any) -> EpisodeBuilder:
        self.recorder.event(event)
        return self

    def finish(self, *, status: str = "finished", answer: str | None = None, submission: dict[str, Any] | None = None,
               web: dict[str, Any] | None = None, embodied: dict[str, Any] | None = None,
               wall_time_s: float = 12.5) -> EpisodeBuilder:
        environments: dict[str, Any] = {}
        if web is not None:
            environments["web"] = web
        if embodied is not None:
            environments["embodied"] = embodied
        # Written as raw JSON, not through the recorder's model: a builder also makes records a server never
        # would (no task), to test how the graders read them.
        self._raw_final_state({
            "schema_version": 1, "episode_id": self.episode_id, "task_id": (self.task or {}).get("id"),
            "domain": (self.task or {}).get("domain"), "status": status, "end_reason": status, "answer": answer,
            "submission": submission, "steps": self.steps, "calls": self.calls, "switches": self.switches,
            "active_environment": self.active, "options": {}, "wall_time_s": wall_time_s,
            "environments": environments,
        })
        return self.close()

    def _raw_final_state(self, payload: dict[str, Any]) -> None:
        (self.directory / "final_state.json").write_text(json.dumps(payload, indent=2), encoding="utf-8")

    def close(self) -> EpisodeBuilder:
        self.recorder.close()
        return self


def recipe_step(recipe_id: str, step: int, of: int) -> dict[str, Any]:
    return {"site": "recipes", "type": "recipe_step", "recipe_id": recipe_id, "step": step, "of": of}


def order_event(order_id: str, store_id: str, *items: dict[str, Any]) -> dict[str, Any]:
    return {"site": "shop", "type": "order_placed", "order": {"order_id": order_id, "store_id": store_id,
                                                              "items": list(items)}}


def item(product_id: str, size: str | None = None, quantity: int = 1) -> dict[str, Any]:
    return {"product_id": product_id, "size": size, "quantity": quantity, "kitchen_type": None}
