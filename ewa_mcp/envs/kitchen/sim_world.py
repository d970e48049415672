"""The built-in kitchen's state: its objects, the agent's pose, what is where, and who can reach what.

``SimWorld`` loads a scene (``reset``), places objects (slots on surfaces and shelves, the floor, the hand),
answers what the agent can see and reach (``sight``: distance, field of view, closed receptacles), and keeps
containment (``_attach``/``_detach``/``_room``). The actions that change it are in sim_moves.py and
sim_hands.py; heating rules in sim_heat.py; the AI2-THOR metadata in sim_metadata.py.
"""

from __future__ import annotations

import math
from typing import Any

from .scenes import GRID, SceneSpec, build_scene, canonical_scene, cell_to_world
from .sim_objects import (
    DEFAULT_VISIBILITY,
    HAND_REACH,
    NEAR_RANGE,
    SLOT_PITCH,
    VIEW_HALF_ANGLE,
    ActionFailed,
    SimEvent,
    SimObject,
    format_object_id,
)
from .vocabulary import RECEPTACLE_CAPACITY


class SimWorld:
    """One kitchen's state; ``KitchenSim`` (sim.py) adds the actions."""

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
        # The pieces of one sliced food lie where it lay: together they take the room of one object. An
        # appliance standing on a counter is not counted: the kitchen took its room off the counter's capacity
        # when it was built (counting it too made a counter with a toaster and two items on it "full").
        held = {c.source_id or c.object_id for c in receptacle.children
                if not (receptacle.object_type == "CounterTop" and c.spec.category == "appliance")}
        return capacity - len(held)

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


    # Heating (sim_heat.HeatRules) and the AI2-THOR metadata (sim_metadata.Reports) build on this state and are
    # mixed into KitchenSim (sim.py); they import this module, never the other way round.
    def _update_heat(self) -> None:
        raise NotImplementedError("sim_heat.HeatRules provides _update_heat")

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


    # ------------------------------------------------------------------ metadata (sim_metadata.Reports)
    def object_metadata(self, obj: SimObject) -> dict[str, Any]:
        raise NotImplementedError("sim_metadata.Reports provides object_metadata")

    def agent_metadata(self) -> dict[str, Any]:
        raise NotImplementedError("sim_metadata.Reports provides agent_metadata")

    def _event(self, action: str, success: bool, error: str, action_return: Any, code: str = "") -> SimEvent:
        raise NotImplementedError("sim_metadata.Reports provides _event")

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
