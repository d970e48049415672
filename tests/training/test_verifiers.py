"""The verifiers adapter with the real verifiers 0.4: a rollout whose scripted model plays the oracle's tool calls
gets 1.0 from the task's reward, a wrong one 0.0; each rollout plays its own bound episode; load_environment builds
the environment verifiers would run. The model is a local OpenAI-compatible server with a script (no LLM, no
network): verifiers' own interception endpoint forwards the harness's requests to it."""

from __future__ import annotations

import asyncio

import pytest
import verifiers.v1 as vf

import ewa_mcp.verifiers_env as ewa_vf
from ewa_mcp.gym import _Runtime

from examples.fake_llm import FakeLLMServer, ScriptedModel
from .helpers import ONE_PER_DOMAIN

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

GEO = ONE_PER_DOMAIN["geolocation"]
WALK = "verifiers-walk-000"  # the navigation task without its map site: a street walk, no browser


@pytest.fixture
def tasks(tmp_path, monkeypatch):
    """The taskset's tasks by id, on a server of the test's own (records in tmp_path); the walk is added to it."""
    from ewa_mcp.task_variants import embodied_only

    monkeypatch.setenv("EWA_TEST_KEY", "unused")
    run_dir = str(tmp_path)
    server = ewa_vf._runtime((), run_dir)
    server.episodes.tasks.add(embodied_only(server.episodes.tasks.get(ONE_PER_DOMAIN["navigation"]), WALK))
    yield {t.data.task_id: t for t in ewa_vf.taskset("suite", tasks=[GEO, WALK], run_dir=run_dir)}, server
    ewa_vf.shutdown()


def oracle(server: _Runtime, task_id: str) -> list[tuple[str, dict]]:
    return [(s.tool, dict(s.args)) for s in server.episodes.tasks.get(task_id).oracle]


async def rollout(task, script):
    model = ScriptedModel(script)
    with FakeLLMServer(model) as llm:
        agent = vf.Agent(ewa_vf.agent_config("scripted", f"{llm.url}/v1", api_key_var="EWA_TEST_KEY"))
        async with agent:
            trace = await agent.run(task)
    return trace, model


def test_taskset_yields_the_chosen_tasks_with_their_intent(tasks):
    by_id, server = tasks
    assert set(by_id) == {GEO, WALK}
    geo = by_id[GEO]
    assert isinstance(geo, ewa_vf.EwaTask) and geo.data.prompt == server.episodes.tasks.get(GEO).intent
    assert geo.data.system_prompt and "list_tasks" not in geo.data.system_prompt


@pytest.mark.parametrize("task_id", [GEO, WALK])
def test_oracle_rollout_earns_one_wrong_rollout_zero(task_id, tasks):
    by_id, server = tasks
    trace, model = asyncio.run(rollout(by_id[task_id], oracle(server, task_id)))
    assert trace.ok, trace.errors
    assert trace.rewards["success"].score == 1.0 and trace.metrics["completion"] == 1.0
    assert len(model.requests) == len(oracle(server, task_id))  # one model turn per tool call, through verifiers
    first = model.requests[0]
    tool_names = {t["function"]["name"] for t in first["tools"]}
    assert not {"list_tasks", "start_episode"} & tool_names  # the bound plane's tools only
    assert not any("episode_id" in (t["function"]["parameters"].get("properties") or {}) for t in first["tools"])
    assert "Task:" in first["messages"][1]["content"]  # the episode's start text: the task and first observation

    wrong = ([("submit_location", {"lat": -33.9, "lng": 151.2})] if task_id == GEO
             else [("street_stop", {})])  # a walk ended where it started
    trace, _ = asyncio.run(rollout(by_id[task_id], wrong))
    assert trace.ok, trace.errors
    assert trace.rewards["success"].score == 0.0 and trace.metrics["completion"] < 1.0


def test_a_model_that_stops_early_scores_zero_and_each_rollout_has_its_own_episode(tasks):
    by_id, server = tasks
    steps = oracle(server, WALK)
    trace_a, _ = asyncio.run(rollout(by_id[WALK], steps[:2]))  # two moves, then a reply without a tool call
    trace_b, _ = asyncio.run(rollout(by_id[WALK], steps))
    assert trace_a.rewards["success"].score == 0.0 and trace_b.rewards["success"].score == 1.0
    records = sorted(p.name for p in server.episodes.run_dir.iterdir() if p.is_dir())
    assert len(records) >= 2  # two episodes, two records
    assert not ewa_vf._LIVE  # every rollout's episode was released after scoring


def test_load_environment_builds_a_single_agent_env_on_the_harness(tmp_path):
    try:
        env = ewa_vf.load_environment("geolocation", tasks=[GEO], run_dir=str(tmp_path))
        assert isinstance(env, vf.SingleAgentEnv)
        assert isinstance(env._harnesses["agent"], ewa_vf.EwaHarness)
        assert [t.data.task_id for t in env.taskset] == [GEO]
        with pytest.raises(ValueError, match="needs one domain"):
            list(ewa_vf.taskset("suite", split="train", split_seed=1, run_dir=str(tmp_path)))
    finally:
        ewa_vf.shutdown()
