"""Street (outdoor) environment tools, declared from the street's action table (actions.py). All go through
env_action, so the episode protocol (active environment, step limit, trajectory record) applies to every call."""

from __future__ import annotations

from mcp.server.mcpserver import MCPServer

from ewa_mcp.core.episodes import EpisodeManager
from ewa_mcp.core.tool_table import register_actions

from .actions import ACTIONS


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    register_actions(mcp, episodes, ACTIONS)
