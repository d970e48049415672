"""A full disk under the run directory: tool errors name the disk, an episode whose record cannot be written ends
and says so (finish_episode included), and eval stops with one line, keeping only whole episodes.

The disk is a real one: a small tmpfs mounted for the test (skipped where this process may not mount)."""

from __future__ import annotations

import errno
import json
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server

from .fixtures import CounterEnv, NoteEnv, counter_task, register, write_tasks


@pytest.fixture
def small_disk(tmp_path) -> Iterator[Path]:
    mount = tmp_path / "disk"
    mount.mkdir()
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(mount)], capture_output=True,
                          text=True)
    if done.returncode != 0:
        pytest.skip(f"cannot mount a small tmpfs here ({done.stderr.strip()[:200]}); needs root")
    try:
        yield mount
    finally:
        subprocess.run(["umount", "-l", str(mount)], check=False)


def fill(disk: Path) -> None:
    """Write into ``disk`` until it is full."""
    with open(disk / "filler", "wb", buffering=0) as f:
        try:
            while True:
                f.write(b"x" * 4096)
        except OSError as exc:
            assert exc.errno == errno.ENOSPC


def _text(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


@pytest.mark.anyio
async def test_a_call_that_cannot_be_recorded_ends_the_episode_and_names_the_disk(tmp_path, small_disk):
    tasks = write_tasks(tmp_path / "tasks", [counter_task(step_limit=500)])
    run = small_disk / "run"
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=run,
                                              environments={"kitchen": CounterEnv, "browser": NoteEnv}))
    register(mcp, episodes)
    async with Client(mcp) as client:
        acting = (await client.call_tool("start_episode", {"task_id": "t-counter"})).structured_content["episode_id"]
        finishing = (await client.call_tool("start_episode", {"task_id": "t-counter"})).structured_content[
            "episode_id"]
        fill(small_disk)

        # The record's last page still has room for a few lines; the call that needs a new one fails.
        for _ in range(100):
            r = await client.call_tool("counter_add", {"episode_id": acting, "amount": 1})
            if r.is_error:
                break
        assert r.is_error
        assert "counter_add was done, but the episode's record could not be written" in _text(r)
        assert "the disk is full" in _text(r) and str(small_disk) in _text(r)
        assert episodes.get(acting).status == "aborted"
        assert "could not be written" in episodes.get(acting).end_reason

        for _ in range(100):  # as above: calls until its record needs space, then finish
            if (await client.call_tool("counter_add", {"episode_id": finishing, "amount": 0})).is_error:
                break
        r = await client.call_tool("finish_episode", {"episode_id": finishing, "answer": "three"})
        assert r.is_error and "has ended" in _text(r) and "could not be written" in _text(r)
        assert episodes.get(finishing).status != "running"  # ended, its browser or kitchen released
        assert all(getattr(env, "closed", True) for env in episodes.get(finishing).environments.values())

        # Nothing is started while the disk stays full, and no half episode folder is left.
        before = sorted(p.name for p in run.iterdir())
        r = await client.call_tool("start_episode", {"task_id": "t-counter"})
        assert r.is_error and "nothing was started" in _text(r) and "the disk is full" in _text(r)
        assert sorted(p.name for p in run.iterdir()) == before
    assert "Traceback" not in _text(r)


def test_eval_stops_with_one_line_and_keeps_only_whole_episodes(tmp_path, small_disk):
    run = small_disk / "run"
    run.mkdir()
    fill(small_disk)
    done = subprocess.run(
        [sys.executable, "-m", "ewa_mcp", "eval", "--agent", "oracle", "--domain", "geolocation", "--sample", "4",
         "--run-dir", str(run), "-q"],
        env={**os.environ, "EWA_RUNS_DIR": str(tmp_path / "runs")}, capture_output=True, text=True, timeout=300)
    assert done.returncode == 2, done.stderr
    errors = [line for line in done.stderr.splitlines() if line.startswith("error:")]
    assert len(errors) == 1, done.stderr
    assert "eval stopped: cannot write the episode record" in errors[0]
    assert "the disk is full" in errors[0] and str(small_disk) in errors[0] and str(run) in errors[0]
    assert "Traceback" not in done.stderr and len(done.stderr.splitlines()) <= 3, done.stderr
    for folder in run.glob("ep-*"):  # only whole episodes are left
        assert json.loads((folder / "final_state.json").read_text())["status"]
