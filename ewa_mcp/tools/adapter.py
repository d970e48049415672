"""The tool adapter: every MCP tool is declared with ``define_tool`` next to its function, naming its title and
its effect on the world; the effect becomes the tool's MCP ``ToolAnnotations`` (as playwright-mcp's tool
types "readOnly"/"destructive" do).

Effects:
  * ``query``: reads the server only, the same answer every time (list_tasks): read-only, idempotent.
  * ``look``: shows an environment or an episode without changing it (get_observation, street_observe,
    browser_snapshot, ...): read-only. Not idempotent in the episode's terms (every call is a step), so
    the hint is left false.
  * ``act``: changes the environment in a way later actions can undo (move, open, click a link): neither
    read-only nor destructive.
  * ``destructive``: changes that cannot be undone (slice or cook food, end the walk, end the episode, a
    click or keystroke that may submit an order).
No tool reaches outside the benchmark (the sites are on loopback), so openWorldHint is always false.
The MCP specification's defaults for a tool without annotations are the opposite (destructive, open world),
so every tool states them; ``check_declared`` refuses a server with a tool that does not.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp_types import ToolAnnotations

Effect = Literal["query", "look", "act", "destructive"]


def tool_annotations(effect: Effect) -> ToolAnnotations:
    if effect not in ("query", "look", "act", "destructive"):
        raise ValueError(f"unknown tool effect {effect!r}; use query, look, act or destructive")
    read_only = effect in ("query", "look")
    return ToolAnnotations(
        read_only_hint=read_only,
        destructive_hint=effect == "destructive",
        idempotent_hint=effect == "query",
        open_world_hint=False,
    )


def define_tool(mcp: MCPServer, *, title: str, effect: Effect, description: str,
                name: str | None = None) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``@define_tool(mcp, title=..., effect=..., description=...)`` in place of ``@mcp.tool(...)``."""
    if not title.strip():
        raise ValueError("a tool needs a title")
    return mcp.tool(name=name, title=title, description=description, annotations=tool_annotations(effect))


def check_declared(mcp: MCPServer) -> None:
    """Every registered tool has a title and annotations (it was declared through define_tool)."""
    missing = [tool.name for tool in mcp._tool_manager.list_tools() if not tool.title or tool.annotations is None]
    if missing:
        raise RuntimeError(f"tools without a title or annotations: {', '.join(missing)}; declare them with "
                           "ewa_mcp.tools.adapter.define_tool")
