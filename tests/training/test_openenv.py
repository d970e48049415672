"""The OpenEnv adapter with the real openenv-core: the oracle earns 1.0 and ends the episode, a no-op earns 0, the
agent's action space has no control tools, and two concurrent sessions on the served app do not cross-talk."""

from __future__ import annotations

import asyncio
import json
import socket
import threading
import time

import pytest

from ewa_mcp.core.paths import task_dirs
from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.openenv_env import EwaAction, EwaEnvClient, EwaOpenEnv, create_ewa_app

from .helpers import ONE_PER_DOMAIN, embodied_only

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

# A street walk without its map site (no browser: starts fast) and a geolocation task as shipped.
WALK = "openenv-walk-000"
GEO = ONE_PER_DOMAIN["geolocation"]


@pytest.fixture(scope="module")
def walk_task():
    store = TaskStore(task_dirs())
    return embodied_only(store.get(ONE_PER_DOMAIN["navigation"]), WALK)


@pytest.fixture(scope="module")
def oracles(walk_task):
    store = TaskStore(task_dirs())
    return {WALK: [(s.tool, dict(s.args)) for s in walk_task.oracle],
            GEO: [(s.tool, dict(s.args)) for s in store.get(GEO).oracle]}


NOOP = {WALK: [("finish_episode", {})], GEO: [("submit_location", {"lat": 0.0, "lng": 0.0})]}
DOMAIN = {WALK: "navigation", GEO: "geolocation"}


def play(env, steps):
    rewards, obs = [], None
    for tool, arguments in steps:
        obs = env.step(EwaAction(tool=tool, arguments=arguments))
        rewards.append(obs.reward)
        if obs.done:
            break
    return rewards, obs


@pytest.mark.parametrize("task_id", [WALK, GEO])
def test_oracle_earns_one_and_ends_noop_earns_zero(task_id, walk_task, oracles, tmp_path):
    env = EwaOpenEnv(DOMAIN[task_id], extra_tasks=[walk_task], run_dir=tmp_path)
    try:
        first = env.reset(seed=0, task_id=task_id)
        assert "Task:" in first.text and not first.done and first.reward == 0.0
        assert env.state.task_id == task_id and env.state.status == "running"
        rewards, last = play(env, oracles[task_id])
        assert len(rewards) == len(oracles[task_id])  # done only on the last step
        assert sum(rewards) == 1.0 and rewards[-1] == 1.0 and last.done
        assert env.state.status == "finished" and env.state.grade["overall_success"] is True
        assert env.state.step_count == len(oracles[task_id])
        with pytest.raises(RuntimeError, match="send a reset"):
            env.step(EwaAction(tool="finish_episode"))

        env.reset(task_id=task_id)  # the same session, a new episode
        rewards, last = play(env, NOOP[task_id])
        assert rewards == [0.0] and last.done
        assert env.state.grade["overall_success"] is False and env.state.step_count == 1
    finally:
        env.close()


def test_the_agent_reaches_no_control_tool(walk_task, tmp_path):
    env = EwaOpenEnv("navigation", extra_tasks=[walk_task], run_dir=tmp_path)
    try:
        first = env.reset(task_id=WALK)
        assert "street_move" in first.tools and "finish_episode" in first.tools
        assert not {"list_tasks", "start_episode"} & set(first.tools)
        assert not any(name.startswith(("geo_", "kitchen_", "browser_")) for name in first.tools)

        # A control tool named anyway is refused as a step, as on the bound MCP plane: the episode goes on.
        for tool, arguments in [("start_episode", {"task_id": GEO}), ("list_tasks", {}),
                                ("street_observe", {"episode_id": "ep-000000000000"})]:
            obs = env.step(EwaAction(tool=tool, arguments=arguments))
            assert obs.ok is False and not obs.done and obs.reward == 0.0
            assert "bound to one episode" in obs.text
        assert env.state.task_id == WALK and env.state.status == "running" and env.state.step_count == 3

        # The action type itself has only the call: nothing to reset, choose a task or name an episode with.
        assert set(EwaAction.model_json_schema()["properties"]) == {"tool", "arguments", "metadata"}
        with pytest.raises(ValueError, match="task_id"):
            EwaAction(tool="street_observe", task_id=GEO)
    finally:
        env.close()


def test_reset_refuses_unknown_tasks_and_parameters(tmp_path):
    env = EwaOpenEnv("geolocation", run_dir=tmp_path)
    try:
        with pytest.raises(RuntimeError, match="send a reset first"):
            env.step(EwaAction(tool="geo_look"))
        with pytest.raises(ValueError, match="unknown task id 'geo-9999'"):
            env.reset(task_id="geo-9999")
        with pytest.raises(ValueError, match="unknown reset parameter"):
            env.reset(difficulty="hard")
        assert env.state.task_id is None
    finally:
        env.close()


