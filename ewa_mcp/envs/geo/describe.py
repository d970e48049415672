"""Text descriptions of views for text-only agents.

A description states what a sighted visitor would see — building style, traffic side, road
markings, vehicles, trees, sky — and quotes sign and plate text verbatim in its own script.
It never names a country or city except where quoted from a sign.
"""

from __future__ import annotations

from .scene import ShopSign, Vehicle, ViewSpec
from .styles import TREE_WORDS, VEHICLE_WORDS, vehicle_look

SHOP_KIND_LOOKS = {
    "pharmacy": "with a green cross",
    "bakery": "with loaves in the window",
    "cafe": "with small tables outside",
    "restaurant": "with a menu board by the door",
    "bank": "with a cash machine in the wall",
    "hotel": "over a glass entrance",
    "grocery": "with crates of fruit and vegetables outside",
    "books": "with books in the window",
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


def describe_view(spec: ViewSpec) -> str:
    s: list[str] = []
    heading = spec.heading
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
    s.append(f"Buildings: {spec.arch.description}.")

    if not spec.pedestrian:
        other = "left" if spec.drive == "right" else "right"
        if spec.composition == "along":
            s.append(f"Traffic keeps to the {spec.drive}: cars on the {spec.drive}-hand side of the road drive away "
                     f"from you showing red tail lights, oncoming cars use the {other}-hand side.")
        else:
            near = "left to right" if spec.drive == "right" else "right to left"
            far = "right to left" if spec.drive == "right" else "left to right"
            s.append(f"In the lane nearer to you traffic moves from your {near.replace(' to ', ' to your ')}; "
                     f"in the far lane from your {far.replace(' to ', ' to your ')}.")
        marks = []
        if spec.centre_line:
            marks.append(f"a broken {spec.centre_line} stripe divides the two directions")
        if spec.edge_line and spec.edge_line != "white":
            marks.append(f"solid {spec.edge_line} stripes run along both kerbs")
        if marks:
            s.append("Paint on the road: " + "; ".join(marks) + ".")

    plated = [v for v in spec.vehicles if v.plate is not None and v.facing == "away"]
    if plated:
        s.append(_plate_sentence(plated[0]))
    specials = [v for v in spec.vehicles if v.kind != "car"]
    if specials:
        s.append("Also in view: " + "; ".join(_vehicle_phrase(v) for v in specials) + ".")
    if spec.tram_tracks:
        s.append("Rail tracks are set into the road under an overhead wire.")
    if spec.skytrain:
        s.append(VEHICLE_WORDS["skytrain"][0].upper() + VEHICLE_WORDS["skytrain"][1:] + ".")
    if spec.arch.wires:
        s.append("Dense bundles of overhead cables hang from poles.")

    if spec.trees:
        kinds = []
        for kind, _side, _depth in spec.trees:
            words = TREE_WORDS.get(kind, kind)
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
        s.append("Shop signs: " + "; ".join(parts) + ".")
    if spec.street_sign is not None:
        ss = spec.street_sign
        s.append(f"A street-name sign ({ss.style.words}) on the {ss.side} reads '{_quote(ss.lines)}'.")
    s.append(f"Sky: {spec.climate.sky_words}.")
    return " ".join(s)
