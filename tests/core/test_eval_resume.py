"""Resumable, honest eval runs: `ewa-mcp eval` into an existing run directory plays only the tasks missing or cut
off there (each task counted once, a cut-off episode's folder replaced); what infrastructure cut off (a server
that shut down, a browser that cannot start, a worker that keeps dying) is recorded and reported apart from the
agent's failures, never scored, and makes the exit status non-zero; a missing Chromium stops the run before the
first episode with the message that fixes it."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
from collections import Counter
from pathlib import Path

import anyio
import pytest
from mcp import Client

from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.runner import play, select_tasks
from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.core.taskmodel import TaskStore

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

GEO = "geo-000[1-4]-baseline"  # four geolocation tasks without a browser: quick to play
CHROMIUM = Path("/usr/bin/chromium")

# A process that opens an episode on a server of its own and is then killed: the record it leaves has no final
# state, as after a power cut or `kill -9` of an eval.
KILLED = textwrap.dedent("""
    import sys
    from pathlib import Path
    import anyio
    from mcp import Client
    from ewa_mcp.server import ServerConfig, build_server

    async def main():
        mcp, _ = build_server(ServerConfig(run_dir=Path(sys.argv[1])))
        async with Client(mcp) as client:
            r = await client.call_tool("start_episode", {"task_id": sys.argv[2]})
            episode = r.structured_content["episode_id"]
            await client.call_tool("geo_look", {"episode_id": episode, "direction": "north"})
            print(episode, flush=True)
            await anyio.sleep(600)

    anyio.run(main)
