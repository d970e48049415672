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
    kitchen_view: Literal["first_person", "map"] | None = Field(
        None, description="kitchen image in vision/both modes: first_person (default, AI2-THOR's camera) or map "
                          "(the labelled top-down plan)")
    kitchen_camera_width: int | None = Field(None, ge=64, le=1024, description="kitchen camera width (default 300)")
    kitchen_camera_height: int | None = Field(None, ge=64, le=1024, description="kitchen camera height (default 300)")
    geolocation_setting: Literal["baseline", "embodied"] | None = Field(
        None, description="override the geolocation task's setting"
    )
    seed: int | None = Field(None, description="override the task's scene seed")
    web_max_chars: int | None = Field(None, ge=500, le=500_000,
                                      description="size budget of the web observation (default 24000 characters)")
    web_viewport_only: bool | None = Field(None, description="web observation lists only elements in the viewport")
    structured: Literal["full", "compact"] | None = Field(
        None, description="structured content of observations: full (the observation's data; the default) or "
                          "compact (status and step counts only; the text carries the observation)")
    web_incremental: bool | None = Field(
        None, description="web observations after an action send only the lines of the page that changed since "
                          "the agent last read it (default true; false: the whole page every time; "
                          "browser_snapshot and get_observation always send the whole page)")
