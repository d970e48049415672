"""Geolocation tools: look around and move (the action table, actions.py), and submit the location, which ends
the episode through the episode manager's atomic finish."""

from __future__ import annotations

import math
from typing import Annotated, Any

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp_types import CallToolResult
from pydantic import BaseModel, Field

from ewa_mcp.core.episodes import EpisodeManager
from ewa_mcp.core.response import compact_requested, footer, tool_result
from ewa_mcp.core.tool_table import EpisodeId, define_tool, register_actions

from .actions import ACTIONS


class SubmissionOutput(BaseModel):
    episode_id: str
    status: str
    end_reason: str | None
    steps: int
    submission: dict[str, Any]


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
    register_actions(mcp, episodes, ACTIONS)

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
        # The text says what the structured content holds: the submission, how the episode ended, the steps.
        text = (f"Location submitted: {answer} (latitude, longitude — continent, country, city, street). Episode "
                f"status {episode.status}" + (f" ({episode.end_reason})" if episode.end_reason else "")
                + f" after {episode.steps} steps. {footer(episode)}")
        return tool_result(out, text, compact=compact_requested(episode))
