"""What an evaluation run reports, shared by every way of playing it (one process, workers, Ray): the outcome
of each episode, the run's summary, the progress display and the error that names a fix. Data only: it imports
nothing else of the evaluation package, so every part of it can use these without an import cycle."""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class EvalError(ValueError):
    """Bad eval input (no matching tasks, bad replay): the message names the fix."""


@dataclass
class EpisodeOutcome:
    task_id: str
    domain: str
    episode_id: str | None
    calls: int = 0
    errors: int = 0
    failure: str | None = None  # the episode could not be played at all
    seconds: float = 0.0
    record_problem: str | None = None  # its record could not be written (a full disk): the run stops


@dataclass
class EvalSummary:
    run_dir: Path
    agent: str
    transport: str
    outcomes: list[EpisodeOutcome] = field(default_factory=list)
    seconds: float = 0.0
    record_problem: str | None = None


def clock(seconds: float) -> str:
    """A duration as m:ss, or h:mm:ss past an hour."""
    seconds = max(0, int(round(seconds)))
    hours, rest = divmod(seconds, 3600)
    return f"{hours}:{rest // 60:02d}:{rest % 60:02d}" if hours else f"{rest // 60}:{rest % 60:02d}"


class Progress:
    """Episodes done, infrastructure failures, time so far and the estimated time left, on stderr.

    On a terminal: one line redrawn in place (a carriage-return frame per episode). Anywhere else (a log file, a
    CI console, a pipe): a plain line per update, at most one every `interval` seconds plus the last, so logs
    hold readable lines and no frames."""

    def __init__(self, total: int, enabled: bool, stream: Any = None, interactive: bool | None = None,
                 interval: float = 10.0):
        self.total, self.done, self.failed, self.enabled = total, 0, 0, enabled
        self.stream = stream if stream is not None else sys.stderr
        if interactive is None:
            isatty = getattr(self.stream, "isatty", None)
            interactive = bool(isatty and isatty())
        self.interactive, self.interval = interactive, interval
        self.started = time.monotonic()
        self.last_line = -float("inf")

    def eta(self, elapsed: float) -> str:
        if not self.done:
            return "?"
        return clock(elapsed / self.done * (self.total - self.done))

    def status(self, elapsed: float) -> str:
        return (f"{self.done}/{self.total} episodes · {self.failed} not played (infrastructure) · "
                f"{clock(elapsed)} elapsed · ETA {self.eta(elapsed)}")

    def tick(self, outcome: EpisodeOutcome) -> None:
        self.done += 1
        self.failed += outcome.failure is not None
        if not self.enabled:
            return
        now = time.monotonic()
        elapsed = now - self.started
        last = self.done == self.total
        if self.interactive:
            width = 30
            filled = int(width * self.done / max(1, self.total))
            self.stream.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {self.status(elapsed)} ")
            if last:
                self.stream.write("\n")
        elif last or now - self.last_line >= self.interval:
            self.last_line = now
            self.stream.write(f"progress: {self.status(elapsed)}\n")
        self.stream.flush()
