"""Reading a run directory as far as the data allows.

Every reader here returns what it could read plus a list of problems; nothing raises on a
missing or damaged file, because a crashed episode must still be graded and reported.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pydantic import TypeAdapter, ValidationError

from ewa_mcp.core.records import FinalState, TrajectoryLine, WebEvent, record_problem
from ewa_mcp.core.taskmodel import SCHEMA_VERSION, AnswerCheck, EmbodiedGoal, Task, WebGoal, has_web_environment

EPISODE_FILES = ("task.json", "trajectory.jsonl", "web_events.jsonl", "final_state.json")

_WEB_GOAL: TypeAdapter[Any] = TypeAdapter(WebGoal)
_EMBODIED_GOAL: TypeAdapter[Any] = TypeAdapter(EmbodiedGoal)
_ANSWER: TypeAdapter[Any] = TypeAdapter(AnswerCheck)


@dataclass
class UnreadableGoal:
    """A goal the grader cannot interpret (unknown kind, bad fields): it is reported, never guessed."""

    side: str
    raw: Any
    reason: str


@dataclass
class TaskView:
    """The parts of a task the grader needs, read leniently from task.json."""

    id: str | None
    domain: str
    web_goals: list[Any]
    embodied_goals: list[Any]
    answer: Any | None
    metadata: dict[str, Any]
    has_web_env: bool
    has_embodied_env: bool
    embodied_kind: str | None
    start_setting: str | None
    unreadable: list[UnreadableGoal] = field(default_factory=list)
    difficulty: str | None = None
    answer_unreadable: str | None = None


@dataclass
class EpisodeRecord:
    directory: Path
    task: TaskView | None
    trajectory: list[dict[str, Any]]
    events: list[dict[str, Any]]
    final_state: dict[str, Any] | None
    problems: list[str] = field(default_factory=list)
    # Parts of the record that do not fit its declared format (ewa_mcp/core/records.py): the episode is then an
    # invalid_record failure, graded from what remained valid, and never crashes the run's grading.
    invalid: list[str] = field(default_factory=list)

    @property
    def unfinished(self) -> bool:
        """The episode never ended (no final_state.json): the server or the harness died mid-episode."""
        return not (self.directory / "final_state.json").exists()

    @property
    def episode_id(self) -> str:
        if self.final_state and isinstance(self.final_state.get("episode_id"), str):
            return self.final_state["episode_id"]
        return self.directory.name


def is_episode_dir(path: Path) -> bool:
    return path.is_dir() and any((path / name).exists() for name in EPISODE_FILES)


def episode_dirs(run_dir: Path) -> list[Path]:
    return sorted(p for p in run_dir.iterdir() if is_episode_dir(p))


def _read_json(path: Path, problems: list[str]) -> Any | None:
    if not path.exists():
        return None
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as exc:
        problems.append(f"{path.name}: unreadable ({exc}); ignored")
    except json.JSONDecodeError as exc:
        problems.append(f"{path.name}: not valid JSON ({exc.msg} at line {exc.lineno}); ignored")
    return None


def read_jsonl(path: Path, problems: list[str]) -> list[dict[str, Any]]:
    """Every complete JSON object line; a torn last line (a crash mid-write) is reported and skipped."""
    if not path.exists():
        return []
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        problems.append(f"{path.name}: unreadable ({exc}); ignored")
        return []
    records: list[dict[str, Any]] = []
    lines = text.split("\n")
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except json.JSONDecodeError:
            last = number == len(lines) or all(not rest.strip() for rest in lines[number:])
            where = "last line" if last else f"line {number}"
            problems.append(f"{path.name}: {where} is not complete JSON (crash mid-write?); skipped")
            continue
        if isinstance(record, dict):
            records.append(record)
        else:
            problems.append(f"{path.name}: line {number} is not a JSON object; skipped")
    return records


def _goal_list(raw: Any, side: str, adapter: TypeAdapter[Any], unreadable: list[UnreadableGoal]) -> list[Any]:
    goals: list[Any] = []
    for item in raw if isinstance(raw, list) else []:
        try:
            goals.append(adapter.validate_python(item))
        except ValidationError as exc:
            first = exc.errors()[0]
            loc = ".".join(str(p) for p in first["loc"]) or "<goal>"
            unreadable.append(UnreadableGoal(side, item, f"{loc}: {first['msg']}"))
    return goals


def task_view(raw: dict[str, Any], problems: list[str]) -> TaskView:
    """A TaskView from task.json; a task that fails the schema is read goal by goal."""
    version = raw.get("schema_version")
    if isinstance(version, int) and version > SCHEMA_VERSION:
        problems.append(f"task.json has schema v{version}, newer than this grader's v{SCHEMA_VERSION}; "
                        "upgrade ewa-mcp to grade every goal")
    try:
        task = Task.model_validate(raw)
    except ValidationError as exc:
        task = None
        problems.append(
            f"task.json does not match task schema v{SCHEMA_VERSION} ({exc.error_count()} problem(s), first: "
            f"{'.'.join(str(p) for p in exc.errors()[0]['loc'])}: {exc.errors()[0]['msg']}); "
            "graded from the goals that could be read"
        )
    if task is not None:
        embodied = task.start.embodied
        return TaskView(
            id=task.id,
            domain=task.domain,
            web_goals=list(task.web_goals),
            embodied_goals=list(task.embodied_goals),
            answer=task.answer,
            metadata=dict(task.metadata),
            has_web_env="web" in task.environment_names(),
            has_embodied_env=embodied is not None,
            embodied_kind=embodied.kind if embodied is not None else None,
            start_setting=getattr(embodied, "setting", None),
            difficulty=task.difficulty if "difficulty" in raw else None,
        )
    unreadable: list[UnreadableGoal] = []
    web_goals = _goal_list(raw.get("web_goals"), "web", _WEB_GOAL, unreadable)
    embodied_goals = _goal_list(raw.get("embodied_goals"), "embodied", _EMBODIED_GOAL, unreadable)
    answer, answer_unreadable = None, None
    if raw.get("answer") is not None:
        try:
            answer = _ANSWER.validate_python(raw["answer"])
        except ValidationError as exc:
            answer_unreadable = f"answer check unreadable ({exc.errors()[0]['msg']})"
    start = given if isinstance(given := raw.get("start"), dict) else {}
    embodied_start = start.get("embodied") if isinstance(start.get("embodied"), dict) else None
    return TaskView(
        id=raw.get("id") if isinstance(raw.get("id"), str) else None,
        domain=domain if isinstance(domain := raw.get("domain"), str) else "unknown",
        web_goals=web_goals,
        embodied_goals=embodied_goals,
        answer=answer,
        metadata=metadata if isinstance(metadata := raw.get("metadata"), dict) else {},
        has_web_env=has_web_environment(start.get("web"), raw.get("web_goals") or []),
        has_embodied_env=embodied_start is not None,
        embodied_kind=embodied_start.get("kind") if embodied_start else None,
        start_setting=embodied_start.get("setting") if embodied_start else None,
        unreadable=unreadable,
        answer_unreadable=answer_unreadable,
        difficulty=raw.get("difficulty") if raw.get("difficulty") in ("easy", "medium", "hard") else None,
    )


def read_episode(directory: Path) -> EpisodeRecord:
    problems: list[str] = []
    raw_task = _read_json(directory / "task.json", problems)
    task: TaskView | None = None
    if raw_task is None:
        if not (directory / "task.json").exists():
            problems.append("task.json missing: the goals are unknown, so the episode cannot be graded")
    elif not isinstance(raw_task, dict):
        problems.append("task.json is not a JSON object: the goals are unknown, so the episode cannot be graded")
    else:
        task = task_view(raw_task, problems)
    invalid: list[str] = []
    trajectory = _valid_lines(read_jsonl(directory / "trajectory.jsonl", problems), TrajectoryLine,
                              "trajectory.jsonl", invalid)
    if not (directory / "trajectory.jsonl").exists():
        problems.append("trajectory.jsonl missing: steps and error analysis use final_state.json only")
    events = _valid_lines(read_jsonl(directory / "web_events.jsonl", problems), WebEvent, "web_events.jsonl", invalid)
    final_state = _read_json(directory / "final_state.json", problems)
    if final_state is None and (directory / "final_state.json").exists():
        invalid.append("final_state.json is not readable JSON")
    elif final_state is not None:
        why = record_problem(FinalState, final_state, "final_state.json")
        if why is not None:
            invalid.append(why)
            final_state = None
    if final_state is None and not (directory / "final_state.json").exists():
        problems.append(
            "final_state.json missing (the episode did not end cleanly): embodied goals cannot be checked; "
            "web goals are graded from web_events.jsonl"
        )
    problems.extend(f"invalid record: {why}" for why in invalid)
    return EpisodeRecord(directory, task, trajectory, events, final_state, problems, invalid)


def _valid_lines(lines: list[dict[str, Any]], model: Any, name: str, invalid: list[str]) -> list[dict[str, Any]]:
    kept = []
    for number, line in enumerate(lines, start=1):
        why = record_problem(model, line, f"{name} record {number}")
        if why is None:
            kept.append(line)
        else:
            invalid.append(why)
    return kept
