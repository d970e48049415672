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
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Any

from .scenes import GRID, SCENE_NAMES, Box, SceneSpec, _PLACES, build_scene, canonical_scene, cell_to_world
from .vocabulary import (
    DELIVERABLE_TYPES,
    PIECE_COUNT,
    PIECE_FOR,
    PIECE_OF,
    RECEPTACLE_ACCEPTS,
    RECEPTACLE_CAPACITY,
    SLICING_TOOLS,
    TYPES,
    TypeSpec,
    accepts,
)

AGENT_Y = 0.9  # AI2-THOR reports the default agent's position at about this height
HAND_REACH = 0.45  # where a held object floats in front of the agent
FIELD_OF_VIEW = 90.0
VIEW_HALF_ANGLE = 50.0  # half the field of view plus a margin for the object's own extent
NEAR_RANGE = 0.4  # closer than this an object is in view whatever the heading (the camera looks down)
DEFAULT_VISIBILITY = 1.5
SURFACE_TYPES = ("CounterTop", "DiningTable", "Shelf")
SLOT_PITCH = 0.2
# What ai2thor's client sends before any scene is loaded.
_BEFORE_SCENE = frozenset({"Reset", "Initialize", "GetScenesInBuild", "ChangeResolution", "Pass", "Done"})


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


