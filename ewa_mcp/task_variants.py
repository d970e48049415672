"""Variants of suite tasks for training and forking: the same task without its web part."""

from __future__ import annotations

from .core.taskmodel import Task


def embodied_only(task: Task, new_id: str) -> Task:
    """The task without its web part: it starts in its embodied environment, keeps only its embodied goals and
    answer, and its oracle drops the browser calls and the switch to the embodied side. Such an episode has no
    browser, so it starts fast and can be forked (ewa_mcp/forking.py)."""
    raw = task.model_dump(mode="json")
    raw["id"] = new_id
    raw["start"]["web"] = None
    raw["start"]["environment"] = "embodied"
    raw["web_goals"] = []
    raw["oracle"] = [step for step in raw["oracle"]
                     if not (step["tool"].startswith("browser_") or step["tool"] == "switch_environment")]
    return Task.model_validate(raw)
