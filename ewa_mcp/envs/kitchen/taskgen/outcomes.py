"""Kitchen outcomes a task's goals are audited against (issue 26, docs/verified.md).

Each outcome is the final state of a real ``KitchenSession`` over the built-in simulator, reached by the
recipe planner (``planner.py``) from the task's kitchen and deliveries:

* ``recipe_outcome`` — a recipe's kitchen steps done perfectly (the oracle's, or its look-alike's);
* ``everything_outcome`` — doing everything: every food cut (the egg cracked), every piece cooked the
  usual way (bread in the toaster, the rest in the pan on a lit burner), a piece of each on one plate,
  the stove off;
* ``whole_first_ops`` — the recipe with every food it cuts and then cooks cooked whole first, cut after.

``grade_kitchen`` checks a task's kitchen goals against such a state with the grader's own checks.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ewa_mcp.envs.kitchen.goals import ObjectIn, ObjectState
from ewa_mcp.graders.models import ConditionResult
from .. import checks
from ..planner import PlanError, _parse_ops, _Planner
from ..vocabulary import PIECE_FOR
from .recipe_goals import FOODS, PIECE_SOURCE


def _planned(scene: str, ops: list[dict[str, Any]], delivered: list[str], stop_on_error: bool) -> Any:
    """The planner after carrying out ``ops`` (None when the kitchen cannot be set up, or an op fails and
    ``stop_on_error``); otherwise a failed op is skipped and the rest go on."""
    try:
        planner = _Planner(scene, 0, delivered)
    except PlanError:
        return None
    planner.expect(_parse_ops(ops))
    cooked: set[str] = set()
    for op in ops:
        try:
            planner.run(_parse_ops([op])[0], cooked)
        except PlanError:
            if stop_on_error:
                return None
    return planner


def _run(scene: str, ops: list[dict[str, Any]], delivered: list[str], stop_on_error: bool) -> dict[str, Any] | None:
    planner = _planned(scene, ops, delivered, stop_on_error)
    return None if planner is None else planner.session.final_state()


def kitchen_calls(scene: str, ops: list[dict[str, Any]], delivered: Sequence[str] = ()) -> list[dict[str, Any]]:
    """The kitchen tool calls that carry out as many of ``ops`` as this kitchen allows (heuristic agents)."""
    planner = _planned(scene, list(ops), list(delivered), stop_on_error=False)
    return [] if planner is None else list(planner.calls)


def kitchen_foods(scene: str, delivered: Sequence[str] = ()) -> list[str]:
    """The food types a kitchen holds at the start, with the delivered ones."""
    try:
        planner = _Planner(scene, 0, list(delivered))
    except PlanError:
        return []
    return sorted({o["objectType"] for o in planner.objects.values()} & FOODS)


def recipe_outcome(scene: str, ops: list[dict[str, Any]], delivered: Sequence[str] = ()) -> dict[str, Any] | None:
    """The final state after a recipe's ops done perfectly, or None when they cannot be done here."""
    return _run(scene, list(ops), list(delivered), stop_on_error=True)


def everything_ops(foods: list[str]) -> list[dict[str, Any]]:
    """Cut, cook and plate every food: what an agent does that covers every recipe at once."""
    ops: list[dict[str, Any]] = []
    for food in sorted(foods):
        piece = PIECE_FOR[food]
        ops.append({"op": "crack" if food == "Egg" else "slice", "object": food})
        ops.append({"op": "cook", "object": piece, "method": "toaster"} if food == "Bread"
                   else {"op": "cook", "object": piece, "method": "stove", "vessel": "Pan"})
        ops.append({"op": "put", "object": piece, "receptacle": "Plate"})
    ops.append({"op": "toggle_off", "object": "StoveBurner"})
    return ops


