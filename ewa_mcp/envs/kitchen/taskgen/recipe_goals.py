"""Kitchen goals from a recipe's step ops: the state the kitchen must be in when the dish is done."""

from __future__ import annotations

from typing import Any

from ewa_mcp.core.taskmodel import ObjectIn, ObjectState

PIECE_SOURCE = {"AppleSliced": "Apple", "BreadSliced": "Bread", "LettuceSliced": "Lettuce",
                "PotatoSliced": "Potato", "TomatoSliced": "Tomato", "EggCracked": "Egg"}
FOODS = {"Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato"}


def recipe_ops(recipe: dict[str, Any]) -> list[dict[str, Any]]:
    return [op for step in recipe["steps"] for op in step.get("ops", [])]


def goals_from_ops(ops: list[dict[str, Any]]) -> list[ObjectState | ObjectIn]:
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
