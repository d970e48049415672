"""Cooking hard, two dishes that share a food (issue 26, principle 6: composition and discrimination).

About a third of the cooking-hard ids (chosen by a seeded shuffle; ids and count stay) ask for two dishes in
one kitchen. Each dish is found the way a hard task finds its recipe (told from its look-alikes by
constraints or a step), and their kitchen steps use the SAME food in different ways: one recipe cooks its
slices (toasted, fried), the other serves its slices raw. One dish goes on a Plate, the other in a Bowl, so
each vessel's goals tell the dishes apart. One piece of the shared food, sliced, gives enough for both; the
agent finds out which foods the two recipes need that the kitchen lacks and orders exactly those.

The kitchen goals: per dish, each of its foods in its vessel with its state (the shared food cooked in one,
raw in the other), nothing else in each vessel, and each recipe's negative conditions. Doing everything,
either look-alike's outcome, and the two treatments of the shared food swapped between the dishes all fail
them (``audit``). The web goal: the two recipes are the last two followed to their end.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ewa_mcp.core.taskmodel import DomainGoal, StartState, Task
from ewa_mcp.envs.browser.goals import OrderPlaced, RecipesCompleted, WebStart
from ewa_mcp.envs.kitchen.goals import KitchenStart, ObjectIn, ObjectState
from ewa_mcp.taskgen.common import call, rng_for, round_robin, step_budget
from ewa_mcp.websites.recipes.catalog import load_catalog
from ewa_mcp.websites.recipes.vocabulary import KITCHEN_PRODUCTS

from ..planner import PlanError, _parse_ops, _Planner, scene_inventory
from . import cooking
from .cooking import (KITCHEN_SCOPE, SCENES, buy_oracle, constraints_for, delivery_store, food_treatments,
                      hard_ask, kitchen_steps, look_alikes, missing_equipment, needed_foods, recipe_web_oracle, step_web_oracle)
from .outcomes import everything_outcome, grade_kitchen, print_audit
from .recipe_goals import PIECE_SOURCE, goals_from_ops, recipe_ops, rival_foods

SHARE = 3  # one in SHARE of the cooking-hard ids takes the two-dish form
PER_PAIR = 6  # at most this many kitchens per pair of recipes
Ask = tuple[str, dict[str, Any], "str | None"]  # (constraint text, search filters, telling step)


def vessel(recipe: dict[str, Any]) -> str | None:
    """The one dish (Plate or Bowl) the recipe serves every food in, else None."""
    served = {v for _, _, v in food_treatments(recipe_ops(recipe)).values()}
    return served.pop() if len(served) == 1 and served <= {"Plate", "Bowl"} else None


def ask_for(recipe: dict[str, Any], catalog: Any) -> Ask | None:
    """How the intent asks for the recipe: the hard form's ask where the recipe has a look-alike of its name,
    else the word (or ingredient) of its name and the constraint that leaves it alone among those recipes."""
    if recipe.get("pair_id") is not None:
        pairs, step = hard_ask(recipe, catalog)
        if pairs:
            return pairs[0][0], pairs[0][1], step
        return None
    options = [(s, f) for s, f in constraints_for(recipe, catalog) if f.get("q") or f.get("include")]
    return (options[0][0], options[0][1], None) if options else None


def dish_pairs(catalog: Any) -> list[tuple[dict[str, Any], dict[str, Any], str]]:
    """(raw dish, cooked dish, shared food): two recipes of different names, each served in one vessel (not
    the same one), that share exactly one food, which both cut and only the second cooks."""
    recipes = sorted(catalog.recipes, key=lambda r: r["id"])
    info = {r["id"]: (food_treatments(recipe_ops(r)), vessel(r)) for r in recipes}
    found: list[tuple[dict[str, Any], dict[str, Any], str]] = []
    for raw in recipes:
        t_raw, v_raw = info[raw["id"]]
        if v_raw is None or ask_for(raw, catalog) is None:
            continue
        for cooked in recipes:
            t_cooked, v_cooked = info[cooked["id"]]
            if v_cooked in (None, v_raw) or cooked["name"] == raw["name"]:
                continue
            shared = set(t_raw) & set(t_cooked)
            if len(shared) != 1:
                continue
            food = shared.pop()
            if not (t_raw[food][0] and t_cooked[food][0]) or t_raw[food][1] or not t_cooked[food][1]:
                continue
            if ask_for(cooked, catalog) is None:
                continue
            found.append((raw, cooked, food))
    return found


def _planner(scene: str, first: list[dict[str, Any]], second: list[dict[str, Any]], delivered: Sequence[str],
             stop_on_error: bool) -> _Planner | None:
    """The planner after the ``first`` dish's ops and then the ``second``'s, in one kitchen (None when it
    cannot be set up, or an op fails and ``stop_on_error``). The raw dish goes first: its pieces are served
    before the other dish cooks the rest, and a served piece is never the one cooked."""
    try:
        planner = _Planner(scene, 0, list(delivered))
    except PlanError:
        return None
    planner.keep_served = True
    planner.expect(_parse_ops([*first, *second]))
    for ops in (first, second):
        cooked: set[str] = set()
        for op in _parse_ops(ops):
            try:
                planner.run(op, cooked)
            except PlanError:
                if stop_on_error:
                    return None
    return planner


def two_outcome(scene: str, first: list[dict[str, Any]], second: list[dict[str, Any]],
                delivered: Sequence[str] = (), stop_on_error: bool = True) -> dict[str, Any] | None:
    planner = _planner(scene, first, second, delivered, stop_on_error)
    return None if planner is None else planner.session.final_state()


def swapped_ops(raw_ops: list[dict[str, Any]], cooked_ops: list[dict[str, Any]],
                food: str) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """The two dishes with the shared food's treatments swapped: the raw dish's pieces cooked the other
    dish's way, the cooked dish's pieces served raw."""
    cooks = [op for op in cooked_ops if op["op"] == "cook" and PIECE_SOURCE.get(op.get("object", ""), op.get("object")) == food]
    raw_new: list[dict[str, Any]] = []
    for op in raw_ops:
        if op["op"] == "put" and PIECE_SOURCE.get(op.get("object", ""), op.get("object")) == food:
            raw_new += cooks
        raw_new.append(op)
    cooked_new = [op for op in cooked_ops if op not in cooks]
    return cooked_new, raw_new  # the now-raw dish first


def two_dish_goals(raw: dict[str, Any], cooked: dict[str, Any], food: str, scene: str, buy: Sequence[str],
                   asks: tuple[Ask, Ask]) -> list[Any]:
    """Each dish's goals (outcome and telling ones, as a one-dish task's), merged: the shared food's
    all-instance conditions give way to per-vessel ones (cooked in one vessel, raw in the other)."""
    catalog = load_catalog()
    present = scene_inventory(scene)["food"] | set(buy)
    raw_ops, cooked_ops = recipe_ops(raw), recipe_ops(cooked)
    used = needed_foods(raw_ops) | needed_foods(cooked_ops)
    goals: list[Any] = []
    for recipe, ops, ask, keep_raw in ((raw, raw_ops, asks[0], True), (cooked, cooked_ops, asks[1], False)):
        _, filters, _ = ask
        word = filters.get("q") or None
        ingredient = filters["include"][0] if not word and filters.get("include") else None
        rivals = [recipe_ops(r) for r in look_alikes(recipe, catalog, word, ingredient)]
        untouched = [f for f in rival_foods(ops, rivals) if f in present and f not in used]
        for goal in goals_from_ops(ops, untouched):
            if isinstance(goal, ObjectState) and goal.object_type == food and goal.prop == "isCooked" \
                    and goal.value is False:
                continue  # the other dish cooks its pieces: raw holds per vessel (below)
            if isinstance(goal, ObjectIn) and goal.object_type == food:
                goal = goal.model_copy(update={"with_state": {**goal.with_state, "isCooked": not keep_raw}})
            if isinstance(goal, DomainGoal) and goal.kind == "holds_only" and food in (getattr(goal, "allowed", None) or []):
                # every piece of the shared food in this dish as the dish has it: one vessel holding it both
                # ways passes for neither dish
                goal = DomainGoal.model_validate({**goal.model_dump(), "cooked": {food: not keep_raw}})
            if goal not in goals:
                goals.append(goal)
    return goals


def _ask_text(recipe: dict[str, Any], ask: Ask) -> str:
    suffix, filters, step = ask
    word = str(filters.get("q") or "").capitalize()
    ingredient = filters["include"][0] if not word and filters.get("include") else None
    if step is not None and word:
        return f'the dish whose name has the word "{word}": of the recipes with "{word}" in their name, the one that {step}'
    if step is not None and ingredient:
        return f'the dish made with "{ingredient}": of the recipes that use {ingredient}, the one that {step}'
    if step is not None:
        return f"{recipe['name']}: of the recipes with that name, the one that {step}"
    if word:
        return (f'the dish whose name has the word "{word}" and that fits this: {suffix} (several recipes have '
                f'"{word}" in their name; only one fits)')
    if ingredient:
        return f'the dish made with "{ingredient}" that fits this: {suffix} (several recipes use {ingredient}; only one fits)'
    return f"{recipe['name']}" + (f" that fits this: {suffix}" if suffix else "")


def _web_oracle(recipe: dict[str, Any], ask: Ask) -> list[Any]:
    _, filters, step = ask
    return recipe_web_oracle(recipe, filters) if step is None else step_web_oracle(recipe, filters)


def make_two_dish_task(task_id: str, raw: dict[str, Any], cooked: dict[str, Any], food: str, scene: str,
                       order: tuple[int, int]) -> Task | None:
    """One two-dish task in ``scene`` (None where the kitchen cannot hold both dishes); ``order`` says which
    dish (0: the raw one, 1: the cooked one) the intent names first."""
    catalog = load_catalog()
    inventory = scene_inventory(scene)
    if missing_equipment(raw, inventory) or missing_equipment(cooked, inventory):
        return None
    raw_ops, cooked_ops = recipe_ops(raw), recipe_ops(cooked)
    buy = sorted((needed_foods(raw_ops) | needed_foods(cooked_ops)) - inventory["food"])
    if not buy:
        return None  # nothing to find out and order: the one-dish form's step stays
    products = [KITCHEN_PRODUCTS[f] for f in buy]
    if delivery_store(products) is None:
        return None
    planner = _planner(scene, raw_ops, cooked_ops, buy, stop_on_error=True)
    if planner is None:
        return None
    asks = (ask_for(raw, catalog), ask_for(cooked, catalog))
    if asks[0] is None or asks[1] is None:
        return None
    goals = two_dish_goals(raw, cooked, food, scene, buy, (asks[0], asks[1]))
    if not all(r.met for r in grade_kitchen(goals, planner.session.final_state())):
        return None
    dishes = [(raw, asks[0]), (cooked, asks[1])]
    first, second = dishes[order[0]], dishes[order[1]]
    f = food.lower()
    intent = (f"Cook two dishes in your kitchen. The first is {_ask_text(*first)}. The second is "
              f"{_ask_text(*second)}. Both recipes use {f}, each in its own way, and each dish is served as its "
              f"own recipe says: one {f}, cut, gives enough for both. Follow each of the two recipes to its last "
              "step (the last two recipes you follow to the end are taken as your choice). Your kitchen lacks "
              "some of the foods the two recipes' kitchen steps need: find out which, and order exactly those "
              "from the shop for delivery to your kitchen before you cook. " + KITCHEN_SCOPE)
    web = [*_web_oracle(*first), *_web_oracle(*second), *buy_oracle(products)]
    oracle = [*web, call("switch_environment", target="embodied", message=f"cook {raw['name']} and {cooked['name']}"),
              *[call(c["tool"], **c["args"]) for c in planner.calls], call("finish_episode")]
    try:
        limit = step_budget("cooking", "hard", len(oracle) + len(raw["steps"]) + len(cooked["steps"]))
    except ValueError:
        return None
    return Task(
        id=task_id, domain="cooking", difficulty="hard", intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="recipes:/"), embodied=KitchenStart(scene=scene)),
        web_goals=[RecipesCompleted(recipe_ids=[first[0]["id"], second[0]["id"]]),
                   *[OrderPlaced(product_id=p) for p in products]],
        embodied_goals=goals,
        step_limit=limit,
        oracle=oracle,
        metadata={"form": "two_dishes", "recipe_id": raw["id"], "recipe_name": raw["name"],
                  "second_recipe_id": cooked["id"], "second_recipe_name": cooked["name"],
                  "shared_food": food, "raw_vessel": vessel(raw), "cooked_vessel": vessel(cooked),
                  "scene": scene, "buy": buy,
                  **{f"{key}_steps": steps for key, steps in kitchen_steps(raw).items()},
                  **{f"second_{key}_steps": steps for key, steps in kitchen_steps(cooked).items()},
                  "asks": [{"recipe_id": d["id"], "constraint": a[0] or None, "filters": a[1], "telling_step": a[2]}
                           for d, a in (first, second)]},
    )


def with_two_dishes(tasks: list[Task]) -> list[Task]:
    """Give one in ``SHARE`` of the cooking-hard ids (a seeded shuffle) the two-dish form, where some pair
    of recipes can be cooked in some kitchen; the other ids keep their one-dish task."""
    catalog = load_catalog()
    hard = [t.id for t in tasks if t.id.startswith("cooking-hard-")]
    chosen = sorted(hard)
    rng = rng_for("cooking", "two-dishes")
    rng.shuffle(chosen)
    chosen = chosen[: len(hard) // SHARE]
    # Every pair in kitchens of its own seeded order, taken round-robin so the pairs spread over the ids.
    queues: list[list[tuple[dict[str, Any], dict[str, Any], str, str]]] = []
    for raw, cooked, food in dish_pairs(catalog):
        scenes = SCENES[:]
        rng_for("cooking", "two-dishes", raw["id"], cooked["id"]).shuffle(scenes)
        queues.append([(raw, cooked, food, s) for s in scenes])

    def make(task_id: str, item: tuple[dict[str, Any], dict[str, Any], str, str]) -> Task | None:
        raw, cooked, food, scene = item
        order = (0, 1) if rng.random() < 0.5 else (1, 0)
        return make_two_dish_task(task_id, raw, cooked, food, scene, order)

    # When no pair has a kitchen left, the remaining ids keep the one-dish form.
    replaced = round_robin(chosen, queues, PER_PAIR, make)
    return [replaced.get(t.id, t) for t in tasks]


def generate() -> list[Task]:
    """The cooking tasks: the one-dish templates (cooking.py), then the two-dish form on its share of hard."""
    return with_two_dishes(cooking.generate())


def audit(tasks: list[Any]) -> dict[str, Any]:
    """For each two-dish task: does the oracle's outcome meet every kitchen goal, and do doing everything,
    each look-alike in place of its dish, and the shared food's treatments swapped each fail one?"""
    catalog = load_catalog()
    counts: dict[str, Any] = {"tasks": 0, "oracle_fails": [], "everything_passes": [], "lookalikes": 0,
                              "lookalike_passes": [], "lookalike_same_kitchen": 0, "lookalike_not_doable": 0, "swap_passes": [],
                              "swap_not_doable": []}
    for task in tasks:
        meta = task.metadata
        if meta.get("form") != "two_dishes":
            continue
        counts["tasks"] += 1
        raw, cooked = catalog.by_id[meta["recipe_id"]], catalog.by_id[meta["second_recipe_id"]]
        scene, buy, food = task.start.embodied.scene, list(meta["buy"]), meta["shared_food"]
        goals = task.embodied_goals

        def passes(state: dict[str, Any] | None) -> bool:
            return state is not None and all(r.met for r in grade_kitchen(goals, state))

        if not passes(two_outcome(scene, recipe_ops(raw), recipe_ops(cooked), buy)):
            counts["oracle_fails"].append(task.id)
        if passes(everything_outcome(scene, buy)):
            counts["everything_passes"].append(task.id)
        swapped = swapped_ops(recipe_ops(raw), recipe_ops(cooked), food)
        state = two_outcome(scene, *swapped, buy, stop_on_error=False)
        if state is None:
            counts["swap_not_doable"].append(task.id)
        elif passes(state):
            counts["swap_passes"].append(task.id)
        for which, recipe in ((0, raw), (1, cooked)):
            for other in catalog.recipes:
                if other["name"] != recipe["name"] or other["id"] == recipe["id"]:
                    continue
                counts["lookalikes"] += 1
                if recipe_ops(other) == recipe_ops(recipe):
                    counts["lookalike_same_kitchen"] += 1  # told apart outside the kitchen: the web goal's job
                    continue
                dishes = [recipe_ops(raw), recipe_ops(cooked)]
                dishes[which] = recipe_ops(other)
                state = two_outcome(scene, dishes[0], dishes[1], buy)
                if state is None:
                    counts["lookalike_not_doable"] += 1  # a food it needs is neither here nor ordered
                elif passes(state):
                    counts["lookalike_passes"].append(f"{task.id} ({recipe['id']} vs {other['id']})")
    return counts


def main(argv: list[str] | None = None) -> int:
    """Print the audit over the two-dish tasks (``python -m ewa_mcp.envs.kitchen.taskgen.two_dishes``)."""
    return print_audit(audit)


if __name__ == "__main__":
    raise SystemExit(main())
