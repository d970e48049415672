"""Deterministic street-view images drawn with Pillow from a Scene.

A pinhole camera 1.7 m above the sidewalk looks along the view heading (90° field of view).
Buildings stand on facade planes either side of the street, broken where cross streets open;
landmarks are drawn by architectural style (columns, spires, stepped crowns, glass grids, ...),
never with their names; shops carry sign boards with their names; tall landmarks rise on the
skyline; intersections show street-name signs. Same scene -> same pixels.

The camera, sky gradient, bundled font and PNG encoding come from the street-view toolkit
(``ewa_mcp/street_drawing``), shared with the geolocation views; the facade patterns by
architectural style and the details a place's description names are this world's own.
"""

from __future__ import annotations

import math
import random

from PIL import Image, ImageDraw

from ewa_mcp.street_drawing.camera import Camera
from ewa_mcp.street_drawing.compass import draw_compass_strip
from ewa_mcp.street_drawing.png import encode_png
from ewa_mcp.street_drawing.sky import sky_gradient
from ewa_mcp.street_drawing.text import bundled_font
from .scene import MATERIAL_WORDS, OPEN_SPACE_KINDS, SKYLINE_SHOWN, Frontage, Scene, details_of, has_look, material_of

WIDTH, HEIGHT = 480, 330  # large enough for a lion by a door or a clock on a tower to read
CAMERA_HEIGHT_M = 1.7
FACADE_X_M = 11.0  # half the distance between facades across a typical street
ROAD_HALF_M = 6.5
SKY = (176, 204, 230)
SKY_TOP = (122, 162, 210)
AHEAD_END_WALL = 200.0  # a street that ends sooner than this shows the building fronts where it ends
ROAD = (86, 88, 92)
SIDEWALK = (170, 166, 158)
LANE = (235, 225, 160)
WALL_TONES = [(150, 98, 80), (178, 140, 110), (120, 110, 104), (196, 180, 150), (140, 120, 100), (110, 84, 72),
              (168, 160, 150), (130, 136, 142)]

STYLE_PALETTES = {
    "art deco": ((214, 200, 170), (150, 130, 100)),
    "gothic": ((170, 168, 160), (95, 92, 88)),
    "beaux-arts": ((232, 222, 200), (170, 160, 140)),
    "renaissance": ((226, 214, 190), (160, 150, 130)),
    "neoclassical": ((236, 230, 214), (170, 165, 150)),
    "greek revival": ((238, 234, 222), (170, 165, 150)),
    "international": ((120, 150, 170), (60, 80, 96)),
    "modern": ((130, 160, 185), (70, 90, 110)),
    "high-tech": ((150, 170, 185), (60, 70, 80)),
    "brutalist": ((150, 148, 140), (100, 98, 92)),
    "georgian": ((160, 72, 56), (240, 236, 226)),
    "federal": ((164, 78, 60), (240, 236, 226)),
    "romanesque": ((140, 96, 72), (90, 60, 45)),
    "second empire": ((214, 206, 190), (90, 100, 96)),
    "postmodern": ((206, 150, 140), (120, 90, 86)),
    "queen anne": ((150, 70, 52), (40, 40, 40)),
    "byzantine": ((196, 130, 100), (150, 110, 80)),
    "tudor": ((170, 110, 80), (70, 50, 40)),
    "palladian": ((210, 190, 160), (150, 130, 110)),
    "flemish": ((236, 232, 224), (150, 150, 150)),
    "neo-futurism": ((150, 175, 195), (200, 190, 170)),
}


def _style_key(style: str) -> str:
    s = style.lower()
    for key in STYLE_PALETTES:
        if key in s:
            return key
    if "modernism" in s:
        return "modern"
    return ""


STREET_CAMERA = Camera(width=WIDTH, height=HEIGHT, horizon=HEIGHT * 0.46, eye_height=CAMERA_HEIGHT_M)  # metres


