"""The kitchen's task models: the start of a kitchen episode and the goal kinds with a typed model (the other
goal kinds it checks, cooked_with and holds_only, are read by the kernel's open ``DomainGoal``). Declared on
``KITCHEN`` (``__init__.py``), from which the kernel assembles the task schema (ewa_mcp/core/taskmodel.py)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from ewa_mcp.core.taskmodel import StrictModel


class KitchenStart(StrictModel):
    kind: Literal["kitchen"] = "kitchen"
    scene: str = "FloorPlan1"
    seed: int = 0


class ObjectState(StrictModel):
    """Embodied (kitchen): some object of exactly this type has ``state[prop] == value``.

    Sliced or cracked pieces count for their source type (TomatoSliced for Tomato)."""

    kind: Literal["object_state"] = "object_state"
    object_type: str
    prop: Literal["isSliced", "isCooked", "isBroken", "isToggled", "isOpen", "isPickedUp"]
    value: bool = True


class ObjectIn(StrictModel):
    """Embodied (kitchen): some object of this type (or a piece of it) is in/on this receptacle type."""

    kind: Literal["object_in"] = "object_in"
    object_type: str
    receptacle_type: str
    # When set, the object must also satisfy these states (e.g. cooked tomato slices on a plate).
    with_state: dict[str, bool] = Field(default_factory=dict)
