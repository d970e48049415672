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
    """One line of trajectory.jsonl: one tool call on the episode."""

    step: int = Field(ge=0)
    tool: str
    args: dict[str, Any] = Field(default_factory=dict)
    ok: bool
    error: str | None = None
    counted: bool = True
    environment: str | None = None
    observation: str = ""
    t: float | None = None
    time: str | None = None
    duration_ms: float | None = None
    images: list[str] | None = None


class FinalState(_Record):
    """final_state.json, written once when the episode ends."""

    schema_version: int | None = None
    episode_id: str | None = None
    task_id: str | None = None
    domain: str | None = None
    status: Literal["finished", "step_limit", "aborted"]
    end_reason: str | None = None
    answer: str | None = None
    submission: dict[str, Any] | None = None
    steps: int | None = Field(default=None, ge=0)
    calls: int | None = Field(default=None, ge=0)
    switches: int | None = Field(default=None, ge=0)
    active_environment: str | None = None
    options: dict[str, Any] = Field(default_factory=dict)
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
    """Why ``payload`` does not fit ``model`` (the first problem, bounded), or None when it fits."""
    try:
        model.model_validate(payload)
    except ValidationError as exc:
        first = exc.errors()[0]
        loc = ".".join(str(p) for p in first["loc"]) or "<root>"
        return f"{where}: {loc}: {first['msg']}"[:300]
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
        record = {
            "step": index,
            "time": _now_iso(),
            "t": time.time(),
            "tool": tool,
            "args": args,
            "ok": ok,
            "error": error,
            "duration_ms": round(duration_ms, 3),
            "environment": environment,
            "counted": counted,
            "observation": digest(observation),
        }
        if images:
            record["images"] = images
        if extra:
            record.update(extra)
        self._append(self._trajectory, record)

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

    def write_final_state(self, state: dict[str, Any]) -> None:
        self._write_json("final_state.json", state)

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
