"""The outdoor world: street graphs of four city cores on real coordinates, points of interest,
rendered street views, walking directions and the street environment the agent walks in."""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, EnvironmentSpec, StatusField

from ..browser import BROWSER, WEB_CHECKS, WEB_GOALS

STREET = EnvironmentSpec(
    "street", "embodied", f"{__name__}.env:StreetEnvironment", f"{__name__}.tools", "street_* tools", tool_order=10,
    instructions="A walk ends at your first street_stop, or else at finish_episode: where you stand then is graded.",
    finish_hint="Where a task involves a walk, the walk ends at your first street_stop or, without one, here: where "
                "you stand now is graded.",
    status_fields=(StatusField("walk_stopped", "tasks with a walk: whether street_stop ended it; null when there is "
                               "no walk", phrase="whether the walk is stopped (tasks with a walk)", when_true="walk stopped", when_false="walk not stopped"),),
    start=f"{__name__}.goals:StreetStart",
    goals=(f"{__name__}.goals:ReachedPlace", f"{__name__}.goals:PassedPlace"),
)

_GOALS = (*WEB_GOALS, "reached_place", "passed_place")
_CHECKS = {**WEB_CHECKS, "reached_place": f"{__name__}.checks:reached_place",
           "passed_place": f"{__name__}.checks:passed_place"}

DOMAINS = [
    Domain(name, (BROWSER, STREET), generator=f"{__name__}.taskgen.{name}:generate", goal_kinds=_GOALS,
           checks=_CHECKS)
    for name in ("navigation", "shopping", "traveling")
]
