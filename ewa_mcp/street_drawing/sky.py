"""The sky: a vertical gradient from the zenith colour to the horizon colour."""

from __future__ import annotations

from PIL import ImageDraw

from .colour import RGB


def sky_gradient(draw: ImageDraw.ImageDraw, width: int, horizon: int, top: RGB, bottom: RGB, band: int = 1) -> None:
    """Fill rows 0..horizon with bands ``band`` pixels high, blending ``top`` into ``bottom``."""
    for y in range(0, horizon + 1, band):
        t = y / max(1, horizon)
        colour = tuple(int(a + (b - a) * t) for a, b in zip(top, bottom, strict=True))
        draw.rectangle([0, y, width, y + band - 1], fill=colour)
