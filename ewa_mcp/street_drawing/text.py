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


# Script fonts (Noto Sans Thai, Devanagari, ...) often lack Latin letters and digits, which then draw as
# empty boxes; in a line of such a script, ASCII runs (a plate's digits) are drawn in the Latin font.
# Right-to-left scripts are drawn whole, so the shaping engine keeps their bidirectional order.
_WHOLE = frozenset({"latin", "greek", "cyrillic", "arabic", "hebrew"})


def runs(text: str, script: str) -> list[tuple[str, str]]:
    """(text, script) pieces of one line: ASCII runs in Latin, the rest in ``script``; spaces join the run
    before them."""
    if script in _WHOLE:
        return [(text, script)]
    out: list[tuple[str, str]] = []
    for ch in text:
        kind = "latin" if (ch.isascii() and not ch.isspace()) else script
        if ch.isspace() and out:
            kind = out[-1][1]
        if out and out[-1][1] == kind:
            out[-1] = (out[-1][0] + ch, kind)
        else:
            out.append((ch, kind))
    return out


def _measure(draw: ImageDraw.ImageDraw, pieces: list[tuple[str, str]], size: int) -> tuple[float, float, float]:
    """Width, top and bottom of the pieces set side by side at ``size``."""
    width, top, bottom = 0.0, 0.0, 0.0
    for i, (text, script) in enumerate(pieces):
        f = fonts.font(script, size)
        _, t, _, b = draw.textbbox((0, 0), text, font=f)
        width += draw.textlength(text, font=f)
        top, bottom = (t, b) if i == 0 else (min(top, t), max(bottom, b))
    return width, top, bottom


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
        pieces = runs(text, script)
        if len(pieces) == 1:
            f, (left, t, r, b) = fit_font(draw, text, script, (x1 - x0) * 0.92, line_h * 0.8)
            tx = x0 + ((x1 - x0) - (r - left)) / 2 - left
            ty = y0 + i * line_h + (line_h - (b - t)) / 2 - t
            draw.text((tx, ty), text, font=f, fill=fill)
            continue
        size = max(7, int(min(28, line_h * 0.8)))
        while size > 7:
            width, t, b = _measure(draw, pieces, size)
            if width <= (x1 - x0) * 0.92 and b - t <= line_h * 0.8:
                break
            size -= 1
        width, t, b = _measure(draw, pieces, size)
        tx = x0 + ((x1 - x0) - width) / 2
        ty = y0 + i * line_h + (line_h - (b - t)) / 2 - t
        for piece, piece_script in pieces:
            f = fonts.font(piece_script, size)
            draw.text((tx, ty), piece, font=f, fill=fill)
            tx += draw.textlength(piece, font=f)


def plain_text(text: str) -> tuple[str, str]:
    """(text, script) for a line that has no Latin twin (a number plate): the native script when a font
    covers it, else its ASCII characters only."""
    script = fonts.script_of(text)
    if fonts.has_font(script):
        return text, script
    return "".join(ch for ch in text if ch.isascii()).strip() or "?", "latin"
