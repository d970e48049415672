"""The places at the agent's own node, drawn close up in the view that faces them (Scene.here).

The text mode says "Right here: on your left, a sign reading ..." at a place's node; the vision mode has no
such line, so the picture must carry it: the view towards a place's entrance shows that place near and large
(a shop's front with its name board, a landmark's front in the material, shape and details its description
names, a park's lawns, trees, paths and pond, a small street's own sign at its mouth), where a walker standing
there would see it. Landmarks keep their names off the picture, as in the text: only what the real place
carries (a shop's sign, a street sign) is written.
"""

from __future__ import annotations

import math
import random

from PIL import ImageDraw

from ewa_mcp.street_drawing.camera import Camera
from ewa_mcp.street_drawing.text import bundled_font
from .scene import (
    LOW_HEIGHT_M,
    OPEN_SPACE_KINDS,
    SIGN_KINDS,
    Frontage,
    Scene,
    details_of,
    is_alley,
    material_of,
    park_features,
    sign_colour_of,
    stated_low,
    wall_colour_of,
)
from .facades import FACADE_X_M, ROAD_HALF_M, _capped_height, _sign_colour, draw_details, draw_facade

FRONT_Z_M = 13.0  # a place straight across the sidewalk: its front this deep (the end wall stands at 14 m)
FRONT_HALF_M = 10.0  # half the width of such a front
SIDE_Z = (12.0, 34.0)  # a place beside a street that goes on ahead: the stretch of its side it fills
PARK_Z_M = 70.0  # a park beside the street: the depth its lawn reaches (no buildings drawn before it)
DETAIL_H_M = 16.0  # the height of the part of a front its details are drawn on (a door, a clock, a dome)
LAWN, PATH, POND, TRUNK, LEAVES = (96, 150, 72), (214, 200, 168), (70, 128, 188), (90, 64, 44), (52, 112, 56)
FOUNTAIN, MONUMENT, STREET_SIGN = (236, 242, 246), (200, 196, 186), (18, 110, 58)
SHOP_GLASS = (150, 190, 210)  # a lit shop window
RAILING = (36, 60, 44)


def park_here(scene: Scene) -> Frontage | None:
    return next((f for f in scene.here if f.kind in OPEN_SPACE_KINDS), None)


def blocked_near(scene: Scene) -> dict[str, float]:
    """Per side of a street that goes on ahead, the depth up to which the places here replace the ordinary
    building fronts (a park's lawn, or a place's own front)."""
    out = {"left": 0.0, "right": 0.0}
    if not scene.road_ahead:
        return out
    for f in scene.here:
        if not sidewalk_entrance(f):  # a stairway down stands in front of the ordinary fronts
            out[f.side] = max(out[f.side], PARK_Z_M if f.kind in OPEN_SPACE_KINDS else SIDE_Z[1])
    return out


def draw_here(draw: ImageDraw.ImageDraw, scene: Scene, cam: Camera, rng: random.Random, cues: set[str],
              windows: list[tuple[float, float, float]]) -> None:
    """Draw every place of scene.here, and add the ids of what is drawn to ``cues`` (scene.here_cues);
    ``windows``: where far towers the text names must show over the roofs (street_view._skyline_windows)."""
    fronts = [f for f in scene.here if f.kind not in OPEN_SPACE_KINDS]
    park = park_here(scene)
    if park is not None:
        _park(draw, scene, cam, rng, park, cues, windows)
    if scene.road_ahead:
        for side in ("left", "right"):
            mine = [f for f in fronts if f.side == side]
            if not mine:
                continue
            step = (SIDE_Z[1] - SIDE_Z[0]) / len(mine)
            for k, f in enumerate(sorted(mine, key=lambda f: abs(f.rel_angle))):
                z0 = SIDE_Z[0] + k * step
                _side_front(draw, cam, rng, f, side, z0, z0 + step, cues, windows)
        return
    # Fronts across the sidewalk, left to right at their bearings, no two overlapping.
    fronts.sort(key=lambda f: f.rel_angle)
    xs = [FRONT_Z_M * math.tan(math.radians(f.rel_angle)) for f in fronts]
    for k, f in enumerate(fronts):
        lo = xs[k] - FRONT_HALF_M if k == 0 else max(xs[k] - FRONT_HALF_M, (xs[k - 1] + xs[k]) / 2)
        hi = xs[k] + FRONT_HALF_M if k == len(fronts) - 1 else min(xs[k] + FRONT_HALF_M, (xs[k] + xs[k + 1]) / 2)
        _facing_front(draw, cam, rng, f, lo, hi, cues, windows)