def draw_facade(draw: ImageDraw.ImageDraw, quad: list[tuple[float, float]], style: str, rng: random.Random,
                base: tuple[int, int, int] | None = None, floors: int = 6,
                wall: tuple[int, int, int] | None = None) -> None:
    """Fill a facade quadrilateral (bottom-near, top-near, top-far, bottom-far) with a style pattern; ``wall``
    (the material its description names) overrides the style's wall colour."""
    key = _style_key(style)
    main, trim = STYLE_PALETTES.get(key, (base or rng.choice(WALL_TONES), (60, 60, 64)))
    main = wall or main
    draw.polygon(quad, fill=main, outline=trim)
    (bx0, by0), (tx0, ty0), (tx1, ty1), (bx1, by1) = quad

    def lerp(a: tuple[float, float], b: tuple[float, float], t: float) -> tuple[float, float]:
        return a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t

    near_h = by0 - ty0
    if near_h < 4:
        return
    columns = max(2, min(14, int(abs(bx1 - bx0) / 5) + 2))
    if key in ("international", "modern", "high-tech", "neo-futurism"):
        for c in range(1, columns):  # glass curtain wall: mullion grid
            t = c / columns
            draw.line([lerp((bx0, by0), (bx1, by1), t), lerp((tx0, ty0), (tx1, ty1), t)], fill=trim, width=1)
        for f in range(1, floors * 2):
            t = f / (floors * 2)
            draw.line([lerp((bx0, by0), (tx0, ty0), t), lerp((bx1, by1), (tx1, ty1), t)], fill=trim, width=1)
        if key == "high-tech":
            draw.line([(bx0, by0), (tx1, ty1)], fill=trim, width=2)
            draw.line([(tx0, ty0), (bx1, by1)], fill=trim, width=2)
        return
    window = (60, 70, 84) if key not in ("georgian", "federal") else (40, 46, 56)
    for f in range(1, floors):
        for c in range(1, columns):
            t, u = c / columns, f / floors
            bottom = lerp((bx0, by0), (bx1, by1), t)
            top = lerp((tx0, ty0), (tx1, ty1), t)
            x, y = lerp(bottom, top, u)
            w = max(1.0, abs(bx1 - bx0) / columns * 0.35)
            h = max(1.0, (bottom[1] - top[1]) / floors * 0.45)
            if key in ("gothic", "romanesque", "byzantine", "tudor"):
                draw.ellipse([x - w, y - h * 1.3, x + w, y - h * 0.3], fill=window)  # arched heads
            draw.rectangle([x - w, y - h, x + w, y], fill=window)
    if key in ("beaux-arts", "renaissance", "neoclassical", "greek revival", "palladian"):
        for c in range(columns + 1):  # a colonnade on the ground floor
            t = c / columns
            bottom = lerp((bx0, by0), (bx1, by1), t)
            top = lerp(bottom, lerp((tx0, ty0), (tx1, ty1), t), 0.3)
            draw.line([bottom, top], fill=trim, width=2)
    if key in ("gothic", "flemish"):  # spires along the roof
        for c in range(0, columns + 1, 2):
            x, y = lerp((tx0, ty0), (tx1, ty1), c / columns)
            draw.polygon([(x - 3, y), (x + 3, y), (x, y - max(6.0, near_h * 0.25))], fill=trim)
    if key == "art deco":  # stepped crown
        x0, y0 = lerp((tx0, ty0), (tx1, ty1), 0.2)
        x1, y1 = lerp((tx0, ty0), (tx1, ty1), 0.8)
        step = max(3.0, near_h * 0.08)
        draw.polygon([(x0, y0), (x0, y0 - step), (x1, y1 - step), (x1, y1)], fill=main, outline=trim)
    if key == "second empire":  # mansard roof
        draw.polygon([(tx0, ty0), (tx1, ty1), (tx1, ty1 - near_h * 0.12), (tx0, ty0 - near_h * 0.12)], fill=trim)
    if key == "postmodern":  # broken pediment
        mx, my = lerp((tx0, ty0), (tx1, ty1), 0.5)
        draw.polygon([(tx0, ty0), (mx - 2, my - near_h * 0.15), (mx - 2, my)], fill=trim)
        draw.polygon([(tx1, ty1), (mx + 2, my - near_h * 0.15), (mx + 2, my)], fill=trim)


# Details a place's description mentions, drawn on its facade (first matching word wins per detail).
GOLD, BRONZE, NEON, LION = (212, 175, 55), (140, 100, 50), (255, 60, 90), (222, 214, 196)
SHUTTER, FLOWER, TIMBER, IRON = (40, 70, 50), (220, 60, 120), (60, 40, 30), (30, 30, 34)


