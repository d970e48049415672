"""Small shape helpers."""

from __future__ import annotations

from typing import Any

from PIL import ImageDraw


def rect(draw: ImageDraw.ImageDraw, x0: float, y0: float, x1: float, y1: float, **kw: Any) -> None:
    """A rectangle from any two opposite corners (mirrored drawings swap them)."""
    draw.rectangle([min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)], **kw)
