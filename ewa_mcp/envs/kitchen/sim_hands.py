"""The built-in kitchen's object actions: pick up, put, drop, open, close, slice, break, cook, toggle, create, spawn.

Each ``_a_<ActionName>`` answers the AI2-THOR action of that name. It checks every precondition first (the
object exists and is interactable, the hand, the receptacle's type and room, the tool a slice needs) and
raises ``ActionFailed`` naming the problem and the fix; only then does it change the kitchen.
"""

from __future__ import annotations

import random
from typing import Any

from .scene_stock import PLACES
from .sim_objects import HAND_REACH, SURFACE_TYPES, ActionFailed, SimObject
from .sim_world import SimWorld
from .vocabulary import (
    DELIVERABLE_TYPES,
    PIECE_COUNT,
    PIECE_FOR,
    PIECE_OF,
    RECEPTACLE_ACCEPTS,
    RECEPTACLE_CAPACITY,
    SLICING_TOOLS,
    accepts,
)


class HandActions(SimWorld):
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
                               f"{self._elsewhere(target, held)}")
        self.held = None
        self.held_from = None
        self._attach(held, target)

    def _elsewhere(self, full: SimObject, held: SimObject) -> str:
        """What to do when ``full`` has no room: the nearest receptacles of its kind (any counter for a
        counter) that take ``held`` and have room, else take something out."""
        kinds = {full.object_type} | ({"CounterTop", "DiningTable"} if full.object_type in SURFACE_TYPES else set())
        ax, az = self.agent_xz()

        def away(o: SimObject) -> float:
            x, _, z = self.position(o)
            return (x - ax) ** 2 + (z - az) ** 2

        others = sorted((o for o in self.objects if o is not full and o.active and o.object_type in kinds
                         and accepts(o.object_type, held.object_type) and self._room(o) > 0), key=away)
        if not others:
            return "take something out first"
        return (f"put it on another one with room ({', '.join(o.object_id for o in others[:3])}) "
                "or take something out first")

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
            preferences = PLACES.get(PIECE_OF.get(obj.object_type, obj.object_type), [("CounterTop", 1.0)])
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
