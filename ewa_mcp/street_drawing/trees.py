"""Street trees by kind (palms, cypresses, conifers, umbrella pines, acacias, bananas, broadleaves
in the colours of their species), drawn at a base point and a scale."""

from __future__ import annotations

import math

from PIL import ImageDraw


def draw_tree(draw: ImageDraw.ImageDraw, kind: str, x: float, base: float, scale: float) -> None:
    trunk = (95, 75, 55)
    green = (70, 120, 60)
    s = scale
    if kind in ("coconut_palm", "palm", "date_palm", "fan_palm"):
        height = {"fan_palm": 260, "coconut_palm": 170}.get(kind, 150) * s
        lean = 18 * s if kind == "coconut_palm" else 0
        draw.line([(x, base), (x + lean, base - height)], fill=(120, 100, 80), width=max(2, int(7 * s)))
        tx, ty = x + lean, base - height
        for ang in range(0, 360, 40):
            a = math.radians(ang)
            draw.line([(tx, ty), (tx + math.cos(a) * 45 * s, ty + math.sin(a) * 22 * s + 12 * s)], fill=(60, 120, 50),
                      width=max(2, int(5 * s)))
    elif kind in ("cypress",):
        draw.ellipse([x - 14 * s, base - 170 * s, x + 14 * s, base - 5 * s], fill=(40, 80, 45))
    elif kind in ("spruce", "pine", "araucaria"):
        for i in range(4):
            w = (50 - i * 10) * s
            top = base - (40 + i * 35) * s
            draw.polygon([(x - w, top + 45 * s), (x, top - 10 * s), (x + w, top + 45 * s)], fill=(35, 75, 45))
        draw.line([(x, base), (x, base - 30 * s)], fill=trunk, width=max(2, int(5 * s)))
    elif kind in ("umbrella_pine", "acacia"):
        draw.line([(x, base), (x, base - 110 * s)], fill=trunk, width=max(2, int(6 * s)))
        draw.ellipse([x - 70 * s, base - 140 * s, x + 70 * s, base - 95 * s],
                     fill=(45, 95, 50) if kind == "umbrella_pine" else (110, 130, 60))
    elif kind == "banana":
        for ang in (-60, -25, 10, 45):
            a = math.radians(ang - 90)
            draw.line([(x, base - 40 * s), (x + math.cos(a) * 60 * s, base - 40 * s + math.sin(a) * 60 * s)],
                      fill=(90, 160, 60), width=max(3, int(12 * s)))
    else:
        colour = {"jacaranda": (140, 100, 190), "birch": (110, 160, 80), "eucalyptus": (120, 145, 120),
                  "ginkgo": (150, 175, 60), "flamboyant": (210, 70, 40), "frangipani": (110, 150, 90),
                  "orange": (60, 120, 50), "olive": (140, 160, 130)}.get(kind, green)
        bark = (235, 235, 230) if kind == "birch" else trunk
        draw.line([(x, base), (x, base - 80 * s)], fill=bark, width=max(2, int(7 * s)))
        draw.ellipse([x - 50 * s, base - 150 * s, x + 50 * s, base - 60 * s], fill=colour)
        if kind == "orange":
            for dx, dy in ((-20, -100), (15, -120), (25, -90)):
                draw.ellipse([x + dx * s - 4 * s, base + dy * s - 4 * s, x + dx * s + 4 * s, base + dy * s + 4 * s],
                             fill=(240, 140, 20))
