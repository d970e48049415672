"""Run directories: what the grader reads, written step by step so a crash loses nothing.

runs/<run_id>/<episode_id>/
    task.json            the task as it was run (with its oracle and goals)
    trajectory.jsonl     one line per tool call, appended and flushed immediately
    web_events.jsonl     events the embedded sites emitted for this episode (page views, orders, ...)
    images/              PNG observations of steps that returned images (vision mode, screenshots)
    final_state.json     written once, when the episode ends
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import threading
import time
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

DIGEST_CHARS = 240


# ---------------------------------------------------------------- the record formats
# Written by EpisodeRecorder (the server) and validated by the graders: a line or file that does not fit
# makes the episode an ``invalid_record`` failure instead of crashing the grading of a whole run.
class _Record(BaseModel):
    # Newer servers may add fields; a grader keeps reading what it knows.
    model_config = ConfigDict(extra="allow")


class TrajectoryLine(_Record):
    """One line of trajectory.jsonl: one tool call on the episode. ``EpisodeRecorder.step`` builds it; every
    field but ``images`` is always written (a value may be null where it says so)."""

    step: int = Field(ge=0, description="the call's number in the episode (1 = the first after start_episode's 0)")
    time: str = Field(description="when the call ended, ISO 8601 UTC")
    t: float = Field(description="the same as a Unix time in seconds")
    tool: str
    args: dict[str, Any] = Field(description="the arguments as the tool received them (a refused call's, bounded)")
    ok: bool = Field(description="false: the call was refused or failed; error says why")
    error: str | None
    duration_ms: float = Field(ge=0)
    environment: str | None = Field(description="the episode's active environment (web or embodied)")
    counted: bool = Field(description="whether the call used a step (every call but start_episode)")
    observation: str = Field(description="a one-line digest of what the call returned")
    images: list[str] | None = Field(default=None, description="the step's images, relative to the episode folder")


class FinalState(_Record):
    """final_state.json, written once when the episode ends (``EpisodeManager`` builds it; a resumed eval writes
    one for an episode it could not play, with only what it knows: the fields below ``end_reason`` may be missing)."""

    schema_version: int
    episode_id: str
    task_id: str
    domain: str
    status: Literal["finished", "step_limit", "aborted"]
    end_reason: str | None
    answer: str | None = None
    submission: dict[str, Any] | None = None
    steps: int | None = Field(default=None, ge=0)
    calls: int | None = Field(default=None, ge=0)
    switches: int | None = Field(default=None, ge=0)
    active_environment: str | None = None
    options: dict[str, Any] = Field(default_factory=dict)
    started_at: str | None = Field(default=None, description="ISO 8601 UTC")
    ended_at: str | None = Field(default=None, description="ISO 8601 UTC")
    wall_time_s: float | None = None
    environments: dict[str, dict[str, Any]] = Field(default_factory=dict)
    # Set when the episode was cut off by something other than the agent (the server shut down, its eval worker
    # died, the environments could not start): graders report it apart and never score it; a resumed eval
    # plays its task again.
    infrastructure_failure: str | None = None


class WebEvent(_Record):
    """One line of web_events.jsonl: something an embedded site saw the episode's browser do."""

    type: str
    site: str | None = None


def record_problem(model: type[BaseModel], payload: Any, where: str) -> str | None:
    """Why ``payload`` does not fit ``model`` (its problems, bounded), or None when it fits."""
    try:
        model.model_validate(payload)
    except ValidationError as exc:
        parts = [f"{'.'.join(str(p) for p in error['loc']) or '<root>'}: {error['msg']}" for error in exc.errors()]
        return f"{where}: {'; '.join(parts[:6])}"[:400]
    return None


def _now_iso() -> str:
    return datetime.now(UTC).isoformat(timespec="milliseconds")


def digest(text: str) -> str:
    """A one-line, bounded summary of an observation for the trajectory."""
    flat = " ".join(text.split())
    return flat if len(flat) <= DIGEST_CHARS else flat[: DIGEST_CHARS - 1] + "…"


# Every message of a RecordWriteError starts so: callers (eval) recognise a record that cannot be written by it.
RECORD_WRITE_MARKER = "cannot write the episode record"


def _mount_point(path: Path) -> Path:
    path = path.resolve()
    while not path.exists() and path != path.parent:
        path = path.parent
    while not os.path.ismount(path) and path != path.parent:
        path = path.parent
    return path


def write_problem(directory: Path, exc: OSError) -> str:
    """What went wrong writing under ``directory``, naming the disk (its mount point and free space) and the fix."""
    full = exc.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG)
    disk = _mount_point(directory)
    try:
        free = f"{shutil.disk_usage(disk).free // 1024} KiB free"
    except OSError:
        free = "free space unknown"
    why = "the disk is full" if full else (exc.strerror or type(exc).__name__)
    return (f"{RECORD_WRITE_MARKER} in {directory}: {why} (the disk mounted at {disk}, {free}); free space there, "
            "or record on another disk (--run-dir DIR, EWA_RUNS_DIR)")


