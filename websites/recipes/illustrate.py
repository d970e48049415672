"""Deterministic SVG illustrations drawn from a recipe's ingredients.

Each kitchen food has a simple drawn shape, shop ingredients are small coloured garnishes, and
the dish sits on a plate or in a bowl as its equipment says. The same recipe always gives the
same picture (positions come from a hash of the id), so the image URL is stable and cacheable.
"""

from __future__ import annotations

import html
import math
import zlib
from typing import Any

WIDTH, HEIGHT = 320, 220
CX, CY = WIDTH / 2, HEIGHT / 2 + 6

# Shop ingredient -> garnish colour.
GARNISH = {
    "Cheddar Cheese": "#f2b632", "Mozzarella": "#fbfaf2", "Chicken Breast": "#e9c8a0", "Butter": "#f7e27a",
    "Olive Oil": "#a9b43c", "Avocado": "#7fae3f", "Peanut Butter": "#b9803f", "Salmon Fillet": "#f08a64",
    "Bacon": "#c0483c", "Sea Salt": "#ffffff", "Black Pepper": "#333333", "Garlic": "#f4efdf",
    "Onion": "#d9b8d8", "Lemon": "#f7e04b", "Honey": "#e7a72a", "Basil": "#3f8f3a",
}
BACKGROUNDS = ["#f6efe4", "#eef4ea", "#f3ecf4", "#eaf1f6", "#f7f1de", "#f4e9e6"]


class _Rand:
    """A tiny deterministic generator so pictures never depend on Python's hash seed."""

    def __init__(self, seed: str) -> None:
        self.state = zlib.crc32(seed.encode()) or 1

    def next(self) -> float:
        self.state = (1103515245 * self.state + 12345) % (2**31)
        return self.state / 2**31


def _food(kind: str, x: float, y: float, sliced: bool, r: _Rand, scale: float = 1.0) -> str:
    angle = int(r.next() * 60 - 30)
    transform = f'transform="translate({x:.1f} {y:.1f}) rotate({angle}) scale({scale:.2f})"'
    if kind == "Tomato":
        if sliced:
            return (f'<g {transform}><circle r="17" fill="#d9382c"/><circle r="12" fill="#ef6b55"/>'
                    '<circle cx="-5" cy="-3" r="2" fill="#f7d36b"/><circle cx="5" cy="2" r="2" fill="#f7d36b"/>'
                    '<circle cx="0" cy="6" r="2" fill="#f7d36b"/></g>')
        return (f'<g {transform}><circle r="20" fill="#d9382c"/>'
                '<path d="M-6 -19 L0 -14 L6 -19 L2 -13 L0 -20 L-2 -13 Z" fill="#3d8a37"/></g>')
    if kind == "Bread":
        if sliced:
            return (f'<g {transform}><path d="M-20 14 L-20 -6 Q-22 -20 -8 -20 Q0 -26 8 -20 Q22 -20 20 -6 L20 14 Z" '
                    'fill="#c98b3f"/><path d="M-15 10 L-15 -5 Q-16 -15 -6 -15 Q0 -19 6 -15 Q16 -15 15 -5 L15 10 Z" '
                    'fill="#f0d59a"/></g>')
        return (f'<g {transform}><rect x="-30" y="-16" width="60" height="32" rx="14" fill="#c98b3f"/>'
                '<path d="M-18 -10 L-12 8 M-4 -12 L2 10 M10 -12 L16 8" stroke="#a86d2a" stroke-width="3"/></g>')
    if kind == "Egg":
        if sliced:  # a cracked egg: white with a yolk
            return (f'<g {transform}><path d="M-22 0 Q-20 -18 0 -16 Q22 -20 21 2 Q20 18 0 17 Q-24 16 -22 0 Z" '
                    'fill="#ffffff" stroke="#e6e0d0"/><circle r="8" fill="#f6b622"/></g>')
        return f'<g {transform}><ellipse rx="13" ry="17" fill="#f4ead7" stroke="#dccfb4"/></g>'
    if kind == "Lettuce":
        leaves = "".join(
            f'<ellipse cx="{12 * math.cos(a):.1f}" cy="{12 * math.sin(a):.1f}" rx="14" ry="9" '
            f'transform="rotate({math.degrees(a):.0f} {12 * math.cos(a):.1f} {12 * math.sin(a):.1f})" '
            f'fill="{"#6fbf4a" if i % 2 else "#8fd16a"}"/>'
            for i, a in enumerate(k * math.pi / 3 for k in range(6))
        )
        return f'<g {transform}>{leaves}<circle r="7" fill="#b7e39a"/></g>'
    if kind == "Potato":
        if sliced:
            return (f'<g {transform}><ellipse rx="17" ry="13" fill="#a97a3d"/><ellipse rx="14" ry="10" '
                    'fill="#f1d58c"/></g>')
        return (f'<g {transform}><ellipse rx="24" ry="16" fill="#b58545"/><circle cx="-8" cy="-4" r="1.8" '
                'fill="#7c5524"/><circle cx="7" cy="3" r="1.8" fill="#7c5524"/></g>')
    if kind == "Apple":
        if sliced:
            return (f'<g {transform}><path d="M-18 6 Q0 -22 18 6 Z" fill="#c7343a"/><path d="M-14 5 Q0 -15 14 5 Z" '
                    'fill="#fbf1d3"/><circle cx="-3" cy="0" r="1.6" fill="#5a3a1a"/>'
                    '<circle cx="3" cy="0" r="1.6" fill="#5a3a1a"/></g>')
        return (f'<g {transform}><circle r="18" fill="#c7343a"/><path d="M0 -18 L2 -26" stroke="#5a3a1a" '
                'stroke-width="3"/><ellipse cx="8" cy="-24" rx="7" ry="3.5" fill="#4f9a3b"/></g>')
    return ""


