"""export-sft: a recorded run becomes chat-format JSONL whose observations are the full ones the agent saw."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from ewa_mcp.evaluation.agents import NoopAgent, OracleAgent
from ewa_mcp.evaluation.runner import play
from ewa_mcp.core.paths import task_dirs
from ewa_mcp.settings import load_settings
from ewa_mcp.core.taskmodel import TaskStore

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = [pytest.mark.browser, pytest.mark.slow]
TASKS = ["geo-0018-baseline", "navigation-boston-000"]


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """An oracle run of two tasks, plus one failed episode (a walk finished where it started)."""
    dirs = task_dirs(load_settings())
    store = TaskStore(dirs)
    run_dir = tmp_path_factory.mktemp("run")
    play([store.get(t) for t in TASKS], OracleAgent(), run_dir=run_dir, task_dirs=dirs, progress=False)
    play([store.get("navigation-boston-001")], NoopAgent(), run_dir=run_dir, task_dirs=dirs, progress=False)
    return run_dir


def export(run_dir, out, *extra):
    proc = subprocess.run([sys.executable, "-m", "ewa_mcp", "export-sft", str(run_dir), "-o", str(out), *extra],
                          capture_output=True, text=True, timeout=300)
    lines = [json.loads(x) for x in out.read_text().splitlines()] if out.exists() else []
    return proc, lines


def test_successful_episodes_become_chat_lines_with_full_observations(run, tmp_path):
    proc, lines = export(run, tmp_path / "sft.jsonl")
    assert proc.returncode == 0, proc.stderr
    assert "2 episode(s) written" in proc.stderr and "1 unsuccessful left out" in proc.stderr
    by_task = {line["metadata"]["task_id"]: line for line in lines}
    assert set(by_task) == set(TASKS)
    nav = by_task["navigation-boston-000"]
    messages = nav["messages"]
    assert [m["role"] for m in messages[:2]] == ["system", "user"]
    assert "Task: Starting at the corner of Berkeley Street" in messages[1]["content"]
    calls = [m["tool_calls"][0]["function"] for m in messages if m["role"] == "assistant"]
    oracle = TaskStore(task_dirs(load_settings())).get("navigation-boston-000").oracle
    assert [c["name"] for c in calls] == [s.tool for s in oracle]
    assert json.loads(calls[0]["arguments"]) == oracle[0].args
    results = [m for m in messages if m["role"] == "tool"]
    assert len(results) == len(calls)
    # The whole directions page, not the record's 240-character digest; and no episode id anywhere.
    assert len(results[0]["content"]) > 2000 and "Accessibility tree" in results[0]["content"]
    assert nav["metadata"]["episode_id"] not in json.dumps(messages)
    names = {t["function"]["name"] for t in nav["tools"]}
    assert {"browser_goto", "street_move", "finish_episode"} <= names and "start_episode" not in names
    assert all("episode_id" not in t["function"]["parameters"]["properties"] for t in nav["tools"])


def test_all_keeps_failed_episodes_and_a_record_that_does_not_replay_is_left_out(run, tmp_path):
    proc, lines = export(run, tmp_path / "all.jsonl", "--all")
    assert proc.returncode == 0 and len(lines) == 3
    assert sorted(line["metadata"]["success"] for line in lines) == [False, True, True]
    # Tamper with a record: a move the agent never made cannot be replayed into what it saw.
    geo = next(p for p in run.iterdir() if p.is_dir() and "geo-0018-baseline" in (p / "task.json").read_text())
    trajectory = geo / "trajectory.jsonl"
    saved = trajectory.read_text()
    try:
        lines_ = [json.loads(x) for x in saved.splitlines()]
        lines_[1]["args"] = {"direction": "bogus"}  # geo_look(direction="north") -> an invalid direction
        trajectory.write_text("".join(json.dumps(x) + "\n" for x in lines_))
        proc, lines = export(run, tmp_path / "tampered.jsonl")
        assert proc.returncode == 0
        assert [line["metadata"]["task_id"] for line in lines] == ["navigation-boston-000"]
        assert f"left out, did not replay as recorded: {geo.name}" in proc.stderr
    finally:
        trajectory.write_text(saved)


def test_a_directory_without_episodes_is_refused(tmp_path):
    proc, _ = export(tmp_path, tmp_path / "x.jsonl")
    assert proc.returncode == 2 and "holds no episode directories" in proc.stderr
    assert not (tmp_path / "x.jsonl").exists()
