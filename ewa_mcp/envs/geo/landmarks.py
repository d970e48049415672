"""Simple, recognisable silhouettes of the landmarks of the easy locations."""

from __future__ import annotations

import random
from collections.abc import Callable

from PIL import ImageDraw

STONE = (214, 204, 180)
DARK = (70, 70, 72)
GOLD = (212, 175, 55)
BRONZE = (90, 80, 60)
CX = 300

Draw = ImageDraw.ImageDraw


def _obelisk(d: Draw, x: float, base: float, height: float, width: float, colour=STONE, tip=GOLD) -> None:
    top = base - height
    d.polygon([(x - width / 2, base), (x + width / 2, base), (x + width * 0.32, top + width * 0.6),
               (x - width * 0.32, top + width * 0.6)], fill=colour, outline=(120, 110, 95))
    d.polygon([(x - width * 0.32, top + width * 0.6), (x + width * 0.32, top + width * 0.6), (x, top)], fill=tip)
    for i in range(6):  # hieroglyph bands
        y = base - height * (0.15 + i * 0.12)
        d.line([(x - width * 0.2, y), (x + width * 0.2, y)], fill=(150, 135, 110))


def _statue_on_plinth(d: Draw, x: float, base: float, scale: float, horse: bool, colour=BRONZE) -> None:
    d.rectangle([x - 30 * scale, base - 40 * scale, x + 30 * scale, base], fill=STONE, outline=(120, 110, 95))
    if horse:
        d.ellipse([x - 28 * scale, base - 75 * scale, x + 22 * scale, base - 50 * scale], fill=colour)
        for dx in (-20, -10, 8, 16):
            d.line([(x + dx * scale, base - 55 * scale), (x + dx * scale, base - 40 * scale)], fill=colour,
                   width=max(1, int(3 * scale)))
        d.line([(x + 20 * scale, base - 70 * scale), (x + 30 * scale, base - 88 * scale)], fill=colour,
               width=max(2, int(7 * scale)))
        d.rectangle([x - 8 * scale, base - 100 * scale, x + 2 * scale, base - 72 * scale], fill=colour)
        d.ellipse([x - 9 * scale, base - 112 * scale, x + 3 * scale, base - 100 * scale], fill=colour)
    else:
        d.rectangle([x - 10 * scale, base - 90 * scale, x + 10 * scale, base - 40 * scale], fill=colour)
        d.ellipse([x - 8 * scale, base - 104 * scale, x + 8 * scale, base - 88 * scale], fill=colour)


