"""Street (outdoor) environment tools: observe, move, stop. All go through env_action, so the
episode protocol (active environment, step limit, trajectory record) applies to every call."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from mcp.server.mcpserver import MCPServer
from mcp_types import CallToolResult
from pydantic import Field

from ..environment import EnvError, Observation
from ..episodes import EpisodeManager
from ..response import StepOutput, env_action

if TYPE_CHECKING:  # imported on first use: the server starts without loading street graphs
    from ..outdoor.env import StreetEnvironment

EpisodeId = Annotated[str, Field(description="the id start_episode returned", min_length=1, max_length=64)]


def _street(env: object) -> StreetEnvironment:
    from ..outdoor.env import StreetEnvironment

    if not isinstance(env, StreetEnvironment):
        raise EnvError(f"this episode's embodied environment is {getattr(env, 'name', type(env).__name__)}, not the "
                       "street; use that environment's tools")
    return env


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    @mcp.tool(description=(
        "Look around in the street: your street and heading, the neighbouring panorama nodes (absolute and "
        "relative heading, distance, street name) and a description of four views (front/right/back/left, or "
        "north/east/south/west with frame='absolute'); view images too when the episode's observation option is "
        "vision or both. Counts as a step, like every call."))
    async def street_observe(
        episode_id: EpisodeId,
        frame: Literal["relative", "absolute"] = "relative",
    ) -> Annotated[CallToolResult, StepOutput]:
        async def act(env: object) -> Observation:
            return _street(env).observation(frame)

        return await env_action(episodes, episode_id, "street_observe", {"frame": frame}, "embodied", act)

    @mcp.tool(description=(
        "Walk to a neighbouring node: direction forward/left/right/back (relative to your heading), or "
        "neighbour = one of the neighbour node ids from street_observe. Your heading becomes the direction "
        "you walked."))
    async def street_move(
        episode_id: EpisodeId,
        direction: Literal["forward", "left", "right", "back"] | None = None,
        neighbour: Annotated[str | None, Field(max_length=64, description="a neighbour node id")] = None,
    ) -> Annotated[CallToolResult, StepOutput]:
        args = {k: v for k, v in {"direction": direction, "neighbour": neighbour}.items() if v is not None}

        async def act(env: object) -> Observation:
            return _street(env).move(direction=direction, neighbour=neighbour)

        return await env_action(episodes, episode_id, "street_move", args, "embodied", act)

    @mcp.tool(description="Declare that you have arrived at the destination. After this, moves are refused.")
    async def street_stop(episode_id: EpisodeId) -> Annotated[CallToolResult, StepOutput]:
        async def act(env: object) -> Observation:
            return _street(env).stop()

        return await env_action(episodes, episode_id, "street_stop", {}, "embodied", act)
