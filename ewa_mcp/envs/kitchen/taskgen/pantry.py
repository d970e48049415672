"""Cooking hard, the recipe the kitchen can make (issue 26, principle 6: composition across worlds).

A share of the one-dish "lacking" ids (a seeded shuffle; ids and count stay) ask for the one recipe, among
the several whose name has a word, that the kitchen can make with the foods it already holds. Every recipe
page lists the foods its kitchen steps need ("from your kitchen"); every other recipe of the word needs at
least one food this kitchen lacks (a different one from recipe to recipe). The choice is decided by the two
worlds together: the agent reads each recipe's kitchen foods on the web and looks through the kitchen (its
fridge and cabinets) for what is there, and neither world alone tells the answer. Nothing is hidden: the
intent says what to find out, each page lists its foods, each container opens.

Goals: the web goal takes the last recipe followed to its end as the choice (reading every candidate to its
end and then the right one last is fine); the kitchen goals are the recipe's (method, what stays whole and
raw, nothing else on the dish), and a food only the other recipes of the word use, where the kitchen has it,
stays whole and raw. ``audit`` shows the oracle passes and that doing everything and every rival's outcome
(its missing foods delivered) fail.
"""

from __future__ import annotations

import re
from collections import Counter
from typing import Any

from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import RecipesCompleted, WebStart
from ewa_mcp.envs.kitchen.goals import KitchenStart
from ewa_mcp.taskgen.common import call, rng_for, round_robin, step_budget
from ewa_mcp.websites.recipes.catalog import _tokens as tokens
from ewa_mcp.websites.recipes.catalog import load_catalog

from ..planner import check_recipe_executable, plan_ops, scene_inventory
from . import two_dishes
from .cooking import (KITCHEN_SCOPE, NAME_WORD_MIN_NAMES, NAME_WORD_SKIP, SCENES, kitchen_goals, kitchen_steps,
                      missing_equipment, named_with, needed_foods, step_web_oracle)
from .outcomes import everything_outcome, grade_kitchen, print_audit, recipe_outcome
from .recipe_goals import recipe_ops

SHARE = 4  # one in SHARE of the one-dish hard ids takes this form
MIN_CANDIDATES = 4  # the word's recipes: a real choice, not a pair
MAX_CANDIDATES = 16  # each page read once (its ingredient list) fits the hard budget with room
# The rivals together lack at least this many different foods: the agent checks each of them in the kitchen.
MIN_LACKED = 2
PER_WORD = 4  # at most this many kitchens per word, so the form spreads over many words


def page_foods(recipe: dict[str, Any]) -> set[str]:
    """The foods the recipe page lists as "from your kitchen" (those its kitchen steps use)."""
    return {i["kitchen_type"] for i in recipe["ingredients"] if i.get("kitchen_type")}


def _words(catalog: Any) -> list[str]:
    """Every word of a recipe name that may ask for a dish: whole words, not a filler."""
    found: set[str] = set()
    for recipe in catalog.recipes:
        for word in tokens(recipe["name"]):
            if (word not in NAME_WORD_SKIP and len(word) >= 3 and word.isalpha()
                    and re.search(rf"\b{re.escape(word)}\b", recipe["name"].lower())):
                found.add(word)
    return sorted(found)


def choice(word: str, scene: str, catalog: Any) -> tuple[dict[str, Any], dict[str, list[str]]] | None:
    """(the one recipe of the word this kitchen can make with what it holds, each other recipe's id -> the
    foods it needs that the kitchen lacks); None where the kitchen does not single one out this way. Every
    other recipe lacks a food here (whatever its equipment), so foods decide; the one is never listed first
    (an agent that opens the first listed must not pass by position)."""
    listed = named_with(word, catalog)
    if not MIN_CANDIDATES <= len(listed) <= MAX_CANDIDATES or len({r["name"] for r in listed}) < NAME_WORD_MIN_NAMES:
        return None
    inventory = scene_inventory(scene)
    makeable = [r for r in listed if page_foods(r) <= inventory["food"]]
    if len(makeable) != 1 or makeable[0]["id"] == listed[0]["id"]:
        return None
    target = makeable[0]
    if not re.search(rf"\b{re.escape(word)}\b", target["name"].lower()):
        return None  # the site's search also lists "Crisp" for "crisps": the dish itself has the word, whole
    if missing_equipment(target, inventory) or not needed_foods(recipe_ops(target)) or not check_recipe_executable(scene, recipe_ops(target))[0]:
        return None
    lacks = {r["id"]: sorted(page_foods(r) - inventory["food"]) for r in listed if r["id"] != target["id"]}
    if len({food for missing in lacks.values() for food in missing}) < MIN_LACKED:
        return None  # one food absent would rule out every rival at once: one look in the kitchen, no choice
    return target, lacks


