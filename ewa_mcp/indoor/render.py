"""A labelled top-down picture of the kitchen, drawn from AI2-THOR metadata with Pillow.

It needs nothing but the metadata (objects' boxes, the agent pose, scene bounds) and the
reachable positions, so it draws any backend's kitchen. Furniture is drawn as boxes, small
objects as dots; objects in reach carry their handle; the agent is an arrow with its view cone.
A side panel lists what is held and what is in reach with their states.
"""

from __future__ import annotations

import io
import math
from collections.abc import Callable, Iterable
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
    labels: list[tuple[float, float, str]] = []
    furniture = [o for o in objects if not o.get("pickupable") and o["objectType"] != "Floor"]
    furniture.sort(key=lambda o: _DRAW_ORDER.index(o["objectType"]) if o["objectType"] in _DRAW_ORDER else 99)
    for obj in furniture:
        box = obj.get("axisAlignedBoundingBox") or {}
        c, s = box.get("center"), box.get("size")
        if not c or not s:
            continue
        a = px(c["x"] - s["x"] / 2, c["z"] + s["z"] / 2)
        b = px(c["x"] + s["x"] / 2, c["z"] - s["z"] / 2)
        colour = _FURNITURE_COLOURS.get(obj["objectType"], (180, 180, 180))
        if obj["objectType"] == "Cabinet" and c["y"] > 1.2:
            draw.rectangle([a, b], outline=colour, width=1)  # wall cabinets: outline above the counter
            continue
        if obj.get("isOpen"):
            colour = tuple(min(255, v + 40) for v in colour)
        if obj["objectType"] == "StoveBurner" and obj.get("isToggled"):
            colour = (230, 90, 30)
        draw.rectangle([a, b], fill=colour, outline=(80, 70, 60))
        if obj.get("visible") and obj["objectType"] not in ("StoveKnob", "Sink", "Cabinet", "Drawer"):
            labels.append(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, label(obj["objectId"])))

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
        if obj.get("visible"):
            labels.append((cx, cz, label(obj["objectId"])))

    position = agent.get("position")
    if position:
        ax, az = px(position["x"], position["z"])
        heading = math.radians((agent.get("rotation") or {}).get("y", 0.0))
        reach = 1.5 * scale
        cone = [(ax, az)]
        for delta in range(-45, 46, 15):
            a = heading + math.radians(delta)
            cone.append((ax + math.sin(a) * reach, az - math.cos(a) * reach))
        draw.polygon(cone, outline=(40, 120, 200))
        tip = (ax + math.sin(heading) * scale * 0.3, az - math.cos(heading) * scale * 0.3)
        left = (ax + math.sin(heading + 2.5) * scale * 0.18, az - math.cos(heading + 2.5) * scale * 0.18)
        right = (ax + math.sin(heading - 2.5) * scale * 0.18, az - math.cos(heading - 2.5) * scale * 0.18)
        draw.polygon([tip, left, right], fill=(30, 100, 220))

    for lx, lz, text in labels:
        draw.text((lx + 3, lz - 5), text, fill=(10, 10, 10), font=small, stroke_width=2, stroke_fill=(255, 255, 255))

    if panel and width > map_w:
        _draw_panel(draw, metadata, label, map_w, width, height)
    return image


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
