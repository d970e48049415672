"""The episode rules an agent cannot bend: an atomic finish, one step rule for every call, tools that
refuse episodes of another domain, and errors that never echo a huge value back."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import anyio
import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server

from .fixtures import CounterEnv, NoteEnv, counter_task, register, write_tasks
from .servers import serve, stop

pytestmark = pytest.mark.anyio

RACERS = 60


def text_of(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


class SlowCounter(CounterEnv):
    """Yields to the event loop inside every action, so racing calls interleave as they do with a real kitchen."""

    async def add(self, amount: int):
        await anyio.sleep(0)
        return await super().add(amount)


@pytest.fixture
def server(tmp_path):
    tasks = write_tasks(tmp_path / "tasks", [counter_task(step_limit=500), counter_task("t-short", step_limit=3),
                                             counter_task("t-web", start="web")])
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "run",
                                              environments={"kitchen": SlowCounter, "browser": NoteEnv}))
    register(mcp, episodes)
    return mcp, episodes, tmp_path / "run"


def trajectory(run: Path, ep: str) -> list[dict[str, Any]]:
    return [json.loads(x) for x in (run / ep / "trajectory.jsonl").read_text().splitlines()]


def check_race(lines: list[dict[str, Any]], results: list[tuple[str, Any]], final: dict[str, Any],
               add_tool: str) -> int:
    """Nothing after the finishing line; every racing call either happened before it or was refused."""
    finish_at = [i for i, x in enumerate(lines) if x["tool"] in ("finish_episode", "submit_location") and x["ok"]]
    assert len(finish_at) == 1 and finish_at[0] == len(lines) - 1, "a call was recorded after the finish"
    applied = sum(1 for x in lines if x["tool"] == add_tool and x["ok"])
    answered_ok = sum(1 for tool, r in results if tool == add_tool and not r.is_error)
    assert applied == answered_ok
    refused = [text_of(r) for tool, r in results if tool == add_tool and r.is_error]
    assert all("has ended" in t for t in refused), refused[:3]
    assert applied + len(refused) == RACERS
    assert final["status"] == "finished" and final["steps"] == len(lines) - 1  # start_episode is no step
    return applied


async def race(client, ep: str, add_tool: str, add_args: dict[str, Any], finish_tool: str,
               finish_args: dict[str, Any]) -> list[tuple[str, Any]]:
    results: list[tuple[str, Any]] = []

    async def call(tool: str, args: dict[str, Any]) -> None:
        results.append((tool, await client.call_tool(tool, {"episode_id": ep, **args})))

    async with anyio.create_task_group() as tg:
        for i in range(RACERS):
            tg.start_soon(call, add_tool, add_args)
            if i == RACERS // 3:
                tg.start_soon(call, finish_tool, finish_args)
    return results


async def test_finish_is_atomic_against_racing_calls(server):
    mcp, _, run = server
    async with Client(mcp) as client:
        for _ in range(5):
            r = await client.call_tool("start_episode", {"task_id": "t-counter"})
            ep = r.structured_content["episode_id"]
            results = await race(client, ep, "counter_add", {"amount": 1}, "finish_episode", {"answer": "done"})
            final = json.loads((run / ep / "final_state.json").read_text())
            applied = check_race(trajectory(run, ep), results, final, "counter_add")
            assert final["environments"]["embodied"]["value"] == 1 + applied  # counter_start 1; nothing after the finish
            assert applied < RACERS  # the finish really raced: some calls came after it


async def test_every_call_is_a_step_and_is_recorded(server):
    mcp, episodes, run = server
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "t-web"})
        ep = r.structured_content["episode_id"]
        refused_env = await client.call_tool("counter_add", {"episode_id": ep, "amount": 1})  # web is active
        invalid = await client.call_tool("counter_add", {"episode_id": ep, "amount": 10_000})  # schema: le=100
        observed = await client.call_tool("get_observation", {"episode_id": ep})
        unknown = await client.call_tool("no_such_tool", {"episode_id": ep})
        assert refused_env.is_error and invalid.is_error and unknown.is_error and not observed.is_error
        assert episodes.get(ep).steps == 4 and episodes.get(ep).steps_left == 1
        await client.call_tool("episode_status", {"episode_id": ep})  # the last step ends the episode
        assert episodes.get(ep).status == "step_limit"
    lines = trajectory(run, ep)
    assert [(x["tool"], x["ok"], x["counted"]) for x in lines] == [
        ("start_episode", True, False), ("counter_add", False, True), ("counter_add", False, True),
        ("get_observation", True, True), ("no_such_tool", False, True), ("episode_status", True, True)]
    assert "amount" in lines[2]["error"] and lines[2]["args"] == {"amount": 10_000}


async def test_an_invalid_answer_is_a_recorded_step_and_keeps_the_episode_open(server):
    mcp, episodes, run = server
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "t-counter"})
        ep = r.structured_content["episode_id"]
        r = await client.call_tool("finish_episode", {"episode_id": ep, "answer": "x" * 5000})  # max 4000
        assert r.is_error and len(text_of(r)) < 1200
        assert episodes.get(ep).status == "running" and episodes.get(ep).steps == 1
        r = await client.call_tool("finish_episode", {"episode_id": ep, "answer": "ok"})
        assert not r.is_error
    lines = trajectory(run, ep)
    assert [(x["tool"], x["ok"]) for x in lines] == [("start_episode", True), ("finish_episode", False),
                                                     ("finish_episode", True)]
    assert len(json.dumps(lines[1])) < 5000  # the refused argument is kept, but bounded


async def test_errors_quote_a_huge_value_only_in_part(server):
    mcp, _, _ = server
    huge = "z" * 1_000_000
    async with Client(mcp) as client:
        for tool, args in [("start_episode", {"task_id": huge}), ("episode_status", {"episode_id": huge}),
                           ("get_observation", {"episode_id": "ep-" + huge})]:
            r = await client.call_tool(tool, args)
            assert r.is_error and len(text_of(r)) < 1000, (tool, len(text_of(r)))


async def test_geolocation_and_domain_tools_refuse_other_domains(tmp_path):
    """submit_location on a cooking episode, and a kitchen tool on a geolocation episode, are refused
    with an error that names the episode's own tools; the episode stays open."""
    from ewa_mcp.core.taskmodel import TaskStore
    from ewa_mcp.core.paths import tasks_dir

    store = TaskStore([tasks_dir()])
    cooking = next(t for t in store.all("cooking"))
    geo = next(t for t in store.all("geolocation") if t.start.environment == "embodied")
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks_dir()], run_dir=tmp_path / "run",
                                              environments={"browser": NoteEnv}))
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": cooking.id})
        ep = r.structured_content["episode_id"]
        r = await client.call_tool("submit_location", {"episode_id": ep, "lat": 1.0, "lng": 2.0})
        assert r.is_error and "geo" in text_of(r) and "kitchen_" in text_of(r)
        assert episodes.get(ep).status == "running"
        r = await client.call_tool("geo_look", {"episode_id": ep})
        assert r.is_error and "works only in episodes with a geo environment" in text_of(r)

        r = await client.call_tool("start_episode", {"task_id": geo.id})
        gep = r.structured_content["episode_id"]
        for tool, args in [("kitchen_rotate", {"direction": "left"}), ("street_stop", {})]:
            r = await client.call_tool(tool, {"episode_id": gep, **args})
            # refused for its domain, not for the active environment (the geo world is active)
            assert r.is_error and "works only in episodes with a" in text_of(r), text_of(r)
            assert "submit_location" in text_of(r)
        assert episodes.get(gep).status == "running"
        r = await client.call_tool("submit_location", {"episode_id": gep, "lat": 1.0, "lng": 2.0})
        assert not r.is_error and episodes.get(gep).status == "finished"


