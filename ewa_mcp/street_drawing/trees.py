"""Street trees by kind, drawn at a base point and a scale, each in the shape and colours its words
name (geo/styles.py TREE_WORDS: "weeping willows", "banyan trees with hanging aerial roots",
"white-barked birches", ...), so a picture tells the kinds apart as the text does. ``draw_tree`` says
whether it drew the kind itself (True) or a generic broadleaf for a kind it does not know (False)."""

from __future__ import annotations

import math
from collections.abc import Callable

from PIL import ImageDraw

RGB = tuple[int, int, int]
TRUNK: RGB = (95, 75, 55)
GREEN: RGB = (70, 120, 60)


def _w(s: float, px: float, least: int = 2) -> int:
    return max(least, int(px * s))


def _trunk(d: ImageDraw.ImageDraw, x: float, base: float, s: float, h: float, width: float = 7,
           colour: RGB = TRUNK) -> None:
    d.line([(x, base), (x, base - h * s)], fill=colour, width=_w(s, width))


def _crown(d: ImageDraw.ImageDraw, x: float, y: float, s: float, rx: float, ry: float, colour: RGB) -> None:
    d.ellipse([x - rx * s, y - ry * s, x + rx * s, y + ry * s], fill=colour)


def _palm(d: ImageDraw.ImageDraw, x: float, base: float, s: float, height: float, lean: float, frond: float,
          colour: RGB = (60, 120, 50)) -> None:
    d.line([(x, base), (x + lean * s, base - height * s)], fill=(120, 100, 80), width=_w(s, 7))
    tx, ty = x + lean * s, base - height * s
    for ang in range(0, 360, 40):
        a = math.radians(ang)
        d.line([(tx, ty), (tx + math.cos(a) * frond * s, ty + math.sin(a) * frond * 0.5 * s + 12 * s)],
               fill=colour, width=_w(s, 5))


def palm(d, x, base, s):
    _palm(d, x, base, s, 150, 0, 45)


def fan_palm(d, x, base, s):  # very tall and thin, a small round head
    _palm(d, x, base, s, 260, 0, 28)


def coconut_palm(d, x, base, s):  # leaning
    _palm(d, x, base, s, 170, 28, 45)


def date_palm(d, x, base, s):  # straight, a thick trunk with a criss-cross of leaf scars
    d.line([(x, base), (x, base - 150 * s)], fill=(140, 110, 75), width=_w(s, 11))
    for k in range(6):
        y = base - (20 + k * 22) * s
        d.line([(x - 5 * s, y), (x + 5 * s, y - 6 * s)], fill=(100, 80, 55), width=1)
    _palm(d, x, base, s, 150, 0, 50, (90, 130, 70))


def cypress(d, x, base, s):
    d.ellipse([x - 14 * s, base - 170 * s, x + 14 * s, base - 5 * s], fill=(40, 80, 45))


def spruce(d, x, base, s):  # dark and conical
    for i in range(4):
        w = (50 - i * 10) * s
        top = base - (40 + i * 35) * s
        d.polygon([(x - w, top + 45 * s), (x, top - 10 * s), (x + w, top + 45 * s)], fill=(30, 62, 40))
    _trunk(d, x, base, s, 30, 5)


def pine(d, x, base, s):  # a bare trunk under a tufted, irregular crown
    _trunk(d, x, base, s, 120, 6, (120, 80, 55))
    for dx, dy, rx in ((-25, -120, 30), (18, -135, 28), (0, -150, 24)):
        _crown(d, x + dx * s, base + dy * s, s, rx, 14, (40, 90, 50))


def araucaria(d, x, base, s):  # a tall trunk with tiers of level branches ending in upturned tufts
    _trunk(d, x, base, s, 220, 6)
    for k in range(5):
        y = base - (90 + k * 30) * s
        reach = (55 - k * 9) * s
        for side in (-1, 1):
            d.line([(x, y), (x + side * reach, y)], fill=(50, 80, 45), width=_w(s, 4))
            d.line([(x + side * reach, y), (x + side * reach, y - 14 * s)], fill=(50, 80, 45), width=_w(s, 6))


def _flat_top(d, x, base, s, colour: RGB, h: float = 110, rx: float = 70) -> None:
    _trunk(d, x, base, s, h, 6)
    for side in (-1, 1):  # branches spreading up to the flat crown
        d.line([(x, base - h * 0.6 * s), (x + side * rx * 0.5 * s, base - (h + 5) * s)], fill=TRUNK, width=_w(s, 3))
    d.ellipse([x - rx * s, base - (h + 30) * s, x + rx * s, base - (h - 15) * s], fill=colour)


