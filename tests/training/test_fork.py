"""Forks: a copy of a running episode that behaves identically from there on, and independently of the original."""

from __future__ import annotations

import json

import pytest
from mcp.server.mcpserver.exceptions import ToolError

from ewa_mcp.core.episodes import EpisodeError
from ewa_mcp.forking import ForkError, fork_episode
from ewa_mcp.graders import grade_episode
from ewa_mcp.server import ServerConfig, build_server

from .helpers import embodied_only

pytestmark = pytest.mark.anyio


@pytest.fixture
async def server(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    cook = next(t for t in sorted(episodes.tasks.all("cooking"), key=lambda t: t.id) if t.id.startswith("cooking-cook"))
    for task, new_id in ((episodes.tasks.get("navigation-boston-000"), "walk-boston-000"), (cook, "kitchen-cook"),
                         (episodes.tasks.get("geo-0079-embodied"), "geo-walk-0100")):
        episodes.tasks.add(embodied_only(task, new_id))
    yield full, episodes
    await episodes.aclose()
    await episodes.services.aclose()


async def call(full, episode_id, tool, args):
    """What the agent reads: the result's text, or the refusal's (refusals must repeat too)."""
    try:
        result = await full.call_tool(tool, {**args, "episode_id": episode_id})
    except ToolError as exc:
        return "refused: " + str(exc).replace(episode_id, "EP")
    return result.content[0].text.replace(episode_id, "EP")


@pytest.mark.parametrize("task_id", ["walk-boston-000", "kitchen-cook", "geo-walk-0100"])
async def test_a_fork_replays_identically_and_grades_like_the_original(server, task_id):
    full, episodes = server
    task = episodes.tasks.get(task_id)
    oracle = [(s.tool, dict(s.args)) for s in task.oracle]
    if task_id.startswith("geo"):  # walk about before submitting, so the fork has a state to copy
        oracle = [("geo_move", {"direction": "north"}), ("geo_look", {"direction": "all"}),
                  ("geo_move", {"direction": "east"}), ("geo_look", {"direction": "south"}), *oracle]
    start = await full.call_tool("start_episode", {"task_id": task_id})
    original = start.structured_content["episode_id"]
    half = len(oracle) // 2
    for tool, args in oracle[:half]:
        await call(full, original, tool, args)
    fork = await fork_episode(episodes, original)
    assert fork.id != original and fork.steps == episodes.get(original).steps
    rest = {eid: [await call(full, eid, tool, args) for tool, args in oracle[half:]] for eid in (original, fork.id)}
    assert rest[original] == rest[fork.id]
    a, b = grade_episode(episodes.run_dir / original), grade_episode(episodes.run_dir / fork.id)
    assert (a.overall_success, a.completion, a.steps) == (b.overall_success, b.completion, b.steps)
    lines = [json.loads(x) for x in (episodes.run_dir / fork.id / "trajectory.jsonl").read_text().splitlines()]
    assert [x["tool"] for x in lines[: half + 2]] == ["start_episode", *(t for t, _ in oracle[:half]), "fork_episode"]


async def test_a_fork_is_independent_of_its_original(server):
    full, episodes = server
    start = await full.call_tool("start_episode", {"task_id": "kitchen-cook"})
    original = start.structured_content["episode_id"]
    before = await call(full, original, "get_observation", {})
    fork = await fork_episode(episodes, original)
    task = episodes.tasks.get("kitchen-cook")
    for step in task.oracle[:6]:  # the fork picks up, slices, moves ...
        await call(full, fork.id, step.tool, dict(step.args))
    assert await call(full, original, "get_observation", {}) == before.replace("step 1/", "step 2/")
    orig_objects = (await episodes.get(original).environments["embodied"].final_state())["objects"]
    fork_objects = (await fork.environments["embodied"].final_state())["objects"]
    assert orig_objects != fork_objects


async def test_web_episodes_are_refused_and_nothing_is_created(server):
    full, episodes = server
    start = await full.call_tool("start_episode", {"task_id": "geo-0018-baseline"})
    geo = start.structured_content["episode_id"]
    await fork_episode(episodes, geo)  # no browser: forkable
    start = await full.call_tool("start_episode", {"task_id": "navigation-boston-000"})
    web = start.structured_content["episode_id"]
    runs_before = sorted(p.name for p in episodes.run_dir.iterdir())
    with pytest.raises(ForkError, match="browser environment .* cannot be forked yet"):
        await fork_episode(episodes, web)
    assert sorted(p.name for p in episodes.run_dir.iterdir()) == runs_before
    await call(full, web, "finish_episode", {})
    with pytest.raises(EpisodeError, match="has ended"):
        await fork_episode(episodes, web)


def test_gym_fork_gives_the_same_observations_and_rewards(tmp_path):
    import gymnasium

    import ewa_mcp.gym  # noqa: F401

    env = gymnasium.make("ewa_mcp/geolocation-v0", run_dir=tmp_path, reward="dense")
    try:
        store = env.unwrapped._runtime.episodes.tasks
        store.add(embodied_only(store.get("geo-0079-embodied"), "geo-walk-0100"))  # no wiki browser: forkable
        env.reset(options={"task_id": "geo-walk-0100"})
        env.step({"tool": "geo_move", "arguments": {"direction": "north"}})
        other = env.unwrapped.fork()
        actions = [{"tool": "geo_look", "arguments": {"direction": "all"}},
                   {"tool": "geo_move", "arguments": {"direction": "east"}},
                   {"tool": "submit_location", "arguments": {"lat": 10.0, "lng": 10.0, "continent": "Asia"}}]
        a = [env.step(x) for x in actions]
        b = [other.step(x) for x in actions]
        assert a == b
        assert a[-1][2] is True  # terminated, in both
        other.close()
        env.reset(options={"task_id": "geo-0018-baseline"})  # the shared server outlives the fork
    finally:
        env.close()