""")


def env(**extra: str) -> dict[str, str]:
    return {**{k: v for k, v in os.environ.items() if not k.startswith("EWA_")}, **extra}


def eval_cli(*argv: str, **extra_env: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", *argv], capture_output=True, text=True,
                          timeout=300, env=env(**extra_env), check=False)


def landed(run_dir: Path) -> Counter[str]:
    return Counter(json.loads((d / "task.json").read_text())["id"] for d in run_dir.iterdir()
                   if (d / "task.json").exists())


def folders_of(run_dir: Path, task_id: str) -> list[Path]:
    return [d for d in run_dir.iterdir() if (d / "task.json").exists()
            and json.loads((d / "task.json").read_text())["id"] == task_id]


def killed_mid_episode(run_dir: Path, task_id: str) -> Path:
    child = subprocess.Popen([sys.executable, "-c", KILLED, str(run_dir), task_id], stdout=subprocess.PIPE,
                             text=True, env=env())
    try:
        assert child.stdout is not None
        episode = child.stdout.readline().strip()
        assert episode.startswith("ep-"), "the episode did not start"
    finally:
        child.send_signal(signal.SIGKILL)
        child.wait(timeout=30)
    return run_dir / episode


async def shut_down_mid_episode(run_dir: Path, task_id: str) -> Path:
    """A server that stops while an episode runs (its client went away)."""
    mcp, _ = build_server(ServerConfig(run_dir=run_dir))
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": task_id})
        episode = r.structured_content["episode_id"]
    return run_dir / episode


def test_resume_plays_only_what_is_missing_or_cut_off(tmp_path: Path) -> None:
    run = tmp_path / "run"
    first = eval_cli("--agent", "oracle", "--tasks", "geo-0001-baseline", "--tasks", "geo-0002-baseline",
                     "--run-dir", str(run), "-q")
    assert first.returncode == 0, first.stderr[-2000:]
    killed = killed_mid_episode(run, "geo-0003-baseline")
    stopped = anyio.run(shut_down_mid_episode, run, "geo-0004-baseline")
    assert not (killed / "final_state.json").exists()
    final = json.loads((stopped / "final_state.json").read_text())
    assert final["status"] == "aborted" and "server shut down" in final["infrastructure_failure"]

    # Graded as it stands: the server's shutdown is reported apart, not as the agent's failure.
    before = grade_run(run)
    assert before.infrastructure == {"geolocation": 1} and before.domains["geolocation"].n == 3
    assert any("geo-0004-baseline" in line for line in before.infrastructure_failures)

    resumed = eval_cli("--agent", "oracle", "--tasks", GEO, "--run-dir", str(run), "--format", "json")
    assert resumed.returncode == 0, resumed.stderr[-2000:]
    assert (f"resuming {run}: 2 of 4 selected tasks already played, 2 to play; 2 cut-off episode(s) replaced"
            in resumed.stderr)
    assert landed(run) == Counter({f"geo-000{k}-baseline": 1 for k in range(1, 5)})  # each task once
    assert not killed.exists() and not stopped.exists()  # the cut-off folders were replaced
    report = json.loads(resumed.stdout)
    assert report["infrastructure"] == {} and report["n_episodes"] == 4
    assert report["domains"]["geolocation"]["overall_accuracy"]["value"] == 1.0  # the oracle's 100 %, not 75 %

    again = eval_cli("--agent", "oracle", "--tasks", GEO, "--run-dir", str(run), "-q")
    assert again.returncode == 0 and "4 of 4 selected tasks already played, 0 to play" in again.stderr
    assert sum(landed(run).values()) == 4

    other = eval_cli("--agent", "noop", "--tasks", GEO, "--run-dir", str(run), "-q")
    assert other.returncode == 2 and "holds a run of agent 'oracle'" in other.stderr
    assert "Pass another --run-dir" in other.stderr and sum(landed(run).values()) == 4


def test_a_browser_that_cannot_start_is_an_infrastructure_failure_not_a_zero(tmp_path: Path) -> None:
    broken = tmp_path / "chromium"
    broken.write_text("#!/bin/sh\necho 'this browser cannot start' >&2\nexit 1\n")
    broken.chmod(0o755)
    run = tmp_path / "run"
    done = eval_cli("--agent", "oracle", "--domain", "traveling", "--domain", "demo", "--sample", "1",
                    "--run-dir", str(run), "--format", "json", EWA_CHROMIUM=str(broken))
    assert done.returncode == 1, done.stderr[-2000:]
    assert "not scored; run the same command with --run-dir" in done.stderr
    report = json.loads(done.stdout)
    assert report["infrastructure"] == {"traveling": 1}
    traveling = report["domains"]["traveling"]
    assert traveling["n"] == 0 and traveling["overall_accuracy"]["value"] is None  # n/a, not 0 %
    assert report["demo"]["overall_accuracy"]["value"] == 1.0  # what could be played is scored as usual
    (line,) = report["infrastructure_failures"]
    assert "the browser environment could not start" in line
    (cut,) = [e for e in report["episodes"] if e["infrastructure_failure"]]
    assert cut["error"] is None  # no agent error category

    table = subprocess.run([sys.executable, "-m", "ewa_mcp.graders.cli", str(run)], capture_output=True,
                           text=True, timeout=120, check=False).stdout
    assert "Not scored: infrastructure failures" in table and "Infrastructure failures (not scored)" in table

    if not CHROMIUM.exists():
        return
    # With a working browser, the same command plays just the task that was cut off.
    again = eval_cli("--agent", "oracle", "--domain", "traveling", "--domain", "demo", "--sample", "1",
                     "--run-dir", str(run), "--format", "json")
    assert again.returncode == 0, again.stderr[-2000:]
    assert "1 of 2 selected tasks already played, 1 to play; 1 cut-off episode(s) replaced" in again.stderr
    report = json.loads(again.stdout)
    assert report["infrastructure"] == {} and report["domains"]["traveling"]["overall_accuracy"]["value"] == 1.0
    assert sum(landed(run).values()) == 2


def test_a_missing_chromium_stops_the_run_before_the_first_episode(tmp_path: Path) -> None:
    run = tmp_path / "run"
    done = eval_cli("--agent", "oracle", "--sample", "1", "--run-dir", str(run), "-q",
                    EWA_CHROMIUM=str(tmp_path / "no-such-chromium"))
    assert done.returncode == 2
    assert "need a browser and none can be started" in done.stderr and "apt-get install chromium" in done.stderr
    assert "Nothing was played" in done.stderr and "Traceback" not in done.stderr
    assert not run.exists()


class DiesOn(OracleAgent):
    """The oracle, except that its worker process dies whenever it meets `target`."""

    def __init__(self, target: str):
        self.target = target

    async def play(self, s):  # type: ignore[no-untyped-def]
        if s.task.id == self.target:
            os._exit(3)
        await super().play(s)


def test_a_task_whose_worker_keeps_dying_is_recorded_as_an_infrastructure_failure(tmp_path: Path) -> None:
    tasks = select_tasks(TaskStore([tasks_dir()]), [GEO], None)
    target = tasks[1].id
    run = tmp_path / "run"
    summary = play(tasks, DiesOn(target), run_dir=run, task_dirs=[tasks_dir()], workers=2, progress=False)
    (failed,) = [o for o in summary.outcomes if o.failure]
    assert failed.task_id == target and "worker died 3 times" in failed.failure
    assert landed(run) == Counter(t.id for t in tasks)
    (folder,) = folders_of(run, target)
    assert "worker died" in json.loads((folder / "final_state.json").read_text())["infrastructure_failure"]
    report = grade_run(run)
    assert report.infrastructure == {"geolocation": 1}
    assert report.domains["geolocation"].n == 3 and report.domains["geolocation"].overall_accuracy.value == 1.0
