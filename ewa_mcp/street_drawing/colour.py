"""Colours: '#rrggbb' strings to RGB tuples, and shading by a factor."""

from __future__ import annotations

RGB = tuple[int, int, int]


def rgb(hex_colour: str) -> RGB:
    h = hex_colour.lstrip("#")
    return int(h[0:2], 16), int(h[2:4], 16), int(h[4:6], 16)


def shade(hex_colour: str, factor: float) -> RGB:
    """The colour with every channel multiplied by ``factor`` (clamped to 0..255)."""
    return tuple(max(0, min(255, int(c * factor))) for c in rgb(hex_colour))  # type: ignore[return-value]
