"""Helpers shared by the domain generators."""

from __future__ import annotations

import hashlib
import random
from contextvars import ContextVar
from collections.abc import Callable, Sequence
from typing import Any, TypeVar
from urllib.parse import urlencode

from ewa_mcp.core.taskmodel import ToolCall


# The split being generated ("" for the public test split). Every generator draws through rng_for, so a salt
# set here (ewa_mcp/taskgen/splits.py) redraws every choice of an unchanged generator, and the public suite,
# generated without one, stays byte for byte what it was.
SPLIT_SALT: ContextVar[str] = ContextVar("ewa_split_salt", default="")


def rng_for(*parts: Any) -> random.Random:
    """A random stream that depends only on its parts and the split being generated (stable across runs and
    Python versions)."""
    salt = SPLIT_SALT.get()
    digest = hashlib.sha256(":".join(map(str, (salt, *parts) if salt else parts)).encode()).digest()
    return random.Random(int.from_bytes(digest[:8], "big"))


def call(tool: str, **args: Any) -> ToolCall:
    return ToolCall(tool=tool, args=args)


def ref(role: str, name: str) -> str:
    """A browser element reference by role and accessible name, resolved when the oracle runs."""
    return f"{role} '{name}'"


def site_url(site: str, path: str, **query: Any) -> str:
    pairs = [(k, v) for k, v in query.items() if v not in (None, "", [])]
    flat: list[tuple[str, Any]] = []
    for k, v in pairs:
        flat.extend((k, x) for x in v) if isinstance(v, (list, tuple)) else flat.append((k, v))
    return f"{site}:{path}" + ("?" + urlencode(flat) if flat else "")


# The step limit of a task: one budget per domain and difficulty, never derived from the oracle's length.
# A limit that follows the oracle gives the answer away (twice the oracle's walk to the right store, read
# against the map's distances, names the store). Each budget is at least the largest limit the old rule gave
# any task of its cell, so no task got tighter; the generators refuse a task whose oracle does not fit.
STEP_BUDGETS: dict[tuple[str, str], int] = {
    ("cooking", "easy"): 210, ("cooking", "medium"): 220, ("cooking", "hard"): 240,
    ("navigation", "easy"): 180, ("navigation", "medium"): 190, ("navigation", "hard"): 280,
    ("shopping", "easy"): 240, ("shopping", "medium"): 270, ("shopping", "hard"): 320,
    ("traveling", "medium"): 150, ("traveling", "hard"): 160,
    # Tasks imported from the paper's release (routes of any length, no difficulty of their own).
    ("navigation", "imported"): 500,
}


def step_budget(domain: str, difficulty: str, oracle_len: int) -> int:
    """The step limit of every ``domain`` task of this ``difficulty``; ``oracle_len`` is only checked to fit."""
    try:
        budget = STEP_BUDGETS[(domain, difficulty)]
    except KeyError:
        raise ValueError(f"no step budget for {domain} {difficulty} tasks; add one to STEP_BUDGETS "
                         "(ewa_mcp/taskgen/common.py)") from None
    if oracle_len > budget:
        raise ValueError(f"a {domain} {difficulty} oracle of {oracle_len} steps exceeds the budget of {budget}; "
                         "raise the budget in STEP_BUDGETS rather than deriving a limit from the oracle")
    return budget


# How a walk ends, said the same way by every intent that involves one (docs/grading.md, "Stop and finish").
# The walk ends at the first street_stop, or else when the episode finishes; where the agent stands then is graded.
WALK_RULE = "Your walk ends where you call street_stop (or finish_episode); be at the destination then."


_Item = TypeVar("_Item")
_Made = TypeVar("_Made")


def round_robin(ids: Sequence[str], queues: list[list[_Item]], cap: int,
                make: Callable[[str, _Item], _Made | None]) -> dict[str, _Made]:
    """Give each id, in order, what ``make`` builds from the queues taken in turn (each queue's items in
    order, at most ``cap`` made from one queue), so a hard form spreads its pairs or words over the ids. Stops
    at the first id no queue can serve: the ids left keep what they had."""
    made_for: dict[str, _Made] = {}
    used = [0] * len(queues)
    turn = 0
    for task_id in ids:
        made = None
        for _ in range(len(queues)):
            i = turn % len(queues)
            turn += 1
            while made is None and queues[i] and used[i] < cap:
                made = make(task_id, queues[i].pop(0))
            if made is not None:
                used[i] += 1
                break
        if made is None:
            break
        made_for[task_id] = made
    return made_for