def draw_details(draw: ImageDraw.ImageDraw, quad: list[tuple[float, float]], hint: str, door: bool = True) -> set[str]:
    """Draw on a facade quadrilateral the visible details its description names (lions by the door, a
    clock, a dome, a statue on top, a spire, columns, an arched door, steps, neon, an awning, globe
    lamps, trees, twin towers, flags), so a vision agent sees what the text tells."""
    found = set(details_of(hint))
    if not found:
        return set()
    (bx0, by0), (tx0, ty0), (tx1, ty1), (bx1, by1) = quad
    near_h = by0 - ty0
    if near_h < 6:
        return set()

    def at(t: float, u: float) -> tuple[float, float]:  # t along the facade (0 near), u up (0 ground)
        bx, by = bx0 + (bx1 - bx0) * t, by0 + (by1 - by0) * t
        tx, ty = tx0 + (tx1 - tx0) * t, ty0 + (ty1 - ty0) * t
        return bx + (tx - bx) * u, by + (ty - by) * u

    def height_at(t: float) -> float:
        return (by0 + (by1 - by0) * t) - (ty0 + (ty1 - ty0) * t)

    mid = 0.5
    h = height_at(mid)
    unit = max(2.0, h / 12)  # about one floor
    if "columns" in found:
        for k in range(7):
            t = 0.15 + 0.7 * k / 6
            draw.line([at(t, 0.02), at(t, 0.45)], fill=(245, 242, 232), width=max(2, int(unit * 0.5)))
        draw.polygon([at(0.12, 0.45), at(0.88, 0.45), at(mid, 0.58)], fill=(236, 232, 220), outline=(120, 120, 120))
    if door and ("arch" in found or "lions" in found or "steps" in found):  # door False: an opening of its own
        x, y = at(mid, 0.0)
        draw.rectangle([x - unit * 1.2, y - unit * 2.2, x + unit * 1.2, y], fill=(40, 36, 34))
        draw.ellipse([x - unit * 1.2, y - unit * 3.4, x + unit * 1.2, y - unit * 1.0], fill=(40, 36, 34))
    if "steps" in found and door:
        x, y = at(mid, 0.0)
        for k in range(3):
            draw.rectangle([x - unit * (3 - k * 0.5), y - unit * 0.3 * (k + 1), x + unit * (3 - k * 0.5),
                            y - unit * 0.3 * k], fill=(214, 208, 196), outline=(150, 146, 138))
    if "lions" in found:
        for t in (mid - 0.16, mid + 0.16):  # two couchant lions on plinths either side of the door
            x, y = at(t, 0.0)
            s = unit * 0.9
            draw.rectangle([x - s * 1.6, y - s * 0.8, x + s * 1.6, y], fill=(200, 196, 186))
            draw.ellipse([x - s * 1.5, y - s * 2.0, x + s * 1.1, y - s * 0.8], fill=LION)
            draw.ellipse([x + s * 0.4, y - s * 2.6, x + s * 1.6, y - s * 1.3], fill=LION,
                         outline=(120, 110, 96))  # the head with its mane
    if "lamps" in found:
        for t in (0.2, 0.8):
            x, y = at(t, 0.0)
            draw.line([(x, y), (x, y - unit * 3)], fill=(30, 60, 40), width=2)
            draw.ellipse([x - unit * 0.6, y - unit * 3.9, x + unit * 0.6, y - unit * 2.7], fill=(120, 220, 140))
    if "awning" in found:
        a, b = at(0.1, 0.2), at(0.9, 0.2)
        draw.polygon([a, b, (b[0], b[1] + unit), (a[0], a[1] + unit)], fill=(170, 30, 40), outline=(90, 10, 20))
    if "neon" in found:
        a, b = at(0.2, 0.7), at(0.8, 0.7)
        draw.line([a, b], fill=NEON, width=max(2, int(unit * 0.6)))
        draw.line([at(0.2, 0.78), at(0.8, 0.78)], fill=(80, 220, 255), width=max(2, int(unit * 0.4)))
    if "clock" in found:
        x, y = at(mid, 0.8)
        r = max(3.0, unit * 1.3)
        draw.ellipse([x - r, y - r, x + r, y + r], fill=(246, 242, 226), outline=GOLD, width=2)
        draw.line([(x, y), (x, y - r * 0.8)], fill=(20, 20, 20), width=2)
        draw.line([(x, y), (x + r * 0.55, y)], fill=(20, 20, 20), width=2)
    if "flags" in found:
        for t in (0.3, 0.7):
            x, y = at(t, 0.62)
            draw.line([(x, y), (x + unit * 2, y - unit)], fill=(60, 60, 60), width=1)
            draw.rectangle([x + unit * 1.2, y - unit * 1.8, x + unit * 2.4, y - unit * 1.0], fill=(30, 60, 160))
    if "shutters" in found or "flowers" in found or "stained" in found:
        for f in (0.3, 0.55, 0.8):  # three rows of windows, each with what the description names
            for t in (0.2, 0.4, 0.6, 0.8):
                x, y = at(t, f)
                w = unit * 0.55
                glass = (150, 60, 120) if "stained" in found else (50, 60, 76)
                draw.rectangle([x - w, y - unit * 1.2, x + w, y], fill=glass)
                if "stained" in found:
                    draw.rectangle([x - w, y - unit * 0.6, x + w, y], fill=(60, 120, 200))
                    draw.line([(x, y - unit * 1.2), (x, y)], fill=(230, 190, 60), width=1)
                if "shutters" in found:
                    draw.rectangle([x - w * 2.0, y - unit * 1.2, x - w, y], fill=SHUTTER)
                    draw.rectangle([x + w, y - unit * 1.2, x + w * 2.0, y], fill=SHUTTER)
                if "flowers" in found:
                    draw.rectangle([x - w * 1.2, y, x + w * 1.2, y + unit * 0.35], fill=(110, 70, 40))
                    for k in range(3):
                        fx = x - w + k * w
                        draw.ellipse([fx - unit * 0.25, y - unit * 0.3, fx + unit * 0.25, y + unit * 0.1],
                                     fill=FLOWER)
    if "gables" in found:
        for t0 in (0.05, 0.38, 0.71):  # half-timbered gables along the roof line
            a, b = at(t0, 1.0), at(t0 + 0.24, 1.0)
            peak = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2 - unit * 3)
            draw.polygon([a, b, peak], fill=(236, 226, 200), outline=TIMBER)
            draw.line([((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), peak], fill=TIMBER, width=2)
            draw.line([a, peak], fill=TIMBER, width=2)
            draw.line([b, peak], fill=TIMBER, width=2)
    if "fence" in found:
        a, b = at(0.0, 0.0), at(1.0, 0.0)
        ya = unit * 1.3
        draw.line([(a[0], a[1] - ya), (b[0], b[1] - ya)], fill=IRON, width=2)
        for k in range(25):
            x, y = at(k / 24, 0.0)
            draw.line([(x, y), (x, y - ya - unit * 0.3)], fill=IRON, width=1)
    top_x, top_y = at(mid, 1.0)
    if "cupola" in found:  # a small lantern with a domed cap on the roof's middle
        draw.rectangle([top_x - unit * 0.9, top_y - unit * 2.0, top_x + unit * 0.9, top_y], fill=(240, 238, 230),
                       outline=(120, 120, 120))
        draw.pieslice([top_x - unit, top_y - unit * 3.0, top_x + unit, top_y - unit], 180, 360, fill=(90, 130, 110))
        top_y -= unit * 3.0
    if "twin" in found:
        for t in (0.25, 0.75):
            x, y = at(t, 1.0)
            draw.rectangle([x - unit * 1.2, y - unit * 4, x + unit * 1.2, y], fill=(190, 180, 160), outline=(90, 90, 90))
    if "dome" in found:
        r = max(4.0, unit * 2.5)
        draw.pieslice([top_x - r, top_y - r, top_x + r, top_y + r], 180, 360, fill=(110, 150, 130), outline=(60, 80, 70))
        top_y -= r
    if "spire" in found:
        draw.polygon([(top_x - unit, top_y), (top_x + unit, top_y), (top_x, top_y - unit * 6)], fill=(96, 92, 88))
        top_y -= unit * 6
    if "statue" in found:
        draw.rectangle([top_x - unit * 0.5, top_y - unit * 2.2, top_x + unit * 0.5, top_y], fill=BRONZE)
        draw.ellipse([top_x - unit * 0.45, top_y - unit * 3.0, top_x + unit * 0.45, top_y - unit * 2.1], fill=BRONZE)
    if "trees" in found:
        for t in (0.15, 0.45, 0.75):
            x, y = at(t, 0.0)
            draw.line([(x, y), (x, y - unit * 2.5)], fill=(90, 60, 40), width=max(2, int(unit * 0.4)))
            draw.ellipse([x - unit * 1.8, y - unit * 5.5, x + unit * 1.8, y - unit * 2.0], fill=(60, 130, 60))
    return found


def _sky_and_ground(draw: ImageDraw.ImageDraw, cam: Camera) -> None:
    h = int(cam.horizon)
    sky_gradient(draw, cam.width, h, SKY_TOP, SKY, band=4)
    draw.rectangle([0, h, cam.width, cam.height], fill=SIDEWALK)


def _hazed(rgb: tuple[int, int, int]) -> tuple[int, int, int]:
    """The colour seen through atmospheric haze (a far skyline)."""
    r, g, b = (int(c * 0.55 + 140 * 0.45) for c in rgb)
    return r, g, b


def _skyline_box(item, cam: Camera) -> tuple[float, float, float, tuple[int, int, int]]:
    """Where a skyline tower is drawn: its centre column, half width, top row, and its hazed colour."""
    x = cam.screen_x(item.rel_angle)
    top = cam.horizon - min(cam.horizon - 4, item.height_m * cam.focal / item.distance_m)
    half = max(3.0, 40.0 * cam.focal / item.distance_m)
    colour = _hazed(STYLE_PALETTES.get(_style_key(item.style), ((150, 160, 172), (0, 0, 0)))[0])
    return x, half, top, colour


MIN_ROOF_M = 4.0  # the lowest a building is drawn when lowered under a skyline tower (one storey)


def _skyline_windows(scene: Scene, cam: Camera) -> list[tuple[float, float, float]]:
    """(x0, x1, lowest roof row) per skyline tower the text names: nearer ordinary buildings in those columns
    are drawn low enough for the tower's top to show over their roofs, as it does in the text."""
    out = []
    for item in sorted(scene.skyline, key=lambda s: s.distance_m)[:2]:
        x, half, top, _ = _skyline_box(item, cam)
        out.append((x - half, x + half, top + (cam.horizon - top) * SKYLINE_SHOWN))
    return out


def _capped_height(height: float, cam: Camera, plane_x: float | None, z0: float, z1: float,
                   windows: list[tuple[float, float, float]]) -> float:
    """``height`` lowered (to one storey at least) so that the roof of a front on the plane x = ``plane_x``
    (None: across the view at depth z0) stays below every window it overlaps, measured at the depth where
    the front meets the window's columns."""
    if plane_x is None:
        lo, hi = cam.project(-60, 0, z0)[0], cam.project(60, 0, z0)[0]
    else:
        lo, hi = sorted((cam.project(plane_x, 0, z0)[0], cam.project(plane_x, 0, z1)[0]))
    for x0, x1, row in windows:
        if hi < x0 or lo > x1:
            continue
        z = z0
        if plane_x is not None:  # the depth of the front at the window's column nearest the screen edge
            edge = x0 if plane_x < 0 else x1
            if (edge - cam.cx) * plane_x > 0:
                z = min(max(plane_x * cam.focal / (edge - cam.cx), z0), z1)
        cap = cam.eye_height + (cam.horizon - row) * z / cam.focal
        height = min(height, max(MIN_ROOF_M, cap))
    return height


def _skyline(draw: ImageDraw.ImageDraw, scene: Scene, cam: Camera) -> None:
    for item in scene.skyline:
        x, half, top, colour = _skyline_box(item, cam)
        key = _style_key(item.style)
        if key == "art deco":
            draw.rectangle([x - half, top + (cam.horizon - top) * 0.25, x + half, cam.horizon], fill=colour)
            draw.rectangle([x - half * 0.6, top + (cam.horizon - top) * 0.1, x + half * 0.6, cam.horizon], fill=colour)
            draw.polygon([(x - half * 0.25, top + 8), (x + half * 0.25, top + 8), (x, top)], fill=colour)
        elif key in ("gothic", "postmodern", "flemish"):
            draw.rectangle([x - half, top + 6, x + half, cam.horizon], fill=colour)
            draw.polygon([(x - half, top + 6), (x + half, top + 6), (x, top - 4)], fill=colour)
        else:
            draw.rectangle([x - half, top, x + half, cam.horizon], fill=colour)


def _side_segments(scene: Scene, side: str, end: float) -> list[tuple[float, float]]:
    """Depth ranges with buildings on one side, cut where cross streets open."""
    cuts = sorted(o.distance_m for o in scene.openings if o.side in (side, "both"))
    segs, start = [], 2.0
    for d in cuts:
        if d - 9 > start:
            segs.append((start, d - 9))
        start = d + 9
    if end > start:
        segs.append((start, end))
    return segs


def _draw_sign(draw: ImageDraw.ImageDraw, cam: Camera, side: str, z: float, text: str, colour: tuple[int, int, int],
               cues: set[str]) -> None:
    x = FACADE_X_M - 0.1 if side == "right" else -FACADE_X_M + 0.1
    z0, z1 = max(2.5, z - 6), z + 6
    p = [cam.project(x, 3.0, z0), cam.project(x, 4.6, z0), cam.project(x, 4.6, z1), cam.project(x, 3.0, z1)]
    draw.polygon(p, fill=colour, outline=(20, 20, 20))
    # Letters scale with distance, but never below a legible 8 px: a far board is drawn larger than life
    # (a label-sized board over it), so every sign the text quotes can be read in the picture too.
    size = max(8, int(1.3 * cam.focal / max(z, 3.0)))
    cx = (p[0][0] + p[3][0]) / 2
    cy = (p[0][1] + p[1][1] + p[2][1] + p[3][1]) / 4
    fnt = bundled_font(min(18, size))
    w = draw.textlength(text, font=fnt)
    board_h = abs(p[0][1] - p[1][1])
    if board_h < size + 2 or abs(p[3][0] - p[0][0]) < w:
        draw.rectangle([cx - w / 2 - 3, cy - size / 2 - 2, cx + w / 2 + 3, cy + size / 2 + 3], fill=colour,
                       outline=(20, 20, 20))
    draw.text((cx - w / 2, cy - size / 2), text, font=fnt, fill=(250, 250, 250))
    cues.add(f"sign:{text}")


def _wall(f: Frontage) -> tuple[int, int, int] | None:
    """The wall colour of the material a place's description names (None: its style's or a random tone)."""
    return MATERIAL_WORDS.get(material_of(f.hint))


def _sign_colour(name: str) -> tuple[int, int, int]:
    palette = [(176, 30, 36), (20, 110, 60), (30, 70, 150), (120, 40, 120), (200, 120, 20), (30, 30, 30)]
    return palette[sum(map(ord, name)) % len(palette)]


def render(scene: Scene, cam: Camera | None = None) -> Image.Image:
    return render_cues(scene, cam)[0]


def render_cues(scene: Scene, cam: Camera | None = None) -> tuple[Image.Image, frozenset[str]]:
    """The view and the ids of what it draws (scene.text_cues names the ids the text gives)."""
    from .here_view import blocked_near, draw_here, park_here  # it draws with this module's facades

    cues: set[str] = set()
    cam = cam or STREET_CAMERA
    rng = random.Random(scene.seed)
    img = Image.new("RGB", (cam.width, cam.height), SKY)
    draw = ImageDraw.Draw(img)
    _sky_and_ground(draw, cam)
    _skyline(draw, scene, cam)
    windows = _skyline_windows(scene, cam)
    end = scene.ahead_length_m if scene.road_ahead else 16.0
    end = max(end, 16.0)
    far = min(end, 240.0)
    if scene.road_ahead:
        road = [cam.project(-ROAD_HALF_M, 0, 2.0), cam.project(-ROAD_HALF_M, 0, far), cam.project(ROAD_HALF_M, 0, far),
                cam.project(ROAD_HALF_M, 0, 2.0)]
        draw.polygon(road, fill=ROAD)
        cues.add("road_ahead")
        for dash_z in range(4, int(far), 12):  # centre line dashes
            draw.line([cam.project(0, 0, dash_z), cam.project(0, 0, dash_z + 5)], fill=LANE, width=2)
        for o in scene.openings:  # cross streets: tarmac reaching out sideways
            for side in (("left", "right") if o.side == "both" else (o.side,)):
                sgn = 1 if side == "right" else -1
                draw.polygon([cam.project(sgn * ROAD_HALF_M, 0, o.distance_m - 6), cam.project(sgn * 60, 0, o.distance_m - 6),
                              cam.project(sgn * 60, 0, o.distance_m + 6), cam.project(sgn * ROAD_HALF_M, 0, o.distance_m + 6)],
                             fill=ROAD)
                cues.add(f"opening:{o.side}:{round(o.distance_m)}")
        if far < AHEAD_END_WALL:
            _end_wall(draw, cam, far + 12, rng, windows=windows)
    elif scene.open_space or park_here(scene):
        cues.add("road_ends")
        _open_ground(draw, cam, rng)
        if scene.open_space:
            cues.add("open_space")
    else:
        cues.add("road_ends")
        facing = next((f for f in scene.frontages if f.side == "ahead" and f.range_m <= 40), None)
        _end_wall(draw, cam, 14.0, rng, facing, cues)
    # Facades, far to near, both sides.
    landmarks: dict[str, list[Frontage]] = {"left": [], "right": []}
    for f in scene.frontages:
        if f.side in landmarks:
            landmarks[f.side].append(f)
    pieces: list[tuple[float, str, float, float, Frontage | None]] = []
    for side in ("left", "right"):
        for z0, z1 in _side_segments(scene, side, far):
            z = z0
            while z < z1:
                w = min(z1 - z, rng.uniform(12, 26))
                lm = next((f for f in landmarks[side] if has_look(f)
                           and z - 10 <= f.distance_m <= z + w + 10), None)
                pieces.append((z, side, z, z + w, lm))
                z += w
    # A described place no street-side piece took (straight ahead, or its entrance in a cross street's
    # gap) still gets its own front, where it stands, so the picture shows what the text names.
    placed = {lm.place_id for *_, lm in pieces if lm is not None} | {f.place_id for f in scene.here}
    if not scene.road_ahead and not scene.open_space:
        placed |= {f.place_id for f in scene.frontages if f.side == "ahead" and f.range_m <= 40}
    for f in scene.frontages[:5]:
        if f.place_id in placed or not has_look(f):
            continue
        z = min(max(f.distance_m, 4.0), max(far, 4.0))
        pieces.append((z, f.side if f.side != "ahead" else "ahead", z - 8, z + 8, f))
        placed.add(f.place_id)
    # The places at this node that lie this way replace the ordinary fronts where they stand (here_view).
    blocked, here_ids = blocked_near(scene), {f.place_id for f in scene.here}
    pieces = [p for p in pieces if p[1] not in blocked or p[2] >= blocked[p[1]]
              or (p[4] is not None and p[4].place_id not in here_ids)]
    for _, side, z0, z1, lm in sorted(pieces, key=lambda p: -p[0]):
        if side == "ahead" and lm is not None:  # a front facing the camera, at the place's bearing
            z = max((z0 + z1) / 2, 8.0)
            cx = z * math.tan(math.radians(lm.rel_angle))
            if lm.kind in OPEN_SPACE_KINDS:  # a park ahead: a lawn with trees at its bearing, no front
                draw.polygon([cam.project(cx - 12, 0, z), cam.project(cx - 12, 0, z + 30), cam.project(cx + 12, 0, z + 30),
                              cam.project(cx + 12, 0, z)], fill=(96, 150, 72))
                for tx in (cx - 8, cx, cx + 8):
                    _park_stretch(draw, cam, tx, z + 2, z + 12, lawn=False)
                low = [cam.project(cx - 12, 0, z), cam.project(cx - 12, 8.0, z), cam.project(cx + 12, 8.0, z),
                       cam.project(cx + 12, 0, z)]
                cues.add(f"facade:{lm.place_id}")
                cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, low, lm.hint)}
                continue
            height = min(80.0, max(18.0, lm.height_m or 30.0))
            if windows and not lm.height_m:
                height = _capped_height(height, cam, None, z, z, windows)
            quad = [cam.project(cx - 12, 0, z), cam.project(cx - 12, height, z), cam.project(cx + 12, height, z),
                    cam.project(cx + 12, 0, z)]
            draw_facade(draw, quad, lm.style, rng, floors=max(3, int(height / 4)), wall=_wall(lm))
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, quad, lm.hint)}
            continue
        x = FACADE_X_M if side == "right" else -FACADE_X_M
        if lm is not None and lm.kind in OPEN_SPACE_KINDS:  # a park along the street: lawn and trees, no front
            _park_stretch(draw, cam, x, z0, z1)
            low = [cam.project(x, 0, z0), cam.project(x, 8.0, z0), cam.project(x, 8.0, z1), cam.project(x, 0, z1)]
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, low, lm.hint)}
            continue
        height = rng.uniform(12, 40) if lm is None else min(80.0, max(18.0, (lm.height_m or 30.0)))
        if windows and (lm is None or not lm.height_m):  # a place of unknown height is no taller than needed
            height = _capped_height(height, cam, x, z0, z1, windows)
        quad = [cam.project(x, 0, z0), cam.project(x, height, z0), cam.project(x, height, z1), cam.project(x, 0, z1)]
        draw_facade(draw, quad, lm.style if lm else "", rng, floors=max(3, int(height / 4)),
                    wall=_wall(lm) if lm else None)
        if lm is not None:
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, quad, lm.hint)}
    for f in sorted(scene.frontages, key=lambda f: -f.distance_m):
        if f.sign and f.side in ("left", "right"):
            _draw_sign(draw, cam, f.side, f.distance_m, f.sign, _sign_colour(f.sign), cues)
        elif f.sign and f.side == "ahead":
            _draw_sign(draw, cam, "right", f.distance_m, f.sign, _sign_colour(f.sign), cues)
    draw_here(draw, scene, cam, rng, cues, windows)
    if scene.street_signs:
        _street_sign(draw, cam, scene.street_signs, cues)
    # A skyline tower counts as drawn only where some of it is still in sight over the nearer roofs.
    for item in scene.skyline:
        x, half, top, colour = _skyline_box(item, cam)
        box = (int(max(0, x - half)), int(max(0, top)), int(min(cam.width, x + half + 1)), int(cam.horizon))
        if box[2] > box[0] and box[3] > box[1] and any(c == colour for _, c in
                                                        img.crop(box).getcolors(maxcolors=1 << 16) or []):
            cues.add(f"skyline:{item.place_id}")
    draw_compass_strip(draw, cam.width, cam.height, scene.heading)
    return img, frozenset(cues)


