"""The street world's task models: the start of a walk and the goal kinds it owns (graded by checks.py from
the walk's final state). Declared on ``STREET`` (``__init__.py``), from which the kernel assembles the task
schema (ewa_mcp/core/taskmodel.py)."""

from __future__ import annotations

from typing import Literal

from ewa_mcp.core.taskmodel import StrictModel


class StreetStart(StrictModel):
    kind: Literal["street"] = "street"
    city: str
    node: str
    heading: float = 0.0


class _StreetTarget(StrictModel):
    """A point of a city's street graph that a walk is checked against."""

    city: str
    node: str
    lat: float
    lng: float
    radius_m: float = 25.0
    place_id: str | None = None


class ReachedPlace(_StreetTarget):
    """Embodied (street): the walk ended (at the first street_stop, else when the episode finished)
    within ``radius_m`` of the target."""

    kind: Literal["reached_place"] = "reached_place"
    # Shopping: the store must be the pickup store of the order that matched the web goal.
    must_match_order_store: bool = False


class Waypoint(StrictModel):
    """A point a walk must have passed earlier (``PassedPlace.after``)."""

    node: str
    lat: float
    lng: float
    place_id: str | None = None


class PassedPlace(_StreetTarget):
    """Embodied (street): the walk passed within ``radius_m`` of a waypoint before it ended, and, with
    ``after``, passed it at some moment after it had passed ``after`` (the order of stops the task gives).
    Passing it earlier too does not count against the walk: a stop may lie on the way to the one before it."""

    kind: Literal["passed_place"] = "passed_place"
    after: Waypoint | None = None