class KitchenSim:
    """One kitchen. ``reset(scene)`` loads a FloorPlan; ``step(action, **args)`` acts in it."""

    def __init__(self, scene: str | None = "FloorPlan1", *, visibility_distance: float = DEFAULT_VISIBILITY,
                 width: int = 300, height: int = 300):
        self.visibility_distance = visibility_distance
        self.width = width
        self.height = height
        self.render_image = False
        self.spec: SceneSpec | None = None
        self.objects: list[SimObject] = []
        self.by_id: dict[str, SimObject] = {}
        self.held: SimObject | None = None
        # Where the held object was picked up from: that receptacle always takes it back (its slot is its own).
        self.held_from: SimObject | None = None
        self._sight_memo: dict[int, tuple[bool, float, str]] | None = None
        self.cell: tuple[int, int] = (0, 0)
        self.rotation = 0.0
        self.horizon = 30.0
        self.sequence_id = 0
        self._order = 0
        self.last_event: SimEvent | None = None
        if scene is not None:
            self.reset(scene)

    # ------------------------------------------------------------------ scene loading
    def reset(self, scene: str) -> SimEvent:
        self.spec = build_scene(canonical_scene(scene))
        self.objects = []
        self.by_id = {}
        self.held = None
        self.held_from = None
        self._order = 0
        seeds = self.spec.objects
        made: list[SimObject] = []
        names: dict[str, int] = {}
        for seed in seeds:
            obj = self._new(seed.object_type)
            obj.box = seed.box
            obj.capacity = seed.capacity
            obj.levels = seed.levels
            obj.rotation = seed.rotation
            if seed.parent is not None:
                self._attach(obj, made[seed.parent])
            if seed.controls is not None:
                obj.controls = made[seed.controls]
            names[obj.object_type] = names.get(obj.object_type, 0) + 1
            obj.name = f"{obj.object_type}_{names[obj.object_type]}"
            self._register(obj)
            made.append(obj)
        (self.cell, self.rotation) = self.spec.start
        self.horizon = 30.0
        self._update_heat()
        self.last_event = self._event("Reset", True, "", None)
        return self.last_event

    def _new(self, object_type: str) -> SimObject:
        self._order += 1
        return SimObject(object_type, self._order)

    def _register(self, obj: SimObject) -> None:
        x, y, z = self.position(obj)
        object_id = format_object_id(obj.object_type, x, y, z) if obj.source_id is None else obj.object_id
        while object_id in self.by_id:  # two objects of a type created at one spot: nudge the id
            x += 0.01
            object_id = format_object_id(obj.object_type, x, y, z)
        obj.object_id = object_id
        self.by_id[object_id] = obj
        self.objects.append(obj)

    # ------------------------------------------------------------------ geometry
    def agent_xz(self) -> tuple[float, float]:
        assert self.spec is not None
        return cell_to_world(self.cell, self.spec.width, self.spec.depth)

    def forward(self) -> tuple[float, float]:
        rad = math.radians(self.rotation)
        return (math.sin(rad), math.cos(rad))

    def position(self, obj: SimObject) -> tuple[float, float, float]:
        if obj.box is not None:
            return obj.box.center
        if obj is self.held or (obj.parent is None and obj.rest is None):
            ax, az = self.agent_xz()
            fx, fz = self.forward()
            return (ax + fx * HAND_REACH, 1.0, az + fz * HAND_REACH)
        if obj.parent is None or obj.parent.object_type == "Floor":
            assert obj.rest is not None
            return (obj.rest[0], obj.spec.size[1] / 2, obj.rest[1])
        return self._slot_position(obj.parent, obj)

    def _slot_position(self, parent: SimObject, obj: SimObject) -> tuple[float, float, float]:
        half_h = obj.spec.size[1] / 2
        offset = obj.piece_index * 0.03
        if parent.box is None:  # a pan, plate or bowl: contents sit on it
            px, py, pz = self.position(parent)
            return (px + offset + ((obj.slot % 3) - 1) * 0.06, py + parent.spec.size[1] / 2 + half_h,
                    pz + ((obj.slot // 3) % 3 - 1) * 0.06)
        box = parent.box
        sx, _, sz = box.size
        along_x = sx >= sz
        long_len, short_len = (sx, sz) if along_x else (sz, sx)
        cols = max(1, int(long_len / SLOT_PITCH))
        rows = max(1, min(3, int(short_len / SLOT_PITCH)))
        per_level = cols * rows
        levels = parent.levels or (box.y1,)
        index = obj.slot
        level = (index // per_level) % len(levels)
        stack = index // (per_level * len(levels))
        col = index % cols
        row = (index // cols) % rows
        a = (col + 0.5) / cols
        b = (row + 0.5) / rows
        if along_x:
            x, z = box.x0 + a * sx + offset, box.z0 + b * sz
        else:
            x, z = box.x0 + b * sx + offset, box.z0 + a * sz
        return (x, levels[level] + stack * 0.05 + half_h, z)

    def _aabb(self, obj: SimObject) -> Box:
        if obj.box is not None:
            return obj.box
        x, y, z = self.position(obj)
        sx, sy, sz = obj.spec.size
        return Box(x - sx / 2, x + sx / 2, y - sy / 2, y + sy / 2, z - sz / 2, z + sz / 2)

    def _enclosing_closed(self, obj: SimObject) -> SimObject | None:
        node = obj.parent
        while node is not None:
            if node.spec.openable and not node.is_open:
                return node
            node = node.parent
        return None

    def sight(self, obj: SimObject) -> tuple[bool, float, str]:
        """(visible, distance, why not) from the agent's current pose."""
        memo = self._sight_memo
        if memo is None:
            return self._sight(obj)
        seen = memo.get(id(obj))
        if seen is None:
            seen = memo[id(obj)] = self._sight(obj)
        return seen

    def _sight(self, obj: SimObject) -> tuple[bool, float, str]:
        if obj is self.held or self._held_ancestor(obj):
            return True, HAND_REACH, ""
        ax, az = self.agent_xz()
        if obj.box is not None:
            b = obj.box
            tx = min(max(ax, b.x0), b.x1)
            tz = min(max(az, b.z0), b.z1)
        else:
            tx, _, tz = self.position(obj)
        dx, dz = tx - ax, tz - az
        distance = math.hypot(dx, dz)
        closed = self._enclosing_closed(obj)
        if closed is not None:
            return False, distance, f"it is inside the closed {closed.object_id}; open that first"
        parent = obj.parent
        if parent is not None and parent.object_type != "Floor":
            # What rests in or on a receptacle is within reach exactly when the receptacle is: the
            # observation lists it as that receptacle's contents, so it must act the same.
            reachable, _, why = self.sight(parent)
            return reachable, distance, why and f"it is in/on {parent.object_id}, which is out of reach: {why}"
        if distance > self.visibility_distance:
            return False, distance, (f"it is {distance:.2f} m away and the reach is {self.visibility_distance:.1f} m; "
                                     "teleport to it or move closer")
        if distance > NEAR_RANGE:
            bearing = math.degrees(math.atan2(dx, dz))
            off = abs((bearing - self.rotation + 180.0) % 360.0 - 180.0)
            if off > VIEW_HALF_ANGLE:
                return False, distance, (f"it is out of view ({off:.0f}° off the agent's heading); "
                                         "rotate towards it or teleport to it")
        return True, distance, ""

    def _held_ancestor(self, obj: SimObject) -> bool:
        node = obj.parent
        while node is not None:
            if node is self.held:
                return True
            node = node.parent
        return False

    def reachable_cells(self) -> frozenset[tuple[int, int]]:
        assert self.spec is not None
        return self.spec.reachable

    # ------------------------------------------------------------------ containment
    def _attach(self, obj: SimObject, parent: SimObject, slot: int | None = None) -> None:
        obj.parent = parent
        obj.rest = None
        if slot is None:
            used = {c.slot for c in parent.children}
            slot = 0
            while slot in used:
                slot += 1
        obj.slot = slot
        parent.children.append(obj)
        if parent.object_type == "Floor":  # things put on the floor lie just ahead of the agent
            ax, az = self.agent_xz()
            fx, fz = self.forward()
            obj.rest = (ax + fx * GRID * 0.8, az + fz * GRID * 0.8)

    def _detach(self, obj: SimObject) -> None:
        if obj.parent is not None:
            obj.parent.children.remove(obj)
        obj.parent = None
        obj.rest = None

    def _room(self, receptacle: SimObject) -> int:
        capacity = receptacle.capacity if receptacle.capacity is not None else RECEPTACLE_CAPACITY.get(
            receptacle.object_type, 8)
        # The pieces of one sliced food lie where it lay: together they take the room of one object.
        return capacity - len({c.source_id or c.object_id for c in receptacle.children})

    def ancestors(self, obj: SimObject) -> list[SimObject]:
        chain = []
        node = obj.parent
        while node is not None:
            chain.append(node)
            node = node.parent
        return chain

    def descendants(self, obj: SimObject) -> list[SimObject]:
        out: list[SimObject] = []
        stack = list(reversed(obj.children))
        while stack:
            node = stack.pop()
            out.append(node)
            stack.extend(reversed(node.children))
        return out

    def burner_lit(self, burner: SimObject) -> bool:
        return any(o.controls is burner and o.is_toggled for o in self.objects if o.object_type == "StoveKnob")

    def _update_heat(self) -> None:
        """Apply what running heat sources and the fridge do to the objects in them."""
        for obj in self.objects:
            if not obj.active or obj.box is not None:
                continue
            parent = obj.parent
            hot = cold = False
            if parent is not None and obj is not self.held:
                kind = parent.object_type
                if kind == "Microwave" and parent.is_toggled:
                    hot = True
                elif kind == "Toaster" and parent.is_toggled and obj.object_type == "BreadSliced":
                    hot = True
                elif kind == "StoveBurner" and self.burner_lit(parent):
                    hot = True
                elif kind in ("Pan", "Pot") and parent.parent is not None and parent is not self.held \
                        and parent.parent.object_type == "StoveBurner" and self.burner_lit(parent.parent):
                    hot = True
                elif kind == "CoffeeMachine" and parent.is_toggled and obj.spec.can_fill:
                    obj.is_filled = True
                    obj.fill_liquid = "coffee"
                    hot = True
                elif kind == "Fridge":
                    cold = True
            obj.temperature = "Hot" if hot else "Cold" if cold else "RoomTemp"
            if hot and obj.spec.cookable:
                obj.is_cooked = True

    # ------------------------------------------------------------------ stepping
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

    def _object(self, args: dict[str, Any]) -> SimObject:
        object_id = args.get("objectId")
        if not object_id:
            raise ActionFailed("objectId is required for this action", "MissingArguments")
        obj = self.by_id.get(str(object_id))
        if obj is None or not obj.active:
            raise ActionFailed(f"Object ID appears to be invalid: {object_id!r} is not in this scene")
        return obj

    def _require_interactable(self, obj: SimObject, args: dict[str, Any]) -> None:
        if args.get("forceAction"):
            return
        visible, _, why = self.sight(obj)
        if not visible:
            raise ActionFailed(f"{obj.object_id} is not interactable: {why}")

    # -- lifecycle
    def _a_Initialize(self, args: dict[str, Any]) -> dict[str, float]:
        grid = float(args.get("gridSize", GRID))
        if abs(grid - GRID) > 1e-6:
            raise ActionFailed(f"gridSize {grid} is not supported: these kitchens are laid out on a {GRID} m grid",
                               "InvalidArgument")
        visibility = float(args.get("visibilityDistance", self.visibility_distance))
        if visibility <= 0:
            raise ActionFailed("visibilityDistance must be positive", "InvalidArgument")
        self.visibility_distance = visibility
        self.render_image = bool(args.get("renderImage", self.render_image))
        return {"cameraNearPlane": 0.1, "cameraFarPlane": 20.0}

    def _a_Reset(self, args: dict[str, Any]) -> SimEvent:
        scene = str(args.get("sceneName") or (self.spec.name if self.spec else "FloorPlan1"))
        try:
            canonical_scene(scene)
        except ValueError as exc:
            raise ActionFailed(str(exc), "InvalidArgument") from None
        return self.reset(scene)

    def _a_GetScenesInBuild(self, args: dict[str, Any]) -> list[str]:
        return [f"{name}_physics" for name in SCENE_NAMES] + list(SCENE_NAMES)

    def _a_ChangeResolution(self, args: dict[str, Any]) -> None:
        self.width = int(args.get("x", self.width))
        self.height = int(args.get("y", self.height))

    def _a_Pass(self, args: dict[str, Any]) -> None:
        return None

    _a_Done = _a_Pass

    def _a_GetReachablePositions(self, args: dict[str, Any]) -> list[dict[str, float]]:
        assert self.spec is not None
        return [
            {"x": x, "y": AGENT_Y, "z": z}
            for x, z in sorted(cell_to_world(c, self.spec.width, self.spec.depth) for c in self.spec.reachable)
        ]

    # -- navigation
    def _move(self, args: dict[str, Any], turn: float) -> None:
        assert self.spec is not None
        magnitude = float(args.get("moveMagnitude", GRID))
        steps = round(magnitude / GRID)
        if steps < 1 or abs(steps * GRID - magnitude) > 1e-6:
            raise ActionFailed(f"moveMagnitude must be a positive multiple of {GRID} m", "InvalidArgument")
        rad = math.radians(self.rotation + turn)
        dx, dz = round(math.sin(rad)), round(math.cos(rad))
        cell = self.cell
        for _ in range(steps):
            nxt = (cell[0] + dx, cell[1] + dz)
            if nxt not in self.spec.reachable:
                blocker = self._blocker(nxt)
                raise ActionFailed(f"Agent is blocked: moving {GRID} m would hit {blocker}")
            cell = nxt
        self.cell = cell

    def _blocker(self, cell: tuple[int, int]) -> str:
        assert self.spec is not None
        x, z = cell_to_world(cell, self.spec.width, self.spec.depth)
        for obj in self.objects:
            b = obj.box
            if b is not None and obj.object_type not in ("Floor", "StoveKnob") and obj.parent is None \
                    and b.x0 <= x <= b.x1 and b.z0 <= z <= b.z1:
                return obj.object_id
        return "a wall"

    def _a_MoveAhead(self, args: dict[str, Any]) -> None:
        self._move(args, 0.0)

    def _a_MoveBack(self, args: dict[str, Any]) -> None:
        self._move(args, 180.0)

    def _a_MoveRight(self, args: dict[str, Any]) -> None:
        self._move(args, 90.0)

    def _a_MoveLeft(self, args: dict[str, Any]) -> None:
        self._move(args, -90.0)

    def _rotate(self, args: dict[str, Any], sign: float) -> None:
        degrees = float(args.get("degrees", 90.0))
        if degrees <= 0 or abs(degrees / 90.0 - round(degrees / 90.0)) > 1e-6:
            raise ActionFailed("degrees must be a positive multiple of 90 in these grid kitchens", "InvalidArgument")
        self.rotation = (self.rotation + sign * degrees) % 360.0

    def _a_RotateRight(self, args: dict[str, Any]) -> None:
        self._rotate(args, 1.0)

    def _a_RotateLeft(self, args: dict[str, Any]) -> None:
        self._rotate(args, -1.0)

    def _look(self, args: dict[str, Any], sign: float) -> None:
        horizon = self.horizon + sign * float(args.get("degrees", 30.0))
        if not -30.0 <= horizon <= 60.0:
            raise ActionFailed("the camera horizon must stay between -30 and 60 degrees")
        self.horizon = horizon

    def _a_LookDown(self, args: dict[str, Any]) -> None:
        self._look(args, 1.0)

    def _a_LookUp(self, args: dict[str, Any]) -> None:
        self._look(args, -1.0)

    def _a_Teleport(self, args: dict[str, Any]) -> None:
        assert self.spec is not None
        position = args.get("position") or {k: args[k] for k in ("x", "y", "z") if k in args}
        if "x" not in position or "z" not in position:
            raise ActionFailed("Teleport needs a position {x, y, z}", "MissingArguments")
        x, z = float(position["x"]), float(position["z"])
        cell = self.spec.cell(x, z)
        wx, wz = cell_to_world(cell, self.spec.width, self.spec.depth)
        if abs(wx - x) > 0.01 or abs(wz - z) > 0.01 or cell not in self.spec.reachable:
            raise ActionFailed(f"Teleport failed: ({x:.2f}, {z:.2f}) is not a reachable position; "
                               "use one from GetReachablePositions")
        rotation = args.get("rotation", self.rotation)
        if isinstance(rotation, dict):
            rotation = rotation.get("y", self.rotation)
        rotation = float(rotation) % 360.0
        if abs(rotation / 90.0 - round(rotation / 90.0)) > 1e-6:
            raise ActionFailed("rotation must be a multiple of 90 degrees in these grid kitchens", "InvalidArgument")
        horizon = float(args.get("horizon", self.horizon))
        if not -30.0 <= horizon <= 60.0:
            raise ActionFailed("horizon must be between -30 and 60 degrees", "InvalidArgument")
        self.cell, self.rotation, self.horizon = cell, round(rotation / 90.0) * 90.0 % 360.0, horizon

    _a_TeleportFull = _a_Teleport

    # -- manipulation
    def _a_PickupObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.pickupable:
            raise ActionFailed(f"{obj.object_id} is not pickupable")
        if self.held is not None:
            if obj is self.held:
                raise ActionFailed(f"the agent is already holding {obj.object_id}")
            raise ActionFailed(f"Agent's hand is already holding {self.held.object_id}; put it down first "
                               "(PutObject or DropHandObject)")
        self._require_interactable(obj, args)
        self.held_from = obj.parent
        self._detach(obj)
        self.held = obj

    def _a_PutObject(self, args: dict[str, Any]) -> None:
        held = self.held
        if held is None:
            raise ActionFailed("Nothing is in the agent's hand to put; pick something up first")
        target = self._object(args)
        if not target.spec.receptacle:
            raise ActionFailed(f"{target.object_id} is not a receptacle")
        if target is held or self._held_ancestor(target):
            raise ActionFailed(f"cannot put {held.object_id} into itself or into something it carries")
        self._require_interactable(target, args)
        if target.spec.openable and not target.is_open:
            raise ActionFailed(f"Target receptacle {target.object_id} is closed; open it first")
        if not accepts(target.object_type, held.object_type):
            allowed = sorted(RECEPTACLE_ACCEPTS.get(target.object_type, ()))
            hint = ", ".join(allowed[:8]) + (" …" if len(allowed) > 8 else "")
            raise ActionFailed(f"{held.object_type} cannot be placed in/on {target.object_type} "
                               f"(a {target.object_type} takes {hint})")
        if self._room(target) <= 0 and target is not self.held_from:
            raise ActionFailed(f"No valid positions to place object found: {target.object_id} is full; "
                               "take something out first")
        self.held = None
        self.held_from = None
        self._attach(held, target)

    def _a_DropHandObject(self, args: dict[str, Any]) -> None:
        held = self.held
        if held is None:
            raise ActionFailed("Nothing is in the agent's hand to drop")
        # It falls onto the surface just ahead of the agent if there is one with room, else to the floor.
        ax, az = self.agent_xz()
        fx, fz = self.forward()
        px, pz = ax + fx * HAND_REACH, az + fz * HAND_REACH
        target = None
        for obj in self.objects:
            b = obj.box
            if obj.object_type in SURFACE_TYPES and b is not None and b.x0 <= px <= b.x1 and b.z0 <= pz <= b.z1 \
                    and accepts(obj.object_type, held.object_type) and self._room(obj) > 0:
                target = obj
                break
        self.held = None
        self.held_from = None
        if target is not None:
            self._attach(held, target)
        else:
            floor = next(o for o in self.objects if o.object_type == "Floor")
            self._attach(held, floor)

    def _a_OpenObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.openable:
            raise ActionFailed(f"{obj.object_id} is not openable")
        self._require_interactable(obj, args)
        if obj.is_open:
            raise ActionFailed(f"{obj.object_id} is already open")
        if obj.object_type == "Microwave" and obj.is_toggled:
            raise ActionFailed(f"{obj.object_id} is running; turn it off (ToggleObjectOff) before opening it")
        obj.is_open = True

    def _a_CloseObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.openable:
            raise ActionFailed(f"{obj.object_id} is not openable")
        self._require_interactable(obj, args)
        if not obj.is_open:
            raise ActionFailed(f"{obj.object_id} is already closed")
        obj.is_open = False

    def _a_SliceObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.sliceable:
            what = "it is already a piece" if obj.object_type in PIECE_OF else "its type cannot be sliced"
            raise ActionFailed(f"{obj.object_id} is not sliceable: {what}")
        if obj is self.held:
            raise ActionFailed(f"put {obj.object_id} down before slicing it")
        if self.held is None or self.held.object_type not in SLICING_TOOLS:
            holding = self.held.object_id if self.held is not None else "nothing"
            raise ActionFailed("SliceObject needs a Knife or ButterKnife in the agent's hand "
                               f"(holding {holding}); pick one up first")
        self._require_interactable(obj, args)
        self._split_into_pieces(obj)

    def _a_BreakObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.breakable:
            raise ActionFailed(f"{obj.object_id} is not breakable")
        if obj.is_broken:
            raise ActionFailed(f"{obj.object_id} is already broken")
        if obj is self.held:
            raise ActionFailed(f"put {obj.object_id} down before breaking it")
        self._require_interactable(obj, args)
        if obj.object_type == "Egg":  # a broken egg is a cracked egg, as in AI2-THOR
            self._split_into_pieces(obj)
        else:
            obj.is_broken = True

    def _split_into_pieces(self, obj: SimObject) -> None:
        parent, slot, rest = obj.parent, obj.slot, obj.rest
        assert parent is not None and obj is not self.held  # callers refuse held objects
        piece_type = PIECE_FOR[obj.object_type]
        self._detach(obj)
        obj.active = False
        obj.is_sliced = True
        del self.by_id[obj.object_id]
        self.objects.remove(obj)
        for i in range(PIECE_COUNT[obj.object_type]):
            piece = self._new(piece_type)
            piece.source_id = obj.object_id
            piece.piece_index = i
            piece.object_id = f"{obj.object_id}|{piece_type}_{i}"
            piece.name = f"{obj.name}_{piece_type}_{i}"
            piece.is_sliced = True  # a goal on the source type is met by its pieces
            piece.is_cooked = obj.is_cooked
            piece.temperature = obj.temperature
            piece.rotation = obj.rotation
            self._attach(piece, parent, slot)
            if parent.object_type == "Floor" and rest is not None:
                piece.rest = (rest[0] + i * 0.03, rest[1])
            self._register(piece)

    def _a_CookObject(self, args: dict[str, Any]) -> None:
        obj = self._object(args)
        if not obj.spec.cookable:
            raise ActionFailed(f"{obj.object_id} is not cookable")
        if obj.is_cooked:
            raise ActionFailed(f"{obj.object_id} is already cooked")
        self._require_interactable(obj, args)
        obj.is_cooked = True

    def _toggle(self, args: dict[str, Any], on: bool) -> None:
        obj = self._object(args)
        if not obj.spec.toggleable:
            if obj.object_type == "StoveBurner":
                knobs = [o.object_id for o in self.objects if o.controls is obj]
                raise ActionFailed(f"{obj.object_id} is not toggleable: turn the StoveKnob that controls it "
                                   f"({', '.join(knobs) or 'none'})")
            raise ActionFailed(f"{obj.object_id} is not toggleable")
        self._require_interactable(obj, args)
        if obj.is_toggled == on:
            raise ActionFailed(f"{obj.object_id} is already {'on' if on else 'off'}")
        if on and obj.object_type == "Microwave" and obj.is_open:
            raise ActionFailed(f"{obj.object_id} is open; close it before turning it on")
        obj.is_toggled = on

    def _a_ToggleObjectOn(self, args: dict[str, Any]) -> None:
        self._toggle(args, True)

    def _a_ToggleObjectOff(self, args: dict[str, Any]) -> None:
        self._toggle(args, False)

    # -- scene edits
    def _a_CreateObjectAtLocation(self, args: dict[str, Any]) -> str:
        object_type = str(args.get("objectType", ""))
        if object_type not in DELIVERABLE_TYPES:
            raise ActionFailed(f"objectType {object_type!r} cannot be created; creatable types: "
                               f"{', '.join(sorted(DELIVERABLE_TYPES))}", "InvalidArgument")
        position = args.get("position") or {}
        try:
            x, y, z = float(position["x"]), float(position.get("y", 1.0)), float(position["z"])
        except (KeyError, TypeError, ValueError):
            raise ActionFailed("CreateObjectAtLocation needs a position {x, y, z}", "MissingArguments") from None
        # The object settles on the highest open surface under the point that can take it.
        candidates = []
        for obj in self.objects:
            b = obj.box
            if b is None or obj.object_type not in SURFACE_TYPES + ("Floor",) or not obj.levels:
                continue
            if b.x0 <= x <= b.x1 and b.z0 <= z <= b.z1 and obj.levels[0] <= y + 0.05 \
                    and accepts(obj.object_type, object_type) and self._room(obj) > 0:
                candidates.append((obj.levels[0], obj.order, obj))
        if not candidates:
            raise ActionFailed(f"No valid positions to place object found at ({x:.2f}, {y:.2f}, {z:.2f})")
        target = max(candidates, key=lambda c: (c[0], -c[1]))[2]
        new = self._new(object_type)
        rotation = args.get("rotation", 0.0)
        new.rotation = float(rotation.get("y", 0.0) if isinstance(rotation, dict) else rotation)
        new.capacity = RECEPTACLE_CAPACITY.get(object_type) if new.spec.receptacle else None
        count = sum(1 for o in self.objects if o.object_type == object_type) + 1
        new.name = f"{object_type}_{count}"
        self._attach(new, target)
        if target.object_type == "Floor":
            new.rest = (x, z)
        self._register(new)
        return new.object_id

    def _a_InitialRandomSpawn(self, args: dict[str, Any]) -> None:
        """Re-place every pickupable object at random (seeded) in compatible receptacles."""
        assert self.spec is not None
        seed = args.get("randomSeed", 0)
        rng = random.Random(f"spawn:{self.spec.name}:{seed}")
        movable = [o for o in self.objects if o.spec.pickupable]
        self.held = None
        self.held_from = None
        for obj in movable:
            self._detach(obj)
        for obj in movable:
            preferences = _PLACES.get(PIECE_OF.get(obj.object_type, obj.object_type), [("CounterTop", 1.0)])
            options = []
            for receptacle_type, weight in preferences:
                for target in self.objects:
                    if target.object_type == receptacle_type and target is not obj and \
                            accepts(receptacle_type, obj.object_type) and \
                            self._room(target) > (0 if target.box is not None else 5) and \
                            obj not in self.ancestors(target):
                        options.append((weight, target))
            if not options:
                options = [(1.0, o) for o in self.objects if o.object_type == "CounterTop" and self._room(o) > 0]
            total = sum(w for w, _ in options)
            pick = rng.random() * total
            chosen = options[-1][1]
            for weight, target in options:
                pick -= weight
                if pick <= 0:
                    chosen = target
                    break
            self._attach(obj, chosen)

    # ------------------------------------------------------------------ metadata
    def _static_metadata(self, obj: SimObject) -> dict[str, Any]:
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

    @staticmethod
    def _box_metadata(x: float, y: float, z: float, box: Box) -> dict[str, Any]:
        cx, cy, cz = box.center
        sx, sy, sz = box.size
        return {
            "position": {"x": round(x, 4), "y": round(y, 4), "z": round(z, 4)},
            "axisAlignedBoundingBox": {
                "center": {"x": round(cx, 4), "y": round(cy, 4), "z": round(cz, 4)},
                "size": {"x": round(sx, 4), "y": round(sy, 4), "z": round(sz, 4)},
            },
        }

    def object_metadata(self, obj: SimObject) -> dict[str, Any]:
        if obj.static_meta is None:
            obj.static_meta = self._static_metadata(obj)
        meta = dict(obj.static_meta)
        if obj.box is not None:  # furniture and appliances never move: their geometry is computed once
            if obj.fixed_meta is None:
                obj.fixed_meta = self._box_metadata(*obj.box.center, obj.box)
            meta.update(obj.fixed_meta)
        else:
            x, y, z = self.position(obj)
            sx, sy, sz = obj.spec.size
            meta["position"] = {"x": x, "y": y, "z": z}
            meta["axisAlignedBoundingBox"] = {"center": {"x": x, "y": y, "z": z}, "size": {"x": sx, "y": sy, "z": sz}}
        visible, distance, _ = self.sight(obj)
        meta["rotation"] = {"x": 0.0, "y": obj.rotation, "z": 0.0}
        meta["visible"] = visible
        meta["isInteractable"] = visible
        meta["distance"] = distance
        if obj.spec.receptacle:
            meta["receptacleObjectIds"] = [c.object_id for c in self.descendants(obj)] if obj.children else []
        else:
            meta["receptacleObjectIds"] = None
        parent = obj.parent
        if parent is None:
            meta["parentReceptacles"] = None
        elif parent.parent is None:
            meta["parentReceptacles"] = [parent.object_id]
        else:
            meta["parentReceptacles"] = [p.object_id for p in self.ancestors(obj)]
        meta["isOpen"] = obj.is_open
        meta["openness"] = 1.0 if obj.is_open else 0.0
        meta["isPickedUp"] = obj is self.held
        meta["isSliced"] = obj.is_sliced
        meta["isCooked"] = obj.is_cooked
        meta["isBroken"] = obj.is_broken
        meta["isToggled"] = obj.is_toggled or (obj.object_type == "StoveBurner" and self.burner_lit(obj))
        meta["isDirty"] = obj.is_dirty
        meta["isFilledWithLiquid"] = obj.is_filled
        meta["fillLiquid"] = obj.fill_liquid
        meta["temperature"] = obj.temperature
        return meta

    def agent_metadata(self) -> dict[str, Any]:
        x, z = self.agent_xz()
        return {
            "name": "agent",
            "position": {"x": x, "y": AGENT_Y, "z": z},
            "rotation": {"x": 0.0, "y": self.rotation, "z": 0.0},
            "cameraHorizon": self.horizon,
            "isStanding": True,
            "inHighFrictionArea": False,
        }

    def _event(self, action: str, success: bool, error: str, action_return: Any, code: str = "") -> SimEvent:
        x, z = self.agent_xz() if self.spec is not None else (0.0, 0.0)
        held = self.held
        bounds = self.spec.bounds if self.spec is not None else Box(0, 0, 0, 0, 0, 0)
        self._sight_memo = {}  # one pose for the whole event: a receptacle's reach is worked out once
        try:
            objects = [self.object_metadata(o) for o in self.objects] if self.spec is not None else []
        finally:
            self._sight_memo = None
        metadata = {
            "objects": objects,
            "agent": self.agent_metadata() if self.spec is not None else {},
            "inventoryObjects": [{"objectId": held.object_id, "objectType": held.object_type}] if held else [],
            "heldObjectPose": None,
            "sceneName": f"{self.spec.name}_physics" if self.spec is not None else "",
            "lastAction": action,
            "lastActionSuccess": success,
            "errorMessage": error,
            "errorCode": code,
            "actionReturn": action_return,
            "screenWidth": self.width,
            "screenHeight": self.height,
            "fov": FIELD_OF_VIEW,
            "cameraPosition": {"x": x, "y": AGENT_Y + 0.675, "z": z},
            "sceneBounds": {
                "center": dict(zip("xyz", bounds.center)),
                "size": dict(zip("xyz", bounds.size)),
            },
            "collided": False,
            "isSceneAtRest": True,
            "agentId": 0,
            "sequenceId": self.sequence_id,
            "thirdPartyCameras": [],
            "colors": [],
        }
        return SimEvent(metadata)

    # ------------------------------------------------------------------ introspection (tests, planner)
    def find(self, object_id: str) -> SimObject:
        return self.by_id[object_id]

    def snapshot(self) -> dict[str, Any]:
        """A comparable copy of the whole mutable state (used to prove failed actions change nothing)."""
        return {
            "agent": (self.cell, self.rotation, self.horizon),
            "held": self.held.object_id if self.held else None,
            "objects": [
                (o.object_id, o.parent.object_id if o.parent else None, o.slot, o.rest, o.is_open, o.is_toggled,
                 o.is_sliced, o.is_cooked, o.is_broken, o.is_filled, o.temperature)
                for o in self.objects
            ],
        }
