"""The geolocation views: a ViewSpec becomes a 600x400 PNG, deterministically.

Three compositions: ``along`` (one-point perspective down the street), ``facade`` (facing
the buildings across the street) and ``landmark`` (a square with its monument). The ground
plane is projected by the toolkit's pinhole camera in inverse depth (``Camera.project_u``:
screen = (W/2 + f*X*u, HY + f*(CAM - Y)*u), u = 1/depth), so facades, windows, lanes and kerbs
converge consistently. Vehicles (``vehicle_drawing.py``) and signs are drawn larger than life so
plates and sign text stay legible at this resolution. Sky, text, trees, colours and PNG encoding
come from the street-view toolkit (``ewa_mcp/street_drawing``), shared with the walked cities.
"""

from __future__ import annotations

import random
from functools import lru_cache

from PIL import Image, ImageDraw

from ewa_mcp.street_drawing import fonts
from ewa_mcp.street_drawing.camera import Camera
from ewa_mcp.street_drawing.colour import rgb, shade
from ewa_mcp.street_drawing.png import encode_png
from ewa_mcp.street_drawing.shapes import rect
from ewa_mcp.street_drawing.sky import sky_gradient
from ewa_mcp.street_drawing.text import draw_centred_lines
from ewa_mcp.street_drawing.trees import draw_tree
from .facade_details import along_roof, along_wall, front_extras, wall_texture, window_trim
from .scene import ShopSign, StreetSign, Text, ViewSpec
from .styles import ArchStyle
from .vehicle_drawing import car_side, vehicle_along

W, H = 600, 400
HY = 175  # the horizon: the vanishing point is (W/2, HY)
CAM = 0.75  # camera height in world units (one unit is about 10 m): the ground at u = 1 is the bottom edge
CAMERA = Camera(width=W, height=H, horizon=HY, eye_height=CAM)  # focal W/2 = 300 px per unit at u = 1
_p = CAMERA.project_u
ROAD_HALF = 0.5
FACADE_X = 0.8


# ------------------------------------------------------------------------------ text
def _drawable_lines(lines: tuple[Text, ...], cues: set[str] | None = None,
                    cue: str = "sign_text") -> list[tuple[str, str]]:
    """The (text, script) lines to draw; with ``cues``, adds ``{cue}:{native}`` for each line drawn in its
    own spelling (a line whose script has no font here is drawn transliterated, which is not the cue)."""
    out = []
    native_lines = [fonts.drawable(t.native, t.latin) for t in lines]
    for (text, script), original in zip(native_lines, lines, strict=True):
        if script == "latin" and text != original.native and any(
            fonts.script_of(o.native) == "latin" for o in lines if o is not original
        ):
            continue  # a companion Latin line exists: don't add a transliteration too
        out.append((text, script))
        if cues is not None and text == original.native:
            cues.add(f"{cue}:{text}")
    return out or [(lines[0].latin, "latin")]


# ------------------------------------------------------------------------------ sky and ground
def _sky(img: Image.Image, spec: ViewSpec, horizon: int, cues: set[str]) -> None:
    draw = ImageDraw.Draw(img)
    cues.add(f"sky:{spec.climate.sky_words}")
    sky_gradient(draw, W, horizon, rgb(spec.climate.sky_top), rgb(spec.climate.sky_bottom))
    for cx, cy, size in spec.clouds:
        x, y = cx * W, cy * horizon
        for dx, dy, r in ((0, 0, 22), (-20, 6, 16), (22, 5, 18), (8, -8, 15)):
            rr = r * size
            draw.ellipse([x + dx * size - rr, y + dy * size - rr * 0.6, x + dx * size + rr, y + dy * size + rr * 0.6],
                         fill=(248, 248, 248))
    if spec.climate is not None and spec.climate.sky_words.endswith("horizon"):
        pts = [(0, horizon)]
        rng = random.Random(spec.seed)
        for x in range(0, W + 40, 40):
            pts.append((x, horizon - rng.randint(15, 55)))
        pts.append((W, horizon))
        draw.polygon(pts, fill=(126, 142, 160))


# ------------------------------------------------------------------------------ buildings (along)
def _facade_quad(side: int, z0: float, z1: float, height: float) -> list[tuple[float, float]]:
    x = side * FACADE_X
    return [_p(x, 0, 1 / z0), _p(x, 0, 1 / z1), _p(x, height, 1 / z1), _p(x, height, 1 / z0)]


