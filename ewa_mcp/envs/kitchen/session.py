"""One kitchen as an agent meets it, over any AI2-THOR-shaped controller.

The session turns agent-level requests ("pick up the Apple", "teleport to Fridge_1") into
AI2-THOR actions on a controller — the built-in ``KitchenSim`` or a real
``ai2thor.controller.Controller`` — and reads back only AI2-THOR metadata, so both backends
share every rule here: object references and handles, teleporting to an object, deliveries
from the shop (their rules in deliveries.py), the observation and the final state.

Object references. An agent may name an object by
  * its objectId (``Apple|+01.00|+00.95|-01.25``),
  * its handle, shown in every observation (``Apple_2``; numbered per type in the order objects
    appear, never reused within an episode), or
  * its bare type (``Apple``; exact type names only, case-insensitive: Egg is not Eggplant and
    Knife is not ButterKnife). A bare type resolves to the only object of that type; if there
    are several, to the only one in reach, or to the nearest one in reach (the reply says which
    and lists the others). With none in reach, a request fails and lists where each one is,
    except Teleport, which goes to the nearest. A sliced food's type names its pieces
    (``Tomato`` after slicing means a ``TomatoSliced`` piece).

What closed doors hide is not known. An object inside a closed cabinet, drawer, fridge or microwave that
the agent has not seen open this episode (``hidden_by``) is, to every reference, as if it were not there:
a bare type neither resolves to it nor is said to be absent because of it, and its handle or objectId
gets the same reply as one that names nothing ("No Egg in sight ... Closed cabinets, drawers and the
fridge you have not looked into may hold one"). So a tool call cannot find, or rule out, food the agent
has not looked for. Once the receptacle has been seen open the object resolves as any other.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, Protocol

from ewa_mcp.core.environment import EnvError
from .actions import TABLE
from .commands import Command, parse_command
from .deliveries import deliver_order
from .vocabulary import (
    PIECE_FOR,
    PIECE_OF,
    SHOP_SOLD_TYPES,
    STAND_INS,
    canonical_type,
    similar_types,
)

TELEPORT_REACH = 1.2  # metres: stand well inside the 1.5 m interaction range
TELEPORT_HALF_ANGLE = 44.0  # keep the target inside the 90° field of view
HEADINGS = {0: "north (+z)", 90: "east (+x)", 180: "south (-z)", 270: "west (-x)"}
_HANDLE = re.compile(r"^([A-Za-z]+)_(\d+)$")


class KitchenActionError(EnvError):
    """A kitchen action that failed; the kitchen is unchanged. The message says why and what to do."""


class Controller(Protocol):
    """What the session needs from a backend: ai2thor's Controller has this shape, and so has KitchenSim."""

    last_event: Any

    def step(self, action: Any = None, **args: Any) -> Any: ...

    def reset(self, scene: str) -> Any: ...


@dataclass
class ActionReport:
    action: str
    ok: bool = True
    target: str | None = None
    notes: list[str] = field(default_factory=list)
    effects: list[str] = field(default_factory=list)

    def line(self, handle_of: Any) -> str:
        words = [self.action]
        if self.target:
            words.append(handle_of(self.target))
        text = f"Done: {' '.join(words)}."
        for extra in self.notes + self.effects:
            text += f" {extra}"
        return text


