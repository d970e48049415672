"""The episode options the geolocation world reads (start_episode's ``options``), declared on ``GEO``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field


class GeoOptions(BaseModel):
    geolocation_setting: Literal["baseline", "embodied"] | None = Field(
        None, description="override the geolocation task's setting"
    )
