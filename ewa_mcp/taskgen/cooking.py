"""Cooking tasks: find the right recipe online (constraints single out one of a look-alike pair),
follow it to its last step, then cook it in a kitchen that holds what it needs — or buy the
missing food on the shop first."""

from __future__ import annotations

from typing import Any

from ..indoor.planner import check_recipe_executable, plan_ops, scene_inventory
from ..taskmodel import KitchenStart, OrderPlaced, RecipeCompleted, StartState, Task, WebStart
from ..websites.recipes.catalog import Filters, load_catalog
from ..websites.recipes.vocabulary import KITCHEN_PRODUCTS
from .common import call, ref, rng_for, site_url, step_limit_for
from .recipe_goals import FOODS, PIECE_SOURCE, goals_from_ops, recipe_ops

SCENES = [f"FloorPlan{i}" for i in range(1, 31)]
TASKS_PER_RECIPE = 5
SHOPPING_VARIANTS_TARGET = 40

DIET_LABEL = {"vegetarian": "Vegetarian", "vegan": "Vegan", "non-vegetarian": "Non-vegetarian"}


def constraints_for(recipe: dict[str, Any], catalog: Any) -> list[tuple[str, dict[str, Any]]]:
    """(intent suffix, search filters) pairs that leave exactly this recipe among those with its name."""
    same_name = [r for r in catalog.recipes if r["name"] == recipe["name"]]
    options: list[tuple[str, dict[str, Any]]] = []
    if len(same_name) == 1:
        options.append(("", {}))
    others = [r for r in same_name if r["id"] != recipe["id"]]
    names = {i["name"] for i in recipe["ingredients"]}
    other_names = set().union(*({i["name"] for i in o["ingredients"]} for o in others)) if others else set()
    options.append((f"Diet type: {DIET_LABEL[recipe['diet']]}", {"diet": recipe["diet"]}))
    options.append((f"Difficulty level: {recipe['difficulty'].capitalize()}", {"difficulty": recipe["difficulty"]}))
    options += [(f"Use equipment: {e}", {"equipment": [e]}) for e in recipe["equipment"]]
    options += [(f"Include ingredient: {n}", {"include": [n]}) for n in sorted(names - other_names)]
    options += [(f"Exclude ingredient: {n}", {"exclude": [n]}) for n in sorted(other_names - names)]
    good = []
    for suffix, filters in options:
        f = Filters(q=recipe["name"], diet=filters.get("diet", ""), difficulty=filters.get("difficulty", ""),
                    include=tuple(filters.get("include", ())), exclude=tuple(filters.get("exclude", ())),
                    equipment=tuple(filters.get("equipment", ())))
        hits = [r for r in catalog.search(f) if r["name"] == recipe["name"]]
        if [r["id"] for r in hits] == [recipe["id"]] and (suffix or len(same_name) == 1):
            good.append((suffix, filters))
    return good


def recipe_web_oracle(recipe: dict[str, Any], filters: dict[str, Any]) -> list[Any]:
    """Search with the constraint's filter, open the recipe, go to its last step.

    The step viewer's URL encodes the step, so the oracle jumps to the last one instead of clicking
    Next n-1 times: same goal, a third of the browser time for a whole-suite run."""
    steps = len(recipe["steps"])
    calls = [call("browser_goto", url=site_url("recipes", "/", q=recipe["name"], **filters)),
             call("browser_click", element=ref("link", recipe["name"]))]
    if steps > 1:
        calls.append(call("browser_goto", url=site_url("recipes", f"/recipe/{recipe['id']}", step=steps)))
    return calls


def buy_oracle(product_id: str) -> list[Any]:
    return [call("browser_goto", url=site_url("shop", f"/product/{product_id}")),
            call("browser_click", element=ref("button", "Add to cart")),
            call("browser_goto", url=site_url("shop", "/checkout")),
            call("browser_click", element=ref("button", "Place order"))]


def needed_foods(ops: list[dict[str, Any]]) -> set[str]:
    return {PIECE_SOURCE.get(op.get("object", ""), op.get("object", "")) for op in ops} & FOODS


def make_task(recipe: dict[str, Any], scene: str, suffix: str, filters: dict[str, Any], n: int,
              buy: str | None = None) -> Task | None:
    ops = recipe_ops(recipe)
    ok, _ = check_recipe_executable(scene, ops, available_extra_types=[buy] if buy else [])
    if not ok:
        return None
    kitchen = [call(c["tool"], **c["args"]) for c in plan_ops(scene, ops, delivered_types=[buy] if buy else [])]
    web = recipe_web_oracle(recipe, filters)
    web_goals: list[Any] = [RecipeCompleted(recipe_id=recipe["id"])]
    intent = f"Cook {recipe['name']}." + (f" {suffix}." if suffix else "")
    if buy:
        product = KITCHEN_PRODUCTS[buy]
        web += buy_oracle(product)
        web_goals.append(OrderPlaced(product_id=product))
        intent += f" Your kitchen has no {buy}: order it online from the shop for delivery first."
    oracle = [*web, call("switch_environment", target="embodied", message=f"cook {recipe['name']}"), *kitchen,
              call("finish_episode")]
    kind = "buy" if buy else "cook"
    return Task(
        id=f"cooking-{recipe['id']}-{kind}-{n:02d}",
        domain="cooking",
        intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="recipes:/"),
                         embodied=KitchenStart(scene=scene)),
        web_goals=web_goals,
        embodied_goals=goals_from_ops(ops),
        # Budget for an agent that reads every step (Next, Next, ...), which the oracle skips.
        step_limit=step_limit_for(len(oracle) + len(recipe["steps"])),
        oracle=oracle,
        metadata={"recipe_id": recipe["id"], "recipe_name": recipe["name"], "scene": scene,
                  "constraint": suffix or None, "pair_id": recipe.get("pair_id"), "buy": buy},
    )


def generate() -> list[Task]:
    catalog = load_catalog()
    inventories = {s: scene_inventory(s) for s in SCENES}
    tasks: list[Task] = []
    shopping = 0
    for recipe in sorted(catalog.recipes, key=lambda r: r["id"]):
        rng = rng_for("cooking", recipe["id"])
        constraints = constraints_for(recipe, catalog)
        if not constraints:
            continue  # cannot be singled out: never written (validation)
        ops = recipe_ops(recipe)
        foods = needed_foods(ops)
        scenes = SCENES[:]
        rng.shuffle(scenes)
        n = 0
        for scene in scenes:
            if n >= TASKS_PER_RECIPE:
                break
            if not foods <= inventories[scene]["food"]:
                continue
            suffix, filters = constraints[n % len(constraints)]
            task = make_task(recipe, scene, suffix, filters, n)
            if task is not None:
                tasks.append(task)
                n += 1
        if shopping < SHOPPING_VARIANTS_TARGET:
            # One variant where exactly one needed food is missing and must be bought online.
            for scene in scenes:
                missing = sorted(foods - inventories[scene]["food"])
                if len(missing) == 1:
                    suffix, filters = constraints[0]
                    task = make_task(recipe, scene, suffix, filters, 0, buy=missing[0])
                    if task is not None:
                        tasks.append(task)
                        shopping += 1
                    break
    return tasks
