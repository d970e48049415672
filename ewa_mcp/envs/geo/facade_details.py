"""The details that make a building look like its description: wall material, chimney stacks,
soot, dormers, shutters, window frames, fire escapes, rooftop water tanks, corrugated roofs.

``view_images.py`` calls these for the two building views: front-on rows (facade views, plain
rectangles) and the perspective facades of the along views (``project(x, y, u)`` maps world
coordinates to the screen). Everything is drawn from the ArchStyle flags in styles.py, the same
style whose ``description`` the text observation quotes; a test checks that every feature the
description names has its flag set, and that setting it changes the picture. Drawing is a few
dozen lines and rectangles per building (the benchmark keeps the cost in view).
"""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import Any

from PIL import ImageDraw

from ewa_mcp.street_drawing.colour import rgb, shade
from .styles import ArchStyle

Project = Callable[[float, float, float], tuple[float, float]]


# ------------------------------------------------------------------------------ front-on rows
def _bond(draw: ImageDraw.ImageDraw, box: tuple[int, int, int, int], joint: Any, course: int, length: int) -> None:
    """Running bond: horizontal joints every ``course`` px, vertical ones every ``length`` px, offset by half a unit
    on alternate courses (brick and ashlar walls alike)."""
    x0, top, x1, base = box
    for row, y in enumerate(range(top + course - 1, base, course)):
        draw.line([(x0, y), (x1, y)], fill=joint)
        for x in range(x0 + (length // 2 if row % 2 else 0), x1, length):
            draw.line([(x, y - course), (x, y)], fill=joint)


def wall_texture(draw: ImageDraw.ImageDraw, box: tuple[int, int, int, int], colour: str, arch: ArchStyle,
                 rng: random.Random) -> None:
    """Material texture over a front-on wall ``box`` (x0, top, x1, base)."""
    x0, top, x1, base = box
    if colour in arch.tiled_colours:  # glazed tiles: a fine white grid with a pattern dot
        for y in range(top + 4, base, 8):
            draw.line([(x0, y), (x1, y)], fill=(236, 240, 246))
        for x in range(x0 + 4, x1, 8):
            draw.line([(x, top), (x, base)], fill=(236, 240, 246))
    elif arch.material == "brick" or colour in arch.brick_colours:
        _bond(draw, box, shade(colour, 1.28), course=6, length=18)  # light mortar, small bricks
    elif arch.material == "stone":
        _bond(draw, box, shade(colour, 0.78), course=12, length=32)  # dark joints, large blocks
    elif arch.material == "wood":
        slat = shade(colour, 0.7)
        for x in range(x0 + 3, x1, 5):
            draw.line([(x, top), (x, base)], fill=slat)
    elif arch.material == "concrete":
        seam = shade(colour, 0.85)
        for x in range(x0 + 24, x1, 48):
            draw.line([(x, top), (x, base)], fill=seam)
    elif arch.material == "glass":
        pane = shade(colour, 1.15)
        for y in range(top + 10, base, 10):
            draw.line([(x0, y), (x1, y)], fill=pane)
        for x in range(x0 + 12, x1, 12):
            draw.line([(x, top), (x, base)], fill=shade(colour, 0.8))
    if arch.soot:  # soot runs down from the cornice in dark streaks
        dark = shade(colour, 0.55)
        draw.rectangle([x0, top, x1, top + 10], fill=dark)
        for _ in range(5):
            x = rng.randint(x0 + 2, max(x0 + 3, x1 - 8))
            draw.rectangle([x, top, x + rng.randint(3, 8), top + rng.randint(25, max(26, (base - top) // 2))],
                           fill=shade(colour, 0.65))


def window_trim(draw: ImageDraw.ImageDraw, wx: float, y0: float, wh: float, arch: ArchStyle) -> None:
    """Frames and shutters round one front-on window centred at ``wx`` (18 px wide)."""
    if arch.window_frame:
        draw.rectangle([wx - 11, y0 - 2, wx + 11, y0 + wh + 2], outline=rgb(arch.window_frame), width=2)
        draw.line([(wx - 9, y0 + wh / 2), (wx + 9, y0 + wh / 2)], fill=rgb(arch.window_frame), width=2)
    if arch.shutters:
        draw.rectangle([wx - 16, y0, wx - 10, y0 + wh], fill=rgb(arch.shutters))
        draw.rectangle([wx + 10, y0, wx + 16, y0 + wh], fill=rgb(arch.shutters))


def front_extras(draw: ImageDraw.ImageDraw, box: tuple[int, int, int, int], floor_px: int, colour: str,
                 arch: ArchStyle, rng: random.Random) -> None:
    """Roof furniture and fittings of one front-on building: chimneys, dormers, water tanks,
    corrugation, fire escapes."""
    x0, top, x1, base = box
    w = x1 - x0
    if arch.fire_escapes:  # black landings on every floor joined by diagonal ladders
        fx0, fx1 = x0 + w * 0.25, x0 + w * 0.7
        for f in range(2, max(3, (base - top) // floor_px)):
            y = base - f * floor_px + 4
            draw.rectangle([fx0, y, fx1, y + 3], fill=(25, 25, 25))
            draw.line([(fx0 + 4, y), (fx1 - 4, y + floor_px)], fill=(25, 25, 25), width=2)
    if arch.roof == "mansard" and arch.dormers:
        for dx in range(18, w - 20, 42):
            draw.rectangle([x0 + dx, top - 20, x0 + dx + 14, top - 4], fill=rgb(arch.palette[0]),
                           outline=(70, 70, 70))
            draw.rectangle([x0 + dx + 3, top - 16, x0 + dx + 11, top - 6], fill=(60, 66, 72))
    if arch.chimneys:
        stack = shade(colour, 0.8) if arch.material == "brick" else shade(colour, 0.7)
        roof_top = top - (22 if arch.roof in ("pitched", "curved_tile", "mansard") else 0)
        for cx in (x0 + w * 0.22, x0 + w * 0.74):
            draw.rectangle([cx - 9, roof_top - 24, cx + 9, top - 2], fill=stack, outline=shade(colour, 0.5))
            for px in (cx - 5, cx + 2):  # chimney pots
                draw.rectangle([px, roof_top - 31, px + 4, roof_top - 24], fill=(176, 96, 60))
    if arch.water_tanks:
        for cx in (x0 + w * 0.3, x0 + w * 0.68):
            draw.rectangle([cx - 9, top - 20, cx + 9, top - 6], fill=(60, 62, 66))
            draw.ellipse([cx - 9, top - 24, cx + 9, top - 16], fill=(90, 92, 96))
            draw.line([(cx - 7, top - 6), (cx - 7, top)], fill=(40, 40, 40), width=2)
            draw.line([(cx + 7, top - 6), (cx + 7, top)], fill=(40, 40, 40), width=2)
    if arch.corrugated and arch.roof in ("pitched", "curved_tile", "gabled"):
        for x in range(x0 + 12, x1 - 10, 5):
            draw.line([(x, top - 20), (x, top)], fill=shade(arch.roof_colour, 0.75))


# ------------------------------------------------------------------------------ perspective facades
def along_wall(draw: ImageDraw.ImageDraw, project: Project, x: float, z0: float, z1: float, height: float,
               colour: str, arch: ArchStyle) -> None:
    """Texture and soot on one perspective facade at ``x`` from depth z0 to z1 (before its windows)."""
    u0, u1 = 1 / z0, 1 / z1
    if colour in arch.tiled_colours:
        step, line = 0.08, (236, 240, 246)
    elif arch.material == "brick" or colour in arch.brick_colours:
        step, line = 0.06, shade(colour, 1.28)
    elif arch.material == "stone":
        step, line = 0.1, shade(colour, 0.78)
    elif arch.material == "glass":
        step, line = 0.1, shade(colour, 1.15)
    else:
        step, line = 0.0, None
    if step and line is not None:
        y = step
        while y < height - 0.02:
            draw.line([project(x, y, u0), project(x, y, u1)], fill=line)
            y += step
    elif arch.material in ("wood", "concrete"):
        n = 10 if arch.material == "wood" else 3
        for i in range(1, n):
            z = z0 + (z1 - z0) * i / n
            draw.line([project(x, 0.27, 1 / z), project(x, height, 1 / z)], fill=shade(colour, 0.72))
    if arch.soot:
        draw.polygon([project(x, height, u0), project(x, height, u1), project(x, height - 0.1, u1),
                      project(x, height - 0.1, u0)], fill=shade(colour, 0.55))


def along_roof(draw: ImageDraw.ImageDraw, project: Project, x: float, side: int, z0: float, z1: float,
               height: float, colour: str, arch: ArchStyle) -> None:
    """Chimney stacks or water tanks on one perspective building's roof (after the roof)."""
    if arch.chimneys or arch.water_tanks:
        roof_y = height + (0.2 if arch.roof in ("pitched", "gabled", "curved_tile", "mansard") else 0)
        inset = side * (0.22 if arch.roof != "flat" else 0.1)
        for frac in (0.3, 0.75):
            u = 1 / (z0 + (z1 - z0) * frac)
            bx, by = project(x - inset, roof_y - 0.05, u)
            tx, ty = project(x - inset, roof_y + 0.2, u)
            half = max(2.0, 0.05 * 300 * u)
            if arch.chimneys:
                draw.rectangle([bx - half, ty, bx + half, by], fill=shade(colour, 0.7))
                draw.rectangle([bx - half * 0.6, ty - half * 0.8, bx + half * 0.6, ty], fill=(176, 96, 60))
            else:
                draw.rectangle([bx - half * 1.4, ty + (by - ty) * 0.4, bx + half * 1.4, by], fill=(60, 62, 66))
