"""The built-in kitchen's object model: ``SimObject``, object ids, ``SimEvent`` and the failure an action raises.

Also the simulator's fixed measures (agent height, reach, field of view, visibility). Nothing here acts:
the state lives in sim_world.py, the actions in sim_moves.py and sim_hands.py, ``KitchenSim`` in sim.py.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .scenes import Box
from .vocabulary import TYPES, TypeSpec

AGENT_Y = 0.9  # AI2-THOR reports the default agent's position at about this height
HAND_REACH = 0.45  # where a held object floats in front of the agent
FIELD_OF_VIEW = 90.0
VIEW_HALF_ANGLE = 50.0  # half the field of view plus a margin for the object's own extent
NEAR_RANGE = 0.4  # closer than this an object is in view whatever the heading (the camera looks down)
DEFAULT_VISIBILITY = 1.5
SURFACE_TYPES = ("CounterTop", "DiningTable", "Shelf")
SLOT_PITCH = 0.2


class ActionFailed(Exception):
    def __init__(self, message: str, code: str = ""):
        super().__init__(message)
        self.message = message
        self.code = code


def format_object_id(object_type: str, x: float, y: float, z: float) -> str:
    return f"{object_type}|{x:+06.2f}|{y:+06.2f}|{z:+06.2f}"


class SimObject:
    __slots__ = (
        "object_id", "object_type", "name", "spec", "box", "parent", "children", "slot", "rest", "rotation",
        "capacity", "levels", "controls", "is_open", "is_toggled", "is_sliced", "is_cooked", "is_broken",
        "is_filled", "fill_liquid", "temperature", "is_dirty", "source_id", "piece_index", "active", "order",
        "static_meta", "fixed_meta",
    )

    def __init__(self, object_type: str, order: int):
        self.object_id = ""
        self.object_type = object_type
        self.name = ""
        self.spec: TypeSpec = TYPES[object_type]
        self.box: Box | None = None
        self.parent: SimObject | None = None
        self.children: list[SimObject] = []
        self.slot = 0
        self.rest: tuple[float, float] | None = None  # x, z where it lies on the floor
        self.rotation = 0.0
        self.capacity: int | None = None
        self.levels: tuple[float, ...] = ()
        self.controls: SimObject | None = None
        self.is_open = False
        self.is_toggled = False
        self.is_sliced = False
        self.is_cooked = False
        self.is_broken = False
        self.is_filled = False
        self.fill_liquid: str | None = None
        self.temperature = "RoomTemp"
        self.is_dirty = False
        self.source_id: str | None = None
        self.piece_index = 0
        self.active = True
        self.order = order
        self.static_meta: dict[str, Any] | None = None  # fields that never change, built once
        self.fixed_meta: dict[str, Any] | None = None  # position and box of furniture, built once


@dataclass
class SimEvent:
    """What ``KitchenSim.step`` returns: the same attributes an ai2thor ``Event`` offers."""

    metadata: dict[str, Any]
    frame: Any = None

    def __bool__(self) -> bool:
        return bool(self.metadata["lastActionSuccess"])