def _building_band(d: Draw, base: float, height: float, colour, arches: bool, x0: float = 0, x1: float = 600) -> None:
    d.rectangle([x0, base - height, x1, base], fill=colour, outline=(110, 100, 90))
    step = 22
    for x in range(int(x0) + 6, int(x1) - 10, step):
        if arches:
            d.chord([x, base - 24, x + 16, base - 2], 180, 360, fill=(80, 70, 60))
            d.rectangle([x, base - 14, x + 16, base], fill=(80, 70, 60))
        for f in range(1, int(height // 22)):
            d.rectangle([x + 4, base - 24 - f * 22, x + 12, base - 12 - f * 22], fill=(90, 80, 70))


def _dome(d: Draw, x: float, base: float, r: float, colour) -> None:
    d.pieslice([x - r, base - r, x + r, base + r], 180, 360, fill=colour, outline=(90, 90, 90))


def _minaret(d: Draw, x: float, base: float, height: float, width: float, colour=(235, 232, 225)) -> None:
    d.rectangle([x - width / 2, base - height, x + width / 2, base], fill=colour, outline=(140, 140, 140))
    d.polygon([(x - width / 2, base - height), (x + width / 2, base - height), (x, base - height - width * 3)],
              fill=(120, 120, 130))
    d.rectangle([x - width * 0.8, base - height * 0.7, x + width * 0.8, base - height * 0.67], fill=(150, 150, 150))


def obelisk(d: Draw, rng: random.Random, h: int) -> None:
    for x in (150, 450):  # fountains
        d.ellipse([x - 45, h - 8, x + 45, h + 14], fill=(120, 150, 170), outline=(90, 90, 90))
        d.rectangle([x - 6, h - 50, x + 6, h], fill=BRONZE)
        d.ellipse([x - 22, h - 60, x + 22, h - 45], fill=BRONZE)
    _obelisk(d, CX, h + 10, 210, 30)
    d.rectangle([CX - 26, h - 10, CX + 26, h + 12], fill=STONE)


def clock_tower(d: Draw, rng: random.Random, h: int) -> None:
    colour = (95, 92, 88)
    _building_band(d, h, 120, colour, arches=True, x0=60, x1=540)
    for x in range(70, 540, 40):
        d.polygon([(x, h - 120), (x + 10, h - 150), (x + 20, h - 120)], fill=colour)
    d.rectangle([CX - 30, h - 230, CX + 30, h - 120], fill=colour, outline=(60, 60, 60))
    d.ellipse([CX - 18, h - 215, CX + 18, h - 179], fill=(235, 230, 210), outline=(30, 30, 30))
    d.polygon([(CX - 30, h - 230), (CX + 30, h - 230), (CX, h - 245 - 20)], fill=(80, 110, 90))
    d.rectangle([CX + 150, h - 150, CX + 162, h + 5], fill=(200, 200, 195))
    d.ellipse([CX + 146, h - 172, CX + 166, h - 148], fill=GOLD)


def equestrian_square(d: Draw, rng: random.Random, h: int) -> None:
    _building_band(d, h, 110, (150, 70, 50), arches=True, x0=0, x1=600)
    for x in (60, 540):
        d.polygon([(x - 12, h - 110), (x + 12, h - 110), (x, h - 160)], fill=(60, 65, 75))
    _statue_on_plinth(d, CX, h + 40, 1.2, horse=True)


def basilica_spires(d: Draw, rng: random.Random, h: int) -> None:
    colour = (200, 185, 150)
    for i, (dx, height) in enumerate(((-120, 200), (-70, 225), (-20, 240), (30, 240), (80, 225), (130, 200))):
        x = CX + dx
        d.polygon([(x - 18, h - 40), (x + 18, h - 40), (x + 6, h - height), (x - 6, h - height)], fill=colour,
                  outline=(140, 125, 95))
        for y in range(int(h - height + 20), int(h - 40), 14):
            d.line([(x - 8, y), (x + 8, y)], fill=(160, 145, 110))
        d.ellipse([x - 5, h - height - 10, x + 5, h - height], fill=(200, 60, 60) if i % 2 else GOLD)
    d.rectangle([CX - 170, h - 60, CX + 170, h], fill=colour)
    d.line([(CX + 200, h), (CX + 200, h - 230)], fill=(220, 180, 40), width=4)  # crane
    d.line([(CX + 120, h - 225), (CX + 280, h - 225)], fill=(220, 180, 40), width=4)


def fountain_obelisk(d: Draw, rng: random.Random, h: int) -> None:
    _building_band(d, h, 90, (210, 150, 90), arches=False)
    d.rectangle([CX + 80, h - 130, CX + 200, h - 90], fill=(225, 210, 180))
    _dome(d, CX + 140, h - 130, 45, (180, 170, 150))
    for x in (CX + 88, CX + 192):
        d.rectangle([x - 8, h - 170, x + 8, h - 90], fill=(225, 210, 180))
    d.ellipse([CX - 110, h + 10, CX + 110, h + 50], fill=(120, 160, 180), outline=(230, 230, 230))
    d.polygon([(CX - 60, h + 30), (CX - 20, h - 30), (CX + 20, h - 30), (CX + 60, h + 30)], fill=(210, 205, 195))
    _obelisk(d, CX, h - 28, 130, 18, tip=(200, 190, 170))


def column(d: Draw, rng: random.Random, h: int) -> None:
    d.rectangle([60, h - 95, 540, h - 10], fill=(200, 190, 165))
    for x in range(180, 430, 25):
        d.rectangle([x, h - 80, x + 8, h - 20], fill=(230, 225, 210))
    d.polygon([(170, h - 80), (CX, h - 115), (440, h - 80)], fill=(200, 190, 165))
    _dome(d, CX, h - 95, 28, (130, 140, 130))
    d.rectangle([CX - 12, h - 235, CX + 12, h + 20], fill=(200, 195, 185), outline=(140, 135, 125))
    d.rectangle([CX - 18, h - 245, CX + 18, h - 232], fill=(170, 165, 150))
    d.rectangle([CX - 5, h - 270, CX + 5, h - 245], fill=DARK)
    d.rectangle([CX - 40, h + 10, CX + 40, h + 40], fill=STONE)
    for dx in (-70, 70):
        d.ellipse([CX + dx - 25, h + 25, CX + dx + 25, h + 45], fill=(40, 40, 40))
        d.ellipse([CX + dx - 8, h + 12, CX + dx + 12, h + 30], fill=(40, 40, 40))


def spire(d: Draw, rng: random.Random, h: int) -> None:
    _building_band(d, h, 70, (190, 170, 150), arches=False, x0=0, x1=240)
    _building_band(d, h, 80, (160, 150, 140), arches=False, x0=360, x1=600)
    d.polygon([(CX - 5, h + 20), (CX + 5, h + 20), (CX + 1, 5), (CX - 1, 5)], fill=(200, 205, 210),
              outline=(150, 155, 160))
    for x in (0, 600):
        d.line([(x, h + 60), (CX, h)], fill=(110, 110, 110), width=2)


def arch_square(d: Draw, rng: random.Random, h: int) -> None:
    _building_band(d, h, 95, (225, 190, 70), arches=True)
    d.rectangle([CX - 60, h - 170, CX + 60, h], fill=(225, 215, 190), outline=(150, 140, 120))
    d.chord([CX - 28, h - 110, CX + 28, h - 20], 180, 360, fill=(70, 65, 60))
    d.rectangle([CX - 28, h - 65, CX + 28, h], fill=(70, 65, 60))
    for dx in (-42, 42):
        d.rectangle([CX + dx - 6, h - 150, CX + dx + 6, h - 10], fill=(235, 228, 210))
    d.rectangle([CX - 18, h - 195, CX + 18, h - 170], fill=BRONZE)
    _statue_on_plinth(d, CX - 150, h + 45, 0.9, horse=True, colour=(60, 95, 80))


def museum_statue(d: Draw, rng: random.Random, h: int) -> None:
    _building_band(d, h, 80, (200, 185, 160), arches=False, x0=120, x1=480)
    _dome(d, CX, h - 80, 45, (90, 120, 110))
    d.rectangle([CX - 4, h - 150, CX + 4, h - 125], fill=GOLD)
    for x in range(140, 470, 40):
        d.rectangle([x, h - 70, x + 10, h - 10], fill=(230, 222, 205))
    for side in (-1, 1):
        _building_band(d, h + 30, 150, (205, 190, 170), arches=False,
                       x0=0 if side < 0 else 480, x1=120 if side < 0 else 600)
    _statue_on_plinth(d, CX, h + 60, 1.1, horse=True, colour=(50, 70, 60))


def onion_domes(d: Draw, rng: random.Random, h: int) -> None:
    d.rectangle([0, h - 60, 260, h], fill=(150, 50, 40))
    for x in range(0, 260, 18):
        d.rectangle([x, h - 70, x + 10, h - 60], fill=(150, 50, 40))
    d.rectangle([160, h - 140, 200, h - 60], fill=(150, 50, 40))
    d.polygon([(160, h - 140), (200, h - 140), (180, h - 185)], fill=(60, 110, 70))
    d.ellipse([174, h - 196, 186, h - 184], fill=(200, 30, 30))
    colours = [(200, 60, 50), (60, 130, 80), (230, 180, 40), (60, 90, 170), (200, 60, 50)]
    for i, (dx, height, r) in enumerate(((-80, 120, 22), (-40, 150, 26), (0, 190, 30), (45, 150, 26), (85, 115, 22))):
        x = 400 + dx
        d.rectangle([x - r * 0.6, h - height, x + r * 0.6, h - 30], fill=(190, 90, 70))
        d.ellipse([x - r, h - height - r * 1.5, x + r, h - height + r * 0.3], fill=colours[i])
        for s in range(-1, 2):
            d.line([(x + s * r * 0.5, h - height - r * 1.4), (x + s * r * 0.5, h - height + r * 0.2)],
                   fill=(250, 250, 250), width=2)
        d.polygon([(x - 4, h - height - r * 1.4), (x + 4, h - height - r * 1.4), (x, h - height - r * 2.2)],
                  fill=GOLD)
    d.rectangle([320, h - 40, 480, h], fill=(190, 90, 70))


def obelisk_mosque(d: Draw, rng: random.Random, h: int) -> None:
    x0 = 330
    d.rectangle([x0, h - 60, x0 + 220, h], fill=(200, 195, 185))
    _dome(d, x0 + 110, h - 60, 70, (150, 155, 165))
    for dx in (40, 180):
        _dome(d, x0 + dx, h - 60, 30, (150, 155, 165))
    for dx in (-10, 230):
        _minaret(d, x0 + dx, h, 190, 10)
    _obelisk(d, 160, h + 25, 170, 22, colour=(190, 150, 140), tip=(190, 150, 140))
    d.rectangle([135, h - 5, 185, h + 25], fill=STONE)


def seated_statue_gate(d: Draw, rng: random.Random, h: int) -> None:
    d.polygon([(80, h - 40), (200, h - 140), (330, h - 60), (420, h - 120), (560, h - 40)], fill=(110, 130, 120))
    d.rectangle([CX - 90, h - 40, CX + 90, h], fill=(170, 160, 150))
    d.polygon([(CX - 110, h - 40), (CX + 110, h - 40), (CX + 80, h - 70), (CX - 80, h - 70)], fill=(60, 70, 70))
    d.rectangle([CX - 60, h - 85, CX + 60, h - 68], fill=(150, 50, 40))
    d.polygon([(CX - 80, h - 85), (CX + 80, h - 85), (CX + 55, h - 105), (CX - 55, h - 105)], fill=(60, 70, 70))
    d.rectangle([CX - 40, h + 40, CX + 40, h + 70], fill=STONE)
    d.rectangle([CX - 26, h - 20, CX + 26, h + 40], fill=GOLD)
    d.ellipse([CX - 14, h - 48, CX + 14, h - 18], fill=GOLD)
    d.rectangle([CX - 40, h + 10, CX + 40, h + 40], fill=GOLD)


def gate_tower(d: Draw, rng: random.Random, h: int) -> None:
    d.rectangle([60, h - 70, 540, h], fill=(170, 40, 40))
    for x in (170, 235, 300, 365, 430):
        d.chord([x - 16, h - 50, x + 16, h - 10], 180, 360, fill=(50, 30, 30))
        d.rectangle([x - 16, h - 30, x + 16, h], fill=(50, 30, 30))
    d.rectangle([CX - 16, h - 62, CX + 16, h - 36], fill=(70, 70, 70))
    d.rectangle([140, h - 120, 460, h - 70], fill=(180, 45, 45))
    for y, inset in ((h - 120, 0), (h - 165, 40)):
        d.polygon([(110 + inset, y), (490 - inset, y), (450 - inset, y - 28), (150 + inset, y - 28)],
                  fill=(225, 180, 40))
    d.rectangle([170, h - 165, 430, h - 148], fill=(180, 45, 45))


def twin_towers(d: Draw, rng: random.Random, h: int) -> None:
    for x in (230, 370):
        for w, top in ((46, 60), (40, 40), (32, 28), (22, 18)):  # setbacks, widest lowest
            d.rectangle([x - w / 2, top, x + w / 2, h], fill=(190, 195, 205), outline=(140, 145, 155))
        d.line([(x, 18), (x, 0)], fill=(160, 165, 175), width=3)
        for y in range(70, h, 8):
            d.line([(x - 22, y), (x + 22, y)], fill=(160, 165, 175))
    d.rectangle([253, 140, 347, 152], fill=(150, 155, 165))


def supertall(d: Draw, rng: random.Random, h: int) -> None:
    for w, top in ((70, 150), (54, 100), (40, 60), (26, 30), (14, 12)):
        d.rectangle([CX - w / 2, top, CX + w / 2, h], fill=(190, 200, 210), outline=(150, 160, 170))
    d.line([(CX, 12), (CX, 0)], fill=(180, 190, 200), width=3)
    for x, height in ((80, 120), (130, 90), (470, 110), (530, 80)):
        d.rectangle([x - 20, h - height, x + 20, h], fill=(150, 165, 180))
    for x in (40, 200, 400, 560):
        d.line([(x, h + 40), (x, h - 40)], fill=(120, 100, 80), width=4)
        d.ellipse([x - 25, h - 55, x + 25, h - 35], fill=(60, 120, 50))


def tower_arch(d: Draw, rng: random.Random, h: int) -> None:
    white = (235, 235, 228)
    d.polygon([(CX - 130, h), (CX - 70, h), (CX - 20, h - 150), (CX - 25, h - 190), (CX - 50, h - 120)], fill=white,
              outline=(170, 170, 165))
    d.polygon([(CX + 130, h), (CX + 70, h), (CX + 20, h - 150), (CX + 25, h - 190), (CX + 50, h - 120)], fill=white,
              outline=(170, 170, 165))
    d.rectangle([CX - 25, h - 215, CX + 25, h - 150], fill=white, outline=(170, 170, 165))
    d.polygon([(CX - 35, h - 215), (CX + 35, h - 215), (CX, h - 240)], fill=(150, 190, 210))
    d.chord([CX - 60, h - 170, CX + 60, h + 40], 180, 360, fill=(130, 150, 170))


def minaret_square(d: Draw, rng: random.Random, h: int) -> None:
    d.rectangle([0, h - 45, 600, h], fill=(190, 100, 70))
    d.rectangle([CX + 60, h - 220, CX + 110, h - 45], fill=(195, 140, 95), outline=(150, 100, 70))
    d.rectangle([CX + 75, h - 250, CX + 95, h - 220], fill=(195, 140, 95))
    d.ellipse([CX + 80, h - 262, CX + 90, h - 250], fill=GOLD)
    for x in range(20, 600, 70):  # stalls with awnings
        colour = rng.choice([(240, 240, 240), (220, 200, 150), (200, 80, 60)])
        d.polygon([(x, h + 20), (x + 50, h + 20), (x + 40, h), (x + 10, h)], fill=colour)
        d.rectangle([x + 5, h + 20, x + 45, h + 40], fill=(120, 80, 50))


def billboards(d: Draw, rng: random.Random, h: int) -> None:
    for x0, x1, top in ((0, 170, 0), (170, 250, 40), (350, 430, 30), (430, 600, 0)):
        d.rectangle([x0, top, x1, h], fill=(60, 60, 70))
        y = top + 8
        while y < h - 30:
            colour = rng.choice([(230, 40, 60), (40, 120, 230), (250, 210, 30), (250, 250, 250), (30, 200, 120)])
            d.rectangle([x0 + 6, y, x1 - 6, y + 40], fill=colour)
            y += 52
    d.polygon([(250, h), (350, h), (330, h - 60), (270, h - 60)], fill=(200, 30, 40))


def flag_cathedral(d: Draw, rng: random.Random, h: int) -> None:
    d.rectangle([340, h - 110, 560, h], fill=(180, 150, 120))
    for x in (350, 530):
        d.rectangle([x - 18, h - 170, x + 18, h - 110], fill=(180, 150, 120))
        _dome(d, x, h - 170, 16, (160, 140, 110))
    _dome(d, 450, h - 110, 30, (160, 140, 110))
    d.rectangle([20, h - 60, 300, h], fill=(170, 90, 70))
    d.line([(200, h + 20), (200, 10)], fill=(180, 180, 180), width=5)
    for i, colour in enumerate(((0, 104, 71), (245, 245, 245), (206, 17, 38))):
        d.rectangle([203 + i * 45, 12, 203 + (i + 1) * 45, 92], fill=colour)
    d.ellipse([255, 40, 271, 62], fill=(140, 100, 50))


def obelisk_avenue(d: Draw, rng: random.Random, h: int) -> None:
    for x0, x1, height in ((0, 130, 140), (130, 230, 110), (370, 470, 120), (470, 600, 150)):
        d.rectangle([x0, h - height, x1, h], fill=(200, 190, 170), outline=(150, 140, 130))
        for f in range(1, height // 20):
            for x in range(x0 + 8, x1 - 8, 18):
                d.rectangle([x, h - f * 20, x + 8, h - f * 20 + 10], fill=(90, 90, 95))
    _obelisk(d, CX, h + 15, 215, 26, colour=(245, 245, 240), tip=(245, 245, 240))
    for y in (h + 40, h + 80, h + 120):
        d.line([(0, y), (600, y)], fill=(245, 245, 245), width=2)


KINDS: dict[str, Callable[[Draw, random.Random, int], None]] = {
    "obelisk": obelisk, "clock_tower": clock_tower, "equestrian_square": equestrian_square,
    "basilica_spires": basilica_spires, "fountain_obelisk": fountain_obelisk, "column": column, "spire": spire,
    "arch_square": arch_square, "museum_statue": museum_statue, "onion_domes": onion_domes,
    "obelisk_mosque": obelisk_mosque, "seated_statue_gate": seated_statue_gate, "gate_tower": gate_tower,
    "twin_towers": twin_towers, "supertall": supertall, "tower_arch": tower_arch,
    "minaret_square": minaret_square, "billboards": billboards, "flag_cathedral": flag_cathedral,
    "obelisk_avenue": obelisk_avenue,
}


def draw_landmark(d: Draw, kind: str, rng: random.Random, horizon: int) -> bool:
    """Draw the landmark of ``kind``; False when no drawing exists for it."""
    fn = KINDS.get(kind)
    if fn is None:
        return False
    fn(d, rng, horizon)
    return True
