"""Heuristic agents: no model, only priors an agent can see (docs/verified.md).

Each agent plays through the real MCP tools like the built-in ones (``ewa-mcp eval --agent <name>``) and
reads only what an agent is shown: the intent, the step limit, the tool results, the public web sites, and,
for the prior agent, the public task files (every *other* task's answer: leave-one-out, so an agent never
reads its own task's answer). A benchmark score above chance says the suite gives something away.
"""

from __future__ import annotations

from typing import Any

# The agents by name, known without importing them (the command line lists them at start-up).
NAMES = ("prior", "geo-lexical", "wiki-search", "order-everywhere", "first-listed", "cook-everything", "look-alike",
         "first-recipe", "cook-union", "directions-walker", "step-limit-store", "nearest-store", "cheapest-store", "stop-elimination")


def heuristic_agent(name: str) -> Any:
    """A fresh heuristic agent by name (KeyError names the choices)."""
    from .table import HEURISTICS

    try:
        return HEURISTICS[name]()
    except KeyError:
        raise KeyError(f"unknown heuristic agent {name!r}; choose one of {', '.join(NAMES)}") from None
