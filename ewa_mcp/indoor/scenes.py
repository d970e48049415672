"""Thirty deterministic kitchens, FloorPlan1 … FloorPlan30, in AI2-THOR's kitchen vocabulary.

Each kitchen is generated from its number alone (``random.Random`` seeded with a string, which
is stable across processes and Python builds): a rectangular room on a 0.25 m grid, counters
along one to three walls (line, L, U or galley), a fridge, a stove with burners and knobs, a sink,
cabinets and drawers, optional island, dining table, shelf and counter appliances, and the
pickupable food and tools placed on or in receptacles. Kitchens differ in which food and tools
they hold, so some recipes need groceries from the shop.

World axes follow AI2-THOR: y is up, the floor is the x–z plane, rotation 0° faces +z (north).
"""

from __future__ import annotations

import random
import re
from collections import deque
from dataclasses import dataclass, field
from functools import lru_cache

from .vocabulary import FOOD_TYPES, accepts

GRID = 0.25  # metres between reachable agent positions, as AI2-THOR's default gridSize
SCENE_COUNT = 30
SCENE_NAMES: tuple[str, ...] = tuple(f"FloorPlan{n}" for n in range(1, SCENE_COUNT + 1))
GENERATOR_VERSION = "ewa-kitchen-v1"

Cell = tuple[int, int]


class SceneError(ValueError):
    """An unknown scene name; the message lists the valid ones."""


def scene_number(name: str) -> int:
    """``FloorPlan7`` (or AI2-THOR's ``FloorPlan7_physics``) -> 7."""
    match = re.fullmatch(r"FloorPlan(\d+)(?:_physics)?", name.strip())
    if not match or not 1 <= int(match.group(1)) <= SCENE_COUNT:
        raise SceneError(
            f"unknown kitchen scene {name!r}; the kitchens are FloorPlan1 … FloorPlan{SCENE_COUNT}"
        )
    return int(match.group(1))


def canonical_scene(name: str) -> str:
    return f"FloorPlan{scene_number(name)}"