def describe(recipe: dict[str, Any]) -> str:
    """Alt text: what the picture shows, in words."""
    foods = [i["name"].lower() for i in recipe["ingredients"] if i.get("kitchen_type")]
    vessel = "bowl" if "Bowl" in recipe["equipment"] and "Plate" not in recipe["equipment"] else "plate"
    listed = ", ".join(foods[:-1]) + (" and " if len(foods) > 1 else "") + foods[-1] if foods else "food"
    return f"Illustration of {recipe['name']}: {listed} on a {vessel}."


def recipe_svg(recipe: dict[str, Any]) -> str:
    r = _Rand(recipe["id"])
    background = BACKGROUNDS[zlib.crc32(recipe["cuisine"].encode()) % len(BACKGROUNDS)]
    in_bowl = "Bowl" in recipe["equipment"] and "Plate" not in recipe["equipment"]
    title = html.escape(describe(recipe))
    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
        f'viewBox="0 0 {WIDTH} {HEIGHT}" role="img" aria-label="{title}">',
        f"<title>{title}</title>",
        f'<rect width="{WIDTH}" height="{HEIGHT}" fill="{background}"/>',
        '<rect y="170" width="320" height="50" fill="#d8c3a5" opacity="0.55"/>',
    ]
    if in_bowl:
        parts.append(f'<ellipse cx="{CX}" cy="{CY + 22}" rx="112" ry="34" fill="#5b7fa6"/>'
                     f'<ellipse cx="{CX}" cy="{CY - 4}" rx="112" ry="40" fill="#7ea3c8"/>'
                     f'<ellipse cx="{CX}" cy="{CY - 4}" rx="100" ry="32" fill="#f3ede0"/>')
    else:
        parts.append(f'<ellipse cx="{CX}" cy="{CY + 4}" rx="120" ry="62" fill="#ffffff" stroke="#d5d0c6"/>'
                     f'<ellipse cx="{CX}" cy="{CY + 4}" rx="92" ry="46" fill="#f7f5ef"/>')
    sliced = {op["object"] for step in recipe["steps"] for op in step["ops"] if op["op"] in ("slice", "crack")}
    foods = [i["kitchen_type"] for i in recipe["ingredients"] if i.get("kitchen_type")]
    # Fewer foods are drawn bigger, and cut foods as a few pieces, so every plate looks full.
    scale = {1: 1.5, 2: 1.25}.get(len(foods), 1.0)
    for index, food in enumerate(foods):
        angle = 2 * math.pi * index / max(len(foods), 1) + r.next() * 0.6
        spread = 0 if len(foods) == 1 else 52
        x, y = CX + spread * math.cos(angle), CY + 0.55 * spread * math.sin(angle)
        pieces = 3 if food in sliced and len(foods) <= 3 else 1
        for piece in range(pieces):
            dx, dy = (piece - (pieces - 1) / 2) * 22 * scale, (r.next() - 0.5) * 10
            parts.append(_food(food, x + dx, y + dy, food in sliced, r, scale))
    extras = [i["name"] for i in recipe["ingredients"] if not i.get("kitchen_type")]
    for name in extras:
        colour = GARNISH.get(name, "#999999")
        for _ in range(3):
            angle, dist = r.next() * 2 * math.pi, 20 + r.next() * 60
            x, y = CX + dist * math.cos(angle), CY + 0.5 * dist * math.sin(angle)
            parts.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{2.5 + r.next() * 2.5:.1f}" fill="{colour}" '
                         'stroke="#00000022"/>')
    parts.append("</svg>")
    return "".join(parts)
