"""End to end: the committed task suites, played by the oracle through the real MCP server (real
Chromium, kitchen, street graphs, sites), graded from the run directory alone. One task per domain;
the whole suite runs in benchmarks/bench_oracle_suite.py."""

from __future__ import annotations

import json
import shutil

import anyio
import pytest

from ewa_mcp.evaluation.agents import NoopAgent, OracleAgent, RandomAgent
from ewa_mcp.evaluation.runner import run_eval, select_tasks
from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

DOMAINS = ["cooking", "navigation", "shopping", "traveling", "geolocation"]
needs_browser = pytest.mark.skipif(
    not (shutil.which("chromium") or shutil.which("chromium-browser")), reason="no Chromium: apt-get install chromium")


@pytest.fixture(scope="module")
def sample():
    store = TaskStore([tasks_dir()])
    assert not store.errors, store.errors[:3]
    tasks = select_tasks(store, None, 1, DOMAINS)
    # the buy-online cooking variant exercises the shop -> kitchen delivery path too
    tasks += [t for t in store.all("cooking") if t.metadata.get("buy")][:1]
    return tasks


def play(agent, tasks, run_dir):
    return anyio.run(lambda: run_eval(tasks, agent, run_dir=run_dir, task_dirs=[tasks_dir()], workers=2,
                                      progress=False))


def test_suite_counts_meet_the_paper():
    store = TaskStore([tasks_dir()])
    counts = {d: len(store.all(d)) for d in DOMAINS}
    assert counts["cooking"] >= 900 and counts["navigation"] >= 144 and counts["shopping"] >= 216
    assert counts["traveling"] >= 110 and counts["geolocation"] >= 142
    buy = [t for t in store.all("cooking") if t.metadata.get("buy")]
    assert len(buy) >= 30
    cities = {t.start.embodied.city for t in store.all("navigation")}
    assert cities == {"manhattan", "philadelphia", "boston", "pittsburgh"}


@needs_browser
def test_oracle_solves_one_task_per_domain(sample, tmp_path):
    summary = play(OracleAgent(), sample, tmp_path / "oracle")
    assert not [o for o in summary.outcomes if o.failure]
    report = grade_run(tmp_path / "oracle")
    failed = [(e.task_id, e.problems, [c.description for c in e.conditions if c.met is False])
              for e in report.episodes if not e.overall_success]
    assert not failed
    assert {e.domain for e in report.episodes} == set(DOMAINS)


@needs_browser
def test_noop_and_random_agents_fail(sample, tmp_path):
    for agent in (NoopAgent(), RandomAgent(seed=1)):
        run = tmp_path / agent.name
        play(agent, sample, run)
        report = grade_run(run)
        assert not any(e.overall_success for e in report.episodes), agent.name
        # every episode still left a complete record
        assert all(json.loads((run / e.episode_id / "final_state.json").read_text())["status"] for e in
                   report.episodes)
