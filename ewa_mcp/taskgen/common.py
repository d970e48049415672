"""Helpers shared by the domain generators."""

from __future__ import annotations

import hashlib
import random
from contextvars import ContextVar
from typing import Any
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


def step_limit_for(oracle_len: int, slack: int = 15) -> int:
    """Room for an agent that is less direct than the oracle, but not unbounded."""
    return max(30, 2 * oracle_len + slack)


# How a walk ends, said the same way by every intent that involves one (docs/grading.md, "Stop and finish").
# The walk ends at the first street_stop, or else when the episode finishes; where the agent stands then is graded.
WALK_RULE = "Your walk ends where you call street_stop (or finish_episode); be at the destination then."