def umbrella_pine(d, x, base, s):
    _flat_top(d, x, base, s, (45, 95, 50))


def acacia(d, x, base, s):
    _flat_top(d, x, base, s, (110, 130, 60), h=90, rx=75)


def rain_tree(d, x, base, s):  # wide-spreading: a crown far wider than tall on a short trunk
    _flat_top(d, x, base, s, (60, 120, 55), h=70, rx=105)


def flamboyant(d, x, base, s):  # a spreading crown of red blossom
    _flat_top(d, x, base, s, (210, 60, 35), h=80, rx=85)
    for dx in (-50, -15, 25, 60):
        _crown(d, x + dx * s, base - 110 * s, s, 12, 6, (90, 130, 60))


def banana(d, x, base, s):  # huge paddle leaves
    for ang in (-60, -25, 10, 45):
        a = math.radians(ang - 90)
        d.line([(x, base - 40 * s), (x + math.cos(a) * 60 * s, base - 40 * s + math.sin(a) * 60 * s)],
               fill=(90, 160, 60), width=_w(s, 12, 3))


def _broadleaf(d, x, base, s, crown: RGB, bark: RGB = TRUNK, h: float = 80, rx: float = 50, ry: float = 45) -> None:
    _trunk(d, x, base, s, h, 7, bark)
    _crown(d, x, base - (h + ry * 0.6) * s, s, rx, ry, crown)


def plane(d, x, base, s):  # broad, with mottled bark
    _broadleaf(d, x, base, s, (85, 135, 65), (150, 140, 110), rx=68, ry=42)
    for k, colour in enumerate(((215, 205, 170), (110, 100, 80), (200, 190, 150))):
        y = base - (12 + k * 22) * s
        d.ellipse([x - 3 * s, y - 5 * s, x + 3 * s, y + 5 * s], fill=colour)


def linden(d, x, base, s):  # rounded
    _broadleaf(d, x, base, s, (75, 125, 60), rx=48, ry=50)


def maple(d, x, base, s):  # leafy: a crown of many lobes
    _trunk(d, x, base, s, 80, 7)
    for dx, dy in ((-30, -120), (30, -120), (0, -150), (-20, -95), (22, -95)):
        _crown(d, x + dx * s, base + dy * s, s, 28, 26, (80, 140, 55))


def chestnut(d, x, base, s):  # white flower candles on a dark crown
    _broadleaf(d, x, base, s, (50, 100, 50), rx=55, ry=50)
    for dx, dy in ((-30, -130), (0, -160), (28, -125), (-12, -105), (20, -150)):
        d.ellipse([x + (dx - 3) * s, base + (dy - 8) * s, x + (dx + 3) * s, base + (dy + 8) * s], fill=(250, 248, 240))


def birch(d, x, base, s):  # white bark with dark marks, a light narrow crown
    _trunk(d, x, base, s, 100, 6, (238, 238, 232))
    for k in range(4):
        y = base - (15 + k * 20) * s
        d.line([(x - 3 * s, y), (x + 3 * s, y)], fill=(40, 40, 40), width=1)
    _crown(d, x, base - 140 * s, s, 32, 48, (120, 170, 80))


def camphor(d, x, base, s):  # dense, dark evergreen
    _trunk(d, x, base, s, 70, 8)
    for dx, dy, r in ((-35, -110, 38), (35, -110, 38), (0, -140, 44), (0, -95, 40)):
        _crown(d, x + dx * s, base + dy * s, s, r, r * 0.85, (30, 82, 40))


def frangipani(d, x, base, s):  # bare forked branches tipped with white flowers
    _trunk(d, x, base, s, 60, 6, (140, 130, 115))
    for ang in (-50, -20, 15, 45):
        a = math.radians(ang - 90)
        ex, ey = x + math.cos(a) * 60 * s, base - 60 * s + math.sin(a) * 60 * s
        d.line([(x, base - 60 * s), (ex, ey)], fill=(140, 130, 115), width=_w(s, 4))
        _crown(d, ex, ey, s, 14, 9, (80, 130, 70))
        for fx in (-6, 6):
            _crown(d, ex + fx * s, ey - 5 * s, s, 4, 4, (255, 255, 250))


def jacaranda(d, x, base, s):  # purple bloom
    _broadleaf(d, x, base, s, (140, 100, 190), rx=58, ry=40)