def _window_grid(draw: ImageDraw.ImageDraw, side: int, z0: float, z1: float, floors: int, arch: ArchStyle,
                 base_colour: str) -> None:
    x = side * FACADE_X
    floor_h = 0.32
    cols = max(2, int((z1 - z0) * 2.2))
    dark = shade(base_colour, 0.45)
    frame = shade(base_colour, 0.75)
    for f in range(1, floors):
        y0 = f * floor_h + 0.08
        y1 = y0 + (0.2 if arch.window in ("tall", "arched", "shuttered") else 0.14)
        for c in range(cols):
            za = z0 + (z1 - z0) * (c + 0.25) / cols
            zb = z0 + (z1 - z0) * (c + 0.75) / cols
            quad = [_p(x, y0, 1 / za), _p(x, y0, 1 / zb), _p(x, y1, 1 / zb), _p(x, y1, 1 / za)]
            draw.polygon(quad, fill=dark, outline=frame)
            if arch.balconies and f % 2 == 1:
                draw.line([_p(x, y0 - 0.01, 1 / (za - 0.05)), _p(x, y0 - 0.01, 1 / (zb + 0.05))], fill=(40, 40, 40),
                          width=2)
        if arch.window == "strip":
            draw.line([_p(x, y1 + 0.02, 1 / z0), _p(x, y1 + 0.02, 1 / z1)], fill=frame, width=1)


def _roof(draw: ImageDraw.ImageDraw, side: int, z0: float, z1: float, top: float, arch: ArchStyle) -> None:
    x = side * FACADE_X
    colour = rgb(arch.roof_colour)
    if arch.roof == "mansard":
        quad = [_p(x, top, 1 / z0), _p(x, top, 1 / z1), _p(x - side * 0.12, top + 0.3, 1 / z1),
                _p(x - side * 0.12, top + 0.3, 1 / z0)]
        draw.polygon(quad, fill=colour)
    elif arch.roof in ("pitched", "gabled", "curved_tile"):
        quad = [_p(x, top, 1 / z0), _p(x, top, 1 / z1), _p(x - side * 0.3, top + 0.25, 1 / z1),
                _p(x - side * 0.3, top + 0.25, 1 / z0)]
        draw.polygon(quad, fill=colour)
    else:
        draw.line([_p(x, top, 1 / z0), _p(x, top, 1 / z1)], fill=shade(arch.palette[0], 0.6), width=3)


BUILDING_SPANS = ((0.7, 2.0), (2.0, 3.6), (3.6, 5.6), (5.6, 8.5))