ROOF_DETAILS = {"gables", "cupola", "dome", "spire", "statue", "twin"}


def _in_sight(cam: Camera, z: float, room: float) -> float:
    """The height (m) at depth z whose top stays ``room`` (a share of the sky's rows) below the picture's top."""
    return cam.eye_height + cam.horizon * (1.0 - room) * z / cam.focal


def _height(f: Frontage, cam: Camera, z: float) -> float:
    """A place's front height; lowered into sight where its roof carries what its description names (a
    steeple, gables, a cupola), so that the roof line and those are in the picture."""
    h = LOW_HEIGHT_M if stated_low(f) else min(80.0, max(12.0, f.height_m or 20.0))
    return min(h, _in_sight(cam, z, 0.4)) if details_of(f.hint) & ROOF_DETAILS else h


def _detail_h(f: Frontage, cam: Camera, z: float, h: float) -> float:
    """The height of the part of a front its details are drawn on: all of it up to DETAIL_H_M, in sight."""
    return min(h, DETAIL_H_M, _in_sight(cam, z, 0.12))


def _board_colour(f: Frontage) -> tuple[int, int, int]:
    if is_alley(f.sign or ""):
        return STREET_SIGN
    return sign_colour_of(f.hint) or _sign_colour(f.sign or "")


def _shopfront(draw: ImageDraw.ImageDraw, quad: list[tuple[float, float]], height_m: float) -> None:
    """A shop's ground floor on a front quad ``height_m`` tall: display windows either side of a glazed door."""
    (bx0, by0), (tx0, ty0), (tx1, ty1), (bx1, by1) = quad
    u = min(0.9, 3.2 / max(height_m, 3.3))

    def at(t: float, v: float) -> tuple[float, float]:
        bx, by = bx0 + (bx1 - bx0) * t, by0 + (by1 - by0) * t
        tx, ty = tx0 + (tx1 - tx0) * t, ty0 + (ty1 - ty0) * t
        return bx + (tx - bx) * v, by + (ty - by) * v

    for t0, t1 in ((0.06, 0.42), (0.58, 0.94)):
        draw.polygon([at(t0, 0.03), at(t0, u), at(t1, u), at(t1, 0.03)], fill=SHOP_GLASS, outline=(40, 40, 44))
    draw.polygon([at(0.44, 0.0), at(0.44, u * 0.85), at(0.56, u * 0.85), at(0.56, 0.0)], fill=(44, 52, 60),
                 outline=(200, 200, 200))


def _mark(draw: ImageDraw.ImageDraw, f: Frontage, quad: list[tuple[float, float]], cues: set[str],
          height_m: float) -> None:
    if f.kind in SIGN_KINDS - {"station"}:
        _shopfront(draw, quad, height_m)
    cues.add(f"here:{f.place_id}")
    cues.add(f"facade:{f.place_id}")
    cues |= {f"detail:{f.place_id}:{d}" for d in draw_details(draw, quad, f.hint)}
    if material_of(f.hint):
        cues.add(f"material:{f.place_id}:{material_of(f.hint)}")


def sidewalk_entrance(f: Frontage) -> bool:
    """A subway entrance: stairs down from the sidewalk (no building front of its own)."""
    text = f.hint.lower()
    return f.kind == "station" and "stair" in text and " down" in text


