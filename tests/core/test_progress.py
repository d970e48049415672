"""The eval progress display: an estimated time left, a bar redrawn in place on a terminal, and plain lines (no
carriage-return frames) in a log, a pipe or a CI console."""

from __future__ import annotations

import io
import os
import subprocess
import sys

from ewa_mcp.evaluation.runner import EpisodeOutcome, Progress, clock


def outcome(failure: str | None = None) -> EpisodeOutcome:
    return EpisodeOutcome(task_id="t", domain="demo", episode_id=None, failure=failure)


def test_clock_formats_minutes_and_hours() -> None:
    assert [clock(s) for s in (0, 9.6, 75, 3599, 3600, 7325)] == ["0:00", "0:10", "1:15", "59:59", "1:00:00",
                                                                  "2:02:05"]


def test_the_eta_is_the_mean_time_per_episode_times_the_episodes_left() -> None:
    log = io.StringIO()
    bar = Progress(4, True, stream=log, interval=0)
    bar.started -= 10  # ten seconds into the run when the first episode ends
    bar.tick(outcome())
    assert "1/4 episodes" in log.getvalue() and "0:10 elapsed · ETA 0:30" in log.getvalue()
    bar.tick(outcome("start_episode: no browser"))
    assert "2/4 episodes · 1 not played (infrastructure)" in log.getvalue()


def test_off_a_terminal_each_update_is_a_line_and_there_is_no_frame() -> None:
    log = io.StringIO()
    bar = Progress(5, True, stream=log, interval=0)
    for _ in range(5):
        bar.tick(outcome())
    text = log.getvalue()
    assert "\r" not in text
    assert text.splitlines() == [line for line in text.splitlines() if line.startswith("progress: ")]
    assert len(text.splitlines()) == 5 and text.splitlines()[-1].startswith("progress: 5/5 episodes")


def test_off_a_terminal_lines_are_spaced_out_but_the_last_is_always_written() -> None:
    log = io.StringIO()
    bar = Progress(50, True, stream=log, interval=3600)
    for _ in range(50):
        bar.tick(outcome())
    lines = log.getvalue().splitlines()
    assert [line.split(" episodes")[0] for line in lines] == ["progress: 1/50", "progress: 50/50"]


def _read_all(fd: int, until: str, timeout: float = 10.0) -> str:
    """What the terminal got: a pty hands its output over in pieces, so read until ``until`` is there (and the
    line after it ends) or the time is up."""
    import select
    import time

    out, deadline = "", time.monotonic() + timeout
    while time.monotonic() < deadline and not (until in out and out.endswith("\n")):
        ready, _, _ = select.select([fd], [], [], 0.1)
        if ready:
            try:
                out += os.read(fd, 65536).decode()
            except OSError:
                break
    return out


def test_on_a_terminal_one_line_is_redrawn_in_place() -> None:
    leader, follower = os.openpty()
    with os.fdopen(follower, "w", encoding="utf-8") as terminal:
        bar = Progress(3, True, stream=terminal)
        assert bar.interactive
        for _ in range(3):
            bar.tick(outcome())
    shown = _read_all(leader, until="3/3 episodes")
    os.close(leader)
    assert shown.count("\r[") == 3 and "3/3 episodes" in shown and "ETA 0:00" in shown


def test_disabled_progress_writes_nothing() -> None:
    log = io.StringIO()
    bar = Progress(2, False, stream=log)
    bar.tick(outcome())
    bar.tick(outcome())
    assert log.getvalue() == "" and bar.done == 2


def test_eval_into_a_log_writes_progress_lines_with_an_eta(tmp_path) -> None:
    done = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "oracle", "--tasks", "demo-hello",
                           "--run-dir", str(tmp_path / "run")], capture_output=True, text=True, timeout=180,
                          check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "\r" not in done.stderr
    assert "progress: 1/1 episodes · 0 not played (infrastructure) ·" in done.stderr and "ETA 0:00" in done.stderr
