"""Every heuristic agent by name: this package's agents (agents.py) and the walking ones (walking.py)."""

from __future__ import annotations

from .agents import AGENTS
from .walking import WALKING

HEURISTICS: dict[str, type] = {a.name: a for a in (*AGENTS, *WALKING)}