def _stairway(draw: ImageDraw.ImageDraw, cam: Camera, f: Frontage, x: float, z: float, cues: set[str]) -> None:
    """A stairway down through the sidewalk at (x, z): the dark opening, its steps, railings on three sides,
    and the station's name board on a post; the details its description names (globe lamps) beside it."""
    w, d, rail = 1.6, 5.0, 1.1
    draw.polygon([cam.project(x - w, 0, z), cam.project(x + w, 0, z), cam.project(x + w, 0, z + d),
                  cam.project(x - w, 0, z + d)], fill=(46, 46, 50))
    for k in range(1, 8):
        zz = z + d * k / 8
        draw.line([cam.project(x - w, 0, zz), cam.project(x + w, 0, zz)], fill=(120, 120, 124), width=1)
    for a, b in (((x - w, z), (x - w, z + d)), ((x + w, z), (x + w, z + d)), ((x - w, z + d), (x + w, z + d))):
        draw.line([cam.project(a[0], rail, a[1]), cam.project(b[0], rail, b[1])], fill=RAILING, width=3)
        for t in (0.0, 0.5, 1.0):
            px, pz = a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t
            draw.line([cam.project(px, 0, pz), cam.project(px, rail, pz)], fill=RAILING, width=2)
    post = x + w + 0.4
    draw.line([cam.project(post, 0, z), cam.project(post, 3.2, z)], fill=RAILING, width=3)
    around = [cam.project(x - w - 1.5, 0, z), cam.project(x - w - 1.5, 6.0, z), cam.project(x + w + 1.5, 6.0, z),
              cam.project(x + w + 1.5, 0, z)]
    cues.add(f"here:{f.place_id}")
    cues.add(f"facade:{f.place_id}")
    cues |= {f"detail:{f.place_id}:{d}" for d in draw_details(draw, around, f.hint, door=False)}
    if f.sign:
        _board(draw, cam, f, cam.project(post, 3.6, z), cues)


def _facing_front(draw: ImageDraw.ImageDraw, cam: Camera, rng: random.Random, f: Frontage, x0: float, x1: float,
                  cues: set[str], windows: list[tuple[float, float, float]]) -> None:
    """A place straight across the sidewalk: its front facing the camera over the world span x0..x1."""
    if sidewalk_entrance(f):  # on the sidewalk in front of the building fronts
        _stairway(draw, cam, f, (x0 + x1) / 2 * 0.7, FRONT_Z_M * 0.7, cues)
        return
    z = FRONT_Z_M
    h = _height(f, cam, z)
    if windows:  # no taller than leaves the far towers the text names in sight over its roof
        h = _capped_height(h, cam, None, z, z, windows)
    dh = _detail_h(f, cam, z, h)
    quad = [cam.project(x0, 0, z), cam.project(x0, h, z), cam.project(x1, h, z), cam.project(x1, 0, z)]
    wall = wall_colour_of(f.hint)
    draw_facade(draw, quad, f.style, rng, floors=max(3, int(h / 4)), wall=wall)
    # Its details and sign on the part in sight (a front half off the picture keeps its door in it).
    half_w = cam.width / 2 * z / cam.focal
    v0, v1 = max(x0, -half_w + 0.5), min(x1, half_w - 0.5)
    if v1 - v0 < 2.0:
        v0, v1 = x0, x1
    if is_alley(f.sign or ""):
        _alley_mouth(draw, cam, (v0 + v1) / 2, z)
    low = [cam.project(v0, 0, z), cam.project(v0, dh, z), cam.project(v1, dh, z), cam.project(v1, 0, z)]
    _mark(draw, f, low, cues, dh)
    if f.sign:
        mid = (v0 + v1) / 2
        if is_alley(f.sign):
            mid = (v0 + v1) / 2 + 1.6
        _board(draw, cam, f, cam.project(mid, 4.6 if not is_alley(f.sign) else 3.2, z), cues)