def _session(client, task_id, steps, barrier, out):
    """One OpenEnv session over /ws: reset, the steps in lockstep with the other session, then the state."""
    with client.websocket_connect("/ws") as ws:
        def send(message):
            ws.send_text(json.dumps(message))
            reply = json.loads(ws.receive_text())
            assert reply["type"] != "error", reply
            return reply["data"]

        first = send({"type": "reset", "data": {"task_id": task_id, "seed": 0}})
        out["first"] = first["observation"]["text"]
        rewards = []
        for i in range(max(len(s) for s in out["all_steps"])):
            barrier.wait(timeout=60)  # both sessions are mid-episode at once
            if i < len(steps) and not (rewards and out["done"]):
                tool, arguments = steps[i]
                reply = send({"type": "step", "data": {"tool": tool, "arguments": arguments}})
                rewards.append(reply["reward"])
                out["done"] = reply["done"]
        out["rewards"] = rewards
        out["state"] = send({"type": "state"})


def test_two_concurrent_sessions_on_the_app_do_not_cross_talk(walk_task, oracles, tmp_path):
    from fastapi.testclient import TestClient

    app = create_ewa_app("suite", max_concurrent_envs=4, extra_tasks=[walk_task], run_dir=tmp_path)
    runtime = app.state.ewa_runtime
    plans = {WALK: oracles[WALK], GEO: NOOP[GEO] + [("geo_look", {})] * 3}  # the geo session ends first
    outs = {tid: {"all_steps": list(plans.values()), "done": False} for tid in plans}
    barrier = threading.Barrier(2)
    with TestClient(app) as client:
        assert client.get("/health").status_code == 200
        threads = [threading.Thread(target=_session, args=(client, tid, plans[tid], barrier, outs[tid]))
                   for tid in plans]
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=240)
        assert not any(t.is_alive() for t in threads)
        schema = client.get("/schema").json()
        assert set(schema["action"]["properties"]) == {"tool", "arguments", "metadata"}
    walk, geo = outs[WALK], outs[GEO]
    assert "rewards" in walk and "rewards" in geo, outs  # both sessions ran to the end
    assert sum(walk["rewards"]) == 1.0 and walk["done"] and len(walk["rewards"]) == len(plans[WALK])
    assert geo["rewards"] == [0.0] and geo["done"]
    assert walk["state"]["task_id"] == WALK and walk["state"]["step_count"] == len(plans[WALK])
    assert geo["state"]["task_id"] == GEO and geo["state"]["step_count"] == 1
    assert walk["state"]["grade"]["overall_success"] is True and geo["state"]["grade"]["overall_success"] is False
    assert walk["state"]["record_id"] != geo["state"]["record_id"]
    assert "Where in the world" in geo["first"] and "Where in the world" not in walk["first"]
    assert runtime.closed  # the app's shutdown stops its ewa-mcp server


async def _client_session(url, task_id, steps, turn):
    """One session through openenv's own WebSocket client over real HTTP; ``turn`` makes the sessions alternate."""
    async with EwaEnvClient(url) as client:
        first = await client.reset(task_id=task_id)
        rewards = []
        for tool, arguments in steps:
            await turn(task_id)
            result = await client.step(EwaAction(tool=tool, arguments=arguments))
            rewards.append(result.reward)
            if result.done:
                break
        return first.observation, rewards, result.done, await client.state()


def test_openenv_client_sessions_over_loopback_http(walk_task, oracles, tmp_path):
    import uvicorn

    app = create_ewa_app("suite", max_concurrent_envs=2, extra_tasks=[walk_task], run_dir=tmp_path)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    try:
        while not server.started:
            time.sleep(0.01)
        plans = {WALK: oracles[WALK], GEO: oracles[GEO]}

        async def both():
            order = asyncio.Condition()
            last = {"task": GEO}

            async def turn(task_id):  # strict alternation while both run, so their steps interleave
                async with order:
                    await asyncio.wait_for(order.wait_for(lambda: last["task"] != task_id or last.get("alone")), 60)
                    last["task"] = task_id
                    order.notify_all()

            async def run(task_id):
                try:
                    return await _client_session(f"http://127.0.0.1:{port}", task_id, plans[task_id], turn)
                finally:
                    async with order:
                        last["alone"] = True
                        order.notify_all()

            return await asyncio.gather(run(WALK), run(GEO))

        (walk_first, walk_rewards, walk_done, walk_state), (geo_first, geo_rewards, geo_done, geo_state) = (
            asyncio.run(both()))
    finally:
        server.should_exit = True
        thread.join(timeout=30)
    assert sum(walk_rewards) == 1.0 and walk_done and sum(geo_rewards) == 1.0 and geo_done
    assert walk_state.task_id == WALK and walk_state.step_count == len(plans[WALK])
    assert geo_state.task_id == GEO and geo_state.step_count == len(plans[GEO])
    assert walk_state.grade["overall_success"] and geo_state.grade["overall_success"]
    assert "street_move" in walk_first.tools and "geo_look" in geo_first.tools
    assert "geo_look" not in walk_first.tools and "street_move" not in geo_first.tools
    assert app.state.ewa_runtime.closed
