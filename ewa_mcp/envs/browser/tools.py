"""Browser tools, declared from the browser's action table (actions.py): WebArena's action space (click, type,
hover, press, scroll, tabs, goto, back/forward) and the two looks (snapshot, screenshot). All go through
env_action on the web side, so the episode protocol applies to every call."""

from __future__ import annotations

from mcp.server.mcpserver import MCPServer

from ewa_mcp.core.episodes import EpisodeManager
from ewa_mcp.core.tool_table import register_actions

from .actions import ACTIONS


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    register_actions(mcp, episodes, ACTIONS)