def _along_buildings(draw: ImageDraw.ImageDraw, spec: ViewSpec, cues: set[str]) -> None:
    arch = spec.arch
    cues.add(f"arch:{spec.arch_key}")
    for side, row in ((-1, spec.buildings_left), (1, spec.buildings_right)):
        for (z0, z1), b in reversed(list(zip(BUILDING_SPANS, row, strict=True))):
            height = b.floors * 0.32
            draw.polygon(_facade_quad(side, z0, z1, height), fill=rgb(b.colour), outline=shade(b.colour, 0.7))
            along_wall(draw, _p, side * FACADE_X, z0, z1, height, b.colour, arch)
            _window_grid(draw, side, z0, z1, b.floors, arch, b.colour)
            # ground floor shopfront
            x = side * FACADE_X
            shop = [_p(x, 0, 1 / z0), _p(x, 0, 1 / z1), _p(x, 0.27, 1 / z1), _p(x, 0.27, 1 / z0)]
            draw.polygon(shop, fill=shade(b.colour, 0.35))
            if arch.awnings or arch.arcade:
                aw = [_p(x, 0.27, 1 / z0), _p(x, 0.27, 1 / z1), _p(x - side * 0.12, 0.22, 1 / z1),
                      _p(x - side * 0.12, 0.22, 1 / z0)]
                draw.polygon(aw, fill=(150, 40, 40) if arch.awnings else shade(b.colour, 0.8))
            if arch.veranda:
                ver = [_p(x, 0.3, 1 / z0), _p(x, 0.3, 1 / z1), _p(x - side * 0.3, 0.3, 1 / z1),
                       _p(x - side * 0.3, 0.3, 1 / z0)]
                draw.polygon(ver, fill=(120, 120, 118))
                for z in (z0 + 0.1, (z0 + z1) / 2):
                    draw.line([_p(x - side * 0.29, 0, 1 / z), _p(x - side * 0.29, 0.3, 1 / z)], fill=(70, 70, 70),
                              width=2)
            if arch.ac_units:
                for f in range(1, b.floors, 2):
                    px, py = _p(x, f * 0.32 + 0.05, 1 / (z0 + 0.3))
                    s = 14 / z0
                    rect(draw, px - s * side * 0.2, py, px + s * 0.8 * -side, py + s * 0.6, fill=(225, 225, 220))
            _roof(draw, side, z0, z1, height, arch)
            along_roof(draw, _p, side * FACADE_X, side, z0, z1, height, b.colour, arch)
            if arch.vertical_signs:
                rng = random.Random(spec.seed + int(z0 * 10) + side)
                px, py = _p(x - side * 0.05, height * 0.85, 1 / (z0 + 0.15))
                _, py2 = _p(x - side * 0.05, 0.35, 1 / (z0 + 0.15))
                w = 18 / z0
                colour = rng.choice([(200, 30, 40), (240, 200, 40), (30, 90, 170), (250, 250, 250)])
                draw.rectangle([min(px, px - side * w), py, max(px, px - side * w), py2], fill=colour)
    # backdrop across the far end of the street
    far_u = 1 / 9.0
    xl, yb = _p(-FACADE_X, 0, far_u)
    xr, _ = _p(FACADE_X, 0, far_u)
    top = _p(0, 1.6, far_u)[1]
    draw.rectangle([xl, top, xr, yb], fill=rgb(spec.arch.palette[-1]))


def _along_ground(draw: ImageDraw.ImageDraw, spec: ViewSpec, cues: set[str]) -> None:
    pave = rgb(spec.arch.pavement)
    draw.polygon([(0, H), (W, H), (W, HY), (0, HY)], fill=pave)
    if spec.pedestrian:
        cues.add("pedestrian")
        for i in range(1, 12):
            u = 1 / (1 + i * 0.7)
            draw.line([_p(-FACADE_X, 0, u), _p(FACADE_X, 0, u)], fill=shade(spec.arch.pavement, 0.88), width=1)
        return
    asphalt = rgb(spec.climate.ground_tint)
    road = [_p(-ROAD_HALF, 0, 1.4), _p(ROAD_HALF, 0, 1.4), _p(ROAD_HALF, 0, 0.01), _p(-ROAD_HALF, 0, 0.01)]
    draw.polygon(road, fill=asphalt)
    for side in (-1, 1):
        draw.line([_p(side * ROAD_HALF, 0, 1.4), _p(side * ROAD_HALF, 0, 0.01)], fill=(200, 200, 195), width=3)
    if spec.edge_line:
        colour = (235, 190, 0) if spec.edge_line == "yellow" else (240, 240, 240)
        for side in (-1, 1):
            draw.line([_p(side * (ROAD_HALF - 0.04), 0, 1.4), _p(side * (ROAD_HALF - 0.04), 0, 0.01)], fill=colour,
                      width=2)
        cues.add(f"edge_line:{spec.edge_line}")
    if spec.centre_line:
        cues.add(f"centre_line:{spec.centre_line}")
        colour = (235, 190, 0) if spec.centre_line == "yellow" else (240, 240, 240)
        z = 1.0
        while z < 30:
            a, b = _p(0, 0, 1 / z), _p(0, 0, 1 / (z + 0.35))
            width = max(1, int(6 / z))
            draw.line([a, b], fill=colour, width=width)
            z += 0.8


def _tram_tracks_along(draw: ImageDraw.ImageDraw) -> None:
    for x in (-0.16, -0.08, 0.08, 0.16):
        draw.line([_p(x, 0, 1.4), _p(x, 0, 0.01)], fill=(90, 90, 92), width=2)
    # overhead catenary
    draw.line([_p(0, 0.75, 1.3), _p(0, 0.75, 0.02)], fill=(40, 40, 40), width=1)