def _side_front(draw: ImageDraw.ImageDraw, cam: Camera, rng: random.Random, f: Frontage, side: str, z0: float,
                z1: float, cues: set[str], windows: list[tuple[float, float, float]]) -> None:
    """A place beside a street that goes on ahead: its front on that side's facade plane, near."""
    x = FACADE_X_M if side == "right" else -FACADE_X_M
    if sidewalk_entrance(f):
        _stairway(draw, cam, f, x * 0.8, z0 + 1.0, cues)  # mid-sidewalk, near
        return
    h = _height(f, cam, z0)
    if windows:
        h = _capped_height(h, cam, x, z0, z1, windows)
    dh = _detail_h(f, cam, z0, h)
    quad = [cam.project(x, 0, z0), cam.project(x, h, z0), cam.project(x, h, z1), cam.project(x, 0, z1)]
    draw_facade(draw, quad, f.style, rng, floors=max(3, int(h / 4)), wall=wall_colour_of(f.hint))
    low = [cam.project(x, 0, z0), cam.project(x, dh, z0), cam.project(x, dh, z1), cam.project(x, 0, z1)]
    _mark(draw, f, low, cues, dh)
    if f.sign:
        zm = (z0 + z1) / 2
        if is_alley(f.sign):  # the street sign on its pole at the alley's mouth, by the kerb
            _alley_mouth_side(draw, cam, x, zm)
        _board(draw, cam, f, cam.project(x * (0.8 if is_alley(f.sign) else 1.0), 4.6 if not is_alley(f.sign)
                                         else 3.2, zm), cues)


def _board(draw: ImageDraw.ImageDraw, cam: Camera, f: Frontage, at: tuple[float, float], cues: set[str]) -> None:
    """A name board centred on ``at`` (kept inside the picture), legible at any distance: a shop's sign over
    its door, or a small street's green street sign."""
    assert f.sign is not None
    fnt = bundled_font(14)
    w = draw.textlength(f.sign, font=fnt)
    cx = min(max(at[0], w / 2 + 6), cam.width - w / 2 - 6)
    cy = min(max(at[1], 12.0), cam.height - 40.0)
    colour = _board_colour(f)
    draw.rectangle([cx - w / 2 - 5, cy - 10, cx + w / 2 + 5, cy + 10], fill=colour, outline=(245, 245, 245), width=2)
    ink = (20, 20, 20) if sum(colour) > 600 else (250, 250, 250)
    draw.text((cx - w / 2, cy - 8), f.sign, font=fnt, fill=ink)
    cues.add(f"sign:{f.sign}")


def _alley_mouth(draw: ImageDraw.ImageDraw, cam: Camera, x: float, z: float) -> None:
    """A narrow cobbled lane running away between the fronts, its far end in light."""
    near = [cam.project(x - 1.8, 0, z), cam.project(x + 1.8, 0, z)]
    far = [cam.project(x + 0.9, 0, z + 60), cam.project(x - 0.9, 0, z + 60)]
    top = [cam.project(x - 1.8, 9, z), cam.project(x + 1.8, 9, z)]
    draw.rectangle([near[0][0], top[0][1], near[1][0], near[0][1]], fill=(188, 204, 222))  # sky down the lane
    draw.polygon([near[0], near[1], far[0], far[1]], fill=(128, 116, 104))
    for k in range(1, 9):  # cobbles: rows across the lane
        zz = z + k * 4
        draw.line([cam.project(x - 1.8, 0, zz), cam.project(x + 1.8, 0, zz)], fill=(96, 88, 80), width=1)
    draw.line([cam.project(x + 1.9, 0, z), cam.project(x + 1.9, 3.8, z)], fill=(50, 60, 50), width=3)  # the pole


def _alley_mouth_side(draw: ImageDraw.ImageDraw, cam: Camera, x: float, z: float) -> None:
    draw.line([cam.project(x * 0.8, 0, z), cam.project(x * 0.8, 3.8, z)], fill=(50, 60, 50), width=3)