def union_ops(candidates: list[list[dict[str, Any]]], plate: str = "common") -> list[dict[str, Any]]:
    """Over-acting among look-alikes: every cut and every cooking any candidate recipe does (a food two of
    them cook in two places is cooked in both), then the pieces on the plate (``plate="common"``: only those
    every candidate serves; ``"all"``: those any serves), then the stove off. What an agent does that cannot
    tell the candidates apart and hopes the grader only asks for what they share."""
    work: list[dict[str, Any]] = []
    puts: list[list[dict[str, Any]]] = []
    for ops in candidates:
        puts.append([op for op in ops if op["op"] == "put"])
        for op in ops:
            if op["op"] not in ("put", "toggle_off") and op not in work:
                work.append(dict(op))
    served = ([op for op in puts[0] if all(op in other for other in puts[1:])] if plate == "common"
              else [op for i, ops in enumerate(puts) for op in ops if op not in [o for p in puts[:i] for o in p]])
    stove = any(op["op"] == "cook" and op.get("method") == "stove" for op in work)
    return work + [dict(op) for op in served] + ([{"op": "toggle_off", "object": "StoveBurner"}] if stove else [])


def whole_first_ops(ops: list[dict[str, Any]]) -> list[dict[str, Any]] | None:
    """The recipe done the careless way: every food it cuts (cracks) and then cooks is cooked whole first
    and cut afterwards (the whole egg into the hot pan, cracked once cooked). None when it cooks no pieces."""
    out = [dict(op) for op in ops]
    changed = False
    for op in ops:
        if op["op"] != "cook" or op.get("object") not in PIECE_SOURCE:
            continue
        source = PIECE_SOURCE[op["object"]]
        cut = next((i for i, o in enumerate(out) if o["op"] in ("slice", "crack") and o.get("object") == source), None)
        if cut is None:
            continue
        out.remove(op)
        out.insert(cut, {**op, "object": source})
        changed = True
    return out if changed else None


def everything_outcome(scene: str, delivered: Sequence[str] = ()) -> dict[str, Any] | None:
    """The final state after doing everything to every food in the kitchen (and the delivered ones)."""
    return _run(scene, everything_ops(kitchen_foods(scene, delivered)), list(delivered), stop_on_error=False)


def grade_kitchen(goals: list[Any], state: dict[str, Any]) -> list[ConditionResult]:
    """Each kitchen goal checked against ``state`` by the grader's check for its kind."""
    objects = state["objects"]
    results: list[ConditionResult] = []
    for goal in goals:
        if isinstance(goal, ObjectState):
            results.append(checks.check_object_state(goal, objects))
        elif isinstance(goal, ObjectIn):
            results.append(checks.check_object_in(goal, objects))
        elif goal.kind == "cooked_with":
            results.append(checks.check_cooked_with(goal, objects))
        elif goal.kind == "holds_only":
            results.append(checks.check_holds_only(goal, objects))
        else:
            raise ValueError(f"no kitchen check for goal kind {goal.kind!r}")
    return results


