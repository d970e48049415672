"""Automatic error analysis: every failed episode gets one category (the first rule that matches,
in the order below) plus the list of all matching rules. Categories follow the paper's error
figure; docs/grading.md states each rule."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from .models import ErrorClassification, ErrorGroup, NavigationResult
from .rundir import EpisodeRecord
from .trajectory import REPEAT_MIN, longest_repeat, page_loop, visits

# key -> (group, label); the order is the priority order of the rules.
CATEGORIES: dict[str, tuple[ErrorGroup, str]] = {
    "invalid_record": ("other", "Invalid record"),
    "incomplete_record": ("other", "Incomplete record"),
    "web_page_loop": ("web_only", "Web page loop"),
    "web_repeated_actions": ("web_only", "Repeated identical web actions"),
    "stuck_in_web": ("cross_domain", "Stuck in web"),
    "stuck_in_embodied": ("cross_domain", "Stuck in embodied"),
    "switching_without_action": ("cross_domain", "Switching without meaningful action"),
    "instruction_action_misalignment": ("cross_domain", "Instruction–action misalignment"),
    "failed_to_reach_object": ("embodied_only", "Failed to reach interactable object"),
    "embodied_repeated_actions": ("embodied_only", "Repeated identical embodied actions"),
    "never_stopped": ("embodied_only", "Never stopped at a destination"),
    "stopped_off_target": ("embodied_only", "Stopped away from the goal"),
    "wrong_answer": ("other", "Wrong or missing answer"),
    "unclassified": ("other", "Unclassified"),
}
GROUP_LABELS: dict[str, str] = {
    "cross_domain": "Cross-domain errors",
    "web_only": "Web-only errors",
    "embodied_only": "Embodied-only errors",
    "other": "Other",
}

TAIL_MIN_ACTIONS = 5  # a final stay this long ...
TAIL_FRACTION = 0.4  # ... and this share of all actions means the agent stayed there
REACH_MIN_ERRORS = 2
# AI2-THOR-style refusals that mean the object was out of reach or out of sight.
REACH_ERROR = re.compile(
    r"out of (reach|range)|too far|not (visible|interactable|reachable|within reach|in view|close enough)|"
    r"cannot reach|can't reach|unreachable|move closer|get closer|blocked|occluded",
    re.IGNORECASE,
)


@dataclass
class Outcome:
    """What grading decided, as the rules need it."""

    web_ok: bool | None
    embodied_ok: bool | None
    answer_ok: bool | None
    has_web_env: bool
    has_embodied_env: bool
    navigation: list[NavigationResult]
    orders: list[dict[str, Any]]


def _tail(all_visits: list[Any]) -> tuple[str | None, int]:
    for visit in reversed(all_visits):
        if visit.actions:
            return visit.env, len(visit.actions)
    return None, 0


def _stayed(env: str, all_visits: list[Any], n_actions: int, n_in_other: int) -> str | None:
    """Evidence that the agent stayed in ``env``: it never acted in the other environment, or its
    last stay in ``env`` was long."""
    if n_in_other == 0:
        return f"no action in the {'embodied' if env == 'web' else 'web'} environment"
    tail_env, tail_len = _tail(all_visits)
    if tail_env == env and tail_len >= max(TAIL_MIN_ACTIONS, TAIL_FRACTION * n_actions):
        return f"the last {tail_len} of {n_actions} actions were in the {env} environment"
    return None


def classify(record: EpisodeRecord, outcome: Outcome) -> ErrorClassification:
    matched: dict[str, str] = {}
    task = record.task
    trajectory = record.trajectory
    web_failed = outcome.web_ok is False
    embodied_failed = outcome.embodied_ok is False
    cross = outcome.has_web_env and outcome.has_embodied_env

    if record.invalid:
        matched["invalid_record"] = "; ".join(record.invalid[:2])
    if record.unfinished:
        matched["incomplete_record"] = "the episode never ended (no final_state.json): " + (
            "; ".join(p for p in record.problems[:2]) or "the server or harness stopped mid-episode")
    elif outcome.web_ok is None or outcome.embodied_ok is None or (
            outcome.answer_ok is None and task and task.answer):
        matched["incomplete_record"] = "; ".join(record.problems[:2]) or "the outcome could not be decided"

    if trajectory:
        all_visits = visits(trajectory)
        n_actions = sum(len(v.actions) for v in all_visits)
        n_web = sum(len(v.actions) for v in all_visits if v.env == "web")
        n_embodied = sum(len(v.actions) for v in all_visits if v.env == "embodied")
        if web_failed:
            loop = page_loop(record.events)
            if loop:
                matched["web_page_loop"] = "cycled among " + ", ".join(loop)
            repeat, tool = longest_repeat(trajectory, "web")
            if repeat >= REPEAT_MIN:
                matched["web_repeated_actions"] = f"{repeat} identical {tool} calls in a row with the same result"
        if cross and embodied_failed:
            why = _stayed("web", all_visits, n_actions, n_embodied)
            if why:
                matched["stuck_in_web"] = why
        if cross and web_failed:
            why = _stayed("embodied", all_visits, n_actions, n_web)
            if why:
                matched["stuck_in_embodied"] = why
        switched_in = [v for v in all_visits if v.via_switch]
        empty = [v for v in switched_in if v.meaningful == 0]
        if cross and len(switched_in) >= 2 and len(empty) >= 2 and 2 * len(empty) >= len(switched_in):
            matched["switching_without_action"] = (
                f"{len(empty)} of {len(switched_in)} switches were followed by no meaningful action"
            )
        if embodied_failed and task is not None and task.embodied_kind == "kitchen":
            reach = [r for r in trajectory if r.get("environment") == "embodied" and r.get("ok") is False
                     and REACH_ERROR.search(str(r.get("error") or ""))]
            if len(reach) >= REACH_MIN_ERRORS:
                matched["failed_to_reach_object"] = f"{len(reach)} actions refused as out of reach, e.g. " + str(
                    reach[-1].get("error"))[:120]
        if embodied_failed:
            repeat, tool = longest_repeat(trajectory, "embodied")
            if repeat >= REPEAT_MIN:
                matched["embodied_repeated_actions"] = f"{repeat} identical {tool} calls in a row with the same result"

    if cross and task is not None:
        why = _misalignment(record, outcome, task)
        if why:
            matched["instruction_action_misalignment"] = why

    for nav in outcome.navigation:
        if nav.success:
            continue
        if not nav.stopped:
            matched.setdefault("never_stopped", "the agent never called street_stop")
        elif not nav.within_radius and nav.distance_to_goal_m is not None:
            matched.setdefault("stopped_off_target", f"stopped {nav.distance_to_goal_m:.0f} m from the goal")

    if outcome.answer_ok is False and outcome.web_ok is not False and outcome.embodied_ok is not False:
        goals = [side for side, ok in (("web", outcome.web_ok), ("embodied", outcome.embodied_ok)) if ok is True]
        matched["wrong_answer"] = ("the answer check failed" + (f" ({' and '.join(goals)} goals met)" if goals else
                                                                 " (the task has no other goal)"))

    order = [key for key in CATEGORIES if key in matched]
    if not order:
        sides = [s for s, failed in (("web", web_failed), ("embodied", embodied_failed)) if failed]
        matched["unclassified"] = f"{' and '.join(sides) or 'some'} goal(s) unmet; no rule matched"
        order = ["unclassified"]
    primary = order[0]
    return ErrorClassification(category=primary, group=CATEGORIES[primary][0], matched=order,
                               evidence={k: matched[k] for k in order})


def _misalignment(record: EpisodeRecord, outcome: Outcome, task: Any) -> str | None:
    """The agent acted in the world, but not on what the web told it."""
    state = ((record.final_state or {}).get("environments") or {}).get("embodied") or {}
    if task.embodied_kind == "kitchen" and isinstance(state.get("objects"), list) and outcome.embodied_ok is False:
        from ewa_mcp.envs.kitchen.checks import changed_off_task, goal_types  # the kitchen's own reading

        off = changed_off_task(state["objects"], goal_types(task.embodied_goals))
        if off:
            return f"changed {', '.join(off)}, which no goal of the task mentions"
    reached: list[Any] = []
    if any(getattr(g, "kind", None) == "reached_place" for g in task.embodied_goals):
        from ewa_mcp.envs.street.goals import ReachedPlace  # the street's goal, imported only for a task with one

        reached = [g for g in task.embodied_goals if isinstance(g, ReachedPlace)]
    for goal, nav in zip(reached, outcome.navigation):
        if nav.success or not nav.stopped:
            continue
        store_nodes = task.metadata.get("store_nodes") if isinstance(task.metadata.get("store_nodes"), dict) else {}
        stores_at_stop = [s for s, node in store_nodes.items() if node == nav.final_node]
        ordered = {o.get("store_id") for o in outcome.orders}
        if goal.must_match_order_store and stores_at_stop and not ordered.intersection(stores_at_stop):
            return f"walked to {stores_at_stop[0]}, not the pickup store of the order"
        if outcome.web_ok is True and not nav.within_radius and nav.distance_to_goal_m is not None:
            return f"the web part succeeded, but the agent stopped {nav.distance_to_goal_m:.0f} m from the goal"
    return None