class KitchenSession:
    def __init__(self, controller: Controller, backend: str, scene: str, seed: int = 0):
        self.controller = controller
        self.backend = backend
        self.scene = scene
        self.seed = seed
        self.handles: dict[str, str] = {}  # objectId -> handle
        self.by_handle: dict[str, str] = {}  # lower-case handle -> objectId
        self._counters: dict[str, int] = {}
        self.meta: dict[str, Any] = {}
        self.objects: dict[str, dict[str, Any]] = {}
        self.reachable: list[tuple[float, float]] = []
        self.deliveries: list[dict[str, Any]] = []
        self._events_seen = 0
        self._pending_notes: list[str] = []
        self.last_report: ActionReport | None = None
        self._last_effects: list[str] = []
        # objectId -> how it got cooked ("Pan", "Pot", "StoveBurner", "Microwave", "Toaster", or "CookObject" for
        # the instant action): a method goal ("fried in the pan") reads it from the final state's cookedBy.
        self.cooked_by: dict[str, str] = {}
        # pieces whose cooking came from the whole food they were cut from (cooked whole, then sliced or
        # cracked): the final state's cookedWhole, so a method goal can tell "crack, then fry" from the reverse
        self.cooked_whole: set[str] = set()
        # openable receptacles the agent has seen open this episode (it opened them, or they stood open in an
        # observation): what a closed one holds is shown only once it has been looked into, as a person
        # remembers what the fridge held after shutting it
        self.seen_open: set[str] = set()

    # ------------------------------------------------------------------ lifecycle
    def reset(self) -> None:
        event = self.controller.reset(self.scene)
        if self.seed:
            event = self.controller.step(action="InitialRandomSpawn", randomSeed=self.seed, forceVisible=False,
                                         numPlacementAttempts=5, placeStationary=True)
            if not event.metadata["lastActionSuccess"]:
                raise KitchenActionError(f"could not scatter the objects with seed {self.seed}: "
                                         f"{event.metadata['errorMessage']}")
        reach = self.controller.step(action="GetReachablePositions")
        self.reachable = [(p["x"], p["z"]) for p in reach.metadata["actionReturn"] or []]
        self.handles.clear()
        self.by_handle.clear()
        self._counters.clear()
        self.deliveries.clear()
        self.cooked_by.clear()
        self.cooked_whole.clear()
        self.seen_open.clear()
        self._events_seen = 0
        self._pending_notes.clear()
        self.last_report = None
        self._refresh(reach.metadata)

    def _refresh(self, metadata: dict[str, Any]) -> None:
        self.meta = metadata
        self.objects = {o["objectId"]: o for o in metadata["objects"]}
        self.seen_open.update(i for i, o in self.objects.items() if o.get("openable") and o.get("isOpen"))
        for obj in metadata["objects"]:
            if obj["objectId"] not in self.handles:
                kind = obj["objectType"]
                self._counters[kind] = self._counters.get(kind, 0) + 1
                handle = f"{kind}_{self._counters[kind]}"
                self.handles[obj["objectId"]] = handle
                self.by_handle[handle.lower()] = obj["objectId"]

    def handle(self, object_id: str | None) -> str:
        if object_id is None:
            return "nothing"
        return self.handles.get(object_id, object_id)

    def _readable(self, message: str) -> str:
        """Replace objectIds in a backend message by handles."""
        for object_id in sorted(self.handles, key=len, reverse=True):
            if object_id in message:
                message = message.replace(object_id, self.handles[object_id])
        return message

    # ------------------------------------------------------------------ state access
    @property
    def agent(self) -> dict[str, Any]:
        return self.meta["agent"]

    @property
    def held_id(self) -> str | None:
        inventory = self.meta.get("inventoryObjects") or []
        return inventory[0]["objectId"] if inventory else None

    def parent_of(self, obj: dict[str, Any]) -> str | None:
        parents = obj.get("parentReceptacles") or []
        return parents[0] if parents else None

    def unlooked(self, object_id: str) -> bool:
        """Whether ``object_id`` is a closed openable receptacle the agent has not seen open this episode."""
        obj = self.objects.get(object_id) or {}
        return bool(obj.get("openable") and obj.get("receptacle") and not obj.get("isOpen")
                    and object_id not in self.seen_open)

    def hidden_by(self, obj: dict[str, Any]) -> str | None:
        """The closed, never-opened receptacle that encloses ``obj`` (so the agent cannot know it is there),
        or None when the agent can see or remembers it."""
        if obj.get("isPickedUp"):
            return None
        stack = list(obj.get("parentReceptacles") or [])
        visited: set[str] = set()
        while stack:
            parent = stack.pop()
            if parent in visited or parent not in self.objects:
                continue
            visited.add(parent)
            if self.unlooked(parent):
                return parent
            stack.extend(self.objects[parent].get("parentReceptacles") or [])
        return None

    def unlooked_receptacles(self) -> list[str]:
        """Handles of the closed receptacles not yet looked into (none of them hidden itself), sorted."""
        ids = [i for i, o in self.objects.items() if self.unlooked(i) and self.hidden_by(o) is None]
        return sorted((self.handle(i) for i in ids), key=_handle_order)

    # ------------------------------------------------------------------ references
    def resolve(self, ref: str, purpose: str) -> tuple[str, list[str]]:
        """(objectId, notes) for an agent's reference; ``purpose`` is "interact" or "teleport"."""
        text = (ref or "").strip().strip("[]'\"").strip()
        if not text:
            raise KitchenActionError("no object named; give a type (Apple), a handle (Apple_1) or an objectId")
        if text in self.objects and self.known(text):
            return text, []
        object_id = self.by_handle.get(text.lower())
        if object_id is not None and object_id not in self.objects:
            raise KitchenActionError(
                f"{self.handles[object_id]} no longer exists (it was sliced or cracked into pieces)"
            )
        if object_id is not None and self.known(object_id):
            return object_id, []
        if "|" in text:  # an id that names nothing, or something behind a door not yet opened: one reply
            raise KitchenActionError(f"no object in sight has the id {text!r}; use a handle from the observation, "
                                     f"such as {self._examples()}")
        handle_match = _HANDLE.match(text)
        kind = canonical_type(handle_match.group(1) if handle_match else text)
        if kind is None:  # no kitchen has such a type: saying so tells nothing about this kitchen
            hints = similar_types(text)
            hint = f" Did you mean {' or '.join(hints)}?" if hints else ""
            raise KitchenActionError(f"{text!r} is not an object type of this kitchen (names are exact AI2-THOR "
                                     f"types such as Apple, Knife, CounterTop).{hint}")
        if handle_match:
            same = sorted((h for h in self.by_handle.values() if self.objects.get(h, {}).get("objectType") == kind
                           and self.known(h)), key=self.handle)
            listed = ", ".join(self.handle(h) for h in same) or "none"
            raise KitchenActionError(f"no {text} in sight; the {kind} objects you have seen are: {listed}."
                                     f"{self._unlooked_hint('more')}")
        return self._resolve_type(kind, purpose)

    def known(self, object_id: str) -> bool:
        """Whether the agent may know ``object_id`` is there: it exists and no closed receptacle it has not
        seen open encloses it."""
        obj = self.objects.get(object_id)
        return obj is not None and self.hidden_by(obj) is None

    def _unlooked_hint(self, what: str) -> str:
        """Where an object not yet seen may be: the closed receptacles not looked into (the observation lists
        them, so naming them tells nothing new), or nothing when every one has been looked into."""
        if not self.unlooked_receptacles():
            return ""
        return (f" Closed cabinets, drawers and the fridge you have not looked into may hold {what}: "
                "open them with kitchen_open (OpenObject) to see.")

    def _missing_hint(self, kind: str) -> str:
        """What to do about a type the kitchen lacks: buy it (only what the shop sells), or use a stand-in
        that is here; otherwise nothing to suggest."""
        if kind in SHOP_SOLD_TYPES:
            advice = "it can be bought on the shopping site; deliveries arrive on a CounterTop."
        else:
            here = [t for t in STAND_INS.get(kind, ())
                    if any(o["objectType"] == t and self.known(i) for i, o in self.objects.items())]
            if not here:
                return " The shop does not sell it."
            advice = f"use {' or '.join(f'a {t}' for t in here)} instead."
        # While doors stay unopened the kitchen may still hold one: the advice is then said as a fallback
        # (a plain "Use a Pan instead" read as "there is no Pot" and sent a player to the wrong vessel).
        return f" If none turns up, {advice}" if self.unlooked_receptacles() else f" {advice[0].upper()}{advice[1:]}"

    def _examples(self) -> str:
        names = [self.handle(i) for i, o in self.objects.items() if o["pickupable"] and self.known(i)][:3]
        return ", ".join(names) or "CounterTop_1"

    def _resolve_type(self, kind: str, purpose: str) -> tuple[str, list[str]]:
        held = self.held_id
        # only what the agent may know is there: food behind a door it has not opened is neither found nor
        # ruled out, so the reply below is the same whether or not some lies hidden
        seen = [o for i, o in self.objects.items() if self.known(i)]
        candidates = [o for o in seen if o["objectType"] == kind]
        notes: list[str] = []
        if not candidates and kind in PIECE_FOR:
            pieces = [o for o in seen if o["objectType"] == PIECE_FOR[kind]]
            if pieces:
                candidates = pieces
                notes.append(f"{kind} is cut into {PIECE_FOR[kind]} pieces; using one of them.")
        if not candidates:
            raise KitchenActionError(f"No {kind} in sight: you have seen none in this kitchen."
                                     f"{self._unlooked_hint('one')}{self._missing_hint(kind)}")
        if purpose == "teleport":
            candidates = [o for o in candidates if o["objectId"] != held and not o["isPickedUp"]]
            if not candidates:
                raise KitchenActionError(f"the only {kind} is in your hand; there is nothing to teleport to")
        if len(candidates) == 1:
            return candidates[0]["objectId"], notes
        if purpose != "teleport":
            in_reach = [o for o in candidates if o["visible"]]
            if held is not None:  # the held object itself is no target for put/slice/...: prefer others
                in_reach = [o for o in in_reach if o["objectId"] != held] or in_reach
            if not in_reach:
                where = "; ".join(self._where(o) for o in sorted(candidates, key=lambda o: o["distance"]))
                example = self.handle(candidates[0]["objectId"])
                raise KitchenActionError(f"no {kind} is within reach; they are: {where}. "
                                         f"Teleport to one first (e.g. Teleport {example}).")
            candidates = in_reach
            if len(candidates) == 1:
                return candidates[0]["objectId"], notes
        candidates.sort(key=lambda o: (o["distance"], self._number(o["objectId"])))
        chosen = candidates[0]["objectId"]
        others = ", ".join(self.handle(o["objectId"]) for o in candidates[1:6])
        if len(candidates) > 6:  # a short list must not read as the whole one
            others += f" and {len(candidates) - 6} more"
        scope = "" if purpose == "teleport" else " in reach"
        notes.append(f"{kind} means {self.handle(chosen)}, the nearest{scope} (others: {others}); "
                     "name a handle to choose.")
        return chosen, notes

    def _number(self, object_id: str) -> int:
        match = _HANDLE.match(self.handle(object_id))
        return int(match.group(2)) if match else 0

    def _where(self, obj: dict[str, Any]) -> str:
        parent = self.parent_of(obj)
        if obj["isPickedUp"]:
            place = "in your hand"
        elif parent is None:
            place = "standing"
        else:
            p = self.objects.get(parent, {})
            closed = " (closed)" if p.get("openable") and not p.get("isOpen") else ""
            place = f"in/on {self.handle(parent)}{closed}"
        return f"{self.handle(obj['objectId'])} {place}, {obj['distance']:.1f} m away"

    # ------------------------------------------------------------------ stepping
    def _step(self, action: str, target: str | None = None, **args: Any) -> dict[str, Any]:
        before = self.objects
        if target is not None:
            args["objectId"] = target
        event = self.controller.step(action=action, **args)
        metadata = event.metadata
        if not metadata["lastActionSuccess"]:
            self.meta = metadata if metadata.get("objects") else self.meta
            shown = f"{action} {self.handle(target)}" if target else action
            raise KitchenActionError(f"{shown} failed: {self._readable(str(metadata['errorMessage']))}")
        self._refresh(metadata)
        self._note_cooking(action, before, self.objects)
        self._last_effects = self._effects(before, self.objects)
        return metadata

    def _note_cooking(self, action: str, before: dict[str, dict[str, Any]], after: dict[str, dict[str, Any]]) -> None:
        """Remember how each newly cooked object got cooked: by the instant CookObject, or by the heat source
        it sits in (its Pan or Pot on a lit burner, the burner itself, the Microwave, the Toaster). Pieces cut
        from a cooked object keep its method."""
        inherited = next((self.cooked_by[i] for i in before if i not in after and i in self.cooked_by), None)
        for object_id, obj in after.items():
            if not obj.get("isCooked") or object_id in self.cooked_by:
                continue
            if object_id not in before:
                if inherited is not None:
                    self.cooked_by[object_id] = inherited
                    self.cooked_whole.add(object_id)
                continue
            if before[object_id].get("isCooked"):
                continue
            if action == "CookObject":
                self.cooked_by[object_id] = "CookObject"
                continue
            parents = [after.get(p, {}).get("objectType", p.split("|", 1)[0])
                       for p in obj.get("parentReceptacles") or [] if isinstance(p, str)]
            source = next((t for t in ("Pan", "Pot", "Toaster", "Microwave", "StoveBurner") if t in parents), None)
            self.cooked_by[object_id] = source or "other"

    def _effects(self, before: dict[str, dict[str, Any]], after: dict[str, dict[str, Any]]) -> list[str]:
        effects: list[str] = []
        created = [i for i in after if i not in before]
        removed = [i for i in before if i not in after]
        if removed and created:
            effects.append(f"{', '.join(self.handle(i) for i in removed)} became "
                           f"{_compress([self.handle(i) for i in created])}.")
        elif created:
            effects.append(f"New: {_compress([self.handle(i) for i in created])}.")
        cooked = [i for i, o in after.items() if o["isCooked"] and i in before and not before[i]["isCooked"]]
        if cooked:
            effects.append(f"Now cooked: {_compress([self.handle(i) for i in cooked])}.")
        filled = [i for i, o in after.items() if o.get("isFilledWithLiquid") and i in before
                  and not before[i].get("isFilledWithLiquid")]
        if filled:
            effects.append(f"Now filled: {', '.join(self.handle(i) for i in filled)}.")
        return effects

    def _report(self, action: str, target: str | None, notes: list[str]) -> ActionReport:
        report = ActionReport(action=action, target=target, notes=notes, effects=list(self._last_effects))
        self.last_report = report
        return report

    # ------------------------------------------------------------------ agent actions
    def run(self, command: Command | str) -> ActionReport:
        """Perform one action written the AI2-THOR way (``PickupObject Apple``), as the action table says."""
        if isinstance(command, str):
            try:
                command = parse_command(command)
            except ValueError as exc:
                raise KitchenActionError(str(exc)) from None
        return self.perform(command.kitchen_action.name, command.args)

    def perform(self, name: str, args: dict[str, Any]) -> ActionReport:
        """Perform the table's action ``name`` (actions.py) with its parameters."""
        action = TABLE.by_name.get(name)
        if action is None:
            raise KitchenActionError(f"unknown kitchen action {name!r}; the actions are: {', '.join(TABLE.by_name)}")
        report: ActionReport = action.run(self, **args)
        return report

    def _thor(self, name: str, **args: Any) -> str:
        """The AI2-THOR name the action table gives action ``name`` with these arguments."""
        try:
            return TABLE.thor_for(name, args)
        except ValueError as exc:
            raise KitchenActionError(str(exc)) from None

    def move(self, direction: str) -> ActionReport:
        return self.plain_action(self._thor("move", direction=direction))

    def rotate(self, direction: str) -> ActionReport:
        return self.plain_action(self._thor("rotate", direction=direction))

    def look(self, direction: str) -> ActionReport:
        return self.plain_action(self._thor("look", direction=direction))

    def teleport(self, ref: str) -> ActionReport:
        object_id, notes = self.resolve(ref, "teleport")
        obj = self.objects[object_id]
        if obj["isPickedUp"] or self._inside_held(obj):
            raise KitchenActionError(f"{self.handle(object_id)} is in your hand; there is nothing to teleport to")
        pose = self.pose_facing(obj)
        if pose is None:
            raise KitchenActionError(f"no standing position within {TELEPORT_REACH} m faces {self.handle(object_id)}; "
                                     "it cannot be reached in this kitchen")
        x, z, rotation = pose
        self._step("TeleportFull", x=x, y=self.agent["position"]["y"], z=z,
                   rotation={"x": 0.0, "y": rotation, "z": 0.0}, horizon=30.0, standing=True)
        after = self.objects[object_id]
        if not after["visible"]:
            parent = self.parent_of(after)
            closed = self.objects.get(parent or "", {})
            if closed.get("openable") and not closed.get("isOpen"):
                notes.append(f"It is inside the closed {self.handle(parent)}: open that to reach it.")
        return self._report("Teleport", object_id, notes)

    def _inside_held(self, obj: dict[str, Any]) -> bool:
        held = self.held_id
        return held is not None and held in (obj.get("parentReceptacles") or [])

    def pose_facing(self, obj: dict[str, Any]) -> tuple[float, float, float] | None:
        """The nearest reachable (x, z, rotation) from which ``obj`` is within reach and in view."""
        box = obj.get("axisAlignedBoundingBox") or {}
        center = box.get("center") or obj["position"]
        size = box.get("size") or {"x": 0.0, "z": 0.0}
        x0, x1 = center["x"] - size["x"] / 2, center["x"] + size["x"] / 2
        z0, z1 = center["z"] - size["z"] / 2, center["z"] + size["z"] / 2
        best: tuple[float, float, float, float, float] | None = None
        for px, pz in self.reachable:
            tx, tz = min(max(px, x0), x1), min(max(pz, z0), z1)
            # Aim at the object's centre line when the box is long, so the whole span is in view.
            dx, dz = tx - px, tz - pz
            distance = math.hypot(dx, dz)
            if distance > TELEPORT_REACH:
                continue
            if distance < 1e-6:
                dx, dz = center["x"] - px, center["z"] - pz
            bearing = math.degrees(math.atan2(dx, dz)) % 360.0
            rotation = (round(bearing / 90.0) * 90) % 360
            off = abs((bearing - rotation + 180.0) % 360.0 - 180.0)
            if off > TELEPORT_HALF_ANGLE and distance > 0.4:
                continue
            key = (round(distance, 3), round(off, 1), px, pz, float(rotation))
            if best is None or key < best:
                best = key
        if best is None:
            return None
        return best[2], best[3], best[4]

    def plain_action(self, action: str) -> ActionReport:
        """Any AI2-THOR action without an object (Pass, LookUp): step, report."""
        self._step(action)
        return self._report(action, None, [])

    def object_action(self, action: str, ref: str) -> ActionReport:
        """Any AI2-THOR action on one object in reach (OpenObject Fridge_1): resolve, step, report."""
        object_id, notes = self.resolve(ref, "interact")
        try:
            self._step(action, object_id)
        except KitchenActionError as exc:
            closed = self._closed_around(self.objects.get(object_id) or {})
            if closed is None or action in ("OpenObject", "CloseObject") or "closed" in str(exc):
                raise
            raise KitchenActionError(f"{exc}. It is inside the closed {self.handle(closed)}: open that first "
                                     f"(OpenObject {self.handle(closed)}).") from None
        return self._report(action, object_id, notes)

    def _closed_around(self, obj: dict[str, Any]) -> str | None:
        """The nearest closed openable receptacle that holds ``obj``, if any."""
        for parent in obj.get("parentReceptacles") or []:
            container = self.objects.get(parent) or {}
            if container.get("openable") and not container.get("isOpen"):
                return parent
        return None

    def pickup(self, ref: str) -> ActionReport:
        return self.object_action("PickupObject", ref)

    def put(self, ref: str) -> ActionReport:
        if self.held_id is None:
            raise KitchenActionError("PutObject failed: nothing is in your hand; pick something up first")
        return self.object_action("PutObject", ref)

    def drop(self) -> ActionReport:
        held = self.held_id
        if held is None:
            raise KitchenActionError("DropHandObject failed: nothing is in your hand")
        self._step("DropHandObject")
        parent = self.parent_of(self.objects[held]) if held in self.objects else None
        notes = [f"It landed in/on {self.handle(parent)}."] if parent else []
        return self._report("DropHandObject", held, notes)

    def open(self, ref: str) -> ActionReport:
        return self.object_action("OpenObject", ref)

    def close(self, ref: str) -> ActionReport:
        return self.object_action("CloseObject", ref)

    def slice(self, ref: str) -> ActionReport:
        return self.object_action("SliceObject", ref)

    def cook(self, ref: str) -> ActionReport:
        return self.object_action("CookObject", ref)

    def break_(self, ref: str) -> ActionReport:
        return self.object_action("BreakObject", ref)

    def toggle(self, ref: str, on: bool) -> ActionReport:
        return self.object_action(self._thor("toggle", state="on" if on else "off"), ref)

    # ------------------------------------------------------------------ deliveries (deliveries.py)
    def receive_deliveries(self, events: list[dict[str, Any]]) -> list[str]:
        """Materialise groceries from new shop orders on a CounterTop; returns what arrived."""
        arrived: list[str] = []
        while self._events_seen < len(events):
            event = events[self._events_seen]
            self._events_seen += 1
            if not isinstance(event, dict) or event.get("site") != "shop" or event.get("type") != "order_placed":
                continue
            arrived.extend(deliver_order(self, event.get("order") or {}))
        self._pending_notes.extend(arrived)
        return arrived

    def take_notes(self) -> list[str]:
        notes, self._pending_notes = self._pending_notes, []
        return notes

    # ------------------------------------------------------------------ final state
    def final_state(self) -> dict[str, Any]:
        objects = []
        for obj in self.meta.get("objects", []):
            record = dict(obj)
            record["handle"] = self.handle(obj["objectId"])
            if obj.get("isCooked") and obj["objectId"] in self.cooked_by:
                record["cookedBy"] = self.cooked_by[obj["objectId"]]
                if obj["objectId"] in self.cooked_whole:
                    record["cookedWhole"] = True
            if obj["objectType"] in PIECE_OF:
                record.setdefault("sourceType", PIECE_OF[obj["objectType"]])
            objects.append(record)
        scene = str(self.meta.get("sceneName", self.scene)).removesuffix("_physics")
        return {
            "backend": self.backend,
            "scene": scene,
            "seed": self.seed,
            "objects": objects,
            "agent": self.meta.get("agent", {}),
            "held": self.held_id,
            "deliveries": [dict(d) for d in self.deliveries],
        }


def _handle_order(handle: str) -> tuple[str, int]:
    kind, _, number = handle.rpartition("_")
    return (kind, int(number) if number.isdigit() else 0)


def _compress(handles: list[str]) -> str:
    """["TomatoSliced_1", ..., "TomatoSliced_5", "Pan_1"] -> "TomatoSliced_1–5, Pan_1"."""
    out: list[str] = []
    runs: list[tuple[str, int, int]] = []
    for handle in handles:
        match = _HANDLE.match(handle)
        if match and runs and runs[-1][0] == match.group(1) and runs[-1][2] + 1 == int(match.group(2)):
            runs[-1] = (runs[-1][0], runs[-1][1], int(match.group(2)))
        elif match:
            runs.append((match.group(1), int(match.group(2)), int(match.group(2))))
        else:
            runs.append((handle, -1, -1))
    for kind, first, last in runs:
        if first < 0:
            out.append(kind)
        elif first == last:
            out.append(f"{kind}_{first}")
        else:
            out.append(f"{kind}_{first}–{last}")
    return ", ".join(out)