class RecordWriteError(RuntimeError):
    """A record file could not be written (a full disk, a read-only one); the message names the disk and the fix."""


class EpisodeRecorder:
    def __init__(self, directory: Path):
        self.directory = directory
        self._lock = threading.Lock()  # sites emit events from their own threads
        try:
            directory.mkdir(parents=True, exist_ok=True)
            self._trajectory = open(directory / "trajectory.jsonl", "a", encoding="utf-8")
            self._events = open(directory / "web_events.jsonl", "a", encoding="utf-8")
        except OSError as exc:
            raise RecordWriteError(write_problem(directory, exc)) from exc

    def write_task(self, task_json: dict[str, Any]) -> None:
        self._write_json("task.json", task_json)

    def _append(self, fh, record: dict[str, Any]) -> None:
        line = json.dumps(record, ensure_ascii=False, default=str)
        with self._lock:
            if fh.closed:
                return
            try:
                fh.write(line + "\n")
                # Flushed to the OS on every step, so a crash of the server loses nothing; no fsync, which
                # would double the cost of a kitchen action for durability against power loss only.
                fh.flush()
            except OSError as exc:
                raise RecordWriteError(write_problem(self.directory, exc)) from exc

    def step(
        self,
        *,
        index: int,
        tool: str,
        args: dict[str, Any],
        ok: bool,
        error: str | None,
        duration_ms: float,
        environment: str | None,
        observation: str,
        counted: bool,
        images: list[str] | None = None,
        extra: dict[str, Any] | None = None,
    ) -> None:
        line = TrajectoryLine(step=index, time=_now_iso(), t=time.time(), tool=tool, args=args, ok=ok, error=error,
                              duration_ms=round(duration_ms, 3), environment=environment, counted=counted,
                              observation=digest(observation), **({"images": images} if images else {}),
                              **(extra or {}))
        self._append(self._trajectory, line.model_dump(mode="json", exclude_unset=True))

    def save_images(self, index: int, images: list[bytes]) -> list[str]:
        """Observation images of one step, as files beside the trajectory (paths relative to the episode)."""
        if not images:
            return []
        folder = self.directory / "images"
        names = []
        try:
            folder.mkdir(exist_ok=True)
            for k, png in enumerate(images):
                name = f"images/step-{index:04d}-{k}.png"
                (self.directory / name).write_bytes(png)
                names.append(name)
        except OSError as exc:
            raise RecordWriteError(write_problem(self.directory, exc)) from exc
        return names

    def event(self, event: dict[str, Any]) -> None:
        self._append(self._events, {"time": _now_iso(), "t": time.time(), **event})

    def write_final_state(self, state: FinalState | dict[str, Any]) -> None:
        """Write final_state.json from its model (a dict is validated into one first: what is written always fits
        the format the graders read)."""
        model = state if isinstance(state, FinalState) else FinalState.model_validate(state)
        self._write_json("final_state.json", model.model_dump(mode="json", exclude_unset=True))

    def _write_json(self, name: str, payload: dict[str, Any]) -> None:
        # Write-then-rename: a reader never sees a half-written file.
        tmp = self.directory / f".{name}.tmp"
        try:
            tmp.write_text(json.dumps(payload, indent=2, ensure_ascii=False, default=str), encoding="utf-8")
            os.replace(tmp, self.directory / name)
        except OSError as exc:
            try:
                tmp.unlink(missing_ok=True)  # never a half-written file beside the record
            except OSError:
                pass
            raise RecordWriteError(write_problem(self.directory, exc)) from exc

    def close(self) -> None:
        with self._lock:
            for fh in (self._trajectory, self._events):
                try:
                    fh.close()
                except OSError:
                    pass  # its last buffered line could not be written: reported when it was appended


def new_run_id() -> str:
    return datetime.now(UTC).strftime("%Y%m%d-%H%M%S-") + os.urandom(3).hex()


def export_records_schema() -> dict[str, Any]:
    """The JSON Schema of the three record formats (docs/records.schema.json; tests/core/test_records_schema.py
    checks the committed file is current). Regenerate with ``python -m ewa_mcp.core.records``."""
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "ewa-mcp run records: runs/<run>/<episode>/",
        "description": "trajectory.jsonl holds one trajectory_line per line, web_events.jsonl one web_event per "
                       "line, final_state.json one final_state.",
        "$defs": {
            "trajectory_line": TrajectoryLine.model_json_schema(),
            "final_state": FinalState.model_json_schema(),
            "web_event": WebEvent.model_json_schema(),
        },
    }


if __name__ == "__main__":
    print(json.dumps(export_records_schema(), indent=2, ensure_ascii=False))
