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

LONG_KINDS = frozenset({"tram", "double_decker", "trolleybus", "minibus", "matatu", "chicken_bus", "painted_bus",
                        "jeepney", "songthaew"})
TWO_WHEELERS = frozenset({"motorbikes", "boda_boda", "bicycles"})
RICKSHAWS = frozenset({"tuk_tuk", "auto_rickshaw", "cycle_rickshaw", "becak"})
SIDE_ON_KINDS = LONG_KINDS | TWO_WHEELERS | RICKSHAWS | {"car", "taxi", "classic_car"}
Project = Callable[[float, float, float], tuple[float, float]]


def _plate_box(draw: ImageDraw.ImageDraw, cx: float, cy: float, w: float, h: float, plate: PlateView,
               cues: set[str]) -> None:
    style = plate.style
    cues.add(f"plate_colours:{style.describe_colours(rear=plate.rear)}")
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
    cues.add(f"plate_text:{plate.text}")
    if plate.caption:
        cues.add(f"plate_caption:{plate.caption}")
    draw_centred_lines(draw, (x0, cy - h / 2, cx + w / 2, cy + h / 2), lines, rgb(style.fg))


def _car_rear(draw: ImageDraw.ImageDraw, cx: float, bottom: float, scale: float, v: Vehicle, rear: bool,
              cues: set[str]) -> None:
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
        _plate_box(draw, cx, bottom - h * 0.4, w * 0.72, h * 0.38, v.plate, cues)


def vehicle_along(draw: ImageDraw.ImageDraw, project: Project, v: Vehicle, cues: set[str] | None = None) -> None:
    """A vehicle in its lane of an along view, seen from behind (or the front), scaled by its depth; adds
    ``vehicle:<kind>`` (and its plate's cues) to ``cues`` when it draws that kind."""
    cues = set() if cues is None else cues
    u = 0.92 - 0.82 * v.depth
    lane = {"left": -0.25, "right": 0.25, "centre": 0.0}[v.side]
    cx, bottom = project(lane, 0, u)
    scale = u * 1.1
    if v.kind in ("car", "taxi", "classic_car"):
        _car_rear(draw, cx, bottom, scale, v, rear=v.facing == "away", cues=cues)
        if v.kind == "taxi":  # the lit roof sign
            w, h = 120 * scale, 70 * scale
            draw.rectangle([cx - 16 * scale, bottom - h * 1.45 - 10 * scale, cx + 16 * scale, bottom - h * 1.45],
                           fill=(250, 230, 90), outline=(30, 30, 30))
        cues.add(f"vehicle:{v.kind}")
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
        cues.add(f"vehicle:{v.kind}")
    elif v.kind in ("tuk_tuk", "auto_rickshaw", "cycle_rickshaw", "becak"):
        w, h = 70 * scale, 80 * scale
        draw.polygon([(cx - w / 2, bottom - h * 0.3), (cx, bottom - h), (cx + w / 2, bottom - h * 0.3)],
                     fill=rgb(v.colour if v.colour != "#c9c9c9" else "#2e7d32"))
        draw.rectangle([cx - w / 2, bottom - h * 0.55, cx + w / 2, bottom - 8 * scale], fill=(40, 40, 40))
        cues.add(f"vehicle:{v.kind}")
    elif v.kind in ("motorbikes", "boda_boda", "bicycles"):
        for i in range(5):
            bx = cx + (i - 2) * 22 * scale
            draw.line([(bx, bottom), (bx, bottom - 40 * scale)], fill=(30, 30, 30), width=max(1, int(3 * scale)))
            draw.ellipse([bx - 6 * scale, bottom - 55 * scale, bx + 6 * scale, bottom - 43 * scale], fill=(80, 60, 50))
        cues.add(f"vehicle:{v.kind}")


