"""The episode options the browser reads (start_episode's ``options``), declared on ``BROWSER``."""

from __future__ import annotations

from pydantic import BaseModel, Field


class BrowserOptions(BaseModel):
    web_max_chars: int | None = Field(None, ge=500, le=500_000,
                                      description="size budget of the web observation (default 24000 characters)")
    web_viewport_only: bool | None = Field(None, description="web observation lists only elements in the viewport")
    web_incremental: bool | None = Field(
        None, description="web observations after an action send only the lines of the page that changed since "
                          "the agent last read it (default true; false: the whole page every time; "
                          "browser_snapshot and get_observation always send the whole page)")
