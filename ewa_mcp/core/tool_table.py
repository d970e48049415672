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

import inspect
from collections.abc import Awaitable, Callable, Iterable
from dataclasses import dataclass, field
from typing import Annotated, Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp_types import CallToolResult, ToolAnnotations
from pydantic import Field

from .response import StepOutput, env_action

Effect = Literal["query", "look", "act", "destructive"]

# The first argument of every tool that acts on an episode.
EpisodeId = Annotated[str, Field(description="the id start_episode returned", min_length=1, max_length=64)]


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
                           "ewa_mcp.core.tool_table.define_tool")


# ---------------------------------------------------------------- action tables
NO_DEFAULT: Any = inspect.Parameter.empty


@dataclass(frozen=True)
class Param:
    """One parameter of a table action: its type (an annotation, with its pydantic ``Field``) and default."""

    annotation: Any
    default: Any = NO_DEFAULT


@dataclass(frozen=True)
class ToolAction:
    """One entry of a world's action table (its ``actions.py``): the MCP tool it becomes and what it does.

    ``run(env, **args)`` acts on the episode's environment of ``side`` and returns its ``Observation``; the tool
    is ``name(episode_id, <params>)``, declared through ``define_tool`` and run through ``response.env_action``,
    so every call passes ``EpisodeManager.act`` (the step rule, the record). The trajectory keeps the call's
    arguments, without those left at None unless ``keep_none``."""

    name: str
    title: str
    effect: Effect
    description: str
    run: Callable[..., Awaitable[Any]]
    params: dict[str, Param] = field(default_factory=dict)
    side: Literal["web", "embodied"] = "embodied"
    keep_none: bool = False


def action_tool(action: ToolAction, episodes: Any) -> Callable[..., Awaitable[Any]]:
    """The tool function of a table action, with the signature the MCP SDK reads its schema from."""
    async def tool(episode_id: str, **args: Any) -> Any:
        recorded = args if action.keep_none else {k: v for k, v in args.items() if v is not None}
        return await env_action(episodes, episode_id, action.name, recorded, action.side,
                                lambda env: action.run(env, **args))

    params = [inspect.Parameter("episode_id", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=EpisodeId)]
    params += [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, annotation=p.annotation, default=p.default)
               for name, p in action.params.items()]
    result = Annotated[CallToolResult, StepOutput]
    tool.__signature__ = inspect.Signature(params, return_annotation=result)  # type: ignore[attr-defined]
    tool.__name__ = tool.__qualname__ = action.name
    return tool


def register_actions(mcp: MCPServer, episodes: Any, actions: Iterable[ToolAction]) -> None:
    """Declare one MCP tool per table action, in the table's order."""
    for action in actions:
        define_tool(mcp, name=action.name, title=action.title, effect=action.effect,
                    description=action.description)(action_tool(action, episodes))
