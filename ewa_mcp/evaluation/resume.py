"""Honest, resumable eval runs: what a run directory already holds, what is left to play, and the record of
the episodes that infrastructure (not the agent) cut off.

A task is *done* in a run directory when one of its episode folders holds a final state without an
``infrastructure_failure``. A folder is *cut off* when it has no final state (the process was killed) or when
its final state names an infrastructure failure (the server shut down, the worker died, the environments did
not start). ``ewa-mcp eval`` into an existing run directory plays only the selected tasks that are not done,
after deleting their cut-off folders, so each task is counted once.

An outcome the eval could not play (``EpisodeOutcome.failure``) is written into the run directory as an
infrastructure failure: its episode's final state is marked, or, when the server never opened an episode, a
folder holding the task and a final state saying why. The grader reports those apart and never scores them.
"""

from __future__ import annotations

import json
import shutil
import uuid
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from ..core.records import EpisodeRecorder
from ..core.taskmodel import SCHEMA_VERSION, Task
from .outcomes import EpisodeOutcome, EvalError

EVAL_FILE = "eval.json"  # who recorded the run: a resume must not mix agents in one run


def _read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return None


@dataclass
class RunState:
    """What a run directory holds, by task id."""

    done: dict[str, list[Path]] = field(default_factory=dict)  # task id -> its complete episode folders
    cut_off: dict[str, list[Path]] = field(default_factory=dict)  # task id -> folders to replace
    unknown: list[Path] = field(default_factory=list)  # folders whose task.json cannot be read


def scan_run(run_dir: Path) -> RunState:
    state = RunState()
    if not run_dir.is_dir():
        return state
    for folder in sorted(run_dir.iterdir()):
        if not folder.is_dir() or folder.name.startswith("."):  # .staging of worker processes
            continue
        task = _read_json(folder / "task.json")
        task_id = task.get("id") if isinstance(task, dict) else None
        if not isinstance(task_id, str):
            if any((folder / name).exists() for name in ("trajectory.jsonl", "final_state.json")):
                state.unknown.append(folder)
            continue
        final = _read_json(folder / "final_state.json")
        complete = isinstance(final, dict) and not final.get("infrastructure_failure")
        (state.done if complete else state.cut_off).setdefault(task_id, []).append(folder)
    return state


@dataclass
class ResumePlan:
    to_play: list[Task]
    already_done: int  # selected tasks with a complete episode
    replaced: list[Path]  # cut-off folders of tasks about to be played again

    def describe(self, run_dir: Path, selected: int) -> str:
        if not self.already_done and not self.replaced:
            return ""
        cut = f"; {len(self.replaced)} cut-off episode(s) replaced" if self.replaced else ""
        return (f"resuming {run_dir}: {self.already_done} of {selected} selected tasks already played, "
                f"{len(self.to_play)} to play{cut}")


def plan_resume(run_dir: Path, tasks: list[Task], agent_name: str) -> ResumePlan:
    """The tasks left to play in run_dir (all of them for a new run directory). Raises EvalError when the run
    was recorded by another agent: resuming would mix two agents' episodes in one table."""
    recorded = _read_json(run_dir / EVAL_FILE)
    if isinstance(recorded, dict) and recorded.get("agent") not in (None, agent_name):
        raise EvalError(f"{run_dir} holds a run of agent {recorded.get('agent')!r}; resuming it with "
                        f"{agent_name!r} would mix two agents in one run. Pass another --run-dir")
    state = scan_run(run_dir)
    to_play = [t for t in tasks if t.id not in state.done]
    replaced = [folder for t in to_play for folder in state.cut_off.get(t.id, [])]
    return ResumePlan(to_play=to_play, already_done=len(tasks) - len(to_play), replaced=replaced)


def start_run(run_dir: Path, plan: ResumePlan, agent_name: str) -> None:
    """Prepare run_dir for the plan: delete the cut-off folders about to be replayed, note the agent."""
    run_dir.mkdir(parents=True, exist_ok=True)
    for folder in plan.replaced:
        shutil.rmtree(folder, ignore_errors=True)
    if not (run_dir / EVAL_FILE).exists():
        (run_dir / EVAL_FILE).write_text(json.dumps({"agent": agent_name}) + "\n", encoding="utf-8")


def record_infrastructure_failures(run_dir: Path, outcomes: list[EpisodeOutcome], tasks: list[Task]) -> int:
    """Write each outcome the eval could not play into run_dir as an infrastructure failure; returns how many."""
    by_id = {t.id: t for t in tasks}
    written = 0
    for outcome in outcomes:
        if outcome.failure is None:
            continue
        reason = outcome.failure[:500]
        folder = run_dir / outcome.episode_id if outcome.episode_id else None
        if folder is not None and folder.is_dir():
            if not _mark(folder, outcome, reason):
                continue
        elif outcome.task_id in by_id:
            _stub(run_dir, by_id[outcome.task_id], reason)
        else:
            continue
        written += 1
    return written


def _final_state(episode_id: str, outcome: EpisodeOutcome, reason: str) -> dict[str, Any]:
    return {"schema_version": SCHEMA_VERSION, "episode_id": episode_id, "task_id": outcome.task_id,
            "domain": outcome.domain, "status": "aborted", "end_reason": f"not played to its end: {reason}",
            "ended_at": datetime.now(UTC).isoformat(), "infrastructure_failure": reason}


def _mark(folder: Path, outcome: EpisodeOutcome, reason: str) -> bool:
    """The server opened the episode: keep what it recorded, and say in its final state why it does not count.
    False when the episode did end by the agent's own finish or step limit (what failed came after: it counts)."""
    path = folder / "final_state.json"
    final = _read_json(path)
    if isinstance(final, dict) and final.get("status") in ("finished", "step_limit"):
        return False
    final = final if isinstance(final, dict) else _final_state(folder.name, outcome, reason)
    final.setdefault("infrastructure_failure", reason)
    tmp = folder / ".final_state.json.tmp"
    tmp.write_text(json.dumps(final, indent=2, ensure_ascii=False, default=str), encoding="utf-8")
    tmp.replace(path)
    return True


def _stub(run_dir: Path, task: Task, reason: str) -> None:
    """No episode was opened (its worker died, start_episode failed): a folder with the task and the reason."""
    episode_id = "ep-" + uuid.uuid4().hex[:12]
    recorder = EpisodeRecorder(run_dir / episode_id)
    try:
        recorder.write_task(task.model_dump(mode="json"))
        outcome = EpisodeOutcome(task_id=task.id, domain=task.domain, episode_id=episode_id)
        recorder.write_final_state(_final_state(episode_id, outcome, reason))
    finally:
        recorder.close()