def car_side(draw: ImageDraw.ImageDraw, cx: float, bottom: float, scale: float, v: Vehicle,
             cues: set[str] | None = None) -> None:
    """A vehicle side-on (facade and landmark views); adds ``vehicle:<kind>`` to ``cues`` for the kinds whose
    side-on shape tells them apart (cars and buses; small three-wheelers and bikes are not drawn so)."""
    if cues is not None and v.kind in SIDE_ON_KINDS:
        cues.add(f"vehicle:{v.kind}")
    if v.kind in TWO_WHEELERS or v.kind in RICKSHAWS:
        _small_side(draw, cx, bottom, scale, v)
        return
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
    if v.kind == "taxi":  # the lit roof sign
        draw.rectangle([cx - 14 * scale, bottom - h * 1.6 - 10 * scale, cx + 14 * scale, bottom - h * 1.6],
                       fill=(250, 230, 90), outline=(30, 30, 30))
    elif v.kind == "classic_car":  # tail fins and a chrome strip
        draw.polygon([(cx - front * w / 2, bottom - h), (cx - front * w / 2, bottom - h * 1.5),
                      (cx - front * w * 0.3, bottom - h)], fill=body, outline=(30, 30, 30))
        draw.line([(cx - w / 2, bottom - h * 0.45), (cx + w / 2, bottom - h * 0.45)], fill=(225, 225, 230),
                  width=max(1, int(3 * scale)))


def _small_side(draw: ImageDraw.ImageDraw, cx: float, bottom: float, scale: float, v: Vehicle) -> None:
    """Two-wheelers (a row of riders on scooters or bicycles) and rickshaws (three wheels under a hood),
    side-on."""
    front = 1 if v.facing == "right" else -1
    r = 10 * scale
    if v.kind in TWO_WHEELERS:
        for i in range(3):
            bx = cx + (i - 1) * 55 * scale
            for dx in (-18, 18):
                draw.ellipse([bx + dx * scale - r, bottom - 2 * r, bx + dx * scale + r, bottom],
                             outline=(20, 20, 20), width=max(1, int(3 * scale)))
            frame = rgb(v.colour) if v.kind != "bicycles" else (40, 40, 40)
            draw.line([(bx - 18 * scale, bottom - r), (bx + 18 * scale * front, bottom - 2.6 * r)], fill=frame,
                      width=max(2, int(5 * scale)))
            draw.line([(bx, bottom - 2.2 * r), (bx, bottom - 4.4 * r)], fill=(60, 60, 80), width=max(2, int(6 * scale)))
            draw.ellipse([bx - 5 * scale, bottom - 5.6 * r, bx + 5 * scale, bottom - 4.4 * r], fill=(80, 60, 50))
        return
    w, h = 90 * scale, 70 * scale
    hood = rgb(v.colour) if v.colour else (40, 120, 50)
    pedal = v.kind in ("cycle_rickshaw", "becak")
    # the hood over the passenger seat, at the back (cycle rickshaw) or in front (becak)
    seat_x = cx - front * w * 0.2 if v.kind != "becak" else cx + front * w * 0.2
    draw.pieslice([seat_x - w * 0.35, bottom - h * 1.3, seat_x + w * 0.35, bottom - h * 0.4], 180, 360, fill=hood,
                  outline=(30, 30, 30))
    draw.rectangle([seat_x - w * 0.35, bottom - h * 0.85, seat_x + w * 0.35, bottom - h * 0.35],
                   fill=hood if not pedal else (120, 40, 40), outline=(30, 30, 30))
    if not pedal:  # the motor rickshaw's closed front with its single front wheel
        draw.polygon([(seat_x + front * w * 0.35, bottom - h * 0.35), (seat_x + front * w * 0.35, bottom - h * 0.9),
                      (seat_x + front * w * 0.65, bottom - h * 0.35)], fill=hood, outline=(30, 30, 30))
    else:  # the rider on a bicycle frame
        rx = cx + front * w * 0.45 if v.kind != "becak" else cx - front * w * 0.45
        draw.line([(rx, bottom - r), (seat_x, bottom - h * 0.4)], fill=(40, 40, 40), width=max(1, int(3 * scale)))
        draw.line([(rx, bottom - 2 * r), (rx, bottom - h)], fill=(60, 60, 80), width=max(2, int(6 * scale)))
        draw.ellipse([rx - 5 * scale, bottom - h - 10 * scale, rx + 5 * scale, bottom - h], fill=(80, 60, 50))
    for along in (-0.4, 0.1, 0.5):
        wx = cx + front * along * w
        draw.ellipse([wx - r, bottom - 2 * r, wx + r, bottom], fill=(20, 20, 20))
