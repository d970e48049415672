"""The server admits what it can serve: a cap on open episodes (per server and per client), idle episodes ended
as aborted with the reason, and episodes owned by the server, so one client leaving ends no other's."""

from __future__ import annotations

import json

import anyio
import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.settings import load_settings

from .fixtures import CounterEnv, NoteEnv, counter_task, register, write_tasks

pytestmark = pytest.mark.anyio


def _server(tmp_path, **settings):
    tasks = write_tasks(tmp_path / "tasks", [counter_task(), counter_task("t-other", step_limit=10_000)])
    mcp, episodes = build_server(ServerConfig(settings=load_settings(settings), task_dirs=[tasks],
                                              run_dir=tmp_path / "run",
                                              environments={"kitchen": CounterEnv, "browser": NoteEnv}))
    register(mcp, episodes)
    return mcp, episodes


def _text(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


async def _start(client, task_id="t-counter") -> str:
    r = await client.call_tool("start_episode", {"task_id": task_id})
    assert not r.is_error, _text(r)
    return r.structured_content["episode_id"]


async def test_one_client_leaving_ends_no_other_clients_episodes(tmp_path):
    mcp, episodes = _server(tmp_path)
    async with Client(mcp) as staying:
        async with Client(mcp) as leaving:
            mine = await _start(staying)
            theirs = await _start(leaving)
        # The client that started `theirs` has gone: both episodes still run, owned by the server.
        assert episodes.get(mine).status == "running" and episodes.get(theirs).status == "running"
        r = await staying.call_tool("counter_add", {"episode_id": mine, "amount": 2})
        assert not r.is_error, _text(r)
        # Any client may finish an episode by its id, also one another client started.
        for episode_id in (mine, theirs):
            r = await staying.call_tool("finish_episode", {"episode_id": episode_id, "answer": "three"})
            assert r.structured_content["status"] == "finished", _text(r)
    for episode_id in (mine, theirs):
        final = json.loads((tmp_path / "run" / episode_id / "final_state.json").read_text())
        assert final["status"] == "finished"


async def test_the_last_client_leaving_stops_the_in_process_server(tmp_path):
    mcp, episodes = _server(tmp_path)
    async with Client(mcp) as first, Client(mcp) as second:
        a, b = await _start(first), await _start(second)
    for episode_id in (a, b):
        final = json.loads((tmp_path / "run" / episode_id / "final_state.json").read_text())
        assert final["status"] == "aborted" and "shut down" in final["end_reason"]
    # The server object can be connected again: a new client is served as by a fresh start.
    async with Client(mcp) as again:
        await _start(again)


async def test_the_server_refuses_past_its_cap_and_names_the_setting(tmp_path):
    mcp, episodes = _server(tmp_path, max_episodes=2)
    async with Client(mcp) as client:
        first = await _start(client)
        await _start(client, "t-other")
        before = sorted(p.name for p in (tmp_path / "run").iterdir())
        refused = await client.call_tool("start_episode", {"task_id": "t-counter"})
        assert refused.is_error
        assert "2 open episodes" in _text(refused) and "EWA_MAX_EPISODES" in _text(refused)
        assert sorted(p.name for p in (tmp_path / "run").iterdir()) == before  # nothing recorded, nothing started
        status = await client.call_tool("episode_status", {"episode_id": first})
        assert status.structured_content["server"]["open_episodes"] == 2
        assert status.structured_content["server"]["max_episodes"] == 2
        assert "2 open episodes of at most 2" in _text(status)
        await client.call_tool("finish_episode", {"episode_id": first, "answer": "three"})
        await _start(client)  # a place is free again


async def test_the_cap_per_client_counts_each_clients_episodes(tmp_path):
    mcp, episodes = _server(tmp_path, max_episodes_per_client=1)
    async with Client(mcp) as one, Client(mcp) as two:
        await _start(one)
        refused = await one.call_tool("start_episode", {"task_id": "t-other"})
        assert refused.is_error and "EWA_MAX_EPISODES_PER_CLIENT" in _text(refused)
        await _start(two)  # another client has its own allowance
        assert episodes.open_episodes() == 2


async def test_idle_episodes_are_ended_as_aborted_with_the_reason(tmp_path):
    mcp, episodes = _server(tmp_path, episode_idle_s=2.0)
    async with Client(mcp) as client:
        idle = await _start(client)
        busy = await _start(client, "t-other")
        status = await client.call_tool("episode_status", {"episode_id": busy})
        assert status.structured_content["server"]["idle_timeout_s"] == 2.0
        # The background sweep ends the idle episode; the one that keeps acting stays.
        with anyio.fail_after(30):
            while episodes.get(idle).status == "running":
                await client.call_tool("counter_add", {"episode_id": busy, "amount": 1})
                await anyio.sleep(0.1)
        assert episodes.get(busy).status == "running"
        refused = await client.call_tool("counter_add", {"episode_id": idle, "amount": 1})
        assert refused.is_error and "has ended (idle" in _text(refused)
        status = await client.call_tool("episode_status", {"episode_id": idle})
        assert status.structured_content["status"] == "aborted"
        assert status.structured_content["server"]["reaped_idle"] == 1
    final = json.loads((tmp_path / "run" / idle / "final_state.json").read_text())
    assert final["status"] == "aborted"
    assert "no call for" in final["end_reason"] and "EWA_EPISODE_IDLE_S" in final["end_reason"]


async def test_an_episode_in_the_middle_of_a_call_is_never_reaped(tmp_path):
    mcp, episodes = _server(tmp_path, episode_idle_s=3600)
    async with Client(mcp) as client:
        episode_id = await _start(client)
        episode = episodes.get(episode_id)
        episode.last_call -= 7200  # as if idle for two hours
        async with episode.lock:  # a call is running
            assert await episodes.reap_idle() == 0
        assert episode.status == "running"
        assert await episodes.reap_idle() == 1
        assert episode.status == "aborted"