def _park_stretch(draw: ImageDraw.ImageDraw, cam: Camera, x: float, z0: float, z1: float,
                  lawn: bool = True) -> None:
    """A park beside the street between depths z0 and z1: lawn from the kerb back, a row of trees along it
    (``lawn`` False: the trees only)."""
    sgn = 1.0 if x > 0 else -1.0
    kerb = sgn * (ROAD_HALF_M + 2.0)
    if lawn:
        draw.polygon([cam.project(kerb, 0, z0), cam.project(kerb, 0, z1), cam.project(sgn * 80, 0, z1),
                      cam.project(sgn * 80, 0, z0)], fill=(96, 150, 72))
    z = z1 - 3.0
    while z > z0:
        bx, by = cam.project(x, 0, z)
        _, ty = cam.project(x, 5.0, z)
        r = 3.4 * cam.focal / z
        draw.line([(bx, by), (bx, ty)], fill=(90, 64, 44), width=max(1, int(r / 4)))
        draw.ellipse([bx - r, ty - r * 1.4, bx + r, ty + r * 0.4], fill=(52, 112, 56))
        z -= 9.0


def _open_ground(draw: ImageDraw.ImageDraw, cam: Camera, rng: random.Random) -> None:
    """Open ground across the sidewalk (a park): a lawn with trees, and far buildings over the tree line."""
    h = cam.horizon
    draw.rectangle([0, h - 18, cam.width, h], fill=(150, 150, 146))  # the far side's buildings, low
    lawn = [cam.project(-80, 0, 6.0), cam.project(-400, 0, 400), cam.project(400, 0, 400), cam.project(80, 0, 6.0)]
    draw.polygon(lawn, fill=(96, 150, 72))
    draw.rectangle([0, cam.project(0, 0, 6.0)[1], cam.width, cam.height], fill=SIDEWALK)
    for _ in range(9):
        z = 14 + rng.uniform(0, 70)
        x = rng.uniform(-40, 40)
        bx, by = cam.project(x, 0, z)
        _, ty = cam.project(x, 4.0, z)
        r = 3.0 * cam.focal / z
        draw.line([(bx, by), (bx, ty)], fill=(90, 64, 44), width=max(1, int(r / 4)))
        draw.ellipse([bx - r, ty - r * 1.4, bx + r, ty + r * 0.4], fill=(52, 112, 56))


