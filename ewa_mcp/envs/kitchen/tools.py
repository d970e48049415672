"""Kitchen tools: one MCP tool per entry of the kitchen action table (ewa_mcp/envs/kitchen/actions.py), plus
kitchen_action for AI2-THOR-style strings.

Every tool goes through ``env_action(..., "embodied", ...)``, so the episode manager refuses it
while the web environment is active and records it in the trajectory.
"""

from __future__ import annotations

import inspect
from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING, Annotated, Any

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ResourceError
from mcp_types import CallToolResult
from pydantic import Field

from ewa_mcp.core.environment import EnvError, Environment, Observation
from ewa_mcp.core.episodes import EpisodeError, EpisodeManager
from .actions import TABLE, KitchenAction
from ewa_mcp.core.response import StepOutput, env_action
from ewa_mcp.core.tool_table import Effect, EpisodeId, define_tool

if TYPE_CHECKING:  # imported on first use: the server starts without loading the simulator
    from .env import KitchenEnvironment

StepResult = Annotated[CallToolResult, StepOutput]


def _kitchen(env: Environment) -> KitchenEnvironment:
    from .env import KitchenEnvironment

    if not isinstance(env, KitchenEnvironment):
        raise EnvError(f"this episode's embodied environment is a {type(env).name}, not a kitchen; "
                       "use that environment's tools")
    return env


def _tool_function(action: KitchenAction,
                   act: Callable[..., Awaitable[CallToolResult]]) -> Callable[..., Awaitable[CallToolResult]]:
    """The tool's function: ``(episode_id, <the action's parameters>)``, with a signature the SDK reads."""

    async def tool(episode_id: str, **args: Any) -> CallToolResult:
        return await act(episode_id, action.tool_name, args, lambda k: k.perform(action.name, args))

    params = [inspect.Parameter("episode_id", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation=EpisodeId)]
    params += [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, annotation=kind)
               for name, kind in action.params.items()]
    tool.__signature__ = inspect.Signature(params, return_annotation=StepResult)  # type: ignore[attr-defined]
    tool.__name__ = tool.__qualname__ = action.tool_name
    return tool


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    async def act(episode_id: str, tool: str, args: dict[str, Any],
                  fn: Callable[[KitchenEnvironment], Awaitable[Observation]]) -> CallToolResult:
        return await env_action(episodes, episode_id, tool, args, "embodied", lambda env: fn(_kitchen(env)))

    for action in TABLE.tools():
        effect: Effect = "look" if action.read_only else "destructive" if action.destructive else "act"
        define_tool(mcp, name=action.tool_name, title=f"Kitchen: {action.title[0].lower()}{action.title[1:]}",
                    effect=effect, description=action.description)(_tool_function(action, act))

    @define_tool(mcp, title="Kitchen: any AI2-THOR action", effect="destructive",
                 description="Any kitchen action written the AI2-THOR way, e.g. 'PickupObject Apple', "
                             "'Teleport [Pan]', 'MoveAhead', 'ToggleObjectOn StoveKnob_1'.")
    async def kitchen_action(
        episode_id: EpisodeId,
        action: Annotated[str, Field(min_length=1, max_length=300, description="e.g. 'SliceObject Tomato'")],
    ) -> StepResult:
        return await act(episode_id, "kitchen_action", {"action": action}, lambda k: k.run(action))

    @mcp.resource("ewa://episodes/{episode_id}/kitchen.png", mime_type="image/png",
                  description="The kitchen of an episode: the agent's camera frame (kitchen_view='map': drawn from above)")
    async def kitchen_image(episode_id: str) -> bytes:
        try:
            episode = episodes.get(episode_id)
        except EpisodeError as exc:
            raise ResourceError(str(exc)) from exc
        env = episode.environments.get("embodied")
        from .env import KitchenEnvironment

        if not isinstance(env, KitchenEnvironment) or env.session is None:
            raise ResourceError(f"episode {episode_id} has no running kitchen")
        return env.image_png()
