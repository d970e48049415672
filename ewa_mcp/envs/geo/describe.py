"""Text descriptions of views for text-only agents.

A description states what a sighted visitor would see — building style, traffic side, road
markings, vehicles, trees, sky — and quotes sign and plate text verbatim in its own script.
It never names a country or city except where quoted from a sign.
"""

from __future__ import annotations

from ewa_mcp.geometry import FOUR_DIRECTIONS
from .scene import ShopSign, Vehicle, ViewSpec
from .styles import TREE_WORDS, VEHICLE_WORDS, vehicle_look

# Each kind's sign carries a pictogram at its left end (view_images.shop_pictogram draws it).
SHOP_KIND_LOOKS = {
    "pharmacy": "with a green cross",
    "bakery": "with a loaf of bread pictured on the sign",
    "cafe": "with a coffee cup pictured on the sign",
    "restaurant": "with a knife and fork pictured on the sign",
    "bank": "with a gold coin pictured on the sign",
    "hotel": "with a bed pictured on the sign",
    "grocery": "with a red apple pictured on the sign",
    "books": "with an open book pictured on the sign",
}


def _quote(lines) -> str:
    return " / ".join(f"{t.native}" for t in lines)


def _shop(sign: ShopSign, where: str) -> str:
    text = f"'{_quote(sign.lines)}' {where} {SHOP_KIND_LOOKS[sign.kind]}"
    if sign.phone:
        text += f", with the phone number '{sign.phone}'"
    return text


def _vehicle_phrase(v: Vehicle) -> str:
    if v.kind not in VEHICLE_WORDS:
        return f"a {v.colour_words} car"
    return vehicle_look(v.kind, v.colour_words or "")


def _plate_sentence(v: Vehicle) -> str:
    assert v.plate is not None
    p = v.plate
    which = "rear" if p.rear else "front"
    colours = p.style.describe_colours(rear=p.rear)
    if p.text is None:
        return f"The cars are too far away to read their number plates (each {which} plate is a {colours})."
    caption = f" under the heading '{p.caption}'" if p.caption else ""
    return (f"The nearest car, a {v.colour_words} saloon, has a {which} number plate: a {colours}, "
            f"reading '{p.text}'{caption}.")


def plate_cues(v: Vehicle) -> set[str]:
    """The cue ids of a car's number plate: its colours (front or rear), and its text when legible."""
    assert v.plate is not None
    p = v.plate
    out = {f"plate_colours:{p.style.describe_colours(rear=p.rear)}"}
    if p.text is not None:
        out.add(f"plate_text:{p.text}")
        if p.caption:
            out.add(f"plate_caption:{p.caption}")
    return out


def shop_cues(sign: ShopSign) -> set[str]:
    """The cue ids of a shop sign: its kind's look and each line's text, in its own script."""
    out = {f"shop:{sign.kind}"} | {f"sign_text:{t.native}" for t in sign.lines}
    if sign.phone:
        out.add(f"phone:{sign.phone}")
    return out