@dataclass(frozen=True)
class Box:
    """An axis-aligned box in world metres."""

    x0: float
    x1: float
    y0: float
    y1: float
    z0: float
    z1: float

    @property
    def center(self) -> tuple[float, float, float]:
        return ((self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2, (self.z0 + self.z1) / 2)

    @property
    def size(self) -> tuple[float, float, float]:
        return (self.x1 - self.x0, self.y1 - self.y0, self.z1 - self.z0)


@dataclass
class ObjectSeed:
    """One object of a generated kitchen, before the simulator brings it to life."""

    object_type: str
    box: Box | None = None  # furniture and appliances have a fixed box; small objects are placed in slots
    parent: int | None = None  # index of the receptacle seed it starts in/on
    capacity: int | None = None
    levels: tuple[float, ...] = ()  # heights (m) where contents rest, one per shelf
    controls: int | None = None  # a StoveKnob's burner (seed index)
    rotation: float = 0.0
    blocks: frozenset[Cell] = frozenset()  # grid cells the agent cannot enter


@dataclass
class SceneSpec:
    name: str
    number: int
    width: int  # grid columns (x)
    depth: int  # grid rows (z)
    shape: str
    objects: list[ObjectSeed]
    reachable: frozenset[Cell]
    start: tuple[Cell, float]
    notes: dict[str, object] = field(default_factory=dict)

    def world(self, cell: Cell) -> tuple[float, float]:
        return cell_to_world(cell, self.width, self.depth)

    def cell(self, x: float, z: float) -> Cell:
        return (round(x / GRID) + self.width // 2, round(z / GRID) + self.depth // 2)

    @property
    def bounds(self) -> Box:
        x0, z0 = self.world((0, 0))
        x1, z1 = self.world((self.width - 1, self.depth - 1))
        return Box(x0 - GRID / 2, x1 + GRID / 2, 0.0, 2.5, z0 - GRID / 2, z1 + GRID / 2)


def cell_to_world(cell: Cell, width: int, depth: int) -> tuple[float, float]:
    return ((cell[0] - width // 2) * GRID, (cell[1] - depth // 2) * GRID)


# ------------------------------------------------------------------ layout: wall runs of modules
@dataclass
class _Run:
    side: str  # north/south/west/east: the wall the run stands against
    start: int  # first cell along the wall
    end: int  # last cell along the wall (inclusive)
    free_ends: tuple[str, ...]  # "start"/"end": ends not touching another run (a fridge may stand there)

    @property
    def length(self) -> int:
        return self.end - self.start + 1


def _run_cells(run: _Run, along0: int, width: int, depth_cells: int, room_w: int, room_d: int) -> list[Cell]:
    cells = []
    for a in range(along0, along0 + width):
        for d in range(depth_cells):
            if run.side == "north":
                cells.append((a, room_d - 1 - d))
            elif run.side == "south":
                cells.append((a, d))
            elif run.side == "west":
                cells.append((d, a))
            else:
                cells.append((room_w - 1 - d, a))
    return cells


def _facing_wall(side: str) -> float:
    """The agent rotation that faces a run standing against ``side``."""
    return {"north": 0.0, "east": 90.0, "south": 180.0, "west": 270.0}[side]


def _cells_box(cells: list[Cell] | frozenset[Cell], width: int, depth: int, y0: float, y1: float,
               shrink: float = 0.0) -> Box:
    xs = [cell_to_world(c, width, depth)[0] for c in cells]
    zs = [cell_to_world(c, width, depth)[1] for c in cells]
    half = GRID / 2 - shrink
    return Box(min(xs) - half, max(xs) + half, y0, y1, min(zs) - half, max(zs) + half)


def _sub_box(box: Box, side: str, frac0: float, frac1: float, y0: float, y1: float,
             depth_frac: tuple[float, float]) -> Box:
    """A part of a run module's box: along-wall fraction [frac0, frac1], depth fraction measured from the wall."""
    d0, d1 = depth_frac
    if side in ("north", "south"):
        x0 = box.x0 + (box.x1 - box.x0) * frac0
        x1 = box.x0 + (box.x1 - box.x0) * frac1
        if side == "north":  # wall at z1
            z1 = box.z1 - (box.z1 - box.z0) * d0
            z0 = box.z1 - (box.z1 - box.z0) * d1
        else:
            z0 = box.z0 + (box.z1 - box.z0) * d0
            z1 = box.z0 + (box.z1 - box.z0) * d1
        return Box(x0, x1, y0, y1, z0, z1)
    z0 = box.z0 + (box.z1 - box.z0) * frac0
    z1 = box.z0 + (box.z1 - box.z0) * frac1
    if side == "west":  # wall at x0
        x0 = box.x0 + (box.x1 - box.x0) * d0
        x1 = box.x0 + (box.x1 - box.x0) * d1
    else:
        x1 = box.x1 - (box.x1 - box.x0) * d0
        x0 = box.x1 - (box.x1 - box.x0) * d1
    return Box(x0, x1, y0, y1, z0, z1)


class _Builder:
    """Accumulates object seeds and blocked cells while a kitchen is laid out."""

    def __init__(self, rng: random.Random, width: int, depth: int):
        self.rng = rng
        self.width = width
        self.depth = depth
        self.objects: list[ObjectSeed] = []
        self.blocked: set[Cell] = set()
        self.counter_tops: list[int] = []
        self.wall_counters: list[tuple[int, _Run]] = []

    def add(self, seed: ObjectSeed) -> int:
        self.objects.append(seed)
        self.blocked |= seed.blocks
        return len(self.objects) - 1

    def box(self, cells: list[Cell], y0: float, y1: float, shrink: float = 0.0) -> Box:
        return _cells_box(cells, self.width, self.depth, y0, y1, shrink)

    # -------------------------------------------------------------- modules
    def floor(self) -> int:
        cells = [(x, z) for x in range(self.width) for z in range(self.depth)]
        return self.add(ObjectSeed("Floor", box=self.box(cells, 0.0, 0.0), capacity=200, levels=(0.0,)))

    def counter(self, run: _Run | None, cells: list[Cell], upper: bool, bays_along: list[list[Cell]]) -> int:
        # room for two objects per 0.25 m of counter length (counters are two cells deep)
        top = self.add(ObjectSeed("CounterTop", box=self.box(cells, 0.9, 0.95), capacity=max(4, len(cells)),
                                  levels=(0.95,), blocks=frozenset(cells)))
        self.counter_tops.append(top)
        if run is not None:
            self.wall_counters.append((top, run))
        for bay in bays_along:
            if self.rng.random() < 0.35:
                self.add(ObjectSeed("Drawer", box=self.box(bay, 0.62, 0.86, shrink=0.02), capacity=6, levels=(0.68,)))
                self.add(ObjectSeed("Cabinet", box=self.box(bay, 0.1, 0.58, shrink=0.02), capacity=6, levels=(0.15,)))
            else:
                self.add(ObjectSeed("Cabinet", box=self.box(bay, 0.1, 0.86, shrink=0.02), capacity=6,
                                    levels=(0.15, 0.5)))
            if upper and self.rng.random() < 0.4:
                self.add(ObjectSeed("Cabinet", box=self.box(bay, 1.5, 2.2, shrink=0.02), capacity=6,
                                    levels=(1.55, 1.9)))
        return top

    def stove(self, run: _Run, cells: list[Cell], burners: int) -> None:
        module = self.box(cells, 0.0, 0.95)
        columns = [(0.05, 0.5), (0.5, 0.95)]  # along the wall
        depth_rows = [(0.1, 0.5), (0.5, 0.9)] if burners == 4 else [(0.3, 0.7)]
        burner_ids = []
        for d in depth_rows:
            for f0, f1 in columns:
                box = _sub_box(module, run.side, f0 + 0.05, f1 - 0.05, 0.92, 0.95, d)
                burner_ids.append(self.add(ObjectSeed("StoveBurner", box=box, capacity=1, levels=(0.95,))))
        for i, burner in enumerate(burner_ids):
            f0 = 0.1 + i * 0.8 / len(burner_ids)
            knob = _sub_box(module, run.side, f0, f0 + 0.06, 0.86, 0.92, (0.96, 1.0))
            self.add(ObjectSeed("StoveKnob", box=knob, controls=burner))
        self.blocked |= set(cells)

    def sink(self, run: _Run, cells: list[Cell], bay: list[Cell]) -> None:
        module = self.box(cells, 0.0, 0.95)
        basin_box = _sub_box(module, run.side, 0.2, 0.8, 0.7, 0.9, (0.15, 0.85))
        self.add(ObjectSeed("Sink", box=_sub_box(module, run.side, 0.1, 0.9, 0.7, 0.95, (0.05, 0.95))))
        self.add(ObjectSeed("SinkBasin", box=basin_box, capacity=6, levels=(0.72,)))
        self.add(ObjectSeed("Cabinet", box=self.box(bay, 0.1, 0.6, shrink=0.02), capacity=6, levels=(0.15,)))
        self.blocked |= set(cells)

    def fridge(self, cells: list[Cell]) -> None:
        self.add(ObjectSeed("Fridge", box=self.box(cells, 0.0, 1.8, shrink=0.03), capacity=12,
                            levels=(0.45, 0.85, 1.25), blocks=frozenset(cells)))


def _split(total: int, parts: int, rng: random.Random) -> list[int]:
    """Split ``total`` wall cells into ``parts`` counter widths (some may be 0)."""
    widths = [0] * parts
    if total <= 0:
        return widths
    k = rng.randint(1, max(1, min(parts, total // 2)))
    chosen = rng.sample(range(parts), k)
    base, rest = divmod(total, k)
    for i, j in enumerate(chosen):
        widths[j] = base + (1 if i < rest else 0)
    return widths


def _bays(cells_by_along: list[list[Cell]]) -> list[list[Cell]]:
    """Group a counter's along-wall columns into cabinet bays of about 0.75 m (three columns)."""
    n = len(cells_by_along)
    bounds = list(range(0, n, 3)) + [n]
    if len(bounds) > 2 and bounds[-1] - bounds[-2] == 1:
        bounds.pop(-2)  # no one-column bay: widen the last one
    return [[c for column in cells_by_along[a:b] for c in column] for a, b in zip(bounds, bounds[1:])]


def _choose_runs(shape: str, w: int, d: int) -> list[_Run]:
    if shape == "line":
        return [_Run("north", 0, w - 1, ("start", "end"))]
    if shape == "L-west":
        return [_Run("north", 0, w - 1, ("end",)), _Run("west", 0, d - 3, ("start",))]
    if shape == "L-east":
        return [_Run("north", 0, w - 1, ("start",)), _Run("east", 0, d - 3, ("start",))]
    if shape == "U":
        return [_Run("north", 0, w - 1, ()), _Run("west", 0, d - 3, ("start",)), _Run("east", 0, d - 3, ("start",))]
    if shape == "galley":
        return [_Run("north", 0, w - 1, ("start", "end")), _Run("south", 0, w - 1, ("start", "end"))]
    raise AssertionError(shape)


def _layout_runs(b: _Builder, runs: list[_Run], rng: random.Random) -> None:
    # Fixed modules: the fridge at a free end, the stove and the sink somewhere along the runs.
    fridge_candidates = [(i, end) for i, run in enumerate(runs) for end in run.free_ends]
    fridge_run, fridge_end = rng.choice(fridge_candidates)
    stove_run = rng.randrange(len(runs))
    sink_run = rng.choice([i for i in range(len(runs)) if i != stove_run] or [stove_run])
    burners = 4 if rng.random() < 0.8 else 2
    for i, run in enumerate(runs):
        modules: list[tuple[str, int]] = []
        if i == stove_run:
            modules.append(("stove", 3 if burners == 4 else 2))
        if i == sink_run:
            modules.append(("sink", 3))
        rng.shuffle(modules)
        fixed = sum(w for _, w in modules) + (3 if i == fridge_run else 0)
        counters = _split(run.length - fixed, len(modules) + 1, rng)
        sequence: list[tuple[str, int]] = []
        for k, module in enumerate(modules):
            if counters[k]:
                sequence.append(("counter", counters[k]))
            sequence.append(module)
        if counters[-1]:
            sequence.append(("counter", counters[-1]))
        if i == fridge_run:
            sequence = [("fridge", 3)] + sequence if fridge_end == "start" else sequence + [("fridge", 3)]
        along = run.start
        for kind, width in sequence:
            if kind == "counter":
                # long counters are split into tops of at most eight cells (2 m)
                offset = 0
                while offset < width:
                    piece = min(8, width - offset)
                    if width - offset - piece == 1:
                        piece -= 1
                    columns = [_run_cells(run, along + offset + k, 1, 2, b.width, b.depth) for k in range(piece)]
                    cells = [c for col in columns for c in col]
                    b.counter(run, cells, upper=True, bays_along=_bays(columns))
                    offset += piece
            elif kind == "stove":
                b.stove(run, _run_cells(run, along, width, 2, b.width, b.depth), burners)
            elif kind == "sink":
                cells = _run_cells(run, along, width, 2, b.width, b.depth)
                b.sink(run, cells, cells)
            elif kind == "fridge":
                b.fridge(_run_cells(run, along, width, 3, b.width, b.depth))
            along += width


def _free_rect(b: _Builder, w: int, d: int, margin: int, rng: random.Random) -> list[Cell] | None:
    """A w×d block of free cells with ``margin`` free cells around it, near the room's middle."""
    options = []
    for x0 in range(margin, b.width - w - margin + 1):
        for z0 in range(margin, b.depth - d - margin + 1):
            ring = [(x, z) for x in range(x0 - margin, x0 + w + margin) for z in range(z0 - margin, z0 + d + margin)]
            if any(c in b.blocked for c in ring):
                continue
            cx, cz = x0 + w / 2, z0 + d / 2
            options.append((abs(cx - b.width / 2) + abs(cz - b.depth / 2), x0, z0))
    if not options:
        return None
    options.sort()
    _, x0, z0 = options[min(len(options) - 1, rng.randrange(3))]
    return [(x, z) for x in range(x0, x0 + w) for z in range(z0, z0 + d)]


def _wall_spot(b: _Builder, rng: random.Random, length: int) -> tuple[list[Cell], str] | None:
    """Free cells against a wall (for a shelf or the garbage can), keeping a free cell in front."""
    options = []
    for side in ("south", "west", "east", "north"):
        for a in range(0, (b.width if side in ("north", "south") else b.depth) - length + 1):
            run = _Run(side, 0, 0, ())
            cells = _run_cells(run, a, length, 1, b.width, b.depth)
            front = _run_cells(run, a, length, 2, b.width, b.depth)
            inside = all(0 <= c[0] < b.width and 0 <= c[1] < b.depth for c in front)
            if inside and all(c not in b.blocked for c in front):
                options.append((cells, side))
    if not options:
        return None
    return options[rng.randrange(len(options))]


# ------------------------------------------------------------------ what the kitchen holds
# Where each pickupable type tends to start: (receptacle type, weight).
_PLACES: dict[str, list[tuple[str, float]]] = {
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


def _choose_inventory(rng: random.Random) -> dict[str, int]:
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
            for receptacle_type, weight in _PLACES[object_type]:
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
    b = _Builder(rng, width, depth)
    b.floor()
    runs = _choose_runs(shape, width, depth)
    _layout_runs(b, runs, rng)
    # An island counter or a dining table in the middle of larger rooms.
    middle = rng.random()
    if shape != "galley" and middle < 0.35:
        cells = _free_rect(b, rng.randint(4, 6), 2, 2, rng)
        if cells:
            xs = sorted({c[0] for c in cells})
            columns = [[c for c in cells if c[0] == x] for x in xs]
            b.counter(None, cells, upper=False, bays_along=_bays(columns))
    elif middle < 0.8:
        cells = _free_rect(b, rng.randint(4, 5), 3, 2, rng)
        if cells:
            b.add(ObjectSeed("DiningTable", box=b.box(cells, 0.0, 0.76, shrink=0.05), capacity=14, levels=(0.76,),
                             blocks=frozenset(cells)))
    if rng.random() < 0.45:
        spot = _wall_spot(b, rng, 2)
        if spot:
            cells, _ = spot
            b.add(ObjectSeed("Shelf", box=b.box(cells, 0.0, 1.6, shrink=0.03), capacity=6, levels=(0.9, 1.3),
                             blocks=frozenset(cells)))
    spot = _wall_spot(b, rng, 1)
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
            box = _sub_box(top_box, run.side, start + 0.02, frac1 - 0.02, 0.95, 0.95 + height, (0.05, 0.75))
            capacity = {"Microwave": 4, "Toaster": 2, "CoffeeMachine": 1}[appliance]
            level = {"Microwave": 1.0, "Toaster": 1.0, "CoffeeMachine": 0.98}[appliance]
            b.add(ObjectSeed(appliance, box=box, parent=top, capacity=capacity, levels=(level,),
                             rotation=_facing_wall(run.side) + 180.0))
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
    counts = _choose_inventory(rng)
    place_objects(b.objects, counts, rng)
    start_rotation = rng.choice([0.0, 90.0, 180.0, 270.0])
    return SceneSpec(
        name=f"FloorPlan{number}", number=number, width=width, depth=depth, shape=shape, objects=b.objects,
        reachable=frozenset(reachable), start=(start_cell, start_rotation),
        notes={"attempt": attempt, "inventory": counts},
    )