def eucalyptus(d, x, base, s):  # tall, with peeling pale bark and a grey-green crown
    _trunk(d, x, base, s, 150, 8, (200, 190, 170))
    for k in range(5):
        y = base - (15 + k * 25) * s
        d.line([(x - 4 * s, y), (x + 2 * s, y - 10 * s)], fill=(150, 110, 80), width=_w(s, 3))
    _crown(d, x, base - 180 * s, s, 40, 38, (120, 145, 120))


def _weeping(d, x, base, s, crown: RGB, strand: RGB, reach: float) -> None:
    _trunk(d, x, base, s, 90, 8)
    _crown(d, x, base - 125 * s, s, 55, 38, crown)
    for k in range(9):
        sx = x + (k - 4) * 12 * s
        d.line([(sx, base - 115 * s), (sx + (k - 4) * 2 * s, base - (115 - reach) * s)], fill=strand, width=_w(s, 3))


def willow(d, x, base, s):  # strands hanging almost to the ground
    _weeping(d, x, base, s, (130, 170, 80), (120, 165, 70), 105)


def pepper_tree(d, x, base, s):
    _weeping(d, x, base, s, (90, 135, 70), (85, 130, 65), 55)


def ginkgo(d, x, base, s):  # fan-shaped leaves on a yellow-green crown
    _broadleaf(d, x, base, s, (150, 175, 60), rx=40, ry=52)
    for dx, dy in ((-18, -140), (14, -120), (-6, -100), (20, -155)):
        d.pieslice([x + (dx - 8) * s, base + (dy - 8) * s, x + (dx + 8) * s, base + (dy + 8) * s], 200, 340,
                   fill=(210, 200, 60))


def zelkova(d, x, base, s):  # vase-shaped: branches rising in a V to a broad top
    _trunk(d, x, base, s, 40, 7)
    for dx in (-40, -15, 15, 40):
        d.line([(x, base - 40 * s), (x + dx * s, base - 115 * s)], fill=TRUNK, width=_w(s, 4))
    _crown(d, x, base - 135 * s, s, 60, 32, (70, 125, 60))


def locust(d, x, base, s):  # the pagoda tree: a crown in layered tiers
    _trunk(d, x, base, s, 70, 7)
    for k, (rx, ry) in enumerate(((60, 18), (48, 16), (34, 14))):
        _crown(d, x, base - (85 + k * 26) * s, s, rx, ry, (65 + k * 10, 120 + k * 8, 60))


def banyan(d, x, base, s):  # a wide crown over many hanging aerial roots
    _trunk(d, x, base, s, 90, 12)
    _crown(d, x, base - 120 * s, s, 90, 40, (45, 100, 45))
    for k in range(8):
        rx = x + (k - 3.5) * 20 * s
        d.line([(rx, base - 95 * s), (rx, base)], fill=(110, 90, 70), width=_w(s, 2, 1))


def orange(d, x, base, s):  # a rounded crown heavy with fruit
    _broadleaf(d, x, base, s, (60, 120, 50))
    for dx, dy in ((-20, -100), (15, -120), (25, -90), (-28, -125), (0, -140)):
        d.ellipse([x + dx * s - 4 * s, base + dy * s - 4 * s, x + dx * s + 4 * s, base + dy * s + 4 * s],
                  fill=(240, 140, 20))


def olive(d, x, base, s):  # a twisted trunk under a silvery grey-green crown
    d.line([(x, base), (x - 8 * s, base - 35 * s), (x + 6 * s, base - 70 * s)], fill=(110, 95, 75), width=_w(s, 9))
    _crown(d, x + 4 * s, base - 100 * s, s, 50, 35, (150, 168, 140))


def fig(d, x, base, s):  # huge: a thick trunk and a vast crown
    _trunk(d, x, base, s, 80, 16)
    _crown(d, x, base - 135 * s, s, 110, 70, (50, 105, 50))


KINDS: dict[str, Callable[[ImageDraw.ImageDraw, float, float, float], None]] = {
    f.__name__: f for f in (palm, fan_palm, coconut_palm, date_palm, cypress, spruce, pine, araucaria, umbrella_pine,
                            acacia, rain_tree, flamboyant, banana, plane, linden, maple, chestnut, birch, camphor,
                            frangipani, jacaranda, eucalyptus, willow, pepper_tree, ginkgo, zelkova, locust, banyan,
                            orange, olive, fig)
}


def draw_tree(draw: ImageDraw.ImageDraw, kind: str, x: float, base: float, scale: float) -> bool:
    """Draw a tree of ``kind``; True when that kind has its own drawing, False for a generic broadleaf."""
    fn = KINDS.get(kind)
    if fn is None:
        _broadleaf(draw, x, base, scale, GREEN)
        return False
    fn(draw, x, base, scale)
    return True
