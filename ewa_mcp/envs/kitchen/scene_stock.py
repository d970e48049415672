"""What a kitchen holds: which food and tools it gets, and where each starts (by type preference).

``PLACES`` is also what AI2-THOR's ``InitialRandomSpawn`` re-placement follows in the simulator (sim_hands.py).
"""

from __future__ import annotations

import random

from .scene_model import ObjectSeed
from .vocabulary import FOOD_TYPES, accepts

# Where each pickupable type tends to start: (receptacle type, weight).
PLACES: dict[str, list[tuple[str, float]]] = {
    "Apple": [("CounterTop", 3), ("Fridge", 3), ("DiningTable", 2), ("Bowl", 1)],
    "Bread": [("CounterTop", 4), ("DiningTable", 2), ("Cabinet", 1)],
    "Egg": [("Fridge", 4), ("CounterTop", 1), ("Bowl", 1)],
    "Lettuce": [("Fridge", 4), ("CounterTop", 2)],
    "Potato": [("CounterTop", 3), ("Cabinet", 1), ("Fridge", 1)],
    "Tomato": [("Fridge", 3), ("CounterTop", 3), ("DiningTable", 1), ("Plate", 1)],
    "Pan": [("StoveBurner", 3), ("CounterTop", 1), ("Cabinet", 2)],
    "Pot": [("StoveBurner", 3), ("Cabinet", 2), ("CounterTop", 1)],
    "Kettle": [("StoveBurner", 2), ("CounterTop", 2)],
    "Bowl": [("Cabinet", 3), ("CounterTop", 2), ("DiningTable", 1), ("Shelf", 1)],
    "Plate": [("Cabinet", 3), ("CounterTop", 1), ("DiningTable", 2), ("Shelf", 1)],
    "Cup": [("Cabinet", 2), ("CounterTop", 2), ("Shelf", 1)],
    "Mug": [("CoffeeMachine", 2), ("Cabinet", 2), ("CounterTop", 1)],
    "Knife": [("Drawer", 2), ("CounterTop", 3)],
    "ButterKnife": [("Drawer", 3), ("CounterTop", 2), ("DiningTable", 1)],
    "Fork": [("Drawer", 3), ("DiningTable", 1), ("CounterTop", 1)],
    "Spoon": [("Drawer", 3), ("CounterTop", 1)],
    "Spatula": [("Drawer", 2), ("CounterTop", 2)],
    "Ladle": [("Drawer", 2), ("CounterTop", 1)],
    "SaltShaker": [("CounterTop", 3), ("Cabinet", 1), ("Shelf", 1), ("DiningTable", 1)],
    "PepperShaker": [("CounterTop", 3), ("Cabinet", 1), ("Shelf", 1)],
}
_TOOL_ODDS: dict[str, float] = {
    "Pan": 0.85, "Pot": 0.7, "Kettle": 0.5, "Bowl": 0.9, "Plate": 0.95, "Cup": 0.7, "Mug": 0.8, "Knife": 0.85,
    "ButterKnife": 0.6, "Fork": 0.7, "Spoon": 0.7, "Spatula": 0.6, "Ladle": 0.4, "SaltShaker": 0.8, "PepperShaker": 0.7,
}
# Placement order: containers first, so food can start in a bowl or on a plate.
_PLACEMENT_ORDER = ["Pan", "Pot", "Kettle", "Bowl", "Plate", "Cup", "Mug", "Knife", "ButterKnife", "Fork", "Spoon",
                    "Spatula", "Ladle", "SaltShaker", "PepperShaker", *FOOD_TYPES]


def choose_inventory(rng: random.Random) -> dict[str, int]:
    counts: dict[str, int] = {}
    foods = [f for f in FOOD_TYPES if rng.random() < 0.72]
    while len(foods) < 3:
        extra = rng.choice([f for f in FOOD_TYPES if f not in foods])
        foods.append(extra)
    for food in FOOD_TYPES:
        if food in foods:
            counts[food] = 2 if rng.random() < 0.25 else 1
    for tool, odds in _TOOL_ODDS.items():
        if rng.random() < odds:
            counts[tool] = 1
    # Every kitchen can slice, has a vessel for the stove and something to serve on.
    if "Knife" not in counts and "ButterKnife" not in counts:
        counts["Knife"] = 1
    if "Pan" not in counts and "Pot" not in counts:
        counts["Pan"] = 1
    counts.setdefault("Plate", 1)
    return counts


def place_objects(objects: list[ObjectSeed], counts: dict[str, int], rng: random.Random) -> None:
    """Append a seed for each pickupable object, in/on a receptacle chosen by type preference."""
    from .vocabulary import RECEPTACLE_CAPACITY, TYPES

    load = [0] * len(objects)
    for object_type in _PLACEMENT_ORDER:
        for _ in range(counts.get(object_type, 0)):
            options: list[tuple[float, int]] = []
            for receptacle_type, weight in PLACES[object_type]:
                for i, o in enumerate(objects):
                    if o.object_type != receptacle_type or not accepts(receptacle_type, object_type):
                        continue
                    # food starts at most three to a bowl or plate
                    room = 3 if receptacle_type in ("Bowl", "Plate") else (o.capacity or 0)
                    if load[i] < room:
                        options.append((weight, i))
            if not options:  # every kitchen has counter room; this keeps odd layouts valid
                options = [(1.0, next(i for i, o in enumerate(objects) if o.object_type == "CounterTop"))]
            total = sum(w for w, _ in options)
            pick = rng.random() * total
            chosen = options[-1][1]
            for weight, index in options:
                pick -= weight
                if pick <= 0:
                    chosen = index
                    break
            load[chosen] += 1
            spec = TYPES[object_type]
            objects.append(ObjectSeed(object_type, parent=chosen,
                                      capacity=RECEPTACLE_CAPACITY.get(object_type) if spec.receptacle else None,
                                      rotation=rng.choice([0.0, 90.0, 180.0, 270.0])))
            load.append(0)
