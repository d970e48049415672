"""Kitchen tools: one MCP tool per AI2-THOR action, plus kitchen_action for AI2-THOR-style strings.

Every tool goes through ``env_action(..., "embodied", ...)``, so the episode manager refuses it
while the web environment is active and records it in the trajectory.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING, Annotated, Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ResourceError
from mcp_types import CallToolResult
from pydantic import Field

from ..environment import EnvError, Environment, Observation
from ..episodes import EpisodeError, EpisodeManager
from ..response import StepOutput, env_action

if TYPE_CHECKING:  # imported on first use: the server starts without loading the simulator
    from ..indoor.env import KitchenEnvironment
from .core import EpisodeId

ObjectRef = Annotated[
    str,
    Field(
        min_length=1,
        max_length=200,
        description="the object: a handle from the observation (Apple_1, Cabinet_3), an objectId, or a type "
        "(Apple; exact AI2-THOR types only — Egg is not Eggplant)",
    ),
]
StepResult = Annotated[CallToolResult, StepOutput]


def _kitchen(env: Environment) -> KitchenEnvironment:
    from ..indoor.env import KitchenEnvironment

    if not isinstance(env, KitchenEnvironment):
        raise EnvError(f"this episode's embodied environment is a {type(env).name}, not a kitchen; "
                       "use that environment's tools")
    return env


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    async def act(episode_id: str, tool: str, args: dict[str, Any],
                  fn: Callable[[KitchenEnvironment], Awaitable[Observation]]) -> CallToolResult:
        return await env_action(episodes, episode_id, tool, args, "embodied", lambda env: fn(_kitchen(env)))

    @mcp.tool(description="Teleport [object]: stand at the nearest spot facing the object, within reach "
                          "(if it is inside a closed receptacle you face that receptacle).")
    async def kitchen_teleport(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_teleport", {"object": object}, lambda k: k.teleport(object))

    @mcp.tool(description="MoveAhead/MoveBack/MoveLeft/MoveRight: step 0.25 m (blocked by furniture).")
    async def kitchen_move(episode_id: EpisodeId, direction: Literal["ahead", "back", "left", "right"]) -> StepResult:
        return await act(episode_id, "kitchen_move", {"direction": direction}, lambda k: k.move(direction))

    @mcp.tool(description="RotateLeft/RotateRight: turn 90 degrees.")
    async def kitchen_rotate(episode_id: EpisodeId, direction: Literal["left", "right"]) -> StepResult:
        return await act(episode_id, "kitchen_rotate", {"direction": direction}, lambda k: k.rotate(direction))

    @mcp.tool(description="PickupObject [object]: take an object in reach into your (empty) hand.")
    async def kitchen_pickup(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_pickup", {"object": object}, lambda k: k.pickup(object))

    @mcp.tool(description="PutObject [receptacle]: put what you hold in/on a receptacle in reach "
                          "(open it first if it is closed).")
    async def kitchen_put(episode_id: EpisodeId, receptacle: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_put", {"receptacle": receptacle}, lambda k: k.put(receptacle))

    @mcp.tool(description="DropHandObject: let go of what you hold (it lands on the surface ahead or the floor).")
    async def kitchen_drop(episode_id: EpisodeId) -> StepResult:
        return await act(episode_id, "kitchen_drop", {}, lambda k: k.drop())

    @mcp.tool(description="OpenObject [object]: open a fridge, cabinet, drawer or microwave in reach.")
    async def kitchen_open(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_open", {"object": object}, lambda k: k.open(object))

    @mcp.tool(description="CloseObject [object]: close an open fridge, cabinet, drawer or microwave in reach.")
    async def kitchen_close(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_close", {"object": object}, lambda k: k.close_object(object))

    @mcp.tool(description="SliceObject [object]: slice food in reach while holding a Knife or ButterKnife "
                          "(an Egg cracks into EggCracked).")
    async def kitchen_slice(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_slice", {"object": object}, lambda k: k.slice(object))

    @mcp.tool(description="CookObject [object]: cook food in reach at once (AI2-THOR's instant cook). Food also "
                          "cooks in a Pan/Pot on a burner whose StoveKnob is on, in a running Microwave, or as "
                          "BreadSliced in a running Toaster.")
    async def kitchen_cook(episode_id: EpisodeId, object: ObjectRef) -> StepResult:
        return await act(episode_id, "kitchen_cook", {"object": object}, lambda k: k.cook(object))

    @mcp.tool(description="ToggleObjectOn/Off [object]: switch a StoveKnob (lights its burner), Microwave, "
                          "Toaster or CoffeeMachine in reach.")
    async def kitchen_toggle(episode_id: EpisodeId, object: ObjectRef, state: Literal["on", "off"]) -> StepResult:
        return await act(episode_id, "kitchen_toggle", {"object": object, "state": state},
                         lambda k: k.toggle(object, state == "on"))

    @mcp.tool(description="Any kitchen action written the AI2-THOR way, e.g. 'PickupObject Apple', "
                          "'Teleport [Pan]', 'MoveAhead', 'ToggleObjectOn StoveKnob_1'.")
    async def kitchen_action(
        episode_id: EpisodeId,
        action: Annotated[str, Field(min_length=1, max_length=300, description="e.g. 'SliceObject Tomato'")],
    ) -> StepResult:
        return await act(episode_id, "kitchen_action", {"action": action}, lambda k: k.run(action))

    @mcp.resource("ewa://episodes/{episode_id}/kitchen.png", mime_type="image/png",
                  description="The kitchen of an episode, drawn from above (or AI2-THOR's frame)")
    async def kitchen_image(episode_id: str) -> bytes:
        try:
            episode = episodes.get(episode_id)
        except EpisodeError as exc:
            raise ResourceError(str(exc)) from exc
        env = episode.environments.get("embodied")
        from ..indoor.env import KitchenEnvironment

        if not isinstance(env, KitchenEnvironment) or env.session is None:
            raise ResourceError(f"episode {episode_id} has no running kitchen")
        return env.image_png()
