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
from .adapter import define_tool

if TYPE_CHECKING:  # imported on first use: the server starts without loading street graphs
    from ..outdoor.env import StreetEnvironment

# The move labels street_observe lists; kept equal to ewa_mcp/outdoor/env.Direction (tests/outdoor/test_mcp.py),
# declared here so the server starts without importing the street environment.
Direction = Literal["forward", "forward-right", "right", "back-right", "back", "back-left", "left", "forward-left"]

EpisodeId = Annotated[str, Field(description="the id start_episode returned", min_length=1, max_length=64)]


def _street(env: object) -> StreetEnvironment:
    from ..outdoor.env import StreetEnvironment

    if not isinstance(env, StreetEnvironment):
        raise EnvError(f"this episode's embodied environment is {getattr(env, 'name', type(env).__name__)}, not the "
                       "street; use that environment's tools")
    return env


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    @define_tool(mcp, title="Look around in the street", effect="look", description=(
        "Look around in the street: your street and heading, the neighbouring panorama nodes (each with a "
        "direction label that is unique here, absolute and relative heading, distance, street name), what is right "
        "here, and a description of four views (front/right/back/left, or north/east/south/west with "
        "frame='absolute'); distances are from where you stand now. View images too when the episode's observation "
        "option is vision or both. Says 'Walk stopped at ...' once the walk is over. Counts as a step, like every call."))
    async def street_observe(
        episode_id: EpisodeId,
        frame: Literal["relative", "absolute"] = "relative",
    ) -> Annotated[CallToolResult, StepOutput]:
        async def act(env: object) -> Observation:
            return _street(env).observation(frame)

        return await env_action(episodes, episode_id, "street_observe", {"frame": frame}, "embodied", act)

    @define_tool(mcp, title="Walk to a neighbouring node", effect="act", description=(
        "Walk to a neighbouring node: direction = one of the labels street_observe lists here (forward, "
        "forward-right, right, back-right, back, back-left, left, forward-left; relative to your heading), or "
        "neighbour = one of the neighbour node ids. A plain forward/right/back/left also works when exactly one "
        "street leads that way; when several do, the move is refused and the error lists them. Your heading "
        "becomes the direction you walked. Refused after street_stop: the walk is over then."))
    async def street_move(
        episode_id: EpisodeId,
        direction: Direction | None = None,
        neighbour: Annotated[str | None, Field(max_length=64, description="a neighbour node id")] = None,
    ) -> Annotated[CallToolResult, StepOutput]:
        args = {k: v for k, v in {"direction": direction, "neighbour": neighbour}.items() if v is not None}

        async def act(env: object) -> Observation:
            return _street(env).move(direction=direction, neighbour=neighbour)

        return await env_action(episodes, episode_id, "street_move", args, "embodied", act)

    @define_tool(mcp, title="End the walk here", effect="destructive", description=(
        "End the walk here: where you stand now is where the walk ended, and that is what is graded (without a "
        "stop, the walk ends where you are when the episode finishes). After this, moves are refused; call "
        "finish_episode to end the episode."))
    async def street_stop(episode_id: EpisodeId) -> Annotated[CallToolResult, StepOutput]:
        async def act(env: object) -> Observation:
            return _street(env).stop()

        return await env_action(episodes, episode_id, "street_stop", {}, "embodied", act)
