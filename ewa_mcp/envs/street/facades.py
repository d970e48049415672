"""The street's building fronts: facade patterns by architectural style, the details a place's description
names (columns, spires, cupolas, ...), the palettes and the sizes of the street. Drawn by the street views
(street_view.py) and by the close-up of the places at the agent's own node (here_view.py), which both build on
these and on nothing of each other.
"""

from __future__ import annotations

import math
import random

from PIL import ImageDraw

from ewa_mcp.street_drawing.camera import Camera
from .scene import details_of

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
DECOY_RGB = 60.0  # an ordinary front's tone at least this far (RGB distance) from a described wall near by

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
                wall: tuple[int, int, int] | None = None,
                avoid: list[tuple[int, int, int]] | tuple[()] = ()) -> None:
    """Fill a facade quadrilateral (bottom-near, top-near, top-far, bottom-far) with a style pattern; ``wall``
    (the material its description names) overrides the style's wall colour; a random tone is none near
    a colour of ``avoid`` (the described places' walls near by: Scene.place_walls)."""
    key = _style_key(style)
    tones = [t for t in WALL_TONES if all(math.dist(t, c) > DECOY_RGB for c in avoid)] or WALL_TONES
    main, trim = STYLE_PALETTES.get(key, (base or rng.choice(tones), (60, 60, 64)))
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


MIN_ROOF_M = 4.0  # the lowest a building is drawn when lowered under a skyline tower (one storey)


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


def _sign_colour(name: str) -> tuple[int, int, int]:
    palette = [(176, 30, 36), (20, 110, 60), (30, 70, 150), (120, 40, 120), (200, 120, 20), (30, 30, 30)]
    return palette[sum(map(ord, name)) % len(palette)]
