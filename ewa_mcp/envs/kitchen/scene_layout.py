"""Kitchen layout: counters along the walls built from modules, and free spots in the room.

A kitchen's walls get runs of counters (line, L, U or galley: ``choose_runs``); ``layout_runs`` fills each run
with modules — a fridge at a free end, a stove with its burners and knobs, a sink, counter tops with cabinets and
drawers under them and wall cabinets above — through a ``Builder`` that collects the object seeds and the
cells they block. ``free_rect`` and ``wall_spot`` find room for an island, a table, a shelf or the garbage can.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

from .scene_model import GRID, Box, Cell, ObjectSeed, cell_to_world


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


def facing_wall(side: str) -> float:
    """The agent rotation that faces a run standing against ``side``."""
    return {"north": 0.0, "east": 90.0, "south": 180.0, "west": 270.0}[side]


def _cells_box(cells: list[Cell] | frozenset[Cell], width: int, depth: int, y0: float, y1: float,
               shrink: float = 0.0) -> Box:
    xs = [cell_to_world(c, width, depth)[0] for c in cells]
    zs = [cell_to_world(c, width, depth)[1] for c in cells]
    half = GRID / 2 - shrink
    return Box(min(xs) - half, max(xs) + half, y0, y1, min(zs) - half, max(zs) + half)


def sub_box(box: Box, side: str, frac0: float, frac1: float, y0: float, y1: float,
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


class Builder:
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
                box = sub_box(module, run.side, f0 + 0.05, f1 - 0.05, 0.92, 0.95, d)
                burner_ids.append(self.add(ObjectSeed("StoveBurner", box=box, capacity=1, levels=(0.95,))))
        for i, burner in enumerate(burner_ids):
            f0 = 0.1 + i * 0.8 / len(burner_ids)
            knob = sub_box(module, run.side, f0, f0 + 0.06, 0.86, 0.92, (0.96, 1.0))
            self.add(ObjectSeed("StoveKnob", box=knob, controls=burner))
        self.blocked |= set(cells)

    def sink(self, run: _Run, cells: list[Cell], bay: list[Cell]) -> None:
        module = self.box(cells, 0.0, 0.95)
        basin_box = sub_box(module, run.side, 0.2, 0.8, 0.7, 0.9, (0.15, 0.85))
        self.add(ObjectSeed("Sink", box=sub_box(module, run.side, 0.1, 0.9, 0.7, 0.95, (0.05, 0.95))))
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


def cabinet_bays(cells_by_along: list[list[Cell]]) -> list[list[Cell]]:
    """Group a counter's along-wall columns into cabinet bays of about 0.75 m (three columns)."""
    n = len(cells_by_along)
    bounds = list(range(0, n, 3)) + [n]
    if len(bounds) > 2 and bounds[-1] - bounds[-2] == 1:
        bounds.pop(-2)  # no one-column bay: widen the last one
    return [[c for column in cells_by_along[a:b] for c in column] for a, b in zip(bounds, bounds[1:])]


def choose_runs(shape: str, w: int, d: int) -> list[_Run]:
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


def layout_runs(b: Builder, runs: list[_Run], rng: random.Random) -> None:
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
                    b.counter(run, cells, upper=True, bays_along=cabinet_bays(columns))
                    offset += piece
            elif kind == "stove":
                b.stove(run, _run_cells(run, along, width, 2, b.width, b.depth), burners)
            elif kind == "sink":
                cells = _run_cells(run, along, width, 2, b.width, b.depth)
                b.sink(run, cells, cells)
            elif kind == "fridge":
                b.fridge(_run_cells(run, along, width, 3, b.width, b.depth))
            along += width


def free_rect(b: Builder, w: int, d: int, margin: int, rng: random.Random) -> list[Cell] | None:
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


def wall_spot(b: Builder, rng: random.Random, length: int) -> tuple[list[Cell], str] | None:
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
