"""Recipe ops -> the kitchen tool calls a perfect agent would make, checked in a fresh simulator.

The recipe content and the task suite use three functions:

* ``plan_ops(scene, ops, seed=0)`` — the tool calls (``{"tool": "kitchen_pickup", "args": {...}}``,
  without ``episode_id``) that carry out ``ops`` from the scene's start state;
* ``check_recipe_executable(scene, ops, available_extra_types=())`` — ``(ok, reason)``: the plan
  runs and every op's effect holds (right after the op, and at the end for lasting effects);
* ``scene_inventory(scene)`` — the food, tool and receptacle types a kitchen holds.

Ops (one step of a recipe may have several):
    {"op": "slice", "object": T}                 T in Apple, Bread, Lettuce, Potato, Tomato
    {"op": "crack", "object": "Egg"}
    {"op": "cook", "object": T, "method": "stove"|"microwave"|"toaster"|"any"}   T a food or piece type
        (a stove cook may add "vessel": "Pan"|"Pot", the one the step names; without it, any Pan or Pot)
    {"op": "put", "object": T, "receptacle": R}  R in Plate, Bowl, Pan, Pot, CounterTop, DiningTable,
                                                 Fridge, Microwave, SinkBasin
    {"op": "open"|"close", "object": R}, {"op": "toggle_on"|"toggle_off", "object": X}

The plan is found by acting: each op is executed on a ``KitchenSession`` over ``KitchenSim``
with the same references an agent would use (handles), so a plan that comes back is one that
ran. Handles are stable for a given scene, seed and delivery order, so the calls replay in an
episode of that kitchen. Deliveries (``delivered_types``) are assumed to arrive before the
first kitchen action, as they do when the agent orders online before cooking.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from .scenes import build_scene, canonical_scene
from .session import KitchenActionError, KitchenSession
from .sim import KitchenSim
from .vocabulary import FOOD_TYPES, PIECE_FOR, PIECE_OF, SLICING_TOOLS, TOOL_TYPES, TYPES

SLICEABLE = ("Apple", "Bread", "Lettuce", "Potato", "Tomato")
PUT_RECEPTACLES = ("Plate", "Bowl", "Pan", "Pot", "CounterTop", "DiningTable", "Fridge", "Microwave", "SinkBasin")
COOK_METHODS = ("stove", "microwave", "toaster", "any")
STOVE_VESSELS = ("Pan", "Pot")
TOGGLEABLE = ("StoveKnob", "StoveBurner", "Microwave", "Toaster", "CoffeeMachine")
OPENABLE = ("Fridge", "Microwave", "Cabinet", "Drawer")
FOOD_OR_PIECE = frozenset(FOOD_TYPES) | frozenset(PIECE_OF)


class PlanError(Exception):
    """The ops cannot be carried out in this kitchen; the message says why."""


@dataclass(frozen=True)
class _Op:
    op: str
    object: str
    method: str | None = None
    receptacle: str | None = None
    vessel: str | None = None

    def describe(self) -> str:
        extra = f" ({self.method})" if self.method else f" -> {self.receptacle}" if self.receptacle else ""
        return f"{self.op} {self.object}{extra}"


def _parse_ops(ops: Sequence[dict[str, Any]]) -> list[_Op]:
    parsed = []
    for i, raw in enumerate(ops):
        if not isinstance(raw, dict) or "op" not in raw or "object" not in raw:
            raise PlanError(f"op {i}: {raw!r} must be an object with 'op' and 'object'")
        kind, obj = str(raw["op"]), str(raw["object"])
        if kind == "slice" and obj not in SLICEABLE:
            raise PlanError(f"op {i}: cannot slice {obj!r}; sliceable types are {', '.join(SLICEABLE)}")
        elif kind == "crack" and obj != "Egg":
            raise PlanError(f"op {i}: only an Egg can be cracked, not {obj!r}")
        elif kind == "cook":
            method = str(raw.get("method", "any"))
            if method not in COOK_METHODS:
                raise PlanError(f"op {i}: cook method {method!r} is not one of {', '.join(COOK_METHODS)}")
            if obj not in FOOD_TYPES and obj not in PIECE_OF:
                raise PlanError(f"op {i}: cannot cook {obj!r}; use a food ({', '.join(FOOD_TYPES)}) or a piece type")
            if method == "toaster" and obj not in ("BreadSliced", "Bread"):
                raise PlanError(f"op {i}: a toaster takes only BreadSliced, not {obj!r}")
            vessel = raw.get("vessel")
            if vessel is not None and (method != "stove" or vessel not in STOVE_VESSELS):
                raise PlanError(f"op {i}: a vessel ({', '.join(STOVE_VESSELS)}) goes only with method 'stove', "
                                f"got {vessel!r} with {method!r}")
            parsed.append(_Op(kind, obj, method=method, vessel=vessel))
            continue
        elif kind == "put":
            receptacle = str(raw.get("receptacle", ""))
            if receptacle not in PUT_RECEPTACLES:
                raise PlanError(f"op {i}: receptacle {receptacle!r} is not one of {', '.join(PUT_RECEPTACLES)}")
            if obj not in TYPES or not TYPES[obj].pickupable:
                raise PlanError(f"op {i}: {obj!r} is not a pickupable kitchen type")
            parsed.append(_Op(kind, obj, receptacle=receptacle))
            continue
        elif kind in ("open", "close") and obj not in OPENABLE:
            raise PlanError(f"op {i}: {obj!r} cannot be opened or closed; openable: {', '.join(OPENABLE)}")
        elif kind in ("toggle_on", "toggle_off") and obj not in TOGGLEABLE:
            raise PlanError(f"op {i}: {obj!r} cannot be switched; switchable: {', '.join(TOGGLEABLE)}")
        elif kind not in ("slice", "crack", "open", "close", "toggle_on", "toggle_off"):
            raise PlanError(f"op {i}: unknown op {kind!r}; ops are slice, crack, cook, put, open, close, "
                            "toggle_on, toggle_off")
        parsed.append(_Op(kind, obj))
    return parsed


def _family(object_type: str) -> tuple[str, ...]:
    """The types that stand for ``object_type`` in a goal: a food and its pieces."""
    if object_type in PIECE_FOR:
        return (object_type, PIECE_FOR[object_type])
    return (object_type,)


class _Planner:
    def __init__(self, scene: str, seed: int, delivered_types: Iterable[str]):
        self.scene = canonical_scene(scene)
        self.session = KitchenSession(KitchenSim(None), "sim", self.scene, seed)
        self.session.reset()
        self.calls: list[dict[str, Any]] = []
        self.chosen: dict[str, str] = {}  # receptacle type -> objectId the plan keeps using (one bowl, one pan)
        self.served: set[str] = set()  # what the plan itself put on a Plate or in a Bowl
        self.dish_foods: dict[str, set[str]] = {}  # dish type -> the food types the ops put there
        # Two dishes of one food (taskgen/two_dishes.py): a piece already served raw is not the one to cook.
        self.keep_served = False
        items = [{"kitchen_type": t, "quantity": 1, "product_id": f"plan-{t}"} for t in delivered_types]
        if items:
            self.session.receive_deliveries([{"site": "shop", "type": "order_placed",
                                              "order": {"order_id": "plan", "fulfilment": "delivery",
                                                        "items": items}}])

    def expect(self, ops: Sequence[_Op]) -> None:
        """Know the whole plan's placements first: food already in a dish that the plan serves there stays."""
        for op in ops:
            if op.op == "put" and op.receptacle is not None:
                self.dish_foods.setdefault(op.receptacle, set()).add(PIECE_OF.get(op.object, op.object))

    # -------------------------------------------------------------- primitives
    @property
    def objects(self) -> dict[str, dict[str, Any]]:
        return self.session.objects

    def h(self, object_id: str) -> str:
        return self.session.handle(object_id)

    def call(self, tool: str, args: dict[str, Any]) -> None:
        try:
            # The same dispatch as the tools: the action table's entry for the tool (actions.py).
            self.session.perform(tool.removeprefix("kitchen_"), dict(args))
        except KitchenActionError as exc:
            raise PlanError(f"{self.scene}: step {len(self.calls) + 1} ({tool} {args}) failed: {exc}") from None
        self.calls.append({"tool": tool, "args": dict(args)})

    def of_type(self, *types: str) -> list[dict[str, Any]]:
        agent = self.session.agent["position"]

        def key(o: dict[str, Any]) -> tuple[float, int]:
            p = o["position"]
            return ((p["x"] - agent["x"]) ** 2 + (p["z"] - agent["z"]) ** 2, self.session._number(o["objectId"]))

        return sorted((o for o in self.objects.values() if o["objectType"] in types), key=key)

    def parent_type(self, obj: dict[str, Any]) -> str | None:
        parent = self.session.parent_of(obj)
        return self.objects[parent]["objectType"] if parent in self.objects else None

    def reach(self, object_id: str) -> None:
        """Stand where ``object_id`` is interactable, opening what encloses it."""
        obj = self.objects[object_id]
        if obj["visible"]:
            return
        hider = self.session.hidden_by(obj)
        if hider is not None:
            # a name behind a door not yet opened resolves to nothing (session.py): open the door first, as
            # an agent must, then go to what it held
            self.reach(hider)
            self.call("kitchen_open", {"object": self.h(hider)})
            obj = self.objects[object_id]
            if obj["visible"]:
                return
        self.call("kitchen_teleport", {"object": self.h(object_id)})
        for parent in obj.get("parentReceptacles") or []:
            container = self.objects.get(parent)
            if container and container["openable"] and not container["isOpen"]:
                self.reach(parent)
                self.call("kitchen_open", {"object": self.h(parent)})
        if not self.objects[object_id]["visible"]:
            self.call("kitchen_teleport", {"object": self.h(object_id)})
        if not self.objects[object_id]["visible"]:
            raise PlanError(f"{self.scene}: {self.h(object_id)} cannot be reached")

    def free_hand(self, keep: frozenset[str] = frozenset()) -> None:
        held = self.session.held_id
        if held is None or self.objects[held]["objectType"] in keep:
            return

        def load(counter: dict[str, Any]) -> int:
            return sum(1 for o in self.objects.values() if self.session.parent_of(o) == counter["objectId"])

        # a counter in reach first, then the emptiest; a full one refuses and leaves everything as it was
        counters = sorted(self.of_type("CounterTop"), key=lambda c: (not c["visible"], load(c)))
        for counter in counters:
            self.reach(counter["objectId"])
            try:
                self.session.put(self.h(counter["objectId"]))
            except KitchenActionError:
                continue
            self.calls.append({"tool": "kitchen_put", "args": {"receptacle": self.h(counter["objectId"])}})
            return
        raise PlanError(f"{self.scene}: no counter has room to put {self.h(held)} down")

    def hold(self, object_id: str) -> None:
        if self.session.held_id == object_id:
            return
        self.free_hand()
        self.reach(object_id)
        self.call("kitchen_pickup", {"object": self.h(object_id)})

    def put_into(self, receptacle_id: str) -> None:
        self.reach(receptacle_id)
        rec = self.objects[receptacle_id]
        if rec["openable"] and not rec["isOpen"]:
            if rec["objectType"] == "Microwave" and rec["isToggled"]:
                self.call("kitchen_toggle", {"object": self.h(receptacle_id), "state": "off"})
            self.call("kitchen_open", {"object": self.h(receptacle_id)})
        self.call("kitchen_put", {"receptacle": self.h(receptacle_id)})

    def knife(self) -> None:
        held = self.session.held_id
        if held is not None and self.objects[held]["objectType"] in SLICING_TOOLS:
            return
        knives = self.of_type("Knife") or self.of_type("ButterKnife")
        if not knives:
            raise PlanError(f"{self.scene} has no Knife or ButterKnife to slice with")
        self.hold(knives[0]["objectId"])

    def instance(self, receptacle_type: str) -> dict[str, Any]:
        known = self.chosen.get(receptacle_type)
        if known in self.objects:
            return self.objects[known]
        found = self.of_type(receptacle_type)
        if not found:
            raise PlanError(f"{self.scene} has no {receptacle_type}")
        if receptacle_type in ("Pan", "Pot"):  # one already on a burner saves two steps
            on_burner = [o for o in found if self.parent_type(o) == "StoveBurner"]
            found = on_burner or found
        if receptacle_type in ("Plate", "Bowl"):  # serve on a clean dish: nothing else on the plate is a goal
            empty = [o for o in found if not any(self.objects.get(i, {}).get("objectType") in FOOD_OR_PIECE
                                                 for i in o.get("receptacleObjectIds") or [])]
            found = empty or found
        self.chosen[receptacle_type] = found[0]["objectId"]
        return found[0]

    def ingredient(self, object_type: str, prefer_cooked: bool) -> dict[str, Any]:
        family = _family(object_type)
        found = self.of_type(*family)
        if not found:
            source = PIECE_OF.get(object_type, object_type)
            how = f"; slice the {source} first" if object_type in PIECE_OF and self.of_type(source) else ""
            raise PlanError(f"{self.scene} has no {object_type}{how}")
        # pieces stand for a sliced food; cooked ones first when the recipe served them cooked
        # and, for two dishes of one food, a piece not yet served (the first dish keeps what it was given)
        found.sort(key=lambda o: (self.keep_served and o["objectId"] in self.served,
                                  not (prefer_cooked and o["isCooked"]), o["objectType"] not in PIECE_OF))
        return found[0]

    def knob_for(self, burner_id: str) -> str:
        for object_id, obj in self.objects.items():
            if burner_id in (obj.get("controlledObjects") or []):
                return object_id
        raise PlanError(f"{self.scene}: no StoveKnob controls {self.h(burner_id)}")

    # -------------------------------------------------------------- ops
    def run(self, op: _Op, cooked_so_far: set[str]) -> None:
        getattr(self, f"op_{op.op}")(op, cooked_so_far)

    def op_slice(self, op: _Op, cooked: set[str]) -> None:
        whole = self.of_type(op.object)
        if not whole:
            if self.of_type(PIECE_FOR[op.object]):
                return  # already sliced
            raise PlanError(f"{self.scene} has no {op.object}")
        target = whole[0]["objectId"]
        if self.session.held_id == target:
            self.free_hand()
        if self.parent_type(self.objects[target]) in ("Fridge", "Cabinet", "Drawer", "Microwave"):
            # take it out to a counter, as a cook would, rather than cutting inside the fridge
            self.hold(target)
            self.free_hand()
        self.knife()
        self.reach(target)
        self.call("kitchen_slice", {"object": self.h(target)})

    op_crack = op_slice

    def op_cook(self, op: _Op, cooked: set[str]) -> None:
        if op.method == "toaster" and op.object == "Bread":
            raise PlanError("a toaster takes BreadSliced: slice the Bread before toasting it")
        item = self.ingredient(op.object, prefer_cooked=False)
        uncooked = [o for o in self.of_type(*_family(op.object)) if not o["isCooked"]
                    and not (self.keep_served and o["objectId"] in self.served)]
        if op.method == "any" and any(o["isCooked"] for o in self.of_type(*_family(op.object))):
            return
        if uncooked:
            item = uncooked[0]
        item_id = item["objectId"]
        if op.method == "any":
            if self.session.held_id == item_id:
                self.free_hand()
            self.reach(item_id)
            self.call("kitchen_cook", {"object": self.h(item_id)})
        elif op.method == "stove":
            self.cook_on_stove(item_id, op.vessel)
        elif op.method == "microwave":
            microwave = self.instance("Microwave")["objectId"]
            self.hold(item_id)
            self.put_into(microwave)
            self.call("kitchen_close", {"object": self.h(microwave)})
            self.call("kitchen_toggle", {"object": self.h(microwave), "state": "on"})
            self.call("kitchen_toggle", {"object": self.h(microwave), "state": "off"})
        else:
            toaster = self.instance("Toaster")["objectId"]
            if any(c for c in self.objects[toaster].get("receptacleObjectIds") or []) and \
                    len(self.objects[toaster]["receptacleObjectIds"]) >= 2:
                raise PlanError(f"{self.scene}: {self.h(toaster)} is full")
            self.hold(item_id)
            self.put_into(toaster)
            if not self.objects[toaster]["isToggled"]:
                self.call("kitchen_toggle", {"object": self.h(toaster), "state": "on"})
        cooked.add(op.object)

    def cook_on_stove(self, item_id: str, wanted: str | None = None) -> None:
        if wanted is not None:
            vessel = self.instance(wanted)  # the vessel the recipe names, or a PlanError saying it is missing
        else:
            vessels = [t for t in STOVE_VESSELS if self.of_type(t)]
            if not vessels:
                raise PlanError(f"{self.scene} has no Pan or Pot to cook on the stove")
            vessel = self.instance(self.chosen.get("_vessel") or vessels[0])
        self.chosen["_vessel"] = vessel["objectType"]
        vessel_id = vessel["objectId"]
        if self.parent_type(vessel) != "StoveBurner":
            burners = [b for b in self.of_type("StoveBurner") if not b.get("receptacleObjectIds")]
            if not burners:
                raise PlanError(f"{self.scene}: every StoveBurner is taken")
            self.hold(vessel_id)
            self.put_into(burners[0]["objectId"])
        burner_id = self.session.parent_of(self.objects[vessel_id])
        assert burner_id is not None
        if self.session.parent_of(self.objects[item_id]) != vessel_id:
            self.hold(item_id)
            self.put_into(vessel_id)
        knob = self.knob_for(burner_id)
        if not self.objects[knob]["isToggled"]:
            self.reach(knob)
            self.call("kitchen_toggle", {"object": self.h(knob), "state": "on"})

    def op_put(self, op: _Op, cooked: set[str]) -> None:
        assert op.receptacle is not None
        family = _family(op.object)
        target = self.instance(op.receptacle)
        target_id = target["objectId"]
        if any(self.session.parent_of(o) == target_id for o in self.of_type(*family)
               if not (op.object in cooked and not o["isCooked"])):
            return  # already there
        item = self.ingredient(op.object, prefer_cooked=op.object in cooked or PIECE_OF.get(op.object) in cooked)
        if item["objectId"] == target_id:
            raise PlanError(f"cannot put {op.object} into itself")
        if op.receptacle in ("Plate", "Bowl"):
            # Clear what the kitchen left in the dish (an apple in the only bowl): nothing else on the plate.
            for other in list(target.get("receptacleObjectIds") or []):
                kind = self.objects.get(other, {}).get("objectType")
                if kind in FOOD_OR_PIECE and other not in self.served \
                        and PIECE_OF.get(kind, kind) not in self.dish_foods.get(op.receptacle, set()):
                    self.hold(other)
                    self.free_hand()
        self.hold(item["objectId"])
        self.put_into(target_id)
        self.served.add(item["objectId"])

    def op_open(self, op: _Op, cooked: set[str]) -> None:
        target = self.instance(op.object)["objectId"]
        if not self.objects[target]["isOpen"]:
            if self.objects[target]["objectType"] == "Microwave" and self.objects[target]["isToggled"]:
                self.reach(target)
                self.call("kitchen_toggle", {"object": self.h(target), "state": "off"})
            self.reach(target)
            self.call("kitchen_open", {"object": self.h(target)})

    def op_close(self, op: _Op, cooked: set[str]) -> None:
        target = self.instance(op.object)["objectId"]
        if self.objects[target]["isOpen"]:
            self.reach(target)
            self.call("kitchen_close", {"object": self.h(target)})

    def _switch_target(self, object_type: str) -> str:
        if object_type in ("StoveBurner", "StoveKnob"):
            vessel_type = self.chosen.get("_vessel")
            vessel = self.objects.get(self.chosen.get(vessel_type, "")) if vessel_type else None
            burner = self.session.parent_of(vessel) if vessel else None
            if burner is None or self.objects[burner]["objectType"] != "StoveBurner":
                burner = self.instance("StoveBurner")["objectId"]  # remembered, so later checks see the same one
            return self.knob_for(burner)
        return self.instance(object_type)["objectId"]

    def op_toggle_on(self, op: _Op, cooked: set[str]) -> None:
        target = self._switch_target(op.object)
        if not self.objects[target]["isToggled"]:
            if self.objects[target]["objectType"] == "Microwave" and self.objects[target]["isOpen"]:
                self.reach(target)
                self.call("kitchen_close", {"object": self.h(target)})
            self.reach(target)
            self.call("kitchen_toggle", {"object": self.h(target), "state": "on"})

    def op_toggle_off(self, op: _Op, cooked: set[str]) -> None:
        if op.object in ("StoveBurner", "StoveKnob"):
            # "Turn off the stove": every burner the plan lit (a recipe may use the Pot and then the Pan),
            # the remembered one last, so the op's own effect check reads the same knob as before.
            remembered = self._switch_target(op.object)
            for knob in [o for o in self.of_type("StoveKnob") if o["objectId"] != remembered] + \
                    [self.objects[remembered]]:
                if self.objects[knob["objectId"]]["isToggled"]:
                    self.reach(knob["objectId"])
                    self.call("kitchen_toggle", {"object": self.h(knob["objectId"]), "state": "off"})
            return
        target = self._switch_target(op.object)
        if self.objects[target]["isToggled"]:
            self.reach(target)
            self.call("kitchen_toggle", {"object": self.h(target), "state": "off"})

    # -------------------------------------------------------------- effects
    def effect_holds(self, op: _Op) -> tuple[bool, str]:
        family = _family(op.object)
        members = self.of_type(*family)
        if op.op in ("slice", "crack"):
            ok = any(o.get("isSliced") and o["objectType"] in PIECE_OF for o in members) or \
                any(o["objectType"] == PIECE_FOR[op.object] for o in self.objects.values())
            return ok, f"no {PIECE_FOR[op.object]} exists"
        if op.op == "cook":
            cooked = [o for o in members if o["isCooked"]]
            if not cooked:
                return False, f"no {op.object} is cooked"
            return True, ""
        if op.op == "put":
            ok = any(self.parent_type(o) == op.receptacle for o in members)
            return ok, f"no {op.object} is in/on a {op.receptacle}"
        if op.op in ("open", "close"):
            target = self.instance(op.object)
            return target["isOpen"] == (op.op == "open"), f"{self.h(target['objectId'])} is not {op.op}"
        target = self.objects[self._switch_target(op.object)]
        want = op.op == "toggle_on"
        return target["isToggled"] == want, f"{self.h(target['objectId'])} is not {'on' if want else 'off'}"