def _skytrain(draw: ImageDraw.ImageDraw) -> None:
    for z in (1.5, 3.0, 5.0, 8.0):
        u = 1 / z
        for x in (-0.12, 0.12):
            draw.rectangle([_p(x - 0.04, 0, u)[0], _p(x, 1.1, u)[1], _p(x + 0.04, 0, u)[0], _p(x, 0, u)[1]],
                           fill=(170, 170, 165))
    deck = [_p(-0.3, 1.1, 1.3), _p(0.3, 1.1, 1.3), _p(0.3, 1.1, 0.02), _p(-0.3, 1.1, 0.02)]
    draw.polygon(deck, fill=(185, 185, 180))
    under = [_p(-0.3, 1.1, 1.3), _p(0.3, 1.1, 1.3), _p(0.3, 1.22, 1.3), _p(-0.3, 1.22, 1.3)]
    draw.polygon(under, fill=(150, 150, 145))


def _wires(draw: ImageDraw.ImageDraw, spec: ViewSpec) -> None:
    for side in (-1, 1):
        for z in (1.4, 2.6, 4.5, 7.5):
            base = _p(side * 0.62, 0, 1 / z)
            top = _p(side * 0.62, 1.0, 1 / z)
            draw.line([base, top], fill=(90, 80, 70), width=max(1, int(5 / z)))
        for h in (0.9, 0.95, 0.85):
            draw.line([_p(side * 0.62, h, 1 / 1.4), _p(side * 0.62, h, 1 / 12)], fill=(30, 30, 30), width=1)
    draw.line([_p(-0.62, 0.93, 1 / 2.6), _p(0.62, 0.9, 1 / 2.6)], fill=(30, 30, 30), width=1)