def audit(tasks: list[Any], fresh_goals: bool = False, over_acting: bool = True) -> dict[str, Any]:
    """For each cooking task: does the oracle's outcome meet every kitchen goal, and do the look-alike's,
    doing everything, cooking whole what the recipe cuts first and (``over_acting``) doing what every
    listed candidate does (union_ops, the plate common or full) each fail at least one? ``fresh_goals``
    grades the goals the generator would write now instead of the task file's."""
    from ewa_mcp.websites.recipes.catalog import load_catalog

    from .cooking import kitchen_goals, made_with, named_with
    from .recipe_goals import recipe_ops

    catalog = load_catalog()
    by_id = {r["id"]: r for r in catalog.recipes}
    counts: dict[str, Any] = {"tasks": 0, "oracle_fails": [], "lookalike_tasks": 0, "lookalike_passes": [], "lookalike_not_doable": 0,
              "lookalike_same_kitchen": 0,
              "everything_passes": [], "whole_first_played": 0, "whole_first_not_doable": 0,
              "whole_first_passes": [], "union_common_passes": [], "union_all_passes": []}
    for task in tasks:
        meta = task.metadata
        if meta.get("form") == "two_dishes":
            continue  # audited by two_dishes.audit (two dishes, the swap)
        recipe = by_id[meta["recipe_id"]]
        buy = meta.get("buy") or []
        delivered = [buy] if isinstance(buy, str) else list(buy)
        scene = task.start.embodied.scene
        goals = (kitchen_goals(recipe, scene, delivered, meta.get("name_word"), meta.get("ingredient"))
                 if fresh_goals else task.embodied_goals)
        counts["tasks"] += 1
        own = recipe_outcome(scene, recipe_ops(recipe), delivered)
        if own is None or not all(r.met for r in grade_kitchen(goals, own)):
            counts["oracle_fails"].append(task.id)
        for other in catalog.recipes:
            if other["name"] != recipe["name"] or other["id"] == recipe["id"]:
                continue
            counts["lookalike_tasks"] += 1
            if recipe_ops(other) == recipe_ops(recipe):
                # told apart only outside the kitchen (honey or cinnamon): the web goal's job
                counts["lookalike_same_kitchen"] += 1
                continue
            state = recipe_outcome(scene, recipe_ops(other), delivered)
            if state is None:
                counts["lookalike_not_doable"] += 1
            elif all(r.met for r in grade_kitchen(goals, state)):
                counts["lookalike_passes"].append(f"{task.id} ({recipe['id']} vs {other['id']})")
        everything = everything_outcome(scene, delivered)
        if everything is not None and all(r.met for r in grade_kitchen(goals, everything)):
            counts["everything_passes"].append(task.id)
        word, ingredient = meta.get("name_word"), meta.get("ingredient")
        listed = (named_with(word.lower(), catalog) if word else made_with(ingredient, catalog) if ingredient
                  else [r for r in catalog.recipes if r["name"] == recipe["name"]])
        if over_acting and len({tuple(map(str, recipe_ops(r))) for r in listed}) > 1:
            for plate in ("common", "all"):
                over = _run(scene, union_ops([recipe_ops(r) for r in listed], plate), delivered, stop_on_error=False)
                if over is not None and all(r.met for r in grade_kitchen(goals, over)):
                    counts[f"union_{plate}_passes"].append(task.id)
        careless = whole_first_ops(recipe_ops(recipe))
        if careless is not None:
            state = recipe_outcome(scene, careless, delivered)
            if state is None:
                counts["whole_first_not_doable"] += 1  # e.g. a whole loaf does not fit the toaster
            else:
                counts["whole_first_played"] += 1
                if all(r.met for r in grade_kitchen(goals, state)):
                    counts["whole_first_passes"].append(task.id)
    return counts


def main(argv: list[str] | None = None) -> int:
    """Print the audit over the cooking tasks (``python -m ewa_mcp.envs.kitchen.taskgen.outcomes [--fresh]
    [--sample N]``)."""
    import argparse

    from ewa_mcp.core.paths import tasks_dir
    from ewa_mcp.core.taskmodel import TaskStore

    parser = argparse.ArgumentParser(description=main.__doc__)
    parser.add_argument("--fresh", action="store_true", help="grade the goals the generator writes now")
    parser.add_argument("--sample", type=int, default=0, help="every n-th task only (0: all)")
    args = parser.parse_args(argv)
    tasks = sorted((t for t in TaskStore([tasks_dir()]).all() if t.domain == "cooking"), key=lambda t: t.id)
    if args.sample:
        tasks = tasks[::args.sample]
    counts = audit(tasks, fresh_goals=args.fresh)
    for key, value in counts.items():
        shown = f"{len(value)}  e.g. {value[:5]}" if isinstance(value, list) else value
        print(f"{key:22} {shown}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())


def print_audit(audit: Any, domain_tasks: str = "cooking") -> int:
    """Print a form's audit (``audit(tasks) -> {name: count or list}``) over the released cooking tasks; the
    ``python -m`` entry of each hard form's generator (two_dishes.py, pantry.py)."""
    from ewa_mcp.core.paths import tasks_dir
    from ewa_mcp.core.taskmodel import TaskStore

    tasks = sorted((t for t in TaskStore([tasks_dir()]).all() if t.domain == domain_tasks), key=lambda t: t.id)
    for key, value in audit(tasks).items():
        shown = f"{len(value)}  e.g. {value[:5]}" if isinstance(value, list) else value
        print(f"{key:22} {shown}")
    return 0
