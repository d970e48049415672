"""The Claude and OpenAI agent examples end to end, offline: real SDKs against a scripted wire-format server,
real MCP server, a run directory the grader can read."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import pytest

from ewa_mcp.core.paths import REPO_ROOT

from .fake_llm import FakeLLMServer, ScriptedModel

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

SCRIPT = [("get_observation", {}), ("no_such_tool", {}), ("finish_episode", {"answer": "hello"})]


def load_example(name: str):
    spec = importlib.util.spec_from_file_location(name, REPO_ROOT / "examples" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


EXAMPLES = [("claude_agent", "ANTHROPIC_API_KEY"), ("openai_agent", "OPENAI_API_KEY")]


def run_example(example: str, model: ScriptedModel, run_dir, *args: str) -> tuple[int, Path]:
    """Run an example agent against the scripted model; its exit code and its one episode's directory."""
    with FakeLLMServer(model) as server:
        base = server.url + ("" if example == "claude_agent" else "/v1")
        rc = load_example(example).main(["--model", "scripted", "--base-url", base, "--run-dir", str(run_dir),
                                         "-q", *args])
    (episode,) = [p for p in run_dir.iterdir() if p.is_dir()]
    return rc, episode


@pytest.mark.parametrize("example, key", EXAMPLES)
def test_example_agent_plays_and_records(example, key, tmp_path, monkeypatch):
    monkeypatch.setenv(key, "test-key")
    model = ScriptedModel(SCRIPT)
    rc, episode = run_example(example, model, tmp_path / "run", "--tasks", "demo-hello", "--transport", "inprocess")
    assert rc == 0
    final = json.loads((episode / "final_state.json").read_text())
    assert final["status"] == "finished" and final["answer"] == "hello"
    tools = [json.loads(x)["tool"] for x in (episode / "trajectory.jsonl").read_text().splitlines()]
    assert tools == ["start_episode", "get_observation", "finish_episode"]  # the unknown tool never reached the server

    first = model.requests[0]
    names = [t["name"] if "name" in t else t["function"]["name"] for t in first["tools"]]
    assert "finish_episode" in names and "start_episode" not in names
    params = [t.get("input_schema") or t["function"]["parameters"] for t in first["tools"]]
    assert all("episode_id" not in p.get("properties", {}) for p in params)  # injected by the harness
    # The model was told about its unknown tool and saw the observation of the real one.
    third = json.dumps(model.requests[2])
    assert "unknown tool" in third and "no_such_tool" in third
    second = json.dumps(model.requests[1])
    assert "this episode has no environment" in second or "step 0/10" in second


@pytest.mark.parametrize("example, key", EXAMPLES)
def test_example_agent_plays_a_task_oracle_over_stdio_and_scores_one(example, key, tmp_path, monkeypatch):
    """The scripted-model trick of the Inspect tests, through each example's own path: the model's tool calls
    are a real task's oracle, the server is the default `ewa-mcp serve` over stdio, the grader scores 1.0."""
    from ewa_mcp.graders import grade_episode
    from ewa_mcp.core.paths import tasks_dir
    from ewa_mcp.core.taskmodel import TaskStore

    monkeypatch.setenv(key, "test-key")
    task = TaskStore([tasks_dir()]).all("geolocation")[0]
    model = ScriptedModel([(call.tool, dict(call.args)) for call in task.oracle])
    rc, episode = run_example(example, model, tmp_path / "run", "--tasks", task.id)  # default transport: stdio
    assert rc == 0
    result = grade_episode(episode)
    assert result.overall_success and result.completion == 1.0, (result.error, result.conditions_met)
    assert result.geolocation and all(result.geolocation.get(level) for level in ("continent", "country", "city"))
    tools = [json.loads(x)["tool"] for x in (episode / "trajectory.jsonl").read_text().splitlines()]
    assert tools == ["start_episode", *(call.tool for call in task.oracle)]


@pytest.mark.parametrize("example, key", EXAMPLES)
def test_example_agent_plays_in_a_worker_process(example, key, tmp_path, monkeypatch):
    """--workers: the agent (its adapter factory) is pickled into a worker process that plays the episode."""
    monkeypatch.setenv(key, "test-key")
    monkeypatch.syspath_prepend(str(REPO_ROOT / "examples"))  # the worker imports the example's factory class
    from ewa_mcp.evaluation import workers

    real, seen = workers.play_in_processes, []

    def spy(tasks, agent, **kw):
        seen.append(agent)
        return real(tasks, agent, **kw)

    monkeypatch.setattr(workers, "play_in_processes", spy)
    model = ScriptedModel(SCRIPT)
    rc, episode = run_example(example, model, tmp_path / "run", "--tasks", "demo-hello", "--transport", "inprocess",
                              "--workers", "2")
    assert rc == 0 and len(seen) == 1
    final = json.loads((episode / "final_state.json").read_text())
    assert final["status"] == "finished" and final["answer"] == "hello"
    assert len(model.requests) == 3  # the model was asked from the worker process, once per turn
