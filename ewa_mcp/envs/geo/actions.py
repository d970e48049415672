"""The geolocation world's action table: look around and walk (geo_look, geo_move), from which tools.py declares
them; submit_location, which ends the episode, is declared beside them in tools.py."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field

from ewa_mcp.core.environment import EnvError, Observation
from ewa_mcp.core.tool_table import Param, ToolAction

if TYPE_CHECKING:  # imported on first use: the server starts without loading the gazetteer
    from .env import GeoEnvironment


def geo(env: Any) -> GeoEnvironment:
    from .env import GeoEnvironment

    if not isinstance(env, GeoEnvironment):
        raise EnvError(f"this tool works in geolocation tasks only; this episode's embodied environment is "
                       f"{getattr(env, 'name', type(env).__name__)}")
    return env


async def _look(env: Any, direction: str) -> Observation:
    return await geo(env).look(direction)


async def _move(env: Any, direction: str | None, neighbour: str | None) -> Observation:
    return await geo(env).move(direction=direction, neighbour=neighbour)


ACTIONS = [
    ToolAction(
        "geo_look", "Geolocation: look around", "look",
        "Geolocation: look around from the current standpoint. direction='all' shows every view the setting "
        "allows (embodied: north, east, south, west; baseline: north only) and the neighbouring standpoints with "
        "absolute and relative heading and distance; a single direction also turns you to face it. Views come "
        "as descriptions (text mode) and/or images (vision mode). Counts as a step, like every call.",
        _look, {"direction": Param(Literal["all", "north", "east", "south", "west"], "all")}),
    ToolAction(
        "geo_move", "Geolocation: walk to a neighbouring standpoint", "act",
        "Geolocation (embodied setting): walk to an adjacent standpoint: direction forward/left/right/back "
        "(relative to where you face) or north/east/south/west, or neighbour = a neighbour id from the "
        "observation (e.g. 'p1'). You then face the way you walked; returns the views from there.",
        _move, {"direction": Param(Literal["forward", "left", "right", "back", "north", "east", "south", "west"]
                                   | None, None),
                "neighbour": Param(Annotated[str | None, Field(max_length=32, description="a neighbour id, e.g. 'p1'")],
                                   None)}),
]