# ------------------------------------------------------------------------------ signs
def shop_pictogram(draw: ImageDraw.ImageDraw, kind: str, cx: float, cy: float, c: float) -> bool:
    """The pictogram of a shop kind (describe.SHOP_KIND_LOOKS words it), centred at (cx, cy) in a square of
    half-side ``c``, on a white disc so it reads on any sign colour. False for a kind without one."""
    if kind not in PICTOGRAM_KINDS:
        return False
    draw.ellipse([cx - c * 1.15, cy - c * 1.15, cx + c * 1.15, cy + c * 1.15], fill=(250, 250, 246))
    if kind == "pharmacy":
        draw.rectangle([cx - c / 3, cy - c, cx + c / 3, cy + c], fill=(40, 170, 60))
        draw.rectangle([cx - c, cy - c / 3, cx + c, cy + c / 3], fill=(40, 170, 60))
    elif kind == "bakery":  # a loaf with three slashes
        draw.ellipse([cx - c, cy - c * 0.55, cx + c, cy + c * 0.55], fill=(196, 134, 62), outline=(110, 70, 30))
        for dx in (-0.45, 0.0, 0.45):
            draw.line([(cx + (dx - 0.15) * c, cy + c * 0.3), (cx + (dx + 0.15) * c, cy - c * 0.3)],
                      fill=(240, 210, 150), width=max(1, int(c / 5)))
    elif kind == "cafe":  # a cup with a handle on a saucer
        draw.rectangle([cx - c * 0.6, cy - c * 0.5, cx + c * 0.3, cy + c * 0.5], fill=(110, 70, 40))
        draw.ellipse([cx + c * 0.15, cy - c * 0.3, cx + c * 0.75, cy + c * 0.25], outline=(110, 70, 40),
                     width=max(1, int(c / 5)))
        draw.line([(cx - c, cy + c * 0.65), (cx + c * 0.7, cy + c * 0.65)], fill=(110, 70, 40),
                  width=max(1, int(c / 4)))
    elif kind == "restaurant":  # a fork and a knife side by side
        w = max(1, int(c / 5))
        draw.line([(cx - c * 0.4, cy - c), (cx - c * 0.4, cy + c)], fill=(40, 40, 40), width=w)
        for dx in (-0.65, -0.4, -0.15):
            draw.line([(cx + dx * c, cy - c), (cx + dx * c, cy - c * 0.4)], fill=(40, 40, 40), width=max(1, w // 2))
        draw.polygon([(cx + c * 0.3, cy - c), (cx + c * 0.6, cy - c * 0.2), (cx + c * 0.4, cy - c * 0.1)],
                     fill=(40, 40, 40))
        draw.line([(cx + c * 0.4, cy - c * 0.2), (cx + c * 0.4, cy + c)], fill=(40, 40, 40), width=w)
    elif kind == "bank":  # a gold coin
        draw.ellipse([cx - c * 0.85, cy - c * 0.85, cx + c * 0.85, cy + c * 0.85], fill=(222, 180, 40),
                     outline=(150, 110, 20), width=max(1, int(c / 6)))
        draw.ellipse([cx - c * 0.45, cy - c * 0.45, cx + c * 0.45, cy + c * 0.45], outline=(150, 110, 20),
                     width=max(1, int(c / 8)))
    elif kind == "hotel":  # a bed: headboard, mattress, legs, pillow
        draw.rectangle([cx - c, cy - c * 0.7, cx - c * 0.75, cy + c * 0.6], fill=(60, 60, 90))
        draw.rectangle([cx - c * 0.75, cy, cx + c, cy + c * 0.3], fill=(60, 60, 90))
        draw.rectangle([cx + c * 0.8, cy + c * 0.3, cx + c, cy + c * 0.6], fill=(60, 60, 90))
        draw.ellipse([cx - c * 0.7, cy - c * 0.35, cx - c * 0.2, cy], fill=(60, 60, 90))
    elif kind == "grocery":  # a red apple with a leaf
        draw.ellipse([cx - c * 0.8, cy - c * 0.6, cx + c * 0.8, cy + c * 0.9], fill=(200, 30, 30))
        draw.line([(cx, cy - c * 0.6), (cx + c * 0.1, cy - c)], fill=(90, 60, 30), width=max(1, int(c / 6)))
        draw.ellipse([cx + c * 0.1, cy - c * 1.0, cx + c * 0.6, cy - c * 0.7], fill=(50, 150, 50))
    elif kind == "books":  # an open book
        draw.polygon([(cx, cy - c * 0.5), (cx - c, cy - c * 0.7), (cx - c, cy + c * 0.6), (cx, cy + c * 0.8)],
                     fill=(40, 80, 160), outline=(20, 40, 90))
        draw.polygon([(cx, cy - c * 0.5), (cx + c, cy - c * 0.7), (cx + c, cy + c * 0.6), (cx, cy + c * 0.8)],
                     fill=(40, 80, 160), outline=(20, 40, 90))
    return True


PICTOGRAM_KINDS = frozenset({"pharmacy", "bakery", "cafe", "restaurant", "bank", "hotel", "grocery", "books"})


def _sign_box(draw: ImageDraw.ImageDraw, box: tuple[float, float, float, float], sign: ShopSign,
              cues: set[str]) -> None:
    draw.rectangle(box, fill=rgb(sign.bg), outline=(30, 30, 30))
    lines = _drawable_lines(sign.lines, cues)
    x0, y0, x1, y1 = box
    c = min(x1 - x0, y1 - y0) * 0.18
    if shop_pictogram(draw, sign.kind, x0 + c * 1.4, (y0 + y1) / 2, c):
        cues.add(f"shop:{sign.kind}")
        box = (x0 + c * 2.6, y0, x1, y1)
    if sign.phone:
        lines = lines + [(sign.phone, "latin")]
        cues.add(f"phone:{sign.phone}")
    draw_centred_lines(draw, box, lines, rgb(sign.fg))


def _street_sign_box(draw: ImageDraw.ImageDraw, box: tuple[float, float, float, float], sign: StreetSign,
                     cues: set[str]) -> None:
    style = sign.style
    cues.add(f"street_sign_style:{style.words}")
    x0, y0, x1, y1 = box
    if style.mount == "pole":
        draw.line([((x0 + x1) / 2, y1), ((x0 + x1) / 2, y1 + 150)], fill=(110, 110, 110), width=4)
    draw.rectangle(box, fill=rgb(style.bg), outline=rgb(style.border), width=3)
    draw_centred_lines(draw, (x0 + 4, y0 + 3, x1 - 4, y1 - 3), _drawable_lines(sign.lines, cues, "street_sign_text"),
                       rgb(style.fg))


# ------------------------------------------------------------------------------ compositions
def _render_along(img: Image.Image, spec: ViewSpec, cues: set[str]) -> None:
    draw = ImageDraw.Draw(img)
    cues.add("composition:along")
    _sky(img, spec, HY, cues)
    _along_ground(draw, spec, cues)
    _along_buildings(draw, spec, cues)
    if spec.tram_tracks:
        _tram_tracks_along(draw)
        cues.add("tram_tracks")
    if spec.arch.wires:
        _wires(draw, spec)
        cues.add("wires")
    for kind, side, depth in spec.trees:
        u = 1 / (1.4 + depth * 6)
        x, base = _p((-1 if side == "left" else 1) * 0.66, 0, u)
        if draw_tree(draw, kind, x, base, u * 1.2):
            cues.add(f"tree:{kind}")
    if spec.skytrain:
        _skytrain(draw)
        cues.add("skytrain")
    # blade signs, nearest last
    per_side: dict[str, int] = {"left": 0, "right": 0}
    for sign in spec.shops:
        i = per_side[sign.side]
        per_side[sign.side] += 1
        side_sign = -1 if sign.side == "left" else 1
        z = 1.7 + i * 1.1
        u = 1 / z
        xa, ya = _p(side_sign * FACADE_X, 0.62, u)
        xb, yb = _p(side_sign * (FACADE_X - 0.42), 0.42, u)
        _sign_box(draw, (min(xa, xb), ya, max(xa, xb), yb), sign, cues)
    other = "left" if spec.drive == "right" else "right"
    for v in sorted(spec.vehicles, key=lambda v: -v.depth):
        vehicle_along(draw, _p, v, cues)
        # a car seen from behind in the driving-side lane (or head-on in the other) shows the traffic side
        if v.kind == "car" and ((v.side, v.facing) in ((spec.drive, "away"), (other, "toward"))):
            cues.add(f"drive:{spec.drive}")
    if spec.street_sign is not None:
        side_sign = -1 if spec.street_sign.side == "left" else 1
        cx = W // 2 + side_sign * 205
        n = len(spec.street_sign.lines)
        _street_sign_box(draw, (cx - 85, 120, cx + 85, 120 + 22 * n + 10), spec.street_sign, cues)


def _side_traffic(draw: ImageDraw.ImageDraw, spec: ViewSpec, cues: set[str], positions: dict[str, tuple[float, float,
                  float]]) -> None:
    """Side-on vehicles of the facade and landmark views; the near lane's direction shows the traffic side
    (with right-hand traffic, near-lane cars move from the viewer's left to right)."""
    near_dir = "right" if spec.drive == "right" else "left"
    in_lane: dict[str, int] = {}
    for v in spec.vehicles:
        lane = "near" if v.side == "near" else "far"
        cx, bottom, scale = positions[lane]
        k = in_lane[lane] = in_lane.get(lane, -1) + 1
        # the next vehicles in the same lane stand apart from the first, never on top of it
        cx += {"near": (0, 300, 160), "far": (0, -130, 130)}[lane][k % 3]
        car_side(draw, cx, bottom, scale, v, cues)
        if v.kind == "car" and v.side == "near" and v.facing == near_dir:
            cues.add(f"drive:{spec.drive}")


def _facade_row(draw: ImageDraw.ImageDraw, spec: ViewSpec, base: int, floor_px: int) -> list[tuple[int, int, int]]:
    """Draw the facing buildings; returns (x0, x1, top) per building."""
    arch = spec.arch
    rng = random.Random(spec.seed)
    x = -10
    spans = []
    for b in spec.buildings_right:
        w = rng.randint(140, 190)
        top = base - b.floors * floor_px
        draw.rectangle([x, top, x + w, base], fill=rgb(b.colour), outline=shade(b.colour, 0.7))
        wall_texture(draw, (x, top, x + w, base), b.colour, arch, rng)
        cols = max(2, w // 40)
        for f in range(1, b.floors):
            y0 = base - (f + 1) * floor_px + 8
            wh = floor_px - 16 if arch.window in ("tall", "arched", "shuttered") else floor_px - 20
            for c in range(cols):
                wx = x + (c + 0.5) * w / cols
                draw.rectangle([wx - 9, y0, wx + 9, y0 + wh], fill=shade(b.colour, 0.45),
                               outline=shade(b.colour, 0.8))
                window_trim(draw, wx, y0, wh, arch)
            if arch.balconies and f % 2 == 1:
                draw.rectangle([x + 6, y0 + wh, x + w - 6, y0 + wh + 4], fill=(40, 40, 40))
            if arch.ac_units and f % 2 == 0:
                draw.rectangle([x + w - 30, y0 + 5, x + w - 12, y0 + 17], fill=(228, 228, 222))
        if arch.roof == "mansard":
            draw.polygon([(x, top), (x + w, top), (x + w - 14, top - 26), (x + 14, top - 26)],
                         fill=rgb(arch.roof_colour))
        elif arch.roof in ("pitched", "curved_tile"):
            draw.polygon([(x - 4, top), (x + w + 4, top), (x + w - 10, top - 22), (x + 10, top - 22)],
                         fill=rgb(arch.roof_colour))
        elif arch.roof == "gabled":
            draw.polygon([(x, top), (x + w, top), (x + w / 2, top - 45)], fill=rgb(b.colour),
                         outline=shade(b.colour, 0.6))
        else:
            draw.rectangle([x - 3, top - 6, x + w + 3, top], fill=shade(b.colour, 0.6))
        front_extras(draw, (x, top, x + w, base), floor_px, b.colour, arch, rng)
        draw.rectangle([x + 4, base - floor_px + 6, x + w - 4, base], fill=shade(b.colour, 0.3))
        if arch.veranda:
            draw.rectangle([x, base - floor_px - 4, x + w, base - floor_px + 4], fill=(120, 120, 118))
            for px in (x + 8, x + w - 8):
                draw.line([(px, base - floor_px), (px, base + 14)], fill=(70, 70, 70), width=3)
        spans.append((x, x + w, top))
        x += w
        if x > W:
            break
    return spans


def _render_facade(img: Image.Image, spec: ViewSpec, cues: set[str]) -> None:
    draw = ImageDraw.Draw(img)
    cues |= {"composition:facade", f"arch:{spec.arch_key}"}
    horizon, base, floor_px = 170, 300, 38
    _sky(img, spec, horizon, cues)
    draw.rectangle([0, horizon, W, base], fill=shade(spec.arch.palette[0], 0.8))
    spans = _facade_row(draw, spec, base, floor_px)
    pave = rgb(spec.arch.pavement)
    draw.rectangle([0, base, W, 322], fill=pave)
    _side_road(draw, spec, cues, 322, pave)
    if spec.tram_tracks:
        for y in (340, 350):
            draw.line([(0, y), (W, y)], fill=(90, 90, 92), width=2)
        cues.add("tram_tracks")
    for kind, _side, depth in spec.trees:
        if draw_tree(draw, kind, 60 + depth * 800 % (W - 120), 318, 0.85):
            cues.add(f"tree:{kind}")
    for sign in spec.shops:
        idx = int(sign.side[1:])
        if idx >= len(spans):
            continue
        x0, x1, _top = spans[idx]
        _sign_box(draw, (max(4, x0 + 10), base - floor_px - 26, min(W - 4, x1 - 10), base - floor_px + 4), sign,
                  cues)
    if spec.arch.wires:
        for y in (195, 205, 214):
            draw.line([(0, y), (W, y + 8)], fill=(30, 30, 30), width=1)
        cues.add("wires")
    _side_traffic(draw, spec, cues, {"near": (170, 392, 1.0), "far": (430, 352, 0.8)})
    if spec.street_sign is not None:
        n = len(spec.street_sign.lines)
        x0 = spans[0][0] + 20 if spans else 20
        _street_sign_box(draw, (max(8, x0), 196, max(8, x0) + 190, 196 + 22 * n + 10), spec.street_sign, cues)


def _side_road(draw: ImageDraw.ImageDraw, spec: ViewSpec, cues: set[str], kerb: int,
               pave: tuple[int, int, int]) -> None:
    """The road crossing the view from ``kerb`` down to the bottom edge (facade and landmark views): paving
    wall to wall on pedestrian streets, else asphalt with its edge and centre lines."""
    if spec.pedestrian:
        draw.rectangle([0, kerb, W, H], fill=pave)
        for y in range(kerb + 8, H, 14):
            draw.line([(0, y), (W, y)], fill=shade(spec.arch.pavement, 0.9))
        cues.add("pedestrian")
        return
    draw.rectangle([0, kerb, W, H], fill=rgb(spec.climate.ground_tint))
    draw.line([(0, kerb), (W, kerb)], fill=(205, 205, 200), width=3)
    mid = (kerb + H) // 2
    if spec.edge_line:
        colour = (235, 190, 0) if spec.edge_line == "yellow" else (240, 240, 240)
        draw.line([(0, kerb + 6), (W, kerb + 6)], fill=colour, width=2)
        draw.line([(0, H - 4), (W, H - 4)], fill=colour, width=2)
        cues.add(f"edge_line:{spec.edge_line}")
    if spec.centre_line:
        colour = (235, 190, 0) if spec.centre_line == "yellow" else (240, 240, 240)
        for x in range(0, W, 60):
            draw.line([(x, mid), (x + 34, mid)], fill=colour, width=4)
        cues.add(f"centre_line:{spec.centre_line}")


def _render_landmark(img: Image.Image, spec: ViewSpec, cues: set[str]) -> None:
    from .landmarks import draw_landmark

    draw = ImageDraw.Draw(img)
    cues |= {"composition:landmark", f"arch:{spec.arch_key}"}
    horizon = 250
    _sky(img, spec, horizon, cues)
    pave = rgb(spec.arch.pavement)
    draw.rectangle([0, horizon, W, H], fill=pave)
    for i in range(1, 9):
        y = horizon + i * i * 2.2
        draw.line([(0, y), (W, y)], fill=shade(spec.arch.pavement, 0.9))
    # the street along the near side of the square, with its markings, under the traffic
    _side_road(draw, spec, cues, 318, pave)
    rng = random.Random(spec.seed)
    # low buildings on both edges of the square
    for side in (0, 1):
        x = 0 if side == 0 else W - 120
        b = spec.buildings_left[0] if side == 0 else spec.buildings_right[0]
        top = horizon - 20 - b.floors * 12
        draw.rectangle([x, top, x + 120, horizon], fill=rgb(b.colour), outline=shade(b.colour, 0.7))
        for f in range(b.floors):
            for c in range(5):
                wx = x + 10 + c * 22
                wy = horizon - 16 - (f + 1) * 12
                draw.rectangle([wx, wy, wx + 8, wy + 7], fill=shade(b.colour, 0.45))
    if spec.landmark is not None and draw_landmark(draw, spec.landmark.kind, rng, horizon):
        cues.add(f"landmark:{spec.landmark.kind}")
    for kind, _side, depth in spec.trees:
        if draw_tree(draw, kind, 30 + depth * 900 % (W - 60), horizon + 10, 0.55):
            cues.add(f"tree:{kind}")
    for i, sign in enumerate(spec.shops):
        x0 = 8 if i == 0 else W - 128
        _sign_box(draw, (x0, horizon - 14, x0 + 120, horizon + 12), sign, cues)
    if spec.arch.wires:  # cables strung across the square's edge from pole to pole
        for x in (40, W - 40):
            draw.line([(x, horizon + 60), (x, horizon - 70)], fill=(90, 80, 70), width=3)
        for y in (-64, -58, -52):
            draw.line([(40, horizon + y), (W - 40, horizon + y + 10)], fill=(30, 30, 30), width=1)
        cues.add("wires")
    _side_traffic(draw, spec, cues, {"near": (140, 392, 0.9), "far": (460, 350, 0.7)})
    if spec.street_sign is not None:
        n = len(spec.street_sign.lines)
        _street_sign_box(draw, (W - 215, 262, W - 15, 262 + 22 * n + 10), spec.street_sign, cues)


def render_view_cues(spec: ViewSpec) -> tuple[Image.Image, frozenset[str]]:
    """The view and the ids of the cues it draws (the same ids describe.describe_view_cues names)."""
    img = Image.new("RGB", (W, H), (255, 255, 255))
    cues: set[str] = set()
    if spec.composition == "along":
        _render_along(img, spec, cues)
    elif spec.composition == "facade":
        _render_facade(img, spec, cues)
    else:
        _render_landmark(img, spec, cues)
    return img, frozenset(cues)


def render_view(spec: ViewSpec) -> Image.Image:
    return render_view_cues(spec)[0]


@lru_cache(maxsize=256)
def render_png(spec: ViewSpec) -> bytes:
    return encode_png(render_view(spec))
