"""Vehicles of the geolocation views: cars from behind or the front with their number plates,
buses, trams, tuk-tuks and motorbikes in the along views, and side-on vehicles in the facade and
landmark views."""

from __future__ import annotations

from collections.abc import Callable

from PIL import ImageDraw

from ewa_mcp.street_drawing.colour import rgb, shade
from ewa_mcp.street_drawing.shapes import rect
from ewa_mcp.street_drawing.text import draw_centred_lines, plain_text
from .scene import PlateView, Vehicle

Project = Callable[[float, float, float], tuple[float, float]]


def _plate_box(draw: ImageDraw.ImageDraw, cx: float, cy: float, w: float, h: float, plate: PlateView) -> None:
    style = plate.style
    bg = style.rear_bg if (plate.rear and style.rear_bg) else style.bg
    draw.rectangle([cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2], fill=rgb(bg), outline=(20, 20, 20))
    x0 = cx - w / 2
    if style.band:
        bw = w * 0.14
        draw.rectangle([x0, cy - h / 2, x0 + bw, cy + h / 2], fill=rgb(style.band_bg))
        if plate.text is not None:
            draw_centred_lines(draw, (x0, cy, x0 + bw, cy + h / 2), [(style.band, "latin")], (255, 255, 255))
        x0 += bw
    if plate.text is None:
        return
    lines = []
    if plate.caption:
        lines.append(plain_text(plate.caption))
    lines.append(plain_text(plate.text))
    draw_centred_lines(draw, (x0, cy - h / 2, cx + w / 2, cy + h / 2), lines, rgb(style.fg))


def _car_rear(draw: ImageDraw.ImageDraw, cx: float, bottom: float, scale: float, v: Vehicle, rear: bool) -> None:
    w, h = 120 * scale, 70 * scale
    body = rgb(v.colour)
    draw.rounded_rectangle([cx - w / 2, bottom - h, cx + w / 2, bottom - h * 0.08], radius=int(8 * scale),
                           fill=body, outline=(30, 30, 30))
    draw.rounded_rectangle([cx - w * 0.38, bottom - h * 1.45, cx + w * 0.38, bottom - h * 0.92],
                           radius=int(10 * scale), fill=shade(v.colour, 0.85), outline=(30, 30, 30))
    draw.rectangle([cx - w * 0.32, bottom - h * 1.35, cx + w * 0.32, bottom - h * 0.98], fill=(60, 75, 90))
    lamp = (200, 20, 20) if rear else (250, 245, 200)
    for s in (-1, 1):
        draw.rectangle([cx + s * w * 0.44 - 9 * scale, bottom - h * 0.8, cx + s * w * 0.44 + 9 * scale,
                        bottom - h * 0.62], fill=lamp)
        draw.ellipse([cx + s * w * 0.34 - 10 * scale, bottom - 10 * scale, cx + s * w * 0.34 + 10 * scale,
                      bottom + 6 * scale], fill=(20, 20, 20))
    if v.plate is not None:
        _plate_box(draw, cx, bottom - h * 0.4, w * 0.72, h * 0.38, v.plate)


def vehicle_along(draw: ImageDraw.ImageDraw, project: Project, v: Vehicle) -> None:
    """A vehicle in its lane of an along view, seen from behind (or the front), scaled by its depth."""
    u = 0.92 - 0.82 * v.depth
    lane = {"left": -0.25, "right": 0.25, "centre": 0.0}[v.side]
    cx, bottom = project(lane, 0, u)
    scale = u * 1.1
    if v.kind in ("car", "taxi", "classic_car"):
        _car_rear(draw, cx, bottom, scale, v, rear=v.facing == "away")
    elif v.kind in ("tram", "trolleybus", "double_decker", "minibus", "matatu", "chicken_bus", "painted_bus",
                    "jeepney", "songthaew"):
        tall = {"tram": 1.9, "double_decker": 2.6, "trolleybus": 1.9}.get(v.kind, 1.4)
        w, h = 150 * scale, 70 * scale * tall
        draw.rectangle([cx - w / 2, bottom - h, cx + w / 2, bottom - 6 * scale], fill=rgb(v.colour),
                       outline=(30, 30, 30))
        rows = 2 if v.kind == "double_decker" else 1
        for r in range(rows):
            top = bottom - h + 10 * scale + r * h / 2
            draw.rectangle([cx - w * 0.42, top, cx + w * 0.42, top + h * 0.25], fill=(60, 75, 90))
        if v.kind in ("tram", "trolleybus"):
            draw.line([(cx, bottom - h), (cx, bottom - h - 30 * scale)], fill=(30, 30, 30), width=2)
    elif v.kind in ("tuk_tuk", "auto_rickshaw", "cycle_rickshaw", "becak"):
        w, h = 70 * scale, 80 * scale
        draw.polygon([(cx - w / 2, bottom - h * 0.3), (cx, bottom - h), (cx + w / 2, bottom - h * 0.3)],
                     fill=rgb(v.colour if v.colour != "#c9c9c9" else "#2e7d32"))
        draw.rectangle([cx - w / 2, bottom - h * 0.55, cx + w / 2, bottom - 8 * scale], fill=(40, 40, 40))
    elif v.kind in ("motorbikes", "boda_boda", "bicycles"):
        for i in range(5):
            bx = cx + (i - 2) * 22 * scale
            draw.line([(bx, bottom), (bx, bottom - 40 * scale)], fill=(30, 30, 30), width=max(1, int(3 * scale)))
            draw.ellipse([bx - 6 * scale, bottom - 55 * scale, bx + 6 * scale, bottom - 43 * scale], fill=(80, 60, 50))


def car_side(draw: ImageDraw.ImageDraw, cx: float, bottom: float, scale: float, v: Vehicle) -> None:
    long = v.kind in ("tram", "double_decker", "trolleybus", "minibus", "matatu", "chicken_bus", "painted_bus",
                      "jeepney", "songthaew")
    w = (260 if long else 140) * scale
    h = (110 if v.kind == "double_decker" else 80 if long else 42) * scale
    body = rgb(v.colour)
    draw.rounded_rectangle([cx - w / 2, bottom - h, cx + w / 2, bottom - 8 * scale], radius=int(6 * scale),
                           fill=body, outline=(30, 30, 30))
    if not long:
        draw.polygon([(cx - w * 0.3, bottom - h), (cx - w * 0.18, bottom - h * 1.6), (cx + w * 0.2, bottom - h * 1.6),
                      (cx + w * 0.32, bottom - h)], fill=shade(v.colour, 0.9), outline=(30, 30, 30))
    else:
        draw.rectangle([cx - w * 0.45, bottom - h * 0.9, cx + w * 0.45, bottom - h * 0.55], fill=(60, 75, 90))
    front = 1 if v.facing == "right" else -1
    rect(draw, cx + front * w / 2 - front * 8 * scale, bottom - h * 0.75, cx + front * w / 2, bottom - h * 0.55,
          fill=(250, 240, 180))
    rect(draw, cx - front * w / 2, bottom - h * 0.75, cx - front * w / 2 + front * 6 * scale, bottom - h * 0.55,
          fill=(200, 20, 20))
    for s in (-0.33, 0.33):
        r = 11 * scale
        draw.ellipse([cx + s * w - r, bottom - 2 * r, cx + s * w + r, bottom], fill=(20, 20, 20))
