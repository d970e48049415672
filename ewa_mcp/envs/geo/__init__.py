"""Geolocation domain: locations, standpoint graphs, rendered views, the environment, task and wiki generators."""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, EnvironmentSpec

from ..browser import BROWSER, WEB_CHECKS, WEB_GOALS

GEO = EnvironmentSpec(
    "geo", "embodied", f"{__name__}.env:GeoEnvironment", f"{__name__}.tools", "geo_look, geo_move and submit_location",
    tool_order=40,
    instructions="Geolocation episodes end with submit_location instead of finish_episode.",
    finish_hint="Geolocation tasks end with submit_location instead.",
    start=f"{__name__}.goals:GeoStart",
    answers=(f"{__name__}.goals:GeoAnswer",),
    options=f"{__name__}.options:GeoOptions",
)

DOMAINS = [Domain("geolocation", (BROWSER, GEO), goal_kinds=WEB_GOALS, checks=WEB_CHECKS, writer=f"{__name__}.taskgen.geolocation:generate_tasks")]