def _kitchen_only_task() -> dict[str, Any]:
    return {"id": "race-kitchen", "domain": "cooking", "intent": "Turn around, then finish.",
            "start": {"environment": "embodied", "embodied": {"kind": "kitchen", "scene": "FloorPlan28", "seed": 0}},
            "step_limit": 500}


async def test_finish_is_atomic_over_http(tmp_path):
    tasks = write_tasks(tmp_path / "tasks", [_kitchen_only_task()])
    proc, port = serve(tmp_path, "--tasks-dir", str(tasks))
    try:
        async with Client(f"http://127.0.0.1:{port}/mcp") as client:
            r = await client.call_tool("start_episode", {"task_id": "race-kitchen"})
            assert not r.is_error, text_of(r)
            ep = r.structured_content["episode_id"]
            await client.call_tool("finish_episode", {"episode_id": ep})
            start_heading = _heading(_episode_dir(tmp_path, ep))
            for _ in range(3):
                r = await client.call_tool("start_episode", {"task_id": "race-kitchen"})
                ep = r.structured_content["episode_id"]
                results = await race(client, ep, "kitchen_rotate", {"direction": "right"}, "finish_episode", {})
                ep_dir = _episode_dir(tmp_path, ep)
                final = json.loads((ep_dir / "final_state.json").read_text())
                applied = check_race(trajectory(ep_dir.parent, ep), results, final, "kitchen_rotate")
                # the kitchen's final heading shows exactly the rotations recorded before the finish
                assert (start_heading + 90 * applied) % 360 == _heading(ep_dir)
    finally:
        stop(proc)


def _episode_dir(tmp_path: Path, ep: str) -> Path:
    [ep_dir] = list((tmp_path / "runs").glob(f"*/{ep}"))
    return ep_dir


def _heading(ep_dir: Path) -> int:
    final = json.loads((ep_dir / "final_state.json").read_text())
    return round(final["environments"]["embodied"]["agent"]["rotation"]["y"]) % 360
