"""AI2-THOR metadata of the built-in kitchen: each object's fields, the agent's, and the whole event.

The fields and their spelling are AI2-THOR's (``objectId``, ``isInteractable``, ``parentReceptacles`` …), so a
session reads ``KitchenSim`` and the real controller alike. What never changes is built once per object.
"""

from __future__ import annotations

from typing import Any

from .scenes import Box
from .sim_objects import AGENT_Y, FIELD_OF_VIEW, SimEvent, SimObject
from .sim_world import SimWorld
from .vocabulary import PIECE_OF


def static_metadata(obj: SimObject) -> dict[str, Any]:
    spec = obj.spec
    static: dict[str, Any] = {
        "name": obj.name,
        "objectId": obj.object_id,
        "objectType": obj.object_type,
        "receptacle": spec.receptacle,
        "openable": spec.openable,
        "pickupable": spec.pickupable,
        "moveable": spec.moveable,
        "sliceable": spec.sliceable,
        "cookable": spec.cookable,
        "breakable": spec.breakable,
        "toggleable": spec.toggleable,
        "dirtyable": spec.dirtyable,
        "canFillWithLiquid": spec.can_fill,
        "canBeUsedUp": False,
        "isUsedUp": False,
        "isHeatSource": spec.heat_source,
        "isColdSource": spec.cold_source,
        "salientMaterials": list(spec.materials) or None,
        "mass": spec.mass,
        "isMoving": False,
        "objectOrientedBoundingBox": None,
        "controlledObjects": [obj.controls.object_id] if obj.controls is not None else None,
    }
    if obj.source_id is not None:
        static["sourceObjectId"] = obj.source_id
        static["sourceType"] = PIECE_OF[obj.object_type]
    return static


def box_metadata(x: float, y: float, z: float, box: Box) -> dict[str, Any]:
    cx, cy, cz = box.center
    sx, sy, sz = box.size
    return {
        "position": {"x": round(x, 4), "y": round(y, 4), "z": round(z, 4)},
        "axisAlignedBoundingBox": {
            "center": {"x": round(cx, 4), "y": round(cy, 4), "z": round(cz, 4)},
            "size": {"x": round(sx, 4), "y": round(sy, 4), "z": round(sz, 4)},
        },
    }


def object_metadata(world: SimWorld, obj: SimObject) -> dict[str, Any]:
    if obj.static_meta is None:
        obj.static_meta = static_metadata(obj)
    meta = dict(obj.static_meta)
    if obj.box is not None:  # furniture and appliances never move: their geometry is computed once
        if obj.fixed_meta is None:
            obj.fixed_meta = box_metadata(*obj.box.center, obj.box)
        meta.update(obj.fixed_meta)
    else:
        x, y, z = world.position(obj)
        sx, sy, sz = obj.spec.size
        meta["position"] = {"x": x, "y": y, "z": z}
        meta["axisAlignedBoundingBox"] = {"center": {"x": x, "y": y, "z": z}, "size": {"x": sx, "y": sy, "z": sz}}
    visible, distance, _ = world.sight(obj)
    meta["rotation"] = {"x": 0.0, "y": obj.rotation, "z": 0.0}
    meta["visible"] = visible
    meta["isInteractable"] = visible
    meta["distance"] = distance
    if obj.spec.receptacle:
        meta["receptacleObjectIds"] = [c.object_id for c in world.descendants(obj)] if obj.children else []
    else:
        meta["receptacleObjectIds"] = None
    parent = obj.parent
    if parent is None:
        meta["parentReceptacles"] = None
    elif parent.parent is None:
        meta["parentReceptacles"] = [parent.object_id]
    else:
        meta["parentReceptacles"] = [p.object_id for p in world.ancestors(obj)]
    meta["isOpen"] = obj.is_open
    meta["openness"] = 1.0 if obj.is_open else 0.0
    meta["isPickedUp"] = obj is world.held
    meta["isSliced"] = obj.is_sliced
    meta["isCooked"] = obj.is_cooked
    meta["isBroken"] = obj.is_broken
    meta["isToggled"] = obj.is_toggled or (obj.object_type == "StoveBurner" and world.burner_lit(obj))
    meta["isDirty"] = obj.is_dirty
    meta["isFilledWithLiquid"] = obj.is_filled
    meta["fillLiquid"] = obj.fill_liquid
    meta["temperature"] = obj.temperature
    return meta


def agent_metadata(world: SimWorld) -> dict[str, Any]:
    x, z = world.agent_xz()
    return {
        "name": "agent",
        "position": {"x": x, "y": AGENT_Y, "z": z},
        "rotation": {"x": 0.0, "y": world.rotation, "z": 0.0},
        "cameraHorizon": world.horizon,
        "isStanding": True,
        "inHighFrictionArea": False,
    }


def scene_event(world: SimWorld, action: str, success: bool, error: str, action_return: Any, code: str = "") -> SimEvent:
    x, z = world.agent_xz() if world.spec is not None else (0.0, 0.0)
    held = world.held
    bounds = world.spec.bounds if world.spec is not None else Box(0, 0, 0, 0, 0, 0)
    world._sight_memo = {}  # one pose for the whole event: a receptacle's reach is worked out once
    try:
        objects = [object_metadata(world, o) for o in world.objects] if world.spec is not None else []
    finally:
        world._sight_memo = None
    metadata = {
        "objects": objects,
        "agent": agent_metadata(world) if world.spec is not None else {},
        "inventoryObjects": [{"objectId": held.object_id, "objectType": held.object_type}] if held else [],
        "heldObjectPose": None,
        "sceneName": f"{world.spec.name}_physics" if world.spec is not None else "",
        "lastAction": action,
        "lastActionSuccess": success,
        "errorMessage": error,
        "errorCode": code,
        "actionReturn": action_return,
        "screenWidth": world.width,
        "screenHeight": world.height,
        "fov": FIELD_OF_VIEW,
        "cameraPosition": {"x": x, "y": AGENT_Y + 0.675, "z": z},
        "sceneBounds": {
            "center": dict(zip("xyz", bounds.center)),
            "size": dict(zip("xyz", bounds.size)),
        },
        "collided": False,
        "isSceneAtRest": True,
        "agentId": 0,
        "sequenceId": world.sequence_id,
        "thirdPartyCameras": [],
        "colors": [],
    }
    return SimEvent(metadata)


class Reports(SimWorld):
    """Mixed into KitchenSim: the AI2-THOR metadata of its state."""

    def object_metadata(self, obj: SimObject) -> dict[str, Any]:
        return object_metadata(self, obj)

    def agent_metadata(self) -> dict[str, Any]:
        return agent_metadata(self)

    def _event(self, action: str, success: bool, error: str, action_return: Any, code: str = "") -> SimEvent:
        return scene_event(self, action, success, error, action_return, code)
