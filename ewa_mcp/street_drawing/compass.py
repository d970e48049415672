"""The compass strip: a band along the bottom edge of a view showing which way the camera faces.

A 90° field of view spans heading-45° .. heading+45° across the image width, so a tick at bearing b
sits where that bearing is seen. Ticks every 15°, letters at the eight compass points, and the
centre bearing in degrees in a box at the middle: an agent reading only the image knows its heading.
"""

from __future__ import annotations

from PIL import ImageDraw

from .text import bundled_font

STRIP_H = 16
POINTS = {0: "N", 45: "NE", 90: "E", 135: "SE", 180: "S", 225: "SW", 270: "W", 315: "NW"}
BAND, INK, MARK = (24, 26, 30), (235, 235, 235), (255, 196, 40)


def draw_compass_strip(draw: ImageDraw.ImageDraw, width: int, height: int, heading: float,
                       fov_deg: float = 90.0) -> None:
    """Draw the strip over the bottom ``STRIP_H`` rows of a ``width`` x ``height`` image."""
    top = height - STRIP_H
    draw.rectangle([0, top, width, height], fill=BAND)
    px_per_deg = width / fov_deg
    left = heading - fov_deg / 2
    fnt = bundled_font(11)
    first = int(left // 15) * 15
    for b in range(first, int(left + fov_deg) + 16, 15):
        x = (b - left) * px_per_deg
        if not 0 <= x <= width:
            continue
        label = POINTS.get(b % 360)
        draw.line([(x, top), (x, top + (6 if label else 3))], fill=INK, width=1)
        if label:
            w = draw.textlength(label, font=fnt)
            draw.text((x - w / 2, top + 4), label, font=fnt, fill=INK)
    # the centre: the bearing the camera faces
    text = f"{round(heading) % 360}°"
    w = draw.textlength(text, font=fnt)
    cx = width / 2
    draw.polygon([(cx - 5, top), (cx + 5, top), (cx, top + 5)], fill=MARK)
    draw.rectangle([cx + 8, top + 2, cx + 12 + w, height - 1], fill=BAND, outline=MARK)
    draw.text((cx + 10, top + 3), text, font=fnt, fill=MARK)
