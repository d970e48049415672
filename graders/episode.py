"""grade_episode: one episode directory -> EpisodeResult.

Unknowns stay unknown: a condition the data cannot decide is ``met=None`` and the episode's
success is None (not gradable) unless some known condition already failed it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ewa_mcp.core import registry
from ewa_mcp.core.taskmodel import TextAnswer

from .answers import check_geo_answer, check_text_answer
from .errors import Outcome, classify
from .models import CheckContext, ConditionResult, EpisodeResult, NavigationResult
from .rundir import EpisodeRecord, TaskView, read_episode


def all_met(conditions: list[ConditionResult]) -> bool | None:
    """Three-valued AND: False if any is unmet, None if any is unknown, True otherwise (and when empty)."""
    values = [c.met for c in conditions]
    if False in values:
        return False
    if None in values:
        return None
    return True


def _last_finish_args(trajectory: list[dict[str, Any]], tool: str) -> dict[str, Any] | None:
    for record in reversed(trajectory):
        if record.get("tool") == tool and record.get("ok") is True and isinstance(record.get("args"), dict):
            return record["args"]
    return None


def _answer_and_submission(record: EpisodeRecord) -> tuple[str | None, dict[str, Any] | None]:
    """From final_state.json; after a crash between the finish call and the final state, from the trajectory."""
    final = record.final_state or {}
    answer = final.get("answer") if isinstance(final.get("answer"), str) else None
    submission = final.get("submission") if isinstance(final.get("submission"), dict) else None
    if record.final_state is None:
        finish = _last_finish_args(record.trajectory, "finish_episode") or {}
        submit = _last_finish_args(record.trajectory, "submit_location")
        answer = finish.get("answer") if isinstance(finish.get("answer"), str) else None
        if submit is not None:
            submission = {k: v for k, v in submit.items() if k != "episode_id"}
    return answer, submission


def _embodied_state(record: EpisodeRecord) -> tuple[dict[str, Any] | None, str | None]:
    if record.final_state is None:
        return None, "no final state"
    state = (record.final_state.get("environments") or {}).get("embodied")
    if not isinstance(state, dict):
        return None, "final_state.json has no embodied environment state"
    if "error" in state:
        return None, f"the embodied environment failed to report its state ({state['error']})"
    return state, None


def _check(goal: Any, side: str, ctx: CheckContext) -> ConditionResult:
    """Grade one goal with the check its world declares (``Domain.checks`` in the world's package)."""
    path = registry.goal_check(goal.kind)
    if path is None:  # the task validated when the domain was registered; this grader process lacks it
        return ConditionResult(side=side, kind=goal.kind, description=goal.kind, met=None,
                               note=f"no registered domain checks goal kind {goal.kind!r}")
    result = registry.load_object(path)(goal, ctx)
    if not isinstance(result, ConditionResult):
        raise TypeError(f"the check {path} returned {type(result).__name__}, not a ConditionResult")
    return result


def _orders_for_pickup(task: TaskView, events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The orders a pickup walk may refer to: those matching an order goal, or every order when there is none."""
    if not events:
        return []
    from ewa_mcp.envs.browser import checks as web  # the shop's orders are the browser world's to read
    from ewa_mcp.envs.browser.goals import OrderPlaced

    goals = [g for g in task.web_goals if isinstance(g, OrderPlaced)]
    if not goals:
        return web.orders(events)
    found: list[dict[str, Any]] = []
    for goal in goals:
        found.extend(o for o in web.matching_orders(events, goal) if o not in found)
    return found


def _is_geo_answer(answer: Any) -> bool:
    from ewa_mcp.envs.geo.goals import GeoAnswer  # imported only for a task with such an answer

    return isinstance(answer, GeoAnswer)


def _setting(task: TaskView, final: dict[str, Any]) -> str | None:
    options = given if isinstance(given := final.get("options"), dict) else {}
    setting = options.get("geolocation_setting") or task.start_setting or task.metadata.get("setting")
    return setting if isinstance(setting, str) else None


def _number(value: Any) -> float | None:
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def grade_record(record: EpisodeRecord, radius_m: float | None = None) -> EpisodeResult:
    final = record.final_state or {}
    task = record.task
    problems = list(record.problems)
    conditions: list[ConditionResult] = []
    navigation: list[NavigationResult] = []
    geolocation: dict[str, Any] | None = None
    orders: list[dict[str, Any]] = []
    answer, submission = _answer_and_submission(record)

    if task is not None:
        events_missing = not (record.directory / "web_events.jsonl").exists()
        for goal in task.web_goals:
            if events_missing:
                conditions.append(ConditionResult(side="web", kind=goal.kind, description=goal.kind, met=None,
                                                  note="web_events.jsonl missing"))
            else:
                conditions.append(_check(goal, "web", CheckContext(state=None, why_no_state=None,
                                                                    events=record.events, metadata=task.metadata,
                                                                    web_goals=list(task.web_goals))))
        if events_missing and task.web_goals:
            problems.append("web_events.jsonl missing: web goals cannot be checked")
        orders = _orders_for_pickup(task, record.events)
        state, why_no_state = _embodied_state(record)
        ctx = CheckContext(state=state, why_no_state=why_no_state, events=record.events, metadata=task.metadata,
                           orders=orders, radius_m=radius_m)
        conditions.extend(_check(goal, "embodied", ctx) for goal in task.embodied_goals)
        navigation = ctx.navigation
        for bad in task.unreadable:
            kind = bad.raw.get("kind") if isinstance(bad.raw, dict) else None
            conditions.append(ConditionResult(side=bad.side, kind=str(kind or "?"), description="unreadable goal",
                                              met=None, note=bad.reason))
        if isinstance(task.answer, TextAnswer):
            conditions.append(check_text_answer(task.answer, answer))
        elif task.answer is not None and _is_geo_answer(task.answer):
            condition, geolocation = check_geo_answer(task.answer, submission)
            conditions.append(condition)
            if condition.met is None and condition.note:
                problems.append(condition.note)
        elif task.answer_unreadable:
            conditions.append(ConditionResult(side="answer", kind="?", description="answer", met=None,
                                              note=task.answer_unreadable))

    web_conditions = [c for c in conditions if c.side == "web"]
    embodied_conditions_all = [c for c in conditions if c.side == "embodied"]
    answer_conditions = [c for c in conditions if c.side == "answer"]
    answer_checked = bool(answer_conditions)
    if task is None:
        web_success = embodied_success = answer_correct = overall = None
        completion = None
    else:
        web_success = all_met(web_conditions)
        embodied_success = all_met(embodied_conditions_all)
        answer_correct = all_met(answer_conditions) if answer_checked else None
        overall = all_met([ConditionResult(side="web", kind="part", description="", met=v)
                           for v in (web_success, embodied_success, *([answer_correct] if answer_checked else []))])
        if record.invalid:
            overall = False  # a record that breaks its own format proves nothing (docs/grading.md)
        completion = sum(1 for c in conditions if c.met is True) / len(conditions) if conditions else None
        if geolocation is not None and isinstance(geolocation.get("completion"), float):
            completion = geolocation["completion"]  # geolocation: the fraction of levels right (ewa_mcp/envs/geo/checks.py)

    trajectory = record.trajectory
    steps = final.get("steps") if isinstance(final.get("steps"), int) else sum(
        1 for r in trajectory if r.get("counted") is True)
    calls = final.get("calls") if isinstance(final.get("calls"), int) else len(trajectory)
    switches = final.get("switches") if isinstance(final.get("switches"), int) else sum(
        1 for r in trajectory if r.get("tool") == "switch_environment" and r.get("ok") is True)
    wall = _number(final.get("wall_time_s"))
    if wall is None:
        times = [r["t"] for r in trajectory if isinstance(r.get("t"), int | float)]
        wall = round(max(times) - min(times), 3) if len(times) >= 2 else None

    domain = task.domain if task is not None else (final.get("domain") if isinstance(final.get("domain"), str)
                                                     else "unknown")
    result = EpisodeResult(
        episode_id=record.episode_id,
        task_id=task.id if task is not None else final.get("task_id"),
        domain=domain,
        difficulty=task.difficulty if task is not None else None,
        setting=_setting(task, final) if task is not None and domain == "geolocation" else None,
        status=final.get("status", "incomplete") if record.final_state is not None else "incomplete",
        end_reason=final.get("end_reason"),
        gradable=overall is not None,
        has_web_goals=bool(task and (task.web_goals or any(u.side == "web" for u in task.unreadable))),
        has_embodied_goals=bool(task and (task.embodied_goals or any(u.side == "embodied" for u in task.unreadable))),
        answer_checked=answer_checked,
        web_success=web_success,
        embodied_success=embodied_success,
        answer_correct=answer_correct,
        overall_success=overall,
        completion=round(completion, 6) if completion is not None else None,
        conditions_met=sum(1 for c in conditions if c.met is True),
        conditions_total=len(conditions),
        conditions=conditions,
        navigation=navigation,
        geolocation=geolocation,
        answer=answer,
        steps=steps,
        calls=calls,
        switches=switches,
        wall_time_s=wall,
        problems=problems,
        infrastructure_failure=str(final["infrastructure_failure"])[:500] if final.get("infrastructure_failure")
        else None,
    )
    if result.infrastructure_failure is not None:
        return result  # not the agent's doing: no error category, and the aggregates leave it out
    if overall is not True:
        outcome = Outcome(
            web_ok=web_success,
            embodied_ok=embodied_success,
            answer_ok=answer_correct,
            has_web_env=bool(task and task.has_web_env),
            has_embodied_env=bool(task and task.has_embodied_env),
            navigation=navigation,
            orders=orders,
        )
        result.error = classify(record, outcome)
    return result


def grade_episode(episode_dir: str | Path, radius_m: float | None = None) -> EpisodeResult:
    """Grade one episode directory (RUN_DIR/<episode_id>/). Never raises on damaged data; problems are listed.

    ``radius_m`` overrides every street goal's radius; None keeps each task's own (25 m by default)."""
    if radius_m is not None and not radius_m > 0:
        raise ValueError(f"radius_m must be a positive number of metres, got {radius_m!r}")
    return grade_record(read_episode(Path(episode_dir)), radius_m)
