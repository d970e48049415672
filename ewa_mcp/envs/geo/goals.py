"""The geolocation world's task models: the start of a geolocation episode and its answer check (graded by
checks.py against the submitted location). Declared on ``GEO`` (``__init__.py``), from which the kernel
assembles the task schema (ewa_mcp/core/taskmodel.py)."""

from __future__ import annotations

from typing import Literal

from ewa_mcp.core.taskmodel import StrictModel


class GeoStart(StrictModel):
    kind: Literal["geo"] = "geo"
    location_id: str
    setting: Literal["baseline", "embodied"] = "embodied"


class GeoAnswer(StrictModel):
    kind: Literal["geolocation"] = "geolocation"
    lat: float
    lng: float
    continent: str
    country: str
    city: str
    street: str
    # The levels overall success asks for; None: all four. A baseline task whose one view shows no street
    # sign leaves the street out (it cannot be read, only guessed); it is still graded and reported.
    graded_levels: list[Literal["continent", "country", "city", "street"]] | None = None
