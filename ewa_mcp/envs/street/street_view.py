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
from .here_view import blocked_near, draw_here, park_here
from .facades import (AHEAD_END_WALL, FACADE_X_M, LANE, ROAD, ROAD_HALF_M, SIDEWALK, SKY, SKY_TOP, STREET_CAMERA,
                      STYLE_PALETTES, _capped_height, _sign_colour, _style_key, draw_details, draw_facade)
from .scene import (LOW_HEIGHT_M, OPEN_SPACE_KINDS, SKYLINE_SHOWN, Frontage, Scene, has_look, stated_low,
                    wall_colour_of)



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


def _skyline_windows(scene: Scene, cam: Camera) -> list[tuple[float, float, float]]:
    """(x0, x1, lowest roof row) per skyline tower the text names: nearer ordinary buildings in those columns
    are drawn low enough for the tower's top to show over their roofs, as it does in the text."""
    out = []
    for item in sorted(scene.skyline, key=lambda s: s.distance_m)[:2]:
        x, half, top, _ = _skyline_box(item, cam)
        out.append((x - half, x + half, top + (cam.horizon - top) * SKYLINE_SHOWN))
    return out


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


def drawn_side(scene: Scene, f: Frontage, far: float) -> str:
    """The side a place's front is drawn on: its own, except that a place straight ahead along a street that
    goes on past it stands beside that street (on the side of the axis it is on), not across the road: the
    text says the street continues there."""
    if f.side == "ahead" and scene.road_ahead and f.distance_m < far:
        return "right" if f.rel_angle >= 0 else "left"
    return f.side


def _wall(f: Frontage) -> tuple[int, int, int] | None:
    """The wall colour its description gives the material it names (None: its style's or a random tone)."""
    return wall_colour_of(f.hint)


def render(scene: Scene, cam: Camera | None = None) -> Image.Image:
    return render_cues(scene, cam)[0]


def render_cues(scene: Scene, cam: Camera | None = None) -> tuple[Image.Image, frozenset[str]]:
    """The view and the ids of what it draws (scene.text_cues names the ids the text gives)."""

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
        if scene.in_park:  # the park goes on past the path's end: lawn to the horizon, no building fronts
            draw.polygon([cam.project(-400, 0, 2.0), cam.project(-400, 0, 2000), cam.project(400, 0, 2000),
                          cam.project(400, 0, 2.0)], fill=(96, 150, 72))
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
        if far < AHEAD_END_WALL and not scene.in_park:
            _end_wall(draw, cam, far + 12, rng, windows=windows, avoid=scene.place_walls)
    elif scene.open_space or park_here(scene):
        cues.add("road_ends")
        _open_ground(draw, cam, rng)
        if scene.open_space:
            cues.add("open_space")
    else:
        cues.add("road_ends")
        facing = next((f for f in scene.frontages if f.side == "ahead" and f.range_m <= 40), None)
        _end_wall(draw, cam, 14.0, rng, facing, cues, avoid=scene.place_walls)
    # Facades, far to near, both sides.
    landmarks: dict[str, list[Frontage]] = {"left": [], "right": []}
    for f in scene.frontages:
        if drawn_side(scene, f, far) in landmarks:
            landmarks[drawn_side(scene, f, far)].append(f)
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
        pieces.append((z, drawn_side(scene, f, far), z - 8, z + 8, f))
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
            height = LOW_HEIGHT_M if stated_low(lm) else min(80.0, max(18.0, lm.height_m or 30.0))
            if windows and not lm.height_m:
                height = _capped_height(height, cam, None, z, z, windows)
            quad = [cam.project(cx - 12, 0, z), cam.project(cx - 12, height, z), cam.project(cx + 12, height, z),
                    cam.project(cx + 12, 0, z)]
            draw_facade(draw, quad, lm.style, rng, floors=max(3, int(height / 4)), wall=_wall(lm))
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, quad, lm.hint)}
            continue
        x = FACADE_X_M if side == "right" else -FACADE_X_M
        if lm is None and scene.in_park:  # a path through a park: lawns and trees either side, no fronts
            _park_stretch(draw, cam, x, z0, z1)
            continue
        if lm is not None and lm.kind in OPEN_SPACE_KINDS:  # a park along the street: lawn and trees, no front
            _park_stretch(draw, cam, x, z0, z1)
            low = [cam.project(x, 0, z0), cam.project(x, 8.0, z0), cam.project(x, 8.0, z1), cam.project(x, 0, z1)]
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, low, lm.hint)}
            continue
        height = (rng.uniform(12, 40) if lm is None else LOW_HEIGHT_M if stated_low(lm)
                  else min(80.0, max(18.0, (lm.height_m or 30.0))))
        if windows and (lm is None or not lm.height_m):  # a place of unknown height is no taller than needed
            height = _capped_height(height, cam, x, z0, z1, windows)
        quad = [cam.project(x, 0, z0), cam.project(x, height, z0), cam.project(x, height, z1), cam.project(x, 0, z1)]
        draw_facade(draw, quad, lm.style if lm else "", rng, floors=max(3, int(height / 4)),
                    wall=_wall(lm) if lm else None, avoid=scene.place_walls if lm is None else ())
        if lm is not None:
            cues.add(f"facade:{lm.place_id}")
            cues |= {f"detail:{lm.place_id}:{d}" for d in draw_details(draw, quad, lm.hint)}
    for f in sorted(scene.frontages, key=lambda f: -f.distance_m):
        if f.sign:
            side = drawn_side(scene, f, far)
            _draw_sign(draw, cam, side if side != "ahead" else "right", f.distance_m, f.sign,
                       _sign_colour(f.sign), cues)
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
              windows: list[tuple[float, float, float]] | None = None,
              avoid: list[tuple[int, int, int]] | tuple[()] = ()) -> None:
    """The building fronts across the end of the view; the place straight ahead, if any, in its style and
    the colour its description gives; otherwise in a tone unlike the described places near by (``avoid``)."""
    height = 28.0
    if windows:
        height = _capped_height(height, cam, None, z, z, windows)
    quad = [cam.project(-60, 0, z), cam.project(-60, height, z), cam.project(60, height, z), cam.project(60, 0, z)]
    draw_facade(draw, [quad[0], quad[1], quad[2], quad[3]], facing.style if facing else "", rng, floors=7,
                wall=_wall(facing) if facing else None, avoid=() if facing else avoid)
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