def _park(draw: ImageDraw.ImageDraw, scene: Scene, cam: Camera, rng: random.Random, f: Frontage,
          cues: set[str], windows: list[tuple[float, float, float]]) -> None:
    """A park: across the sidewalk (render_cues has drawn the open ground) or beside the street going on
    ahead (its lawn replaces that side's first buildings); a path into it, trees, and the pond, fountain
    or monument its description names, near the bearing of its entrance."""
    features = park_features(f.hint)
    if scene.road_ahead:
        sgn = 1.0 if f.side == "right" else -1.0
        h = cam.horizon
        x_edge = cam.project(sgn * (ROAD_HALF_M + 2.0), 0, PARK_Z_M)[0]
        band = [x_edge, h - 14, cam.width if sgn > 0 else 0, h]
        draw.rectangle([min(band[0], band[2]), band[1], max(band[0], band[2]), band[3]], fill=(150, 150, 146))
        kerb = sgn * (ROAD_HALF_M + 2.0)
        draw.polygon([cam.project(kerb, 0, 2.0), cam.project(kerb, 0, PARK_Z_M),
                      cam.project(sgn * 200, 0, PARK_Z_M), cam.project(sgn * 200, 0, 2.0)], fill=LAWN)
        centre_x, z_mid = sgn * 22.0, 30.0
    else:
        centre_x, z_mid = 30.0 * math.tan(math.radians(f.rel_angle)), 30.0
    cues.add(f"park:{f.place_id}:lawn")
    if "pond" in features:
        pts = [cam.project(centre_x + 9 * math.cos(a / 8 * math.pi), 0, z_mid + 7 * math.sin(a / 8 * math.pi))
               for a in range(16)]
        draw.polygon(pts, fill=POND, outline=(40, 90, 140))
        cues.add(f"park:{f.place_id}:pond")
    if "paths" in features:
        px = centre_x * 0.25
        draw.polygon([cam.project(px - 1.5, 0, 4.0), cam.project(px + 1.5, 0, 4.0),
                      cam.project(centre_x + 12, 0, z_mid + 20), cam.project(centre_x + 9, 0, z_mid + 20)], fill=PATH)
        cues.add(f"park:{f.place_id}:paths")
    if "fountain" in features:
        bx, by = cam.project(centre_x - 6, 0, z_mid - 8)
        r = 2.5 * cam.focal / (z_mid - 8)
        draw.ellipse([bx - r, by - r * 0.3, bx + r, by + r * 0.3], fill=FOUNTAIN, outline=(120, 130, 140))
        draw.line([(bx, by), (bx, by - r)], fill=FOUNTAIN, width=max(2, int(r / 5)))
        cues.add(f"park:{f.place_id}:fountain")
    if "monument" in features:
        bx, by = cam.project(centre_x + 4, 0, z_mid + 12)
        _, ty = cam.project(centre_x + 4, 9.0, z_mid + 12)
        w = 0.9 * cam.focal / (z_mid + 12)
        draw.polygon([(bx - w, by), (bx + w, by), (bx + w * 0.5, ty + w), (bx, ty), (bx - w * 0.5, ty + w)],
                     fill=MONUMENT)
        cues.add(f"park:{f.place_id}:monument")
    trees = [(centre_x + rng.uniform(-24, 24), rng.uniform(12, 60)) for _ in range(8)]
    if scene.road_ahead:
        sgn = 1.0 if f.side == "right" else -1.0
        trees = [(sgn * rng.uniform(ROAD_HALF_M + 4, 40), z) for _, z in trees]
    for x, z in sorted(trees, key=lambda t: -t[1]):
        bx, by = cam.project(x, 0, z)
        _, ty = cam.project(x, 4.5, z)
        r = 3.2 * cam.focal / z
        if any(bx + r >= x0 and bx - r <= x1 for x0, x1, _ in windows):
            continue  # no crown in front of a far tower the text names
        draw.line([(bx, by), (bx, ty)], fill=TRUNK, width=max(1, int(r / 4)))
        draw.ellipse([bx - r, ty - r * 1.4, bx + r, ty + r * 0.4], fill=LEAVES)
    cues.add(f"park:{f.place_id}:trees")
    cues.add(f"here:{f.place_id}")

