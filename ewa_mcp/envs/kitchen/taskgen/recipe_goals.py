"""Kitchen goals from a recipe's step ops: the state the kitchen must be in when the dish is done."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ewa_mcp.core.taskmodel import DomainGoal
from ewa_mcp.envs.kitchen.goals import ObjectIn, ObjectState

PIECE_SOURCE = {"AppleSliced": "Apple", "BreadSliced": "Bread", "LettuceSliced": "Lettuce",
                "PotatoSliced": "Potato", "TomatoSliced": "Tomato", "EggCracked": "Egg"}
FOODS = {"Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato"}
# A recipe's cook method -> the heat sources (the final state's cookedBy) that meet it. A stove cook names its
# vessel; food in a Pan or Pot only cooks when the vessel stands on a lit burner.
METHOD_SOURCES = {"toaster": ["Toaster"], "microwave": ["Microwave"], "stove": ["Pan", "Pot"]}
# Where food heats up: a food put there may cook without a cook op, so no "stays raw" goal is set for it.
HEATED = {"Pan", "Pot", "Microwave", "Toaster", "StoveBurner"}
DISHES = ("Plate", "Bowl")


def recipe_ops(recipe: dict[str, Any]) -> list[dict[str, Any]]:
    return [op for step in recipe["steps"] for op in step.get("ops", [])]


def goals_from_ops(ops: list[dict[str, Any]], untouched: Sequence[str] = ()) -> list[ObjectState | ObjectIn | DomainGoal]:
    """What the recipe's outcome is (``outcome_goals``) and what tells it apart (``telling_goals``)."""
    return [*outcome_goals(ops), *telling_goals(ops, untouched)]


def rival_foods(ops: list[dict[str, Any]], rivals: list[list[dict[str, Any]]]) -> list[str]:
    """Foods a look-alike recipe works with (cuts, cooks or serves) and this one never touches."""
    mine = {PIECE_SOURCE.get(op.get("object", ""), op.get("object", "")) for op in ops}
    theirs = [PIECE_SOURCE.get(op.get("object", ""), op.get("object", "")) for other in rivals for op in other]
    return sorted({f for f in theirs if f in FOODS and f not in mine})


def telling_goals(ops: list[dict[str, Any]], untouched: Sequence[str] = ()) -> list[ObjectState | DomainGoal]:
    """The conditions that fail for a look-alike's outcome and for doing everything (issue 26):

    - the method, for every cook op: toasted in the Toaster, cooked in the Microwave, cooked in the Pan
      (or Pot) the step names on a lit burner; the instant CookObject never meets these; and where the
      recipe cuts or cracks a food before it cooks it, the pieces themselves are cooked (``as_piece``):
      a whole egg fried and then cracked, or a potato fried whole and then sliced, fails;
    - what stays as it was: a food the recipe uses but never cuts stays whole, one it never cooks (nor
      puts where it would heat) stays raw;
    - a food only the look-alike works with (``untouched``, those in the kitchen) stays whole and raw;
    - the stove is off at the end when the recipe turns it off;
    - nothing else on the plate (bowl): each dish holds only the foods the recipe puts there last.
    """
    used: list[str] = []
    cut: set[str] = set()
    cooked: set[str] = set()
    heated: set[str] = set()
    methods: dict[str, list[str]] = {}
    cooked_as_piece: set[str] = set()  # foods the recipe cuts (cracks) first and then cooks as pieces
    last_put: dict[str, str] = {}
    ever_put: dict[str, list[str]] = {}
    stove_off = False
    for op in ops:
        obj = op.get("object", "")
        source = PIECE_SOURCE.get(obj, obj)
        if source in FOODS and source not in used:
            used.append(source)
        if op["op"] in ("slice", "crack"):
            cut.add(source)
        elif op["op"] == "cook":
            cooked.add(source)
            if obj in PIECE_SOURCE:
                cooked_as_piece.add(source)
            wanted = [op["vessel"]] if op.get("vessel") else METHOD_SOURCES.get(op.get("method", ""), [])
            if wanted:
                methods.setdefault(source, [])
                methods[source] += [m for m in wanted if m not in methods[source]]
        elif op["op"] == "put" and source in FOODS:
            last_put[source] = op["receptacle"]
            ever_put.setdefault(op["receptacle"], [])
            if source not in ever_put[op["receptacle"]]:
                ever_put[op["receptacle"]].append(source)
            if op["receptacle"] in HEATED:
                heated.add(source)
        elif op["op"] in ("toggle_on", "toggle_off") and obj in ("StoveBurner", "StoveKnob"):
            stove_off = op["op"] == "toggle_off"
    goals: list[ObjectState | DomainGoal] = [
        DomainGoal(kind="cooked_with", object_type=source, methods=wanted,
                   **({"as_piece": True} if source in cooked_as_piece else {}))
        for source, wanted in methods.items()]
    goals += [ObjectState(object_type=f, prop="isSliced", value=False) for f in used if f not in cut]
    goals += [ObjectState(object_type=f, prop="isCooked", value=False) for f in used
              if f not in cooked and f not in heated]
    for food in untouched:
        if food not in used:
            goals += [ObjectState(object_type=food, prop="isSliced", value=False),
                      ObjectState(object_type=food, prop="isCooked", value=False)]
    if stove_off:
        goals.append(ObjectState(object_type="StoveKnob", prop="isToggled", value=False))
    for dish in DISHES:
        # a food mixed in the bowl and then served on the plate leaves pieces behind: it may stay there
        if any(last_put.get(f) == dish for f in used):
            goals.append(DomainGoal(kind="holds_only", receptacle_type=dish, allowed=ever_put[dish]))
    return goals


def outcome_goals(ops: list[dict[str, Any]]) -> list[ObjectState | ObjectIn]:
    """Final states only: what was sliced/cracked, what was cooked, and where each food ended up.

    Intermediate placements (slices into a pan before cooking, then onto a plate) are process,
    not outcome: only the last placement of a food counts, with the states it has by then."""
    sliced: list[str] = []
    cooked: list[str] = []
    placed: dict[str, tuple[str, bool]] = {}  # source food -> (receptacle, placed as pieces)
    for op in ops:
        obj = op.get("object", "")
        source = PIECE_SOURCE.get(obj, obj)
        if op["op"] in ("slice", "crack") and source not in sliced:
            sliced.append(source)
        elif op["op"] == "cook" and source not in cooked:
            cooked.append(source)
        elif op["op"] == "put" and source in FOODS:
            placed[source] = (op["receptacle"], obj in PIECE_SOURCE)
    goals: list[ObjectState | ObjectIn] = [ObjectState(object_type=s, prop="isSliced", value=True) for s in sliced]
    goals += [ObjectState(object_type=s, prop="isCooked", value=True) for s in cooked]
    for source, (receptacle, as_piece) in placed.items():
        state: dict[str, bool] = {}
        if as_piece:
            state["isSliced"] = True
        if source in cooked:
            state["isCooked"] = True
        goals.append(ObjectIn(object_type=source, receptacle_type=receptacle, with_state=state))
    return goals
