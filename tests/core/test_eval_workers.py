"""`ewa-mcp eval --workers N`: episodes spread over worker processes land in one run directory, each task exactly
once, graded as a one-process run grades them; a worker killed mid-episode has that episode played again
elsewhere and its partial record never lands."""

from __future__ import annotations

import json
import os
import signal
import threading
import time
from collections import Counter
from pathlib import Path

import anyio
import pytest

from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.ledger import Ledger
from ewa_mcp.evaluation.runner import EvalError, run_eval, select_tasks
from ewa_mcp.evaluation.workers import STAGING, play_in_processes
from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow


def small_tasks():
    store = TaskStore([tasks_dir()])
    return select_tasks(store, None, 3, ["geolocation", "navigation"]) + select_tasks(store, ["demo-*"], None)


class StallOnce(OracleAgent):
    """The oracle, except that the first time it meets `target` it writes its pid to `marker` and stalls."""

    def __init__(self, target: str, marker: Path):
        self.target, self.marker = target, marker

    async def play(self, s):
        if s.task.id == self.target and not self.marker.exists():
            partial = self.marker.with_suffix(".partial")  # written then renamed: the test never reads it half-written
            partial.write_text(str(os.getpid()))
            partial.replace(self.marker)
            await anyio.sleep(120)
        await super().play(s)


def landed(run_dir: Path) -> Counter:
    """task id -> how many episode folders of the run directory hold it."""
    return Counter(json.loads((d / "task.json").read_text())["id"]
                   for d in run_dir.iterdir() if (d / "task.json").exists())


def grades(run_dir: Path) -> dict[str, tuple]:
    return {e.task_id: (e.overall_success, tuple(c.met for c in e.conditions)) for e in grade_run(run_dir).episodes}


def grades_in_one_process(tasks, run_dir: Path) -> dict[str, tuple]:
    """The oracle's grades for these tasks played in this process: what every other way of running must match."""
    anyio.run(lambda: run_eval(tasks, OracleAgent(), run_dir=run_dir, task_dirs=[tasks_dir()], progress=False))
    return grades(run_dir)


@pytest.fixture(scope="module")
def one_process_grades(tmp_path_factory):
    return grades_in_one_process(small_tasks(), tmp_path_factory.mktemp("one-process"))


def drive_until_stalled(play, marker: Path) -> tuple[threading.Thread, dict, int]:
    """Run ``play()`` in a thread until the StallOnce episode has started; return the thread, the dict its
    summary lands in (``result["summary"]``) and the pid of the process holding the stalled episode."""
    result: dict = {}
    driver = threading.Thread(target=lambda: result.update(summary=play()))
    driver.start()
    deadline = time.monotonic() + 120
    while not marker.exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert marker.exists(), "the stalling episode never started"
    return driver, result, int(marker.read_text())


def test_two_workers_land_each_episode_once_even_when_one_is_killed(tmp_path, one_process_grades):
    """Every task's episode lands exactly once and grades as in one process; the episode a killed worker was
    playing is played again by another, and its partial record (open in the dead worker's staging folder)
    never reaches the run directory."""
    tasks = small_tasks()
    target = tasks[len(tasks) // 2].id
    marker = tmp_path / "stalled.pid"
    run_dir = tmp_path / "run"
    # Two episodes at once in each worker: the killed one holds the stalled episode and maybe another.
    driver, result, pid = drive_until_stalled(
        lambda: play_in_processes(tasks, StallOnce(target, marker), workers=2, concurrency=2, run_dir=run_dir,
                                  task_dirs=[tasks_dir()], progress=False), marker)
    # The stalled episode's record is open in that worker's staging folder, not in the run directory.
    assert target not in landed(run_dir)
    os.kill(pid, signal.SIGKILL)
    driver.join(timeout=180)
    assert not driver.is_alive()
    summary = result["summary"]
    assert not [o.failure for o in summary.outcomes if o.failure]
    assert sorted(o.task_id for o in summary.outcomes) == sorted(t.id for t in tasks)
    assert landed(run_dir) == Counter(t.id for t in tasks)
    assert all((d / "final_state.json").exists() for d in run_dir.iterdir())
    assert not (run_dir / STAGING).exists()
    assert grades(run_dir) == one_process_grades


def test_an_agent_that_cannot_be_pickled_is_refused_with_the_fix(tmp_path):
    agent = OracleAgent()
    agent.hook = lambda: None  # a lambda cannot cross to a process
    with pytest.raises(EvalError, match="picklable.*--workers 1"):
        play_in_processes(small_tasks()[:1], agent, workers=2, run_dir=tmp_path, task_dirs=[tasks_dir()],
                          progress=False)


def test_ledger_accepts_each_slot_once_and_takes_back_a_lost_workers_slots():
    tasks = small_tasks()[:3]
    ledger = Ledger(tasks, max_attempts=2)
    a, b = ledger.take("a"), ledger.take("b")
    ok = ledger.finish("b", b, object())
    assert ok and not ledger.finish("b", b, object())  # a second outcome for the same slot is dropped
    assert ledger.lost("a", "killed") == []  # back in the queue, first in line
    assert not ledger.finish("a", a, object())  # a lost worker's late outcome is dropped
    assert ledger.take("c") == a
    (given_up,) = ledger.lost("c", "killed again")
    assert given_up.task_id == tasks[a].id and "died 2 times" in given_up.failure
    c = ledger.take("c")
    assert ledger.finish("c", c, object()) and ledger.complete


def scale_args(*argv):
    from ewa_mcp.cli import build_parser
    from ewa_mcp.evaluation.scale import scale_options

    return scale_options(build_parser().parse_args(["eval", *argv]))


def test_scale_options_read_and_refuse_with_the_fix():
    assert scale_args().workers == 1 and scale_args().ray is None
    opts = scale_args("--workers", "3", "--concurrency", "2")
    assert (opts.workers, opts.concurrency) == (3, 2)
    assert scale_args("--ray").ray.address is None  # Ray's own rule: RAY_ADDRESS, the local cluster, a new one
    ray = scale_args("--ray", "head:6379", "--ray-actors", "4", "--ray-num-cpus", "2").ray
    assert (ray.address, ray.actors, ray.num_cpus) == ("head:6379", 4, 2.0)
    for argv, fix in [(["--workers", "0"], "at least 1"), (["--concurrency", "0"], "at least 1"),
                      (["--ray", "--workers", "2"], "--ray-actors"), (["--ray-actors", "2"], "needs --ray"),
                      (["--ray", "--ray-num-cpus", "0"], "positive")]:
        with pytest.raises(EvalError, match=fix):
            scale_args(*argv)


def test_ray_is_not_imported_unless_asked_for():
    import subprocess
    import sys

    code = ("import sys, ewa_mcp.cli, ewa_mcp.evaluation.runner, ewa_mcp.evaluation.workers, "
            "ewa_mcp.evaluation.scale; ewa_mcp.cli.build_parser(); print('ray' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "False", out.stderr[-500:]
