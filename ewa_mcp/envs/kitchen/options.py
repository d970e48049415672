"""The episode options the kitchen reads (start_episode's ``options``), declared on ``KITCHEN``."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field


class KitchenOptions(BaseModel):
    kitchen_backend: Literal["sim", "ai2thor"] | None = Field(
        None, description="indoor backend (default: EWA_KITCHEN_BACKEND or the built-in simulator)"
    )
    kitchen_view: Literal["first_person", "map"] | None = Field(
        None, description="kitchen image in vision/both modes: first_person (default, AI2-THOR's camera) or map "
                          "(the labelled top-down plan)")
    kitchen_camera_width: int | None = Field(None, ge=64, le=1024, description="kitchen camera width (default 300)")
    kitchen_camera_height: int | None = Field(None, ge=64, le=1024, description="kitchen camera height (default 300)")
