"""Per-episode options a client may pass to start_episode."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field


class EpisodeOptions(BaseModel):
    model_config = ConfigDict(extra="forbid")

    observation: Literal["text", "vision", "both"] = Field(
        "text", description="text: scene graph / accessibility tree; vision: images; both: all"
    )
    kitchen_backend: Literal["sim", "ai2thor"] | None = Field(
        None, description="indoor backend (default: EWA_KITCHEN_BACKEND or the built-in simulator)"
    )
    geolocation_setting: Literal["baseline", "embodied"] | None = Field(
        None, description="override the geolocation task's setting"
    )
    seed: int | None = Field(None, description="override the task's scene seed")
