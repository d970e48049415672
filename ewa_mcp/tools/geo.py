"""Geolocation tools: look around, move to an adjacent standpoint, submit the location."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp_types import CallToolResult
from pydantic import BaseModel, Field

from ..environment import EnvError
from ..episodes import EpisodeManager
from ..response import StepOutput, env_action, footer, tool_result
from .adapter import define_tool

if TYPE_CHECKING:  # imported on first use: the server starts without loading the gazetteer
    from ..geo.env import GeoEnvironment

EpisodeId = Annotated[str, Field(description="the id start_episode returned", min_length=1, max_length=64)]


class SubmissionOutput(BaseModel):
    episode_id: str
    status: str
    end_reason: str | None
    steps: int
    submission: dict[str, Any]


def _geo(env: Any) -> GeoEnvironment:
    from ..geo.env import GeoEnvironment

    if not isinstance(env, GeoEnvironment):
        raise EnvError(f"this tool works in geolocation tasks only; this episode's embodied environment is "
                       f"{getattr(env, 'name', type(env).__name__)}")
    return env


def validate_submission(lat: float, lng: float, continent: str | None, country: str | None) -> str | None:
    """The problem with a submission (and how to fix it), or None when it is valid."""
    from ..geo.names import CONTINENTS, country_suggestions, resolve_continent, resolve_country

    if not (isinstance(lat, int | float) and math.isfinite(lat) and -90 <= lat <= 90):
        return (f"lat={lat!r} is out of range: latitude must be a number from -90 (south) to 90 (north) in decimal "
                "degrees")
    if not (isinstance(lng, int | float) and math.isfinite(lng) and -180 <= lng <= 180):
        return (f"lng={lng!r} is out of range: longitude must be a number from -180 (west) to 180 (east) in decimal "
                "degrees")
    if continent and resolve_continent(continent) is None:
        return (f"unknown continent {continent!r}; use one of {', '.join(CONTINENTS)} "
                "(or the codes AF, AN, AS, EU, NA, OC, SA)")
    if country and not resolve_country(country):
        close = country_suggestions(country)
        hint = f" Close matches: {', '.join(close)}." if close else ""
        return (f"unknown country {country!r}; give the country's English or local name (e.g. 'Ivory Coast' or "
                f"\"Côte d'Ivoire\") or its ISO 3166 code in capitals ('CI' or 'CIV').{hint}")
    return None


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    @define_tool(mcp, title="Geolocation: look around", effect="look", description=(
        "Geolocation: look around from the current standpoint. direction='all' shows every view the setting "
        "allows (embodied: north, east, south, west; baseline: north only) and the neighbouring standpoints with "
        "absolute and relative heading and distance; a single direction also turns you to face it. Views come "
        "as descriptions (text mode) and/or images (vision mode). Counts as a step, like every call."))
    async def geo_look(
        episode_id: EpisodeId,
        direction: Literal["all", "north", "east", "south", "west"] = "all",
    ) -> Annotated[CallToolResult, StepOutput]:
        return await env_action(episodes, episode_id, "geo_look", {"direction": direction}, "embodied",
                                lambda env: _geo(env).look(direction))

    @define_tool(mcp, title="Geolocation: walk to a neighbouring standpoint", effect="act", description=(
        "Geolocation (embodied setting): walk to an adjacent standpoint: direction forward/left/right/back "
        "(relative to where you face) or north/east/south/west, or neighbour = a neighbour id from the "
        "observation (e.g. 'p1'). You then face the way you walked; returns the views from there."))
    async def geo_move(
        episode_id: EpisodeId,
        direction: Literal["forward", "left", "right", "back", "north", "east", "south", "west"] | None = None,
        neighbour: Annotated[str | None, Field(max_length=32, description="a neighbour id, e.g. 'p1'")] = None,
    ) -> Annotated[CallToolResult, StepOutput]:
        args = {k: v for k, v in {"direction": direction, "neighbour": neighbour}.items() if v is not None}
        return await env_action(episodes, episode_id, "geo_move", args, "embodied",
                                lambda env: _geo(env).move(direction=direction, neighbour=neighbour))

    @define_tool(mcp, title="Geolocation: submit the location", effect="destructive", description=(
        "Geolocation: submit where you are and end the episode. lat/lng in decimal degrees (required); "
        "continent, country, city and street as names (optional but each is scored). Invalid values are "
        "refused with the valid form and the episode stays open."))
    async def submit_location(
        episode_id: EpisodeId,
        lat: Annotated[float, Field(description="latitude, -90..90")],
        lng: Annotated[float, Field(description="longitude, -180..180")],
        continent: Annotated[str | None, Field(max_length=64)] = None,
        country: Annotated[str | None, Field(max_length=128)] = None,
        city: Annotated[str | None, Field(max_length=128)] = None,
        street: Annotated[str | None, Field(max_length=200)] = None,
    ) -> Annotated[CallToolResult, SubmissionOutput]:
        args = {"lat": lat, "lng": lng, "continent": continent, "country": country, "city": city, "street": street}
        problem = validate_submission(lat, lng, continent, country)

        def check(_episode: Any) -> None:
            # Refused like any failed call: recorded, one step used, the episode stays open.
            if problem is not None:
                raise ToolError(problem)

        submission = {k: (v.strip() if isinstance(v, str) else v) or None for k, v in args.items()
                      if k not in ("lat", "lng")}
        submission = {"lat": float(lat), "lng": float(lng), **submission}
        answer = (f"{lat:.5f}, {lng:.5f} — " + ", ".join(str(submission[k] or "?") for k in
                                                          ("continent", "country", "city", "street")))
        episode = await episodes.finish(episode_id, answer=answer, submission=submission, tool="submit_location",
                                        args=args, requires="geo", check=check)
        out = SubmissionOutput(episode_id=episode.id, status=episode.status, end_reason=episode.end_reason,
                               steps=episode.steps, submission=submission)
        return tool_result(out, f"Location submitted: {answer}. {footer(episode)}")
