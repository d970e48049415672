"""The lamp's tools, from its action table. Their names start with the environment's registry name, so a lamp tool
called on another domain's episode is refused before it runs."""

from __future__ import annotations

from typing import Any

from ewa_mcp.core.tool_table import register_actions

from .actions import ACTIONS


def register(mcp: Any, episodes: Any) -> None:
    register_actions(mcp, episodes, ACTIONS)
