"""A labelled top-down picture of the kitchen, drawn from AI2-THOR metadata with Pillow.

It needs nothing but the metadata (objects' boxes, the agent pose, scene bounds) and the
reachable positions, so it draws any backend's kitchen. Furniture is drawn as boxes, small
objects as dots; the agent is an arrow with its view cone. Every object that can be seen from
above (not shut in a closed receptacle) carries its handle — objects in reach first and in bold
blue, then the rest nearest first — placed so that no two labels overlap: a label that finds no
free spot near its object is left out (the side panel still lists everything in reach).
A side panel lists what is held and what is in reach with their states.
"""

from __future__ import annotations

import io
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from PIL import Image, ImageDraw, ImageFont

from .vocabulary import FOOD_TYPES, PIECE_OF

_FURNITURE_COLOURS = {
    "CounterTop": (214, 201, 178), "DiningTable": (190, 150, 110), "Shelf": (170, 140, 110),
    "Cabinet": (160, 120, 80), "Drawer": (185, 145, 100), "Fridge": (200, 215, 230), "Microwave": (90, 90, 100),
    "StoveBurner": (60, 60, 60), "StoveKnob": (30, 30, 30), "Sink": (170, 185, 195), "SinkBasin": (120, 160, 200),
    "Toaster": (150, 150, 160), "CoffeeMachine": (80, 60, 50), "GarbageCan": (100, 120, 100),
}
_FOOD_COLOURS = {
    "Apple": (200, 30, 40), "Bread": (205, 160, 90), "Egg": (245, 240, 225), "Lettuce": (90, 170, 70),
    "Potato": (170, 130, 80), "Tomato": (230, 60, 40),
}
# Lower cabinets and drawers sit under the counter top, so the top is drawn over them.
_DRAW_ORDER = ["Floor", "Cabinet", "Drawer", "DiningTable", "Shelf", "CounterTop", "Fridge", "Sink", "SinkBasin",
               "StoveBurner", "StoveKnob", "GarbageCan", "Microwave", "Toaster", "CoffeeMachine"]


@lru_cache(maxsize=4)
def _font(size: int) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    try:
        return ImageFont.load_default(size=size)
    except TypeError:  # older Pillow without sized default fonts
        return ImageFont.load_default()


