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
    # Memory (docs/web.md, "Memory"): the warm pool falls back to pool_keep_idle contexts once they have been
    # idle pool_idle_s; a page quiet for idle_gc_s gets one full garbage collection (0 turns that off).
    pool_keep_idle: int = Field(2, ge=0, le=8)
    pool_idle_s: float = Field(30.0, gt=0, le=86_400)
    idle_gc_s: float = Field(10.0, ge=0, le=3_600)
