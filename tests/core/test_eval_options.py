"""`ewa-mcp eval --observation MODE`: the agent's episode options reach start_episode, so the oracle plays in
any observation mode through the real in-process server."""

from __future__ import annotations

import json

import pytest
from mcp import Client

from ewa_mcp.cli import build_parser
from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.playing import play_episode
from ewa_mcp.server import ServerConfig, build_server

from .fixtures import CounterEnv, NoteEnv, counter_task, register, write_tasks

pytestmark = pytest.mark.anyio


@pytest.mark.parametrize("options", [None, {"observation": "vision"}])
async def test_play_episode_passes_the_agents_episode_options(tmp_path, options):
    tasks = write_tasks(tmp_path / "tasks", [counter_task()])
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "run",
                                              environments={"kitchen": CounterEnv, "browser": NoteEnv}))
    register(mcp, episodes)
    agent = OracleAgent()
    if options:
        agent.episode_options = options
    task = episodes.tasks.get("t-counter")
    async with Client(mcp) as client:
        outcome = await play_episode(client, task, agent)
    assert outcome.failure is None and outcome.episode_id
    first = json.loads((tmp_path / "run" / outcome.episode_id / "trajectory.jsonl").read_text().splitlines()[0])
    assert first["tool"] == "start_episode"
    assert first["args"]["options"]["observation"] == (options or {"observation": "text"})["observation"]


def test_eval_accepts_an_observation_mode_and_refuses_others(capsys):
    parser = build_parser()
    assert parser.parse_args(["eval", "--observation", "vision"]).observation == "vision"
    assert parser.parse_args(["eval"]).observation is None
    with pytest.raises(SystemExit):
        parser.parse_args(["eval", "--observation", "pictures"])
    assert "invalid choice" in capsys.readouterr().err
