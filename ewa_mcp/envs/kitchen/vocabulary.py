"""The kitchen vocabulary: AI2-THOR object types, their actionable properties and what fits where.

Type names and property names follow AI2-THOR's object metadata so that metadata from the
simulator and from a real AI2-THOR build read the same. The receptacle table is ours: it is
close to AI2-THOR's placement rules but admits what the recipes need (cracked eggs in a pan,
bread slices in a toaster, any food on a plate).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Category = Literal["food", "piece", "tool", "receptacle", "appliance", "structure"]

FOOD_TYPES: tuple[str, ...] = ("Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato")
# SliceObject turns a food into pieces of these types; an egg "slices" into one cracked egg.
PIECE_OF: dict[str, str] = {
    "AppleSliced": "Apple",
    "BreadSliced": "Bread",
    "EggCracked": "Egg",
    "LettuceSliced": "Lettuce",
    "PotatoSliced": "Potato",
    "TomatoSliced": "Tomato",
}
PIECE_FOR: dict[str, str] = {source: piece for piece, source in PIECE_OF.items()}
# How many pieces one slice action makes (our counts; AI2-THOR's vary by asset).
PIECE_COUNT: dict[str, int] = {"Apple": 4, "Bread": 6, "Egg": 1, "Lettuce": 5, "Potato": 4, "Tomato": 5}

UTENSILS: tuple[str, ...] = ("Knife", "ButterKnife", "Fork", "Spoon", "Spatula", "Ladle")
SHAKERS: tuple[str, ...] = ("SaltShaker", "PepperShaker")
DISHES: tuple[str, ...] = ("Bowl", "Plate", "Cup", "Mug")
VESSELS: tuple[str, ...] = ("Pan", "Pot", "Kettle")
TOOL_TYPES: tuple[str, ...] = VESSELS + DISHES + UTENSILS + SHAKERS
SLICING_TOOLS: frozenset[str] = frozenset({"Knife", "ButterKnife"})

_FOODISH = frozenset(FOOD_TYPES) | frozenset(PIECE_OF)
_ALL_PICKUPABLE = _FOODISH | frozenset(TOOL_TYPES)

# receptacle type -> the object types it accepts
RECEPTACLE_ACCEPTS: dict[str, frozenset[str]] = {
    "CounterTop": _ALL_PICKUPABLE,
    "DiningTable": _ALL_PICKUPABLE,
    "Shelf": _ALL_PICKUPABLE,
    "Floor": _ALL_PICKUPABLE,
    "Cabinet": _ALL_PICKUPABLE,
    "Drawer": frozenset(UTENSILS + SHAKERS),
    "Fridge": _FOODISH | frozenset(DISHES) | {"Pan", "Pot"},
    "Microwave": _FOODISH | frozenset(DISHES),  # nothing metal
    "StoveBurner": frozenset(VESSELS),
    "Toaster": frozenset({"BreadSliced"}),
    "CoffeeMachine": frozenset({"Mug", "Cup"}),
    "SinkBasin": _FOODISH | frozenset(DISHES + VESSELS + UTENSILS),
    "GarbageCan": _FOODISH | frozenset(UTENSILS + SHAKERS) | {"Cup", "Mug"},
    "Pan": _FOODISH | {"Spatula"},
    "Pot": _FOODISH | {"Ladle", "Spoon"},
    "Bowl": _FOODISH | {"Spoon", "Fork", "Ladle"},
    "Plate": _FOODISH | frozenset(UTENSILS),
}

# How many objects a receptacle holds (pieces made by slicing in place do not need room).
RECEPTACLE_CAPACITY: dict[str, int] = {
    "DiningTable": 14, "Shelf": 6, "Floor": 200, "Cabinet": 6, "Drawer": 6, "Fridge": 12, "Microwave": 4,
    "StoveBurner": 1, "Toaster": 2, "CoffeeMachine": 1, "SinkBasin": 6, "GarbageCan": 8,
    "Pan": 8, "Pot": 10, "Bowl": 8, "Plate": 8,
}  # CounterTop: two per 0.25 m of length, set per instance


@dataclass(frozen=True)
class TypeSpec:
    name: str
    category: Category
    pickupable: bool = False
    moveable: bool = False
    receptacle: bool = False
    openable: bool = False
    sliceable: bool = False
    cookable: bool = False
    breakable: bool = False
    toggleable: bool = False
    dirtyable: bool = False
    can_fill: bool = False
    heat_source: bool = False
    cold_source: bool = False
    materials: tuple[str, ...] = ()
    mass: float = 0.0
    size: tuple[float, float, float] = (0.1, 0.1, 0.1)  # x, y, z extent in metres (for small objects)


def _food(name: str, size: tuple[float, float, float], mass: float) -> TypeSpec:
    return TypeSpec(name, "food", pickupable=True, sliceable=True, cookable=True, breakable=name == "Egg",
                    materials=("Food",), mass=mass, size=size)


def _piece(name: str, size: tuple[float, float, float]) -> TypeSpec:
    # All pieces are cookable here because the recipes cook them (fried tomato slices, toast).
    return TypeSpec(name, "piece", pickupable=True, cookable=True, materials=("Food",), mass=0.03, size=size)


def _tool(name: str, materials: tuple[str, ...], size: tuple[float, float, float], mass: float, **kw: bool) -> TypeSpec:
    return TypeSpec(name, "tool", pickupable=True, materials=materials, mass=mass, size=size, **kw)


TYPES: dict[str, TypeSpec] = {
    spec.name: spec
    for spec in [
        _food("Apple", (0.08, 0.09, 0.08), 0.2),
        _food("Bread", (0.25, 0.12, 0.12), 0.5),
        _food("Egg", (0.05, 0.06, 0.05), 0.06),
        _food("Lettuce", (0.2, 0.18, 0.2), 0.4),
        _food("Potato", (0.1, 0.07, 0.07), 0.2),
        _food("Tomato", (0.08, 0.07, 0.08), 0.15),
        _piece("AppleSliced", (0.04, 0.08, 0.06)),
        _piece("BreadSliced", (0.02, 0.11, 0.11)),
        _piece("EggCracked", (0.09, 0.02, 0.09)),
        _piece("LettuceSliced", (0.03, 0.15, 0.15)),
        _piece("PotatoSliced", (0.02, 0.06, 0.06)),
        _piece("TomatoSliced", (0.02, 0.07, 0.07)),
        _tool("Pan", ("Metal",), (0.45, 0.06, 0.28), 1.0, receptacle=True, dirtyable=True),
        _tool("Pot", ("Metal",), (0.3, 0.15, 0.3), 1.5, receptacle=True, dirtyable=True, can_fill=True),
        _tool("Kettle", ("Metal",), (0.2, 0.22, 0.2), 1.0, can_fill=True),
        _tool("Bowl", ("Ceramic",), (0.18, 0.08, 0.18), 0.4, receptacle=True, breakable=True, dirtyable=True,
              can_fill=True),
        _tool("Plate", ("Ceramic",), (0.25, 0.02, 0.25), 0.5, receptacle=True, breakable=True, dirtyable=True),
        _tool("Cup", ("Glass",), (0.08, 0.12, 0.08), 0.25, breakable=True, dirtyable=True, can_fill=True),
        _tool("Mug", ("Ceramic",), (0.1, 0.1, 0.1), 0.3, breakable=True, dirtyable=True, can_fill=True),
        _tool("Knife", ("Metal",), (0.3, 0.02, 0.03), 0.15),
        _tool("ButterKnife", ("Metal",), (0.2, 0.02, 0.02), 0.08),
        _tool("Fork", ("Metal",), (0.19, 0.02, 0.03), 0.05),
        _tool("Spoon", ("Metal",), (0.18, 0.02, 0.04), 0.05),
        _tool("Spatula", ("Plastic",), (0.3, 0.03, 0.07), 0.1),
        _tool("Ladle", ("Metal",), (0.3, 0.07, 0.09), 0.15),
        _tool("SaltShaker", ("Glass",), (0.04, 0.1, 0.04), 0.1),
        _tool("PepperShaker", ("Glass",), (0.04, 0.1, 0.04), 0.1),
        TypeSpec("CounterTop", "receptacle", receptacle=True),
        TypeSpec("DiningTable", "receptacle", receptacle=True, moveable=True),
        TypeSpec("Shelf", "receptacle", receptacle=True),
        TypeSpec("Floor", "structure", receptacle=True),
        TypeSpec("Cabinet", "receptacle", receptacle=True, openable=True),
        TypeSpec("Drawer", "receptacle", receptacle=True, openable=True),
        TypeSpec("Fridge", "appliance", receptacle=True, openable=True, cold_source=True),
        TypeSpec("Microwave", "appliance", receptacle=True, openable=True, toggleable=True, heat_source=True,
                 moveable=True),
        TypeSpec("StoveBurner", "appliance", receptacle=True, heat_source=True),
        TypeSpec("StoveKnob", "appliance", toggleable=True),
        TypeSpec("Sink", "structure"),
        TypeSpec("SinkBasin", "receptacle", receptacle=True),
        TypeSpec("Toaster", "appliance", receptacle=True, toggleable=True, heat_source=True, moveable=True),
        TypeSpec("CoffeeMachine", "appliance", receptacle=True, toggleable=True, heat_source=True, moveable=True),
        TypeSpec("GarbageCan", "receptacle", receptacle=True, moveable=True),
    ]
}

# What a shop order may deliver into the kitchen (food and tools, not furniture).
DELIVERABLE_TYPES: frozenset[str] = frozenset(FOOD_TYPES) | frozenset(TOOL_TYPES)
# What the shop actually sells for the kitchen: its food, nothing else (a test checks this against the
# shop's catalogue). Only these may be suggested as "can be bought".
SHOP_SOLD_TYPES: frozenset[str] = frozenset(FOOD_TYPES)
# What does the same job when a kitchen lacks a type (a pot on the stove for a pan, ...).
STAND_INS: dict[str, tuple[str, ...]] = {
    "Pan": ("Pot",), "Pot": ("Pan",), "Knife": ("ButterKnife",), "ButterKnife": ("Knife",),
    "Cup": ("Mug",), "Mug": ("Cup",),
}


def accepts(receptacle_type: str, object_type: str) -> bool:
    allowed = RECEPTACLE_ACCEPTS.get(receptacle_type)
    return allowed is not None and object_type in allowed


def canonical_type(name: str) -> str | None:
    """Exact type match, ignoring case only ("apple" -> "Apple"; "Eggplant" -> None)."""
    if name in TYPES:
        return name
    lowered = name.lower()
    for type_name in TYPES:
        if type_name.lower() == lowered:
            return type_name
    return None


def similar_types(name: str, limit: int = 3) -> list[str]:
    """Types that share a prefix or substring with ``name``, for "did you mean" hints."""
    lowered = name.lower()
    hits = [t for t in sorted(TYPES) if lowered in t.lower() or t.lower() in lowered]
    return hits[:limit]