def render_topdown(
    metadata: dict[str, Any],
    reachable: Iterable[tuple[float, float]],
    *,
    width: int = 640,
    height: int = 480,
    label: Callable[[str], str] | None = None,
    panel: bool = True,
) -> Image.Image:
    label = label or (lambda object_id: object_id.split("|")[0])
    objects = metadata.get("objects") or []
    agent = metadata.get("agent") or {}
    bounds = metadata.get("sceneBounds") or {}
    centre = bounds.get("center") or {"x": 0.0, "z": 0.0}
    size = bounds.get("size") or {"x": 6.0, "z": 6.0}
    map_w = height if panel and width > height else width
    scale = min((map_w - 20) / max(size["x"], 0.5), (height - 20) / max(size["z"], 0.5))
    ox = map_w / 2 - centre["x"] * scale
    oz = height / 2 + centre["z"] * scale  # +z (north) is up in the picture

    def px(x: float, z: float) -> tuple[float, float]:
        return (ox + x * scale, oz - z * scale)

    image = Image.new("RGB", (width, height), (245, 245, 240))
    draw = ImageDraw.Draw(image)
    x0, y0 = px(centre["x"] - size["x"] / 2, centre["z"] + size["z"] / 2)
    x1, y1 = px(centre["x"] + size["x"] / 2, centre["z"] - size["z"] / 2)
    draw.rectangle([x0, y0, x1, y1], fill=(235, 232, 222), outline=(60, 60, 60), width=3)
    dot = max(1.0, scale * 0.03)
    for x, z in reachable:
        cx, cz = px(x, z)
        draw.ellipse([cx - dot, cz - dot, cx + dot, cz + dot], fill=(205, 205, 195))

    small = _font(10)
    labels: list[Label] = []
    by_id = {o["objectId"]: o for o in objects}
    furniture = [o for o in objects if not o.get("pickupable") and o["objectType"] != "Floor"]
    furniture.sort(key=lambda o: _DRAW_ORDER.index(o["objectType"]) if o["objectType"] in _DRAW_ORDER else 99)
    for obj in furniture:
        box = obj.get("axisAlignedBoundingBox") or {}
        c, s = box.get("center"), box.get("size")
        if not c or not s:
            continue
        a = px(c["x"] - s["x"] / 2, c["z"] + s["z"] / 2)
        b = px(c["x"] + s["x"] / 2, c["z"] - s["z"] / 2)
        colour: tuple[int, ...] = _FURNITURE_COLOURS.get(obj["objectType"], (180, 180, 180))
        if obj["objectType"] == "Cabinet" and c["y"] > 1.2:
            draw.rectangle([a, b], outline=colour, width=1)  # wall cabinets: outline above the counter
            continue
        if obj.get("isOpen"):
            colour = tuple(min(255, v + 40) for v in colour)
        if obj["objectType"] == "StoveBurner" and obj.get("isToggled"):
            colour = (230, 90, 30)
        draw.rectangle([a, b], fill=colour, outline=(80, 70, 60))
        kind = obj["objectType"]
        if kind not in ("StoveKnob", "Sink") and (obj.get("visible") or kind not in ("Cabinet", "Drawer")) \
                and _seen_from_above(obj, by_id):
            labels.append(Label((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, label(obj["objectId"]),
                                bool(obj.get("visible")), obj.get("distance", 0.0)))

    for obj in objects:
        if not obj.get("pickupable") or obj.get("isPickedUp"):
            continue
        p = obj["position"]
        cx, cz = px(p["x"], p["z"])
        source = PIECE_OF.get(obj["objectType"], obj["objectType"])
        colour = _FOOD_COLOURS.get(source, (70, 90, 160))
        r = max(2.0, scale * (0.05 if source in FOOD_TYPES else 0.06))
        if obj.get("isCooked"):
            colour = tuple(int(v * 0.55) for v in colour)
        draw.ellipse([cx - r, cz - r, cx + r, cz + r], fill=colour, outline=(30, 30, 30))
        if _seen_from_above(obj, by_id):
            labels.append(Label(cx, cz, label(obj["objectId"]), bool(obj.get("visible")), obj.get("distance", 0.0)))

    position = agent.get("position")
    if position:
        ax, az = px(position["x"], position["z"])
        heading = math.radians((agent.get("rotation") or {}).get("y", 0.0))
        reach = 1.5 * scale
        cone = [(ax, az)]
        for delta in range(-45, 46, 15):
            angle = heading + math.radians(delta)
            cone.append((ax + math.sin(angle) * reach, az - math.cos(angle) * reach))
        draw.polygon(cone, outline=(40, 120, 200))
        tip = (ax + math.sin(heading) * scale * 0.3, az - math.cos(heading) * scale * 0.3)
        left = (ax + math.sin(heading + 2.5) * scale * 0.18, az - math.cos(heading + 2.5) * scale * 0.18)
        right = (ax + math.sin(heading - 2.5) * scale * 0.18, az - math.cos(heading - 2.5) * scale * 0.18)
        draw.polygon([tip, left, right], fill=(30, 100, 220))

    placements = place_labels(labels, draw, small, (0, 0, map_w, height))
    image.info["labels"] = placements  # what was labelled where (not written into the PNG)
    for placed in placements:
        colour = (10, 40, 160) if placed.label.in_reach else (40, 40, 40)
        lx, ly = placed.label.x, placed.label.y
        bx0, by0, bx1, by1 = placed.box
        if not (bx0 - 6 <= lx <= bx1 + 6 and by0 - 6 <= ly <= by1 + 6):  # moved away: a leader line to the object
            draw.line([(lx, ly), (min(max(lx, bx0), bx1), min(max(ly, by0), by1))], fill=(120, 120, 120), width=1)
        draw.text(placed.origin, placed.label.text, fill=colour, font=small, stroke_width=2,
                  stroke_fill=(255, 255, 255))

    if panel and width > map_w:
        _draw_panel(draw, metadata, label, map_w, width, height)
    return image


@dataclass(frozen=True)
class Label:
    x: float  # the object's point in the picture
    y: float
    text: str
    in_reach: bool
    distance: float


@dataclass(frozen=True)
class PlacedLabel:
    label: Label
    box: tuple[float, float, float, float]  # left, top, right, bottom of the text (with its outline)
    origin: tuple[float, float]  # where draw.text puts it


# Where a label may sit relative to its object's point (dx, dy of the text's top-left, in units of the
# text's width w and height h): right, left, above, below, the corners, then the same further out.
_SPOTS = [(0.15, -0.5), (-1.15, -0.5), (-0.5, -1.3), (-0.5, 0.3), (0.15, -1.4), (0.15, 0.4), (-1.15, -1.4),
          (-1.15, 0.4)]
_SPOTS += [(dx * k, dy + (k - 1) * (1.0 if dy > 0 else -1.0 if dy < -0.6 else 0.0)) for k in (2, 3)
           for dx, dy in _SPOTS[:8] if (dx, dy) != (-0.5, -0.5)]
_SPOTS += [(0.15, -0.5 + d) for d in (-2.2, 2.2, -3.3, 3.3)] + [(-1.15, -0.5 + d) for d in (-2.2, 2.2, -3.3, 3.3)]


def _seen_from_above(obj: dict[str, Any], by_id: dict[str, dict[str, Any]]) -> bool:
    """Not held, and not shut inside a closed receptacle (a closed fridge hides what is in it)."""
    if obj.get("isPickedUp"):
        return False
    for parent in obj.get("parentReceptacles") or []:
        p = by_id.get(parent, {})
        if p.get("openable") and not p.get("isOpen"):
            return False
    return True


def place_labels(labels: list[Label], draw: ImageDraw.ImageDraw, font: Any,
                 area: tuple[float, float, float, float]) -> list[PlacedLabel]:
    """Greedy collision-free placement: objects in reach first, then by distance; each label takes the
    first spot around its point that overlaps no placed label and stays inside ``area``; one with no
    free spot is left out."""
    placed: list[PlacedLabel] = []
    pad = 1.0
    for item in sorted(labels, key=lambda lb: (not lb.in_reach, lb.distance, lb.text)):
        left, top, right, bottom = draw.textbbox((0, 0), item.text, font=font, stroke_width=2)
        w, h = right - left, bottom - top
        for fx, fy in _SPOTS:
            x, y = item.x + fx * w, item.y + fy * h
            box = (x, y, x + w, y + h)
            if box[0] < area[0] or box[1] < area[1] or box[2] > area[2] or box[3] > area[3]:
                continue
            if any(box[0] < o.box[2] + pad and o.box[0] < box[2] + pad and box[1] < o.box[3] + pad
                   and o.box[1] < box[3] + pad for o in placed):
                continue
            placed.append(PlacedLabel(item, box, (x - left, y - top)))
            break
    return placed


def _draw_panel(draw: ImageDraw.ImageDraw, metadata: dict[str, Any], label: Callable[[str], str],
                left: int, width: int, height: int) -> None:
    font = _font(11)
    draw.rectangle([left, 0, width, height], fill=(255, 255, 255))
    held = metadata.get("inventoryObjects") or []
    lines = ["Holding:", "  " + (label(held[0]["objectId"]) if held else "nothing"), "", "In reach:"]
    for obj in sorted((o for o in metadata.get("objects") or [] if o.get("visible") and not o.get("isPickedUp")
                       and o["objectType"] not in ("Floor", "Sink")), key=lambda o: o.get("distance", 0.0)):
        tags = []
        if obj.get("openable"):
            tags.append("open" if obj.get("isOpen") else "closed")
        if obj.get("toggleable") or obj["objectType"] == "StoveBurner":
            tags.append("on" if obj.get("isToggled") else "off")
        if obj.get("isCooked"):
            tags.append("cooked")
        lines.append("  " + label(obj["objectId"]) + (f" ({', '.join(tags)})" if tags else ""))
    y = 8
    for line in lines:
        if y > height - 14:
            draw.text((left + 8, y), "  …", fill=(0, 0, 0), font=font)
            break
        draw.text((left + 8, y), line, fill=(0, 0, 0), font=font)
        y += 14


def png_bytes(image: Image.Image) -> bytes:
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", optimize=False, compress_level=3)
    return buffer.getvalue()


def frame_png(frame: Any) -> bytes:
    """PNG of an ai2thor RGB frame (a H×W×3 uint8 array)."""
    return png_bytes(Image.fromarray(frame))
