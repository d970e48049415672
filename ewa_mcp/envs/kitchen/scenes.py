"""Thirty deterministic kitchens, FloorPlan1 … FloorPlan30, in AI2-THOR's kitchen vocabulary.

Each kitchen is generated from its number alone (``random.Random`` seeded with a string, which
is stable across processes and Python builds): a rectangular room on a 0.25 m grid, counters
along one to three walls (line, L, U or galley), a fridge, a stove with burners and knobs, a sink,
cabinets and drawers, optional island, dining table, shelf and counter appliances, and the
pickupable food and tools placed on or in receptacles. Kitchens differ in which food and tools
they hold, so some recipes need groceries from the shop.

The parts: scene_model.py (scene names, ``Box``, ``ObjectSeed``, ``SceneSpec``, the grid), scene_layout.py
(counters and modules along the walls), scene_stock.py (the food and tools and where they start); this module
puts one kitchen together (``build_scene``), checks the agent can reach most of the floor, and re-exports the
model's names.
"""

from __future__ import annotations

import random
from collections import deque
from functools import lru_cache

from .scene_layout import Builder, cabinet_bays, choose_runs, facing_wall, free_rect, layout_runs, sub_box, wall_spot
from .scene_model import (
    GENERATOR_VERSION,
    GRID,
    SCENE_COUNT,
    SCENE_NAMES,
    Box,
    Cell,
    ObjectSeed,
    SceneError,
    SceneSpec,
    canonical_scene,
    cell_to_world,
    scene_number,
)
from .scene_stock import choose_inventory, place_objects

__all__ = [
    "GENERATOR_VERSION", "GRID", "SCENE_COUNT", "SCENE_NAMES", "Box", "Cell", "ObjectSeed", "SceneError", "SceneSpec",
    "build_scene", "canonical_scene", "cell_to_world", "scene_number",
]


# ------------------------------------------------------------------ reachability
def _reachable_from(start: Cell, free: set[Cell]) -> set[Cell]:
    seen = {start}
    queue = deque([start])
    while queue:
        x, z = queue.popleft()
        for nxt in ((x + 1, z), (x - 1, z), (x, z + 1), (x, z - 1)):
            if nxt in free and nxt not in seen:
                seen.add(nxt)
                queue.append(nxt)
    return seen


@lru_cache(maxsize=None)
def build_scene(name: str) -> SceneSpec:
    """The kitchen called ``name`` (FloorPlan1 … FloorPlan30); the same every time."""
    number = scene_number(name)
    for attempt in range(50):
        spec = _generate(number, attempt)
        if spec is not None:
            return spec
    raise AssertionError(f"could not lay out FloorPlan{number}")  # pragma: no cover - generator bug


def _generate(number: int, attempt: int) -> SceneSpec | None:
    rng = random.Random(f"{GENERATOR_VERSION}:{number}:{attempt}")
    shape = rng.choice(["line", "L-west", "L-east", "U", "galley", "L-west", "U"])
    width = rng.randint(18, 24)
    depth = rng.randint(16, 22) if shape != "galley" else rng.randint(14, 16)
    b = Builder(rng, width, depth)
    b.floor()
    runs = choose_runs(shape, width, depth)
    layout_runs(b, runs, rng)
    # An island counter or a dining table in the middle of larger rooms.
    middle = rng.random()
    if shape != "galley" and middle < 0.35:
        cells = free_rect(b, rng.randint(4, 6), 2, 2, rng)
        if cells:
            xs = sorted({c[0] for c in cells})
            columns = [[c for c in cells if c[0] == x] for x in xs]
            b.counter(None, cells, upper=False, bays_along=cabinet_bays(columns))
    elif middle < 0.8:
        cells = free_rect(b, rng.randint(4, 5), 3, 2, rng)
        if cells:
            b.add(ObjectSeed("DiningTable", box=b.box(cells, 0.0, 0.76, shrink=0.05), capacity=14, levels=(0.76,),
                             blocks=frozenset(cells)))
    if rng.random() < 0.45:
        spot = wall_spot(b, rng, 2)
        if spot:
            cells, _ = spot
            b.add(ObjectSeed("Shelf", box=b.box(cells, 0.0, 1.6, shrink=0.03), capacity=6, levels=(0.9, 1.3),
                             blocks=frozenset(cells)))
    spot = wall_spot(b, rng, 1)
    if spot is None:
        return None
    b.add(ObjectSeed("GarbageCan", box=b.box(spot[0], 0.0, 0.45, shrink=0.04), capacity=8, levels=(0.1,),
                     blocks=frozenset(spot[0])))
    # Counter appliances stand on counters against a wall.
    wall_tops = list(b.wall_counters)
    rng.shuffle(wall_tops)
    appliance_odds = [("Microwave", 0.85, 2), ("Toaster", 0.7, 1), ("CoffeeMachine", 0.7, 1)]
    used: dict[int, int] = {}
    for appliance, odds, cells_needed in appliance_odds:
        if rng.random() >= odds:
            continue
        for top, run in wall_tops:
            top_box = b.objects[top].box
            assert top_box is not None
            length = max(top_box.x1 - top_box.x0, top_box.z1 - top_box.z0)
            free_cells = round(length / GRID) - used.get(top, 0)
            if free_cells < cells_needed + 1:
                continue
            start = used.get(top, 0) * GRID / length
            frac1 = start + cells_needed * GRID / length
            height = {"Microwave": 0.35, "Toaster": 0.2, "CoffeeMachine": 0.35}[appliance]
            box = sub_box(top_box, run.side, start + 0.02, frac1 - 0.02, 0.95, 0.95 + height, (0.05, 0.75))
            capacity = {"Microwave": 4, "Toaster": 2, "CoffeeMachine": 1}[appliance]
            level = {"Microwave": 1.0, "Toaster": 1.0, "CoffeeMachine": 0.98}[appliance]
            b.add(ObjectSeed(appliance, box=box, parent=top, capacity=capacity, levels=(level,),
                             rotation=facing_wall(run.side) + 180.0))
            used[top] = used.get(top, 0) + cells_needed
            # the appliance takes counter room
            b.objects[top].capacity = max(2, (b.objects[top].capacity or 0) - 2 * cells_needed)
            break
    # The agent starts on a free cell near the middle of the room.
    free = {(x, z) for x in range(width) for z in range(depth)} - b.blocked
    if not free:
        return None
    centre = (width / 2, depth / 2)
    start_cell = min(free, key=lambda c: (abs(c[0] - centre[0]) + abs(c[1] - centre[1]), c))
    reachable = _reachable_from(start_cell, free)
    if len(reachable) < 0.8 * len(free):
        return None
    counts = choose_inventory(rng)
    place_objects(b.objects, counts, rng)
    start_rotation = rng.choice([0.0, 90.0, 180.0, 270.0])
    return SceneSpec(
        name=f"FloorPlan{number}", number=number, width=width, depth=depth, shape=shape, objects=b.objects,
        reachable=frozenset(reachable), start=(start_cell, start_rotation),
        notes={"attempt": attempt, "inventory": counts},
    )