def make_pantry_task(task_id: str, word: str, scene: str, catalog: Any) -> Task | None:
    found = choice(word, scene, catalog)
    if found is None:
        return None
    recipe, lacks = found
    goals = kitchen_goals(recipe, scene, [], word)
    own = recipe_outcome(scene, recipe_ops(recipe))
    if own is None or not all(r.met for r in grade_kitchen(goals, own)):
        return None
    for rival_id, missing in lacks.items():
        state = recipe_outcome(scene, recipe_ops(catalog.by_id[rival_id]), missing)
        if state is not None and all(r.met for r in grade_kitchen(goals, state)):
            return None  # the kitchen alone could not tell this rival: the form needs it to
    w = word.capitalize()
    intent = (f'Cook the dish whose name has the word "{w}" that your kitchen can make with the foods it already '
              f'holds. Several recipes have "{w}" in their name, and each recipe page lists the foods its kitchen '
              "steps need (marked \"from your kitchen\"). Exactly one of them needs only foods your kitchen holds "
              "now; every other one needs at least one food your kitchen lacks. Find out which one (read the "
              "recipes, and look through your kitchen, its fridge and cabinets included), follow it to its last "
              "step (the last recipe you follow to the end is taken as your choice) and cook it; nothing needs "
              "ordering. " + KITCHEN_SCOPE)
    web = step_web_oracle(recipe, {"q": word})
    kitchen = [call(c["tool"], **c["args"]) for c in plan_ops(scene, recipe_ops(recipe))]
    oracle = [*web, call("switch_environment", target="embodied", message=f"cook {recipe['name']}"), *kitchen,
              call("finish_episode")]
    # A careful agent also opens every recipe of the word (a page each) and reads the chosen one step by step.
    try:
        limit = step_budget("cooking", "hard", len(oracle) + len(lacks) + 1 + len(recipe["steps"]))
    except ValueError:
        return None
    steps = kitchen_steps(recipe)
    return Task(
        id=task_id, domain="cooking", difficulty="hard", intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="recipes:/"), embodied=KitchenStart(scene=scene)),
        web_goals=[RecipesCompleted(recipe_ids=[recipe["id"]])],
        embodied_goals=goals,
        step_limit=limit,
        oracle=oracle,
        metadata={"form": "pantry", "recipe_id": recipe["id"], "recipe_name": recipe["name"], "scene": scene,
                  "name_word": word, "constraint": None, "telling_step": None, "pair_id": recipe.get("pair_id"),
                  "buy": None, "rivals_lack": lacks,
                  "kitchen_steps": steps["kitchen"], "not_kitchen_steps": steps["not_kitchen"]},
    )


def candidates(catalog: Any) -> list[list[tuple[str, str]]]:
    """Per word (sorted), its (word, scene) choices in a seeded order of kitchens."""
    queues: list[list[tuple[str, str]]] = []
    for word in _words(catalog):
        scenes = SCENES[:]
        rng_for("cooking", "pantry", word).shuffle(scenes)
        found = [(word, s) for s in scenes if choice(word, s, catalog) is not None]
        if found:
            queues.append(found)
    return queues


def with_pantry(tasks: list[Task]) -> list[Task]:
    """Give one in ``SHARE`` of the one-dish hard ids (a seeded shuffle) this form, words taken round-robin
    (at most ``PER_WORD`` kitchens each); the other ids keep their task."""
    catalog = load_catalog()
    lacking = sorted(t.id for t in tasks if t.difficulty == "hard" and not t.metadata.get("form"))
    rng_for("cooking", "pantry").shuffle(lacking)
    chosen = lacking[: len(lacking) // SHARE]
    queues = candidates(catalog)
    seen: set[tuple[str, str]] = set()

    def make(task_id: str, item: tuple[str, str]) -> Task | None:
        word, scene = item
        made = make_pantry_task(task_id, word, scene, catalog)
        if made is None or (made.metadata["recipe_id"], scene) in seen:
            return None  # nothing to make, or the same dish in the same kitchen asked by another word
        seen.add((made.metadata["recipe_id"], scene))
        return made

    # Words taken round-robin; when no word has a kitchen left, the remaining ids keep their form.
    replaced = round_robin(chosen, queues, PER_WORD, make)
    return [replaced.get(t.id, t) for t in tasks]


def generate() -> list[Task]:
    """The cooking tasks: the one-dish and two-dish forms (two_dishes.generate), then this form on its share."""
    return with_pantry(two_dishes.generate())


def audit(tasks: list[Any]) -> dict[str, Any]:
    """For each pantry task: the oracle's outcome meets every kitchen goal; doing everything fails them; each
    rival recipe of the word, cooked with its missing foods delivered, fails them (or cannot be done); and
    which foods the rivals lack, counted (balance)."""
    catalog = load_catalog()
    counts: dict[str, Any] = {"tasks": 0, "words": set(), "oracle_fails": [], "everything_passes": [],
                              "rivals": 0, "rival_passes": [], "rival_not_doable": 0, "lacked": Counter()}
    for task in tasks:
        meta = task.metadata
        if meta.get("form") != "pantry":
            continue
        counts["tasks"] += 1
        counts["words"].add(meta["name_word"])
        recipe = catalog.by_id[meta["recipe_id"]]
        scene, goals = task.start.embodied.scene, task.embodied_goals

        def passes(state: dict[str, Any] | None) -> bool:
            return state is not None and all(r.met for r in grade_kitchen(goals, state))

        if not passes(recipe_outcome(scene, recipe_ops(recipe))):
            counts["oracle_fails"].append(task.id)
        if passes(everything_outcome(scene)):
            counts["everything_passes"].append(task.id)
        for rival_id, missing in meta["rivals_lack"].items():
            counts["rivals"] += 1
            counts["lacked"].update(missing)
            state = recipe_outcome(scene, recipe_ops(catalog.by_id[rival_id]), missing)
            if state is None:
                counts["rival_not_doable"] += 1
            elif passes(state):
                counts["rival_passes"].append(f"{task.id} ({rival_id})")
    counts["words"] = len(counts["words"])
    counts["lacked"] = dict(counts["lacked"].most_common())
    return counts


def main(argv: list[str] | None = None) -> int:
    """Print the audit over the pantry tasks (``python -m ewa_mcp.envs.kitchen.taskgen.pantry``)."""
    return print_audit(audit)


if __name__ == "__main__":
    raise SystemExit(main())
