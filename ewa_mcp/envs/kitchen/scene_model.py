"""The kitchens' names and shapes: scene names, ``Box``, ``ObjectSeed``, ``SceneSpec`` and the 0.25 m grid.

What a generated kitchen is, not how it is made (scene_layout.py, scene_stock.py and scenes.py make it).
World axes follow AI2-THOR: y is up, the floor is the x–z plane, rotation 0° faces +z (north).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

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
