"""Shared by the training tests: embodied-only variants of suite tasks (no browser), and a task per domain."""

from __future__ import annotations

from ewa_mcp.taskmodel import Task


def embodied_only(task: Task, new_id: str) -> Task:
    """The task without its web part: it starts in its embodied environment, keeps only its embodied goals, and
    its oracle drops the browser calls and the switch to the embodied side."""
    raw = task.model_dump(mode="json")
    raw["id"] = new_id
    raw["start"]["web"] = None
    raw["start"]["environment"] = "embodied"
    raw["web_goals"] = []
    raw["oracle"] = [step for step in raw["oracle"]
                     if not (step["tool"].startswith("browser_") or step["tool"] == "switch_environment")]
    return Task.model_validate(raw)


# One task per domain (the first of its domain in id order has each domain's usual shape).
ONE_PER_DOMAIN = {
    "navigation": "navigation-boston-000",
    "cooking": "cooking-buy-0001",
    "shopping": "shopping-calories-000",
    "traveling": "traveling-boston-005",
    "geolocation": "geo-0001-baseline",
}