def _play(planner: _Planner, parsed: list[_Op]) -> str | None:
    """Run every op on the planner's kitchen; the first op whose effect does not hold, and why (None: all do)."""
    planner.expect(parsed)
    cooked: set[str] = set()
    for op in parsed:
        planner.run(op, cooked)
        ok, why = planner.effect_holds(op)
        if not ok:
            return f"after '{op.describe()}' {why}"
    return None


def plan_ops(scene_name: str, ops: Sequence[dict[str, Any]], seed: int = 0,
             delivered_types: Iterable[str] = ()) -> list[dict[str, Any]]:
    """The kitchen tool calls that carry out ``ops`` in ``scene_name`` from its start state.

    Raises ``PlanError`` when they cannot be carried out (a missing food or tool, a bad op)."""
    parsed = _parse_ops(ops)
    planner = _Planner(scene_name, seed, delivered_types)
    problem = _play(planner, parsed)
    if problem:
        raise PlanError(f"{planner.scene}: {problem}")
    return planner.calls


def check_recipe_executable(scene_name: str, ops: Sequence[dict[str, Any]],
                            available_extra_types: Iterable[str] = ()) -> tuple[bool, str]:
    """Whether ``ops`` can be carried out in ``scene_name`` (buying ``available_extra_types`` it lacks).

    Runs the plan in a fresh simulator and checks each op's effect right after it and the lasting
    ones (slices, cooking, final placements) at the end. Returns (ok, reason)."""
    try:
        parsed = _parse_ops(ops)
        scene = canonical_scene(scene_name)
    except (PlanError, ValueError) as exc:
        return False, str(exc)
    have = scene_inventory(scene)
    present = have["food"] | have["tools"]
    needed = {PIECE_OF.get(op.object, op.object) for op in parsed if op.op in ("slice", "crack", "cook", "put")}
    needed |= {op.receptacle for op in parsed if op.receptacle in TOOL_TYPES}
    needed |= {op.vessel for op in parsed if op.vessel}
    deliveries = sorted(t for t in set(available_extra_types) if t not in present and t in needed)
    missing = sorted(t for t in needed if t in FOOD_TYPES + TOOL_TYPES and t not in present and t not in deliveries)
    if missing:
        return False, f"{scene} has no {', '.join(missing)} and it is not among the types that can be bought"
    try:
        planner = _Planner(scene, 0, deliveries)
        problem = _play(planner, parsed)
        if problem:
            return False, problem
        # lasting effects: every slice and cook, and the last placement of each object type
        last_put: dict[str, _Op] = {}
        for op in parsed:
            if op.op == "put":
                last_put[op.object] = op
        for op in [o for o in parsed if o.op in ("slice", "crack", "cook")] + list(last_put.values()):
            ok, why = planner.effect_holds(op)
            if not ok:
                return False, f"at the end, '{op.describe()}' no longer holds: {why}"
    except PlanError as exc:
        return False, str(exc)
    bought = f" after buying {', '.join(deliveries)}" if deliveries else ""
    return True, f"executable in {scene}{bought} with {len(planner.calls)} kitchen actions"


def scene_inventory(scene_name: str) -> dict[str, set[str]]:
    """{"food": ..., "tools": ..., "receptacles": ...}: the types the kitchen holds at the start."""
    spec = build_scene(canonical_scene(scene_name))
    types = {o.object_type for o in spec.objects}
    return {
        "food": {t for t in types if t in FOOD_TYPES},
        "tools": {t for t in types if t in TOOL_TYPES},
        "receptacles": {t for t in types if TYPES[t].receptacle and not TYPES[t].pickupable},
    }
