"""What one directional view shows: a deterministic scene specification.

The same ``ViewSpec`` drives the Pillow renderer (view_images.py) and the text description for
text-only agents (describe.py), so both observation modes carry exactly the same cues.

Where the cues appear follows the location's difficulty (see locations.py):

=========  ======================  ===========================  ==============================
level      country cues            city cues (plates with a      street-name sign
                                   region, area codes, local
                                   transport)
=========  ======================  ===========================  ==============================
easy       every view              every view                   p0 north (and ahead at others)
city       every view              only after moving (p1..p4)   one step away (p1, p2)
street     every view              every view                   two steps away (p3, p4)
hard       every view              shared ones only (transport,  two steps away (p3, p4)
                                   trees); never a deciding one
=========  ======================  ===========================  ==============================

"hard" is not a cue level but the hard split of hardness.py, over city- and street-level locations.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from ewa_mcp.geometry import DIRECTION_DEG, FOUR_DIRECTIONS, angle_diff
from .cities import City
from .countries import Country, StreetSignStyle
from .hardness import is_hard
from .graph import Standpoint, build_graph
from .languages import SHOP_KINDS, shop_words
from .locations import Landmark, Location
from .plates import PlateStyle
from .seeding import rng_for
from .styles import ARCH, CLIMATE, ArchStyle, Climate, colour_hex

SHOP_COLOURS: tuple[tuple[str, str], ...] = (
    ("#1f5fb0", "#ffffff"), ("#b01818", "#ffffff"), ("#0b6b2e", "#ffffff"), ("#f2c200", "#111111"),
    ("#ffffff", "#111111"), ("#222222", "#f2c200"), ("#6a1b9a", "#ffffff"), ("#ef7d1a", "#111111"),
)


@dataclass(frozen=True)
class Text:
    native: str
    latin: str  # the transliteration drawn when no font covers the native script


@dataclass(frozen=True)
class ShopSign:
    kind: str
    lines: tuple[Text, ...]
    phone: str | None
    side: str  # left / right (along views) or the building index (facade views) as "b0".."b3"
    bg: str
    fg: str


@dataclass(frozen=True)
class StreetSign:
    lines: tuple[Text, ...]
    style: StreetSignStyle
    side: str  # left / right


@dataclass(frozen=True)
class PlateView:
    text: str | None  # None: too far away to read
    caption: str | None
    style: PlateStyle
    rear: bool


@dataclass(frozen=True)
class Vehicle:
    kind: str  # car, taxi, tram, double_decker, minibus, tuk_tuk, ... (styles.VEHICLE_WORDS)
    colour: str
    colour_words: str
    side: str  # along views: left/right/centre of the road; facade views: near/far lane
    facing: str  # away / toward (along views); left / right = direction of travel (facade views)
    depth: float  # 0 = nearest, 1 = vanishing point
    plate: PlateView | None = None


@dataclass(frozen=True)
class Building:
    colour: str
    floors: int


@dataclass(frozen=True)
class ViewSpec:
    location_id: str
    standpoint: str
    heading: str  # north / east / south / west
    composition: str  # along / facade / landmark
    arch_key: str
    arch: ArchStyle
    climate: Climate
    drive: str  # left / right
    pedestrian: bool
    centre_line: str | None
    edge_line: str | None
    buildings_left: tuple[Building, ...]
    buildings_right: tuple[Building, ...]  # facade views use this row for the facing buildings
    trees: tuple[tuple[str, str, float], ...]  # (kind, side, depth)
    shops: tuple[ShopSign, ...]
    street_sign: StreetSign | None
    vehicles: tuple[Vehicle, ...]
    landmark: Landmark | None
    tram_tracks: bool
    skytrain: bool
    clouds: tuple[tuple[float, float, float], ...]  # (x, y, size) in 0..1 units
    city_cues: bool
    seed: int


def _text(native: str, latin: str | None = None) -> Text:
    return Text(native, latin if latin is not None else native)


def _sign_lines(lines: tuple[str, ...]) -> tuple[Text, ...]:
    # Location signs already pair a local-script line with a Latin one where signs do;
    # a line in a script without a font is simply not drawn (fonts.py), never replaced.
    return tuple(_text(line) for line in lines)


def ahead_heading(loc: Location, sp: Standpoint) -> str:
    """The compass view that looks along the street away from the start (towards p3 from p1)."""
    direction = loc.bearing if sp.offset_m >= 0 else (loc.bearing + 180) % 360
    return min(FOUR_DIRECTIONS, key=lambda h: abs(angle_diff(direction, DIRECTION_DEG[h])))


def city_cues_visible(loc: Location, sp: Standpoint) -> bool:
    """Whether the city's cues show here: hard locations show only the shared ones (transport,
    trees, buildings) everywhere and never a deciding one (see hardness.py)."""
    return is_hard(loc) or loc.difficulty != "city" or sp.steps_from_start >= 1


def street_sign_visible(loc: Location, sp: Standpoint, heading: str) -> bool:
    if loc.difficulty == "easy":
        return heading == "north" if sp.steps_from_start == 0 else heading == ahead_heading(loc, sp)
    wanted_steps = 1 if loc.difficulty == "city" and not is_hard(loc) else 2
    return sp.steps_from_start == wanted_steps and heading == ahead_heading(loc, sp)


def _phone(rng, country: Country, city: City) -> str:
    template = country.phone.replace("{a}", city.area_code or "")
    return "".join(str(rng.randrange(10)) if ch == "#" else ch for ch in template)


def _shop_word(loc: Location, code: str, kind: str, slot: str) -> tuple[str, str]:
    """The word a shop of this kind shows in this language here: one of the country's own (languages.
    COUNTRY_WORDS), chosen by a generator of its own so that the view's other draws stay as they were."""
    options = shop_words(loc.country.iso, code, kind)
    return options[0] if len(options) == 1 else rng_for(loc.id, "shop-word", code, kind, slot).choice(options)


