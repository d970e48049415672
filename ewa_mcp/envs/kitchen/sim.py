"""A deterministic pure-Python kitchen that answers AI2-THOR actions with AI2-THOR metadata.

``KitchenSim`` has the shape of ``ai2thor.controller.Controller`` where it matters:
``step(action="PickupObject", objectId=...)`` returns an event whose ``metadata`` carries
``lastActionSuccess``, ``errorMessage``, ``actionReturn``, ``agent`` and ``objects`` (every
object with AI2-THOR's fields). A failed action changes nothing: every action checks all its
preconditions before it mutates anything.

Semantics kept from AI2-THOR: one object in hand; objects are interactable when visible (within
``visibilityDistance``, in the 90° field of view, not shut inside a closed receptacle) unless
``forceAction``; SliceObject needs a Knife or ButterKnife in hand and replaces the object by
``<Type>Sliced`` pieces (an egg by one ``EggCracked``); CookObject cooks instantly; food in a
Pan/Pot on a burner whose StoveKnob is on, in a running Microwave, or bread slices in a running
Toaster become cooked; receptacles accept only compatible types and have limited room.

The simulator is split by job: sim_objects.py (``SimObject``, object ids, ``SimEvent``, ``ActionFailed``, the
fixed measures), sim_world.py (``SimWorld``: the scene's state, placement, sight and reach, containment),
sim_heat.py (cooking and heating rules), sim_metadata.py (the AI2-THOR metadata), sim_moves.py (lifecycle and
navigation actions) and sim_hands.py (object actions). This module joins them into ``KitchenSim`` and
dispatches ``step`` to the ``_a_<ActionName>`` handler of the action.
"""

from __future__ import annotations

from typing import Any

from .sim_hands import HandActions
from .sim_heat import HeatRules
from .sim_metadata import Reports
from .sim_moves import MoveActions
from .sim_objects import (
    AGENT_Y,
    DEFAULT_VISIBILITY,
    FIELD_OF_VIEW,
    HAND_REACH,
    NEAR_RANGE,
    SLOT_PITCH,
    SURFACE_TYPES,
    VIEW_HALF_ANGLE,
    ActionFailed,
    SimEvent,
    SimObject,
    format_object_id,
)

__all__ = [
    "AGENT_Y", "DEFAULT_VISIBILITY", "FIELD_OF_VIEW", "HAND_REACH", "NEAR_RANGE", "SLOT_PITCH", "SURFACE_TYPES",
    "VIEW_HALF_ANGLE", "ActionFailed", "KitchenSim", "SimEvent", "SimObject", "format_object_id",
]

# What ai2thor's client sends before any scene is loaded.
_BEFORE_SCENE = frozenset({"Reset", "Initialize", "GetScenesInBuild", "ChangeResolution", "Pass", "Done"})


class KitchenSim(MoveActions, HandActions, HeatRules, Reports):
    """One kitchen. ``reset(scene)`` loads a FloorPlan; ``step(action, **args)`` acts in it."""

    def step(self, action: str | dict[str, Any] | None = None, **args: Any) -> SimEvent:
        if isinstance(action, dict):
            args = {**action, **args}
            action = args.pop("action", None)
        args.pop("sequenceId", None)
        args.pop("raise_for_failure", None)
        name = str(action or "")
        handler = getattr(self, f"_a_{name}", None) if name.isidentifier() else None
        try:
            if handler is None:
                raise ActionFailed(f"Invalid action: {name!r} is not an action this kitchen knows", "InvalidAction")
            if self.spec is None and name not in _BEFORE_SCENE:
                raise ActionFailed("No scene is loaded; call Reset with a sceneName first", "InvalidAction")
            result = handler(args)
            if isinstance(result, SimEvent):
                self.last_event = result
                return result
            self._update_heat()
            self.last_event = self._event(name, True, "", result)
        except ActionFailed as failure:
            self.last_event = self._event(name, False, failure.message, None, failure.code)
        return self.last_event