def _end_wall(draw: ImageDraw.ImageDraw, cam: Camera, z: float, rng: random.Random,
              facing: Frontage | None = None, cues: set[str] | None = None,
              windows: list[tuple[float, float, float]] | None = None) -> None:
    """The building fronts across the end of the view; the place straight ahead, if any, in its style."""
    height = 28.0
    if windows:
        height = _capped_height(height, cam, None, z, z, windows)
    quad = [cam.project(-60, 0, z), cam.project(-60, height, z), cam.project(60, height, z), cam.project(60, 0, z)]
    draw_facade(draw, [quad[0], quad[1], quad[2], quad[3]], facing.style if facing else "", rng, floors=7)
    if facing is not None:
        front = [cam.project(-14, 0, z), cam.project(-14, 22, z), cam.project(14, 22, z), cam.project(14, 0, z)]
        drawn = draw_details(draw, front, facing.hint)
        if cues is not None:
            cues.add(f"facade:{facing.place_id}")
            cues |= {f"detail:{facing.place_id}:{d}" for d in drawn}


def _street_sign(draw: ImageDraw.ImageDraw, cam: Camera, names: list[str], cues: set[str]) -> None:
    fnt = bundled_font(10)
    x, y = cam.width - 8, 10
    draw.line([(x - 4, y), (x - 4, cam.height * 0.9)], fill=(50, 60, 50), width=3)  # the pole
    for name in names:  # every name the text's "Street signs here" gives
        w = draw.textlength(name, font=fnt)
        draw.rectangle([x - w - 12, y, x - 2, y + 14], fill=(18, 110, 58), outline=(240, 240, 240))
        draw.text((x - w - 7, y + 1), name, font=fnt, fill=(250, 250, 250))
        cues.add(f"street_sign:{name}")
        y += 17


def render_png(scene: Scene, cam: Camera | None = None) -> bytes:
    return encode_png(render(scene, cam), colours=128)
