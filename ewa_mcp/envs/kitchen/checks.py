"""Kitchen goals, checked against the AI2-THOR-style object list in the final state.

Rules (each fixes a defect of the reference grader):
- types match exactly: a Pot is not a Potato, a ButterKnife is not a Knife;
- a sliced or cracked piece counts for its source (TomatoSliced_1 with sourceType "Tomato" is a
  Tomato), and a piece's existence means its source was sliced;
- a goal value of False needs *every* instance (and piece) of the type to be False;
- a receptacle goal compares the object's direct parent with the *expected* receptacle type.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ewa_mcp.envs.kitchen.goals import ObjectIn, ObjectState

from ewa_mcp.graders.models import CheckContext, ConditionResult

Obj = dict[str, Any]


def type_of_id(object_id: str) -> str:
    """AI2-THOR ids start with the type ("Plate|+0.10|+0.90|-1.20")."""
    return object_id.split("|", 1)[0]


def is_piece(obj: Obj) -> bool:
    source = obj.get("sourceType")
    return isinstance(source, str) and bool(source) and source != obj.get("objectType")


def instances(objects: list[Obj], object_type: str) -> list[Obj]:
    """Objects of exactly this type, and pieces whose source is this type."""
    return [o for o in objects if o.get("objectType") == object_type or (is_piece(o) and o.get("sourceType") == object_type)]


def state_of(obj: Obj, prop: str, object_type: str) -> bool:
    """The object's state as seen for a goal about ``object_type``.

    A TomatoSliced piece viewed as a Tomato is sliced, whatever its own isSliced says
    (AI2-THOR reports pieces as not sliceable, hence isSliced False)."""
    if prop == "isSliced" and is_piece(obj) and obj.get("objectType") != object_type:
        return True
    return obj.get(prop) is True


def direct_parent_types(obj: Obj, by_id: dict[str, Obj]) -> list[str]:
    """Types of the receptacles directly holding ``obj``.

    parentReceptacles may list ancestors too (a slice on a plate on a counter); a parent that
    is itself an ancestor of another listed parent is not direct. A parent's type comes from
    the object list when it is there (AI2-THOR's SinkBasin id starts with "Sink|"), else from
    its id prefix."""
    parents = [p for p in obj.get("parentReceptacles") or [] if isinstance(p, str)]
    ancestors: set[str] = set()
    for p in parents:
        ancestors.update(a for a in (by_id.get(p, {}).get("parentReceptacles") or []) if isinstance(a, str))
    direct = [p for p in parents if p not in ancestors]
    return [by_id[p].get("objectType", type_of_id(p)) if p in by_id else type_of_id(p) for p in direct]


def _handle(obj: Obj) -> str:
    return str(obj.get("objectId") or obj.get("name") or obj.get("objectType"))


def check_object_state(goal: ObjectState, objects: list[Obj]) -> ConditionResult:
    found = instances(objects, goal.object_type)
    description = f"{goal.object_type}.{goal.prop} == {goal.value}"
    if not found:
        return ConditionResult(side="embodied", kind=goal.kind, description=description, met=False,
                               note=f"no {goal.object_type} in the kitchen")
    true_ones = [_handle(o) for o in found if state_of(o, goal.prop, goal.object_type)]
    met = bool(true_ones) if goal.value else not true_ones
    detail = {"instances": len(found), f"{goal.prop}_true": true_ones[:10]}
    note = None
    if not goal.value and true_ones:
        note = f"{len(true_ones)} of {len(found)} {goal.object_type} instance(s) have {goal.prop} True"
    return ConditionResult(side="embodied", kind=goal.kind, description=description, met=met, detail=detail, note=note)


def check_object_in(goal: ObjectIn, objects: list[Obj]) -> ConditionResult:
    by_id = {o["objectId"]: o for o in objects if isinstance(o.get("objectId"), str)}
    found = instances(objects, goal.object_type)
    description = f"{goal.object_type} in {goal.receptacle_type}"
    if goal.with_state:
        description += " with " + ", ".join(f"{k}={v}" for k, v in sorted(goal.with_state.items()))
    if not found:
        return ConditionResult(side="embodied", kind=goal.kind, description=description, met=False,
                               note=f"no {goal.object_type} in the kitchen")
    placed = [o for o in found if goal.receptacle_type in direct_parent_types(o, by_id)]
    good = [o for o in placed if all(state_of(o, k, goal.object_type) == v for k, v in goal.with_state.items())]
    detail = {
        "instances": len(found),
        "in_receptacle": [_handle(o) for o in placed][:10],
        "where": sorted({t for o in found for t in direct_parent_types(o, by_id)}),
    }
    note = None
    if placed and not good:
        note = f"{goal.object_type} is in {goal.receptacle_type} but not in the required state"
    return ConditionResult(side="embodied", kind=goal.kind, description=description, met=bool(good),
                           detail=detail, note=note)


def goal_types(goals: list[Any]) -> set[str]:
    """Every object and receptacle type the kitchen goals mention (for the misalignment rule)."""
    types: set[str] = set()
    for g in goals:
        if isinstance(g, ObjectState):
            types.add(g.object_type)
        elif isinstance(g, ObjectIn):
            types.update((g.object_type, g.receptacle_type))
        elif getattr(g, "kind", None) in ("cooked_with", "holds_only"):
            # a food a negative condition names ("the tomato stays whole") is wanted: touching it is a
            # goal failure, not instruction-action misalignment; the same for the dish's allowed foods
            extra = [_field(g, "object_type"), _field(g, "receptacle_type"), *(_field(g, "allowed") or [])]
            types.update(t for t in extra if isinstance(t, str))
    return types


def changed_off_task(objects: list[Obj], wanted: set[str]) -> list[str]:
    """Food the agent sliced, cracked, cooked or broke although no goal mentions it.

    Scenes start with nothing sliced, cooked or broken, so any such state is the agent's doing."""
    off: set[str] = set()
    for o in objects:
        own = o.get("objectType")
        source = o.get("sourceType") if is_piece(o) else own
        touched = is_piece(o) or any(o.get(p) is True for p in ("isSliced", "isCooked", "isBroken"))
        if touched and own not in wanted and source not in wanted:
            off.add(str(source))
    return sorted(off)


def _objects(goal: Any, ctx: CheckContext) -> list[Obj] | ConditionResult:
    state = ctx.state
    if state is None:
        return ctx.unknown("embodied", goal, ctx.why_no_state)
    if not isinstance(state.get("objects"), list):
        return ctx.unknown("embodied", goal,
                           f"the embodied final state ({state.get('name', '?')}) has no kitchen object list")
    return state["objects"]


# ---------------------------------------------------------------- goals that tell a recipe apart (issue 26)
# Heat sources a method goal can name. The instant CookObject is not one: it stays in the action space
# (AI2-THOR's own action), but it cooks "somehow", so it never meets a goal that names how (docs/grading.md).
COOK_METHODS = ("Pan", "Pot", "StoveBurner", "Microwave", "Toaster")
FOOD_SOURCES = frozenset(("Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato"))


def _field(goal: Any, name: str) -> Any:
    return getattr(goal, name, None) if not isinstance(goal, dict) else goal.get(name)


def _source(obj: Obj) -> str:
    return str(obj.get("sourceType")) if is_piece(obj) else str(obj.get("objectType"))


def check_cooked_with(goal: Any, objects: list[Obj]) -> ConditionResult:
    """Some instance (or piece) of ``object_type`` was cooked by one of ``methods`` (the final state's
    ``cookedBy``): fried in the pan means cooked in a Pan on a lit burner, toasted means in the Toaster."""
    kind = str(_field(goal, "kind") or "cooked_with")
    object_type, methods = _field(goal, "object_type"), _field(goal, "methods")
    if not isinstance(object_type, str) or not isinstance(methods, list) or not methods \
            or not all(isinstance(m, str) for m in methods):
        return ConditionResult(side="embodied", kind=kind, description="cooked_with (malformed)", met=None,
                               note="a cooked_with goal needs object_type (a type) and methods (a list of "
                                    f"{', '.join(COOK_METHODS)})")
    # Optional: True, cooked as pieces (cut or cracked first, then cooked: a whole egg fried and then cracked
    # fails); False, cooked whole (cut only afterwards, if at all). Absent: either.
    as_piece = _field(goal, "as_piece")
    if as_piece is not None and not isinstance(as_piece, bool):
        return ConditionResult(side="embodied", kind=kind, description="cooked_with (malformed)", met=None,
                               note="cooked_with's as_piece is true (cut first, then cooked) or false (cooked whole)")
    piece_word = PIECE_WORD.get(object_type, "pieces")
    description = f"{object_type} cooked in {' or '.join(methods)}"
    if as_piece is not None:
        description += f" ({piece_word} cooked as such)" if as_piece else " (cooked whole)"
    found = instances(objects, object_type)
    if not found:
        return ConditionResult(side="embodied", kind=kind, description=description, met=False,
                               note=f"no {object_type} in the kitchen")
    cooked = [o for o in found if o.get("isCooked") is True]
    right_way = [o for o in cooked if o.get("cookedBy") in methods]
    good = [o for o in right_way if as_piece is None or _cooked_as_piece(o) == as_piece]
    how = sorted({str(o.get("cookedBy", "unknown")) for o in cooked})
    note = None
    if cooked and not right_way:
        note = (f"{object_type} is cooked, but by {', '.join(how)}, not in {' or '.join(methods)}"
                + (" (the instant cook never meets a method goal)" if "CookObject" in how else ""))
    elif right_way and not good:
        note = (f"{object_type} was cooked whole and cut afterwards: the recipe cuts (cracks) it first and cooks the "
                f"{piece_word}" if as_piece else
                f"{object_type} was cut before it was cooked: the recipe cooks it whole")
    detail: dict[str, Any] = {"instances": len(found), "cooked_by": how}
    if as_piece is not None:
        detail["cooked_as_piece"] = sorted({_cooked_as_piece(o) for o in right_way})
    return ConditionResult(side="embodied", kind=kind, description=description, met=bool(good),
                           detail=detail, note=note)


# What the pieces of a food are called in a note ("the recipe cracks it first and cooks the cracked egg").
PIECE_WORD = {"Egg": "cracked egg", "Bread": "slices", "Potato": "slices", "Tomato": "slices",
              "Apple": "slices", "Lettuce": "pieces"}


def _cooked_as_piece(obj: Obj) -> bool:
    """A piece cooked after it was cut (not one that inherited its cooking from the whole food: the final
    state marks those ``cookedWhole``)."""
    return is_piece(obj) and obj.get("cookedWhole") is not True


def check_holds_only(goal: Any, objects: list[Obj]) -> ConditionResult:
    """Nothing else on the plate: every ``receptacle_type`` that holds one of the ``allowed`` foods holds no
    other food, and no receptacle of that type holds a food the agent sliced or cooked that is not allowed
    (a second plate of extras does not hide them). Food counts by its source (a TomatoSliced is a Tomato)."""
    kind = str(_field(goal, "kind") or "holds_only")
    receptacle, allowed = _field(goal, "receptacle_type"), _field(goal, "allowed")
    if not isinstance(receptacle, str) or not isinstance(allowed, list) or not all(isinstance(a, str) for a in allowed):
        return ConditionResult(side="embodied", kind=kind, description="holds_only (malformed)", met=None,
                               note="a holds_only goal needs receptacle_type (a type) and allowed (a list of food types)")
    description = f"nothing but {', '.join(allowed) or 'nothing'} in/on {receptacle}"
    by_id = {o["objectId"]: o for o in objects if isinstance(o.get("objectId"), str)}
    contents: dict[str, list[Obj]] = {}
    for o in objects:
        if _source(o) not in FOOD_SOURCES:
            continue
        parents = [p for p in o.get("parentReceptacles") or [] if isinstance(p, str)]
        ancestors = {a for p in parents for a in (by_id.get(p, {}).get("parentReceptacles") or []) if isinstance(a, str)}
        for p in parents:
            if p not in ancestors and by_id.get(p, {}).get("objectType", type_of_id(p)) == receptacle:
                contents.setdefault(p, []).append(o)
    # Optional (two dishes of one food): every piece of these foods in the dish is cooked (True) or raw (False),
    # so one vessel holding the food both ways does not pass for either dish.
    cooked_as = _field(goal, "cooked")
    if cooked_as is not None and (not isinstance(cooked_as, dict)
                                  or not all(isinstance(v, bool) for v in cooked_as.values())):
        return ConditionResult(side="embodied", kind=kind, description="holds_only (malformed)", met=None,
                               note="holds_only's cooked is a map of food type to true (cooked) or false (raw)")
    if cooked_as:
        description += " (" + ", ".join(f"{f} {'cooked' if v else 'raw'}" for f, v in sorted(cooked_as.items())) + ")"
    extra: set[str] = set()
    wrong: set[str] = set()
    dish = 0
    for held in contents.values():
        sources = {_source(o) for o in held}
        if sources & set(allowed):
            dish += 1
            extra |= sources - set(allowed)
            states: dict[str, bool] = cooked_as or {}
            wrong |= {_source(o) for o in held if _source(o) in states
                      and (o.get("isCooked") is True) != states[_source(o)]}
        else:
            extra |= {_source(o) for o in held if is_piece(o) or o.get("isCooked") is True or o.get("isSliced") is True}
    met = dish > 0 and not extra and not wrong
    note = None
    if extra:
        note = f"{receptacle} also holds {', '.join(sorted(extra))}, which the recipe does not put there"
    elif wrong:
        note = (f"{receptacle} holds {', '.join(sorted(wrong))} both ways or the other way: every piece there "
                "must be as this dish has it")
    elif not dish:
        note = f"no {receptacle} holds {' or '.join(allowed)}"
    detail: dict[str, Any] = {"receptacles": len(contents), "extra": sorted(extra)}
    if cooked_as:
        detail["wrong_state"] = sorted(wrong)
    return ConditionResult(side="embodied", kind=kind, description=description, met=met, detail=detail, note=note)


def _on_objects(check: Callable[[Any, list[Obj]], ConditionResult]) -> Callable[[Any, CheckContext], ConditionResult]:
    """A goal kind's entry point (Domain.checks): its check on the kitchen's objects, or unknown without them."""

    def entry(goal: Any, ctx: CheckContext) -> ConditionResult:
        objects = _objects(goal, ctx)
        return objects if isinstance(objects, ConditionResult) else check(goal, objects)

    return entry


object_state = _on_objects(check_object_state)
object_in = _on_objects(check_object_in)
cooked_with = _on_objects(check_cooked_with)
holds_only = _on_objects(check_holds_only)
