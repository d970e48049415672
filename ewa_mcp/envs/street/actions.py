"""The street's action table: one entry per tool (observe, move, stop), from which tools.py declares them."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field

from ewa_mcp.core.environment import EnvError, Observation
from ewa_mcp.core.tool_table import Param, ToolAction

if TYPE_CHECKING:  # imported on first use: the server starts without loading street graphs
    from .env import StreetEnvironment

# The move labels street_observe lists; kept equal to env.Direction (tests/outdoor/test_mcp.py), declared here
# so the server starts without importing the street environment.
Direction = Literal["forward", "forward-right", "right", "back-right", "back", "back-left", "left", "forward-left"]
Frame = Literal["relative", "absolute"]


def street(env: Any) -> StreetEnvironment:
    from .env import StreetEnvironment

    if not isinstance(env, StreetEnvironment):
        raise EnvError(f"this episode's embodied environment is {getattr(env, 'name', type(env).__name__)}, not the "
                       "street; use that environment's tools")
    return env


async def _observe(env: Any, frame: Frame) -> Observation:
    return street(env).observation(frame)


async def _move(env: Any, direction: str | None, neighbour: str | None) -> Observation:
    return street(env).move(direction=direction, neighbour=neighbour)


async def _stop(env: Any) -> Observation:
    return street(env).stop()


ACTIONS = [
    ToolAction(
        "street_observe", "Look around in the street", "look",
        "Look around in the street: the neighbouring panorama nodes (each with a direction label that is unique "
        "here, absolute and relative heading and distance) and four views (front/right/back/left, or "
        "north/east/south/west with frame='absolute'); distances are from where you stand now. Text mode adds your "
        "street, each neighbour's street, what is right here and a description of each view; vision mode gives the "
        "four view images instead (street names are on the signs in them). Says 'Walk stopped at ...' once the walk "
        "is over. Counts as a step, like every call.",
        _observe, {"frame": Param(Frame, "relative")}),
    ToolAction(
        "street_move", "Walk to a neighbouring node", "act",
        "Walk to a neighbouring node: direction = one of the labels street_observe lists here (forward, "
        "forward-right, right, back-right, back, back-left, left, forward-left; relative to your heading), or "
        "neighbour = one of the neighbour node ids. A plain forward/right/back/left also works when exactly one "
        "street leads that way; when several do, the move is refused and the error lists them. Your heading "
        "becomes the direction you walked. Refused after street_stop: the walk is over then.",
        _move, {"direction": Param(Direction | None, None),
                "neighbour": Param(Annotated[str | None, Field(max_length=64, description="a neighbour node id")],
                                   None)}),
    ToolAction(
        "street_stop", "End the walk here", "destructive",
        "End the walk here: where you stand now is where the walk ended, and that is what is graded (without a "
        "stop, the walk ends where you are when the episode finishes). After this, moves are refused; call "
        "finish_episode to end the episode.",
        _stop),
]
