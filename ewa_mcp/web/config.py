"""Server-wide browser options: the ``browser`` setting (ewa_mcp/settings.py; ``EWA_BROWSER__HEADLESS=false``)."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field


class BrowserConfig(BaseModel):
    model_config = ConfigDict(extra="forbid")

    executable_path: str | None = None
    headless: bool = True
    allow_origins: list[str] = Field(default_factory=list, description="extra http(s) origins the browser may reach")
    viewport_width: int = Field(1280, ge=320, le=3840)
    viewport_height: int = Field(720, ge=240, le=2160)
    max_chars: int = Field(24_000, ge=500, le=500_000, description="accessibility tree budget per observation")
    viewport_only: bool = False
    action_timeout_s: float = Field(5.0, gt=0, le=120)
    navigation_timeout_s: float = Field(15.0, gt=0, le=300)
    settle_timeout_s: float = Field(5.0, gt=0, le=120)
