"""Text on street views: sign lines fitted and centred in a box, in the right font for their script,
and Pillow's bundled font for plain Latin labels."""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from PIL import ImageDraw, ImageFont

from . import fonts


@lru_cache(maxsize=64)
def bundled_font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """Pillow's bundled font: no system font needed, identical output on every machine."""
    return ImageFont.load_default(size=max(6, size))


def fit_font(draw: ImageDraw.ImageDraw, text: str, script: str, max_w: float, max_h: float,
             max_size: int = 28) -> tuple[Any, tuple[float, float, float, float]]:
    """The largest font (7 px at least) in which ``text`` fits max_w x max_h, and the text's bounding box."""
    size = max(7, int(min(max_size, max_h)))
    while size > 7:
        f = fonts.font(script, size)
        left, top, right, bottom = draw.textbbox((0, 0), text, font=f)
        if right - left <= max_w and bottom - top <= max_h:
            return f, (left, top, right, bottom)
        size -= 1
    f = fonts.font(script, 7)
    return f, draw.textbbox((0, 0), text, font=f)


def draw_centred_lines(draw: ImageDraw.ImageDraw, box: tuple[float, float, float, float],
                       lines: list[tuple[str, str]], fill: tuple[int, int, int] | str) -> None:
    """Centre each (text, script) line in its share of the box."""
    if not lines:
        return
    x0, y0, x1, y1 = box
    line_h = (y1 - y0) / len(lines)
    for i, (text, script) in enumerate(lines):
        if not text:
            continue
        f, (left, t, r, b) = fit_font(draw, text, script, (x1 - x0) * 0.92, line_h * 0.8)
        tx = x0 + ((x1 - x0) - (r - left)) / 2 - left
        ty = y0 + i * line_h + (line_h - (b - t)) / 2 - t
        draw.text((tx, ty), text, font=f, fill=fill)


def plain_text(text: str) -> tuple[str, str]:
    """(text, script) for a line that has no Latin twin (a number plate): the native script when a font
    covers it, else its ASCII characters only."""
    script = fonts.script_of(text)
    if fonts.has_font(script):
        return text, script
    return "".join(ch for ch in text if ch.isascii()).strip() or "?", "latin"