def _shop_signs(rng, loc: Location, slots: list[str], with_phone: bool) -> tuple[ShopSign, ...]:
    city, country = loc.city, loc.country
    langs = city.langs or country.langs
    kinds = rng.sample(SHOP_KINDS, k=len(slots))
    phone_slot = rng.randrange(len(slots)) if with_phone else -1
    signs = []
    for i, (slot, kind) in enumerate(zip(slots, kinds, strict=True)):
        lines = [_text(*_shop_word(loc, langs[0], kind, slot))]
        # Bilingual places write a second language under the first on most signs.
        if len(langs) > 1 and rng.random() < 0.7:
            word = _shop_word(loc, langs[rng.randrange(1, len(langs))], kind, slot)
            if word[0] != lines[0].native:
                lines.append(_text(*word))
        bg, fg = SHOP_COLOURS[rng.randrange(len(SHOP_COLOURS))]
        phone = _phone(rng, country, city) if i == phone_slot else None
        signs.append(ShopSign(kind, tuple(lines), phone, slot, bg, fg))
    return tuple(signs)


def _transport(city: City) -> list[tuple[str, str]]:
    out = []
    for feature in city.transport:
        kind, _, colour = feature.partition(":")
        out.append((kind, colour))
    return out


def _plate(rng, style: PlateStyle, region: str | None, legible: bool, rear: bool) -> PlateView:
    text = style.text(rng, region) if legible else None
    return PlateView(text, style.caption_text(region) if legible else None, style, rear)


def _vehicles(rng, loc: Location, composition: str, city_cues: bool) -> tuple[Vehicle, ...]:
    country, city = loc.country, loc.city
    plate_style = country.plate
    # A regional plate is a deciding cue: legible only where city cues show, never at hard locations.
    region_ok = (city_cues and not is_hard(loc)) or not plate_style.has_region
    transport = _transport(city) if city_cues else []
    vehicles: list[Vehicle] = []
    car_colours = (("#d9d9d9", "silver"), ("#f4f4f4", "white"), ("#222222", "black"), ("#8b1e1e", "dark red"),
                   ("#24407a", "dark blue"), ("#6d6d6d", "grey"))
    if loc.pedestrian:
        # Only rail vehicles and bicycles use pedestrian streets.
        for kind, colour in transport:
            if kind in ("tram", "bicycles"):
                side = "centre" if composition == "along" else "far"
                facing = rng.choice(["away", "toward"]) if composition == "along" else rng.choice(["left", "right"])
                vehicles.append(Vehicle(kind, colour_hex(colour), colour, side, facing, 0.35))
        return tuple(vehicles)

    drive_side = country.drive
    other_side = "left" if drive_side == "right" else "right"
    if composition == "along":
        near_depth = 0.12 if region_ok else 0.5
        colour, words = rng.choice(car_colours)
        vehicles.append(Vehicle("car", colour, words, drive_side, "away", near_depth,
                                _plate(rng, plate_style, city.plate_region, region_ok, rear=True)))
        colour, words = rng.choice(car_colours)
        vehicles.append(Vehicle("car", colour, words, other_side, "toward", 0.45,
                                _plate(rng, plate_style, city.plate_region, False, rear=False)))
        for depth in (0.7, 0.82):
            colour, words = rng.choice(car_colours)
            side = rng.choice([drive_side, other_side])
            vehicles.append(Vehicle("car", colour, words, side, "away" if side == drive_side else "toward", depth))
    else:
        # Facing across the street: near-lane traffic keeps to the driving side, so with
        # right-hand traffic it moves from the viewer's left to right.
        near_dir = "right" if drive_side == "right" else "left"
        far_dir = "left" if near_dir == "right" else "right"
        colour, words = rng.choice(car_colours)
        vehicles.append(Vehicle("car", colour, words, "near", near_dir, 0.1))
        colour, words = rng.choice(car_colours)
        vehicles.append(Vehicle("car", colour, words, "far", far_dir, 0.3))
    for kind, colour in transport[:2]:
        if kind in ("skytrain",):
            continue
        if composition == "along":
            side = "centre" if kind == "tram" else rng.choice([drive_side, other_side])
            facing = "away" if side == drive_side else "toward" if side == other_side else rng.choice(["away",
                                                                                                         "toward"])
            vehicles.append(Vehicle(kind, colour_hex(colour), colour, side, facing, rng.uniform(0.3, 0.55)))
        else:
            lane = rng.choice(["near", "far"])
            near_dir = "right" if drive_side == "right" else "left"
            facing = near_dir if lane == "near" else ("left" if near_dir == "right" else "right")
            vehicles.append(Vehicle(kind, colour_hex(colour), colour, lane, facing, 0.2))
    return tuple(vehicles)