def facade_lanes(heading: str, drive: str) -> tuple[tuple[str, str, str], tuple[str, str, str]]:
    """(from, to, compass) of the near and the far lane's traffic in a view across the street.

    The view looks across the street from the kerb behind the viewer, so the near lane is the one on the
    viewer's side. Traffic keeping to the right has that kerb on its right: it moves to the viewer's
    right, which is the facing turned a quarter clockwise (facing north, eastward). Turned round at the
    same standpoint, the view looks across from the other kerb: the near lane is the other lane, and it
    too moves left to right, but westward; the compass words say which lane is which."""
    turn = 90 if drive == "right" else 270
    near_to = FOUR_DIRECTIONS[(FOUR_DIRECTIONS.index(heading) + turn // 90) % 4]
    far_to = FOUR_DIRECTIONS[(FOUR_DIRECTIONS.index(near_to) + 2) % 4]
    if drive == "right":
        return ("left", "right", f"{near_to}ward"), ("right", "left", f"{far_to}ward")
    return ("right", "left", f"{near_to}ward"), ("left", "right", f"{far_to}ward")


def describe_view(spec: ViewSpec) -> str:
    return describe_view_cues(spec)[0]


def describe_view_cues(spec: ViewSpec) -> tuple[str, frozenset[str]]:
    """The description and the ids of the cues it names (scene.py's cue ids; the renderer reports the ids
    it draws, and a test checks that every cue the text names is drawn)."""
    s: list[str] = []
    cues: set[str] = {f"composition:{spec.composition}", f"arch:{spec.arch_key}", f"sky:{spec.climate.sky_words}"}
    heading = spec.heading
    if spec.pedestrian:
        cues.add("pedestrian")
    if spec.composition == "along":
        kind = "a pedestrian street paved wall to wall" if spec.pedestrian else "a two-way street"
        s.append(f"Looking {heading} along {kind}.")
    elif spec.composition == "facade":
        kind = "the pedestrian street" if spec.pedestrian else "the street"
        s.append(f"Looking {heading} across {kind} at the buildings opposite.")
    else:
        s.append(f"Looking {heading} across a large open square.")
    if spec.landmark is not None:
        s.append(spec.landmark.description[0].upper() + spec.landmark.description[1:] + ".")
        cues.add(f"landmark:{spec.landmark.kind}")
    s.append(f"Buildings: {spec.arch.description}.")

    if not spec.pedestrian:
        cues.add(f"drive:{spec.drive}")
        other = "left" if spec.drive == "right" else "right"
        if spec.composition == "along":
            s.append(f"Traffic keeps to the {spec.drive}: cars on the {spec.drive}-hand side of the road drive away "
                     f"from you showing red tail lights, oncoming cars use the {other}-hand side.")
        else:
            near, far = facade_lanes(spec.heading, spec.drive)
            s.append(f"In the lane nearer to you traffic moves from your {near[0]} to your {near[1]} "
                     f"({near[2]}); in the far lane from your {far[0]} to your {far[1]} ({far[2]}).")
        marks = []
        if spec.centre_line:
            marks.append(f"a broken {spec.centre_line} stripe divides the two directions")
            cues.add(f"centre_line:{spec.centre_line}")
        if spec.edge_line and spec.edge_line != "white":
            marks.append(f"solid {spec.edge_line} stripes run along both kerbs")
            cues.add(f"edge_line:{spec.edge_line}")
        if marks:
            s.append("Paint on the road: " + "; ".join(marks) + ".")

    plated = [v for v in spec.vehicles if v.plate is not None and v.facing == "away"]
    if plated:
        s.append(_plate_sentence(plated[0]))
        cues |= plate_cues(plated[0])
    specials = [v for v in spec.vehicles if v.kind != "car"]
    if specials:
        s.append("Also in view: " + "; ".join(_vehicle_phrase(v) for v in specials) + ".")
        cues |= {f"vehicle:{v.kind}" for v in specials}
    if spec.tram_tracks:
        s.append("Rail tracks are set into the road under an overhead wire.")
        cues.add("tram_tracks")
    if spec.skytrain:
        s.append(VEHICLE_WORDS["skytrain"][0].upper() + VEHICLE_WORDS["skytrain"][1:] + ".")
        cues.add("skytrain")
    if spec.arch.wires:
        s.append("Dense bundles of overhead cables hang from poles.")
        cues.add("wires")

    if spec.trees:
        kinds = []
        for kind, _side, _depth in spec.trees:
            words = TREE_WORDS.get(kind, kind)
            cues.add(f"tree:{kind}")
            if words not in kinds:
                kinds.append(words)
        s.append("Trees: " + ", ".join(kinds) + ".")

    if spec.shops:
        parts = []
        for sign in spec.shops:
            if sign.side in ("left", "right"):
                where = f"on the {sign.side}"
            else:
                where = f"on building {int(sign.side[1:]) + 1} from the left"
            parts.append(_shop(sign, where))
            cues |= shop_cues(sign)
        s.append("Shop signs: " + "; ".join(parts) + ".")
    if spec.street_sign is not None:
        ss = spec.street_sign
        s.append(f"A street-name sign ({ss.style.words}) on the {ss.side} reads '{_quote(ss.lines)}'.")
        cues |= {f"street_sign_text:{t.native}" for t in ss.lines} | {f"street_sign_style:{ss.style.words}"}
    s.append(f"Sky: {spec.climate.sky_words}.")
    return " ".join(s), frozenset(cues)