def _buildings(rng, arch: ArchStyle, n: int) -> tuple[Building, ...]:
    lo, hi = arch.floors
    return tuple(Building(rng.choice(arch.palette), rng.randint(lo, hi)) for _ in range(n))


def _trees(rng, loc: Location, climate: Climate, composition: str) -> tuple[tuple[str, str, float], ...]:
    kinds = loc.city.trees or climate.trees
    count = rng.randint(1, 3) if composition != "landmark" else rng.randint(0, 2)
    sides = ("left", "right") if composition == "along" else ("front",)
    trees = []
    for _ in range(count):
        trees.append((rng.choice(kinds), rng.choice(sides), round(rng.uniform(0.05, 0.6), 3)))
    return tuple(sorted(trees, key=lambda t: -t[2]))  # far first, so near trees draw on top


def deciding_city_cues(loc: Location, spec: ViewSpec) -> list[str]:
    """What in a composed view names one city by itself: an area-coded telephone number (in a country
    whose numbers carry one) and a legible regional number plate. A landmark names its city too; that is
    the easy level's own cue (``spec.landmark``)."""
    found = []
    if "{a}" in loc.country.phone:
        found += [f"phone {s.phone}" for s in spec.shops if s.phone]
    found += [f"plate {v.plate.text}" for v in spec.vehicles
              if v.plate and v.plate.text and v.plate.style.has_region]
    return found


@lru_cache(maxsize=4096)
def compose_view(loc: Location, standpoint_id: str, heading: str) -> ViewSpec:
    if heading not in FOUR_DIRECTIONS:
        raise ValueError(f"heading must be one of {FOUR_DIRECTIONS}, not {heading!r}")
    graph = build_graph(loc)
    sp = graph[standpoint_id]
    rng = rng_for("view", loc.id, standpoint_id, heading)
    city, country = loc.city, loc.country
    arch_key = city.arch or country.arch
    arch = ARCH[arch_key]
    climate = CLIMATE[city.climate]

    rel = abs(angle_diff(DIRECTION_DEG[heading], loc.bearing))
    along = min(rel, 180 - rel) <= 45
    composition = "landmark" if (loc.landmark and heading == "north") else ("along" if along else "facade")
    city_cues = city_cues_visible(loc, sp)

    if composition == "along":
        slots = ["left", "right"] + rng.sample(["left", "right"], k=rng.randint(0, 2))
    elif composition == "facade":
        slots = [f"b{i}" for i in rng.sample(range(4), k=rng.randint(2, 4))]
    else:
        slots = ["left", "right"][: rng.randint(1, 2)]
    area_coded = "{a}" in country.phone
    deciding = city_cues and not is_hard(loc)
    roll = rng.random()
    # Where the city's cues show, an area-coded number always does (the difficulty table promises
    # a city cue in those views); elsewhere most shop signs carry a number without one.
    with_phone = (deciding or not area_coded) and (roll < 0.85 or (deciding and area_coded))

    sign = None
    if street_sign_visible(loc, sp, heading):
        style = country.sign if is_hard(loc) else (city.sign or country.sign)
        sign = StreetSign(_sign_lines(loc.sign), style, rng.choice(["left", "right"]))

    transport_kinds = {k for k, _ in _transport(city)} if city_cues else set()
    return ViewSpec(
        location_id=loc.id,
        standpoint=standpoint_id,
        heading=heading,
        composition=composition,
        arch_key=arch_key,
        arch=arch,
        climate=climate,
        drive=country.drive,
        pedestrian=loc.pedestrian,
        centre_line=None if loc.pedestrian else country.centre_line,
        edge_line=None if loc.pedestrian else country.edge_line,
        buildings_left=_buildings(rng, arch, 4),
        buildings_right=_buildings(rng, arch, 4),
        trees=_trees(rng, loc, climate, composition),
        shops=_shop_signs(rng, loc, slots, with_phone),
        street_sign=sign,
        vehicles=_vehicles(rng, loc, composition, city_cues),
        landmark=loc.landmark if composition == "landmark" else None,
        tram_tracks="tram" in transport_kinds and composition != "landmark",
        skytrain="skytrain" in transport_kinds and composition == "along",
        clouds=tuple((rng.random(), rng.uniform(0.05, 0.6), rng.uniform(0.5, 1.2)) for _ in range(climate.clouds)),
        city_cues=city_cues,
        seed=rng.randrange(2**31),
    )
