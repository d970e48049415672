"""Cooking tasks: find the right recipe online (constraints single out one of a look-alike pair),
follow it to its last step, then cook it in a kitchen that holds what it needs — or buy the
missing food on the shop, for delivery to the kitchen, first.

Three templates, each with its difficulty:
  * cook (easy): the recipe asked for by a word of its name that several recipes share (else an ingredient
    several use) and the constraints that leave it alone among them, every food in the kitchen;
  * buy (medium): the same, one needed food missing and ordered for delivery;
  * hard (by composition, issue 26): the recipe is told from the other recipes of a word of its name (or of
    an ingredient) only by what one of its steps, or two together, do to a food (cooked in the pan, toasted,
    kept raw; no search filter says it), or, where no step tells them apart, by two constraints that only
    together single it out; two needed foods are
    missing, and the intent does not say which: the agent compares the recipe's kitchen foods with the
    kitchen, then orders exactly those for delivery (in one order) before it cooks.
"""

from __future__ import annotations

import functools
import itertools
import re
from collections.abc import Callable, Iterator
from typing import Any

from ..planner import check_recipe_executable, plan_ops, scene_inventory
from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import OrderPlaced, RecipeCompleted, WebStart
from ewa_mcp.envs.kitchen.goals import KitchenStart
from ewa_mcp.websites.recipes.catalog import Filters, load_catalog
from ewa_mcp.websites.recipes.catalog import _fold as fold
from ewa_mcp.websites.recipes.catalog import _token_in as token_in
from ewa_mcp.websites.recipes.catalog import _tokens as tokens
from ewa_mcp.websites.shop import catalog as shop_catalog
from ewa_mcp.websites.recipes.vocabulary import EQUIPMENT_WORDS, KITCHEN_PRODUCTS, required_equipment
from ewa_mcp.taskgen.common import call, ref, rng_for, site_url, step_budget
from .recipe_goals import FOODS, PIECE_SOURCE, goals_from_ops, recipe_ops, rival_foods

SCENES = [f"FloorPlan{i}" for i in range(1, 31)]
TASKS_PER_RECIPE = 5  # cook and hard tasks of one recipe, together
HARD_PER_RECIPE = 3  # of those, hard ones (recipes with a look-alike and two or more kitchen foods)
SHOPPING_VARIANTS_TARGET = 40
DIFFICULTY = {"cook": "easy", "buy": "medium", "hard": "hard"}
# Every cooking intent says which parts of a recipe the kitchen goal leaves out (issue 16).
KITCHEN_SCOPE = ("Only the kitchen steps count: steps and ingredients the recipe page marks as not in the "
                 "kitchen are not part of the kitchen goal. Do what they say, the way they say it, and no more: "
                 "food they do not cut or cook stays whole and raw, and a dish holds only what they put on it.")

DIET_LABEL = {"vegetarian": "Vegetarian", "vegan": "Vegan", "non-vegetarian": "Non-vegetarian"}


def constraint_options(recipe: dict[str, Any], catalog: Any, others: list[dict[str, Any]] | None = None,
                       wide: bool = False) -> list[tuple[str, dict[str, Any]]]:
    """Every (intent suffix, search filter) that is true of this recipe and tells it from some look-alike
    (``others``: those of its name when not given)."""
    if others is None:
        others = [r for r in catalog.recipes if r["name"] == recipe["name"] and r["id"] != recipe["id"]]
    names = {i["name"] for i in recipe["ingredients"]}
    other_names = set().union(*({i["name"] for i in o["ingredients"]} for o in others)) if others else set()
    options: list[tuple[str, dict[str, Any]]] = []
    options.append((f"Diet type: {DIET_LABEL[recipe['diet']]}", {"diet": recipe["diet"]}))
    options.append((f"Difficulty level: {recipe['difficulty'].capitalize()}", {"difficulty": recipe["difficulty"]}))
    options += [(f"Use equipment: {e}", {"equipment": [e]}) for e in recipe["equipment"]]
    # Among same-named recipes an ingredient tells only when the others lack it; among many recipes that
    # share a word of their names, any ingredient of this one narrows the list.
    include = names if wide else names - other_names
    options += [(f"Include ingredient: {n}", {"include": [n]}) for n in sorted(include)]
    options += [(f"Exclude ingredient: {n}", {"exclude": [n]}) for n in sorted(other_names - names)]
    return options


def singles_out(recipe: dict[str, Any], catalog: Any, filters: dict[str, Any]) -> bool:
    """Searching the recipe's name with these filters leaves exactly this recipe among those of its name."""
    f = Filters(q=recipe["name"], diet=filters.get("diet", ""), difficulty=filters.get("difficulty", ""),
                include=tuple(filters.get("include", ())), exclude=tuple(filters.get("exclude", ())),
                equipment=tuple(filters.get("equipment", ())))
    return [r["id"] for r in catalog.search(f) if r["name"] == recipe["name"]] == [recipe["id"]]


# Words of a dish's name that name no kind of dish ("Salmon with Crispy Potatoes": salmon, crispy, potatoes).
NAME_WORD_SKIP = {"and", "with", "in", "a", "the", "of", "over", "for", "on", "to", "de", "style"}
NAME_WORD_MIN_NAMES = 3  # recipes of at least this many names share the word: a real choice


def _filters(q: str, filters: dict[str, Any]) -> Filters:
    return Filters(q=q, diet=filters.get("diet", ""), difficulty=filters.get("difficulty", ""),
                   cuisine=filters.get("cuisine", ""), include=tuple(filters.get("include", ())),
                   exclude=tuple(filters.get("exclude", ())), equipment=tuple(filters.get("equipment", ())))


def named_with(word: str, catalog: Any, filters: dict[str, Any] | None = None) -> list[dict[str, Any]]:
    """The recipes a search for ``word`` (with the filters) lists whose name has the word, in listed order."""
    return [r for r in catalog.search(_filters(word, filters or {})) if token_in(word, fold(r["name"]))]


def _one_else_two(options: list[tuple[str, dict[str, Any]]], lists: Callable[[dict[str, Any]], list[dict[str, Any]]],
                  recipe_id: str) -> list[tuple[str, dict[str, Any]]]:
    """The constraints, one, else two together, under which ``lists`` (a search) lists only the recipe."""
    def alone(f: dict[str, Any]) -> bool:
        return [r["id"] for r in lists(f)] == [recipe_id]

    found = [(suffix, f) for suffix, f in options if alone(f)]
    if not found:
        for i, (s1, f1) in enumerate(options):
            for s2, f2 in options[i + 1:]:
                merged = merge_filters(f1, f2)
                if merged is not None and alone(merged):
                    found.append((f"{s1}. {s2}", merged))
    return found


Asked = tuple[str, list[tuple[str, dict[str, Any]]]]  # what a recipe is asked by, and the constraints


def _per_recipe(find: Callable[[dict[str, Any], Any], Asked]) -> Callable[[dict[str, Any], Any], Asked]:
    """``find(recipe, catalog)``, cached per recipe for the shipped catalogue (the generator asks about each
    recipe many times); any other catalogue (a test's) is searched afresh."""
    cached = functools.cache(lambda recipe_id: find(load_catalog().by_id[recipe_id], load_catalog()))

    def lookup(recipe: dict[str, Any], catalog: Any) -> Asked:
        return cached(recipe["id"]) if catalog is load_catalog() else find(recipe, catalog)

    return lookup


def _find_name_word_constraints(recipe: dict[str, Any],
                                catalog: Any) -> tuple[str, list[tuple[str, dict[str, Any]]]]:
    """A word of the recipe's name that the names of several recipes share, and the constraints (one, else
    two together) that leave it alone among them; ("", []) when no word does. Named outright, a recipe
    with a name of its own needs no choosing (following the only recipe of that name was the task), and
    one with a same-named look-alike is a choice between two (issue 26: the look-alike and first-recipe
    agents scored there). Asked for by the word, the agent must tell it from the other recipes of that
    word by the constraint. A word whose search lists the target first is taken only where no other word
    serves, and never for a recipe with a look-alike: there opening the first listed recipe would pass
    every time, where its name leaves that a coin toss."""
    paired = any(r["name"] == recipe["name"] and r["id"] != recipe["id"] for r in catalog.recipes)
    best: tuple[tuple[bool, int], str, list[tuple[str, dict[str, Any]]]] = ((False, 0), "", [])
    for word in reversed(tokens(recipe["name"])):
        if word in NAME_WORD_SKIP or len(word) < 3:
            continue
        listed = named_with(word, catalog)
        if len({r["name"] for r in listed}) < NAME_WORD_MIN_NAMES:
            continue
        others = [r for r in listed if r["id"] != recipe["id"]]
        options = constraint_options(recipe, catalog, others, wide=True)
        alone = _one_else_two(options, functools.partial(named_with, word, catalog), recipe["id"])
        # The word most recipes share first (more to choose from), then one constraint over two.
        not_first = listed[0]["id"] != recipe["id"]
        if paired and not not_first:
            continue
        rank = (not_first, len(listed) * (2 if alone and ". " not in alone[0][0] else 1))
        if alone and rank > best[0]:
            best = (rank, word, [(suffix, {**f, "q": word}) for suffix, f in alone])
    return best[1], best[2]


name_word_constraints = _per_recipe(_find_name_word_constraints)


def made_with(ingredient: str, catalog: Any, filters: dict[str, Any] | None = None) -> list[dict[str, Any]]:
    """The recipes the site lists for its ingredient filter (with the other filters), in listed order."""
    merged = merge_filters({"include": [ingredient]}, filters or {}) or {}
    return catalog.search(_filters("", merged))


def _find_ingredient_constraints(recipe: dict[str, Any],
                                 catalog: Any) -> tuple[str, list[tuple[str, dict[str, Any]]]]:
    """For a recipe no word of whose name serves: an ingredient of it that the recipes of several names
    use, whose list (the site's ingredient filter) does not show the target first, and the constraints
    (one, else two together) that leave it alone among them; ("", []) when none does. The filters carry
    the ingredient in ``include``."""
    best: tuple[int, str, list[tuple[str, dict[str, Any]]]] = (0, "", [])
    for ingredient in sorted({i["name"] for i in recipe["ingredients"]}):
        listed = made_with(ingredient, catalog)
        if len({r["name"] for r in listed}) < NAME_WORD_MIN_NAMES or listed[0]["id"] == recipe["id"]:
            continue
        others = [r for r in listed if r["id"] != recipe["id"]]
        options = [(suffix, f) for suffix, f in constraint_options(recipe, catalog, others, wide=True)
                   if f.get("include") != [ingredient]]
        alone = _one_else_two(options, functools.partial(made_with, ingredient, catalog), recipe["id"])
        rank = len(listed) * (2 if alone and ". " not in alone[0][0] else 1)
        if alone and rank > best[0]:
            best = (rank, ingredient, [(suffix, {"q": "", **(merge_filters({"include": [ingredient]}, f) or {})})
                                       for suffix, f in alone])
    return best[1], best[2]


ingredient_constraints = _per_recipe(_find_ingredient_constraints)


def _asking_words(recipe: dict[str, Any], catalog: Any) -> Iterator[tuple[str, list[dict[str, Any]]]]:
    """The words of the recipe's name (last first) that a paired recipe can be asked by, with what a search for
    each lists: words the names of several recipes share, whose list does not show the target first."""
    for word in reversed(tokens(recipe["name"])):
        if word in NAME_WORD_SKIP or len(word) < 3:
            continue
        listed = named_with(word, catalog)
        if len({r["name"] for r in listed}) >= NAME_WORD_MIN_NAMES and listed[0]["id"] != recipe["id"]:
            yield word, listed


@functools.cache
def _three_constraints_by_word(recipe_id: str) -> tuple[str, list[tuple[str, dict[str, Any]]]]:
    """For a recipe with a same-named look-alike that neither a word of its name nor an ingredient serves
    with one or two constraints: a word of its name whose list does not show it first, and three
    constraints that together leave it alone among that word's recipes; ("", []) when none do. Named, it
    would be a coin toss for an agent that opens the first listed recipe (the lower id of the pair)."""
    catalog = load_catalog()
    recipe = catalog.by_id[recipe_id]
    for word, listed in _asking_words(recipe, catalog):
        options = constraint_options(recipe, catalog, [r for r in listed if r["id"] != recipe["id"]], wide=True)
        found: list[tuple[str, dict[str, Any]]] = []
        for a, b, c in itertools.combinations(options, 3):
            merged = merge_filters(a[1], b[1])
            merged = merge_filters(merged, c[1]) if merged is not None else None
            if merged is not None and [r["id"] for r in named_with(word, catalog, merged)] == [recipe["id"]]:
                found.append((f"{a[0]}. {b[0]}. {c[0]}", {**merged, "q": word}))
        if found:
            return word, found
    return "", []


def _three_together(options: list[tuple[str, dict[str, Any]]], lists: Callable[[dict[str, Any]], list[dict[str, Any]]],
                    recipe_id: str) -> list[tuple[str, dict[str, Any]]]:
    """The constraints, three together, under which ``lists`` (a search) lists only the recipe."""
    found: list[tuple[str, dict[str, Any]]] = []
    for a, b, c in itertools.combinations(options, 3):
        merged = merge_filters(a[1], b[1])
        merged = merge_filters(merged, c[1]) if merged is not None else None
        if merged is not None and [r["id"] for r in lists(merged)] == [recipe_id]:
            found.append((f"{a[0]}. {b[0]}. {c[0]}", merged))
    return found


@functools.cache
def _cuisine_constraints(recipe_id: str) -> tuple[str, list[tuple[str, dict[str, Any]]]]:
    """For a recipe no word or ingredient serves with the usual constraints: a word of its name, else an
    ingredient of it, whose list (of several names) does not show it first, and the constraints (one, else
    two, else three together) that leave it alone there, the cuisine among them ("Cuisine: Irish": the site
    filters by it); ("", []) when none do. Named, a paired recipe was a coin toss for an agent that opens
    the first listed recipe, and a unique name needed no choosing; a word whose list shows it first, a sure
    pass."""
    catalog = load_catalog()
    recipe = catalog.by_id[recipe_id]
    cuisine = (f"Cuisine: {recipe['cuisine']}", {"cuisine": recipe["cuisine"]})
    searches: list[tuple[str, dict[str, Any], list[tuple[str, dict[str, Any]]], Callable[..., Any]]] = []
    for word, listed in _asking_words(recipe, catalog):
        options = constraint_options(recipe, catalog, [r for r in listed if r["id"] != recipe_id], wide=True)
        searches.append((word, {"q": word}, [*options, cuisine], functools.partial(named_with, word, catalog)))
    for ingredient, listed in _asking_ingredients(recipe, catalog):
        options = [(suffix, f) for suffix, f in constraint_options(
            recipe, catalog, [r for r in listed if r["id"] != recipe_id], wide=True) if f.get("include") != [ingredient]]
        searches.append((ingredient, {"q": "", "include": [ingredient]}, [*options, cuisine],
                         functools.partial(made_with, ingredient, catalog)))
    for find in (_one_else_two, _three_together):
        for key, search, options, lists in searches:
            found = find(options, lists, recipe_id)
            if found:
                return key, [(suffix, {**f, **(merge_filters(search, f) or {})}) for suffix, f in found]
    return "", []


def look_alikes(recipe: dict[str, Any], catalog: Any, word: str | None = None,
                ingredient: str | None = None) -> list[dict[str, Any]]:
    """The recipes a task for this one must be told from: those that share the word the intent asks by
    (``word``; its same-named look-alike among them), else those of its name, or, for a name no other
    recipe has, those that share the word such a task asks by."""
    if word:
        return [r for r in named_with(word, catalog) if r["id"] != recipe["id"]]
    if ingredient:
        return [r for r in made_with(ingredient, catalog) if r["id"] != recipe["id"]]
    same = [r for r in catalog.recipes if r["name"] == recipe["name"] and r["id"] != recipe["id"]]
    if same:
        return same
    word, _ = name_word_constraints(recipe, catalog)
    return [r for r in named_with(word, catalog) if r["id"] != recipe["id"]] if word else []


def constraints_for(recipe: dict[str, Any], catalog: Any) -> list[tuple[str, dict[str, Any]]]:
    """(intent suffix, search filters) pairs for the one-constraint templates (cook, buy): those that leave
    exactly this recipe among the recipes whose name has a word of its name (the filters carry the word as
    ``q``); where no word is shared by enough names, those that leave it alone among the recipes of its
    name, or, for a name no other recipe has, the name alone (nothing to choose; docs/verified.md).

    Asked by its name, a recipe with one same-named look-alike was a choice between two: opening the first
    listed and ignoring the constraint passed half of those tasks (issue 26, the first-recipe agent).
    Among the several recipes of a word the first listed is seldom the one."""
    unique = sum(r["name"] == recipe["name"] for r in catalog.recipes) == 1
    word, by_word = name_word_constraints(recipe, catalog)
    if by_word and named_with(word, catalog)[0]["id"] != recipe["id"]:
        return by_word
    # No word of the name serves (or its list shows the target first): ask by an ingredient instead.
    _, by_ingredient = ingredient_constraints(recipe, catalog)
    if by_ingredient:
        return by_ingredient
    if not unique and catalog is load_catalog():
        _, by_three = _three_constraints_by_word(recipe["id"])
        if by_three:
            return by_three
    if catalog is load_catalog():
        # The cuisine, a filter no other form uses, where nothing else leaves it alone (docs/verified.md).
        _, by_cuisine = _cuisine_constraints(recipe["id"])
        if by_cuisine:
            return by_cuisine
    if by_word:
        return by_word
    good: list[tuple[str, dict[str, Any]]] = [("", {})] if unique else []
    good += [(suffix, f) for suffix, f in constraint_options(recipe, catalog) if singles_out(recipe, catalog, f)]
    return good


def merge_filters(a: dict[str, Any], b: dict[str, Any]) -> dict[str, Any] | None:
    """Both filters at once (None when they set the same single-valued filter)."""
    merged = dict(a)
    for key, value in b.items():
        if key in ("diet", "difficulty", "cuisine"):
            if key in merged:
                return None
            merged[key] = value
        else:
            merged[key] = [*merged.get(key, []), *value]
    return merged


def two_constraints(recipe: dict[str, Any], catalog: Any) -> list[tuple[str, dict[str, Any]]]:
    """Pairs of constraints that together single out a recipe with a look-alike, best first: pairs where
    neither constraint alone does (the agent must apply both), then the others."""
    if recipe.get("pair_id") is None:
        return []
    options = constraint_options(recipe, catalog)
    alone = {suffix: singles_out(recipe, catalog, f) for suffix, f in options}
    pairs: list[tuple[int, str, dict[str, Any]]] = []
    for i, (s1, f1) in enumerate(options):
        for s2, f2 in options[i + 1:]:
            merged = merge_filters(f1, f2)
            if merged is not None and singles_out(recipe, catalog, merged):
                pairs.append((int(alone[s1]) + int(alone[s2]), f"{s1}. {s2}", merged))
    pairs.sort(key=lambda item: item[0])  # stable: the options' own order within a rank
    return [(suffix, merged) for _, suffix, merged in pairs]


def word_pairs(recipe: dict[str, Any], catalog: Any) -> list[tuple[str, dict[str, Any]]]:
    """Hard: pairs of constraints that together leave a recipe with a look-alike alone among the recipes of a
    word of its name (the filters carry the word as ``q``), pairs where neither constraint alone does first;
    [] when no word serves. Named outright, the pair was a choice between two: opening the first listed
    recipe passed about 44 % of hard tasks (issue 26, the first-recipe agent). A word whose search lists
    the target first is never used."""
    if recipe.get("pair_id") is None:
        return []
    for word, listed in _asking_words(recipe, catalog):
        others = [r for r in listed if r["id"] != recipe["id"]]
        options = constraint_options(recipe, catalog, others, wide=True)

        def alone(f: dict[str, Any], word: str = word) -> bool:
            return [r["id"] for r in named_with(word, catalog, f)] == [recipe["id"]]

        single = {suffix: alone(f) for suffix, f in options}
        pairs: list[tuple[int, str, dict[str, Any]]] = []
        for i, (s1, f1) in enumerate(options):
            for s2, f2 in options[i + 1:]:
                merged = merge_filters(f1, f2)
                if merged is not None and alone(merged):
                    pairs.append((int(single[s1]) + int(single[s2]), f"{s1}. {s2}", {**merged, "q": word}))
        if pairs:
            pairs.sort(key=lambda item: item[0])  # stable: the options' own order within a rank
            return [(suffix, merged) for _, suffix, merged in pairs]
    return []


def food_treatments(ops: list[dict[str, Any]]) -> dict[str, tuple[bool, frozenset[str], str | None]]:
    """Per food the recipe works with: (cut or cracked, every place it cooks, empty for raw, where it is
    served). Every place, not the last: a potato fried in the pan and then warmed in the microwave is cooked
    in a pan on the stove, as a reader of its steps would say."""
    out: dict[str, tuple[bool, frozenset[str], str | None]] = {}
    for op in ops:
        obj = op.get("object", "")
        food = PIECE_SOURCE.get(obj, obj)
        if food not in FOODS:
            continue
        cut, cook, served = out.get(food, (False, frozenset(), None))
        if op["op"] in ("slice", "crack"):
            cut = True
        elif op["op"] == "cook":
            cook = cook | {str(op.get("vessel") or op.get("method"))}
        elif op["op"] == "put" and op.get("receptacle") in ("Plate", "Bowl"):
            served = op["receptacle"]
        out[food] = (cut, cook, served)
    return out


COOKED_IN = {"toaster": "toasts the {f} in the toaster", "microwave": "cooks the {f} in the microwave",
             "Pan": "cooks the {f} in a pan on the stove", "Pot": "cooks the {f} in a pot on the stove"}


def telling_step(recipe: dict[str, Any], catalog: Any) -> str | None:
    """How one of the recipe's steps treats a food that every look-alike also uses but treats otherwise
    (cooked another way or not at all, cut or left whole, served on a plate or in a bowl), in plain words:
    "the version that keeps the tomato raw". No search filter says this; only the steps do (issue 26,
    principle 6: a recipe told apart only by a step). None when no food tells them apart this way."""
    mine = food_treatments(recipe_ops(recipe))
    rivals = [food_treatments(recipe_ops(r)) for r in catalog.recipes
              if r["name"] == recipe["name"] and r["id"] != recipe["id"]]
    if not rivals:
        return None
    for food, (cut, cook, served) in sorted(mine.items()):
        f = food.lower()
        theirs = [r.get(food) for r in rivals]
        if any(t is None for t in theirs):
            continue  # a food the look-alike lacks is what an ingredient filter tells apart
        for method in sorted(cook):
            if method in COOKED_IN and all(method not in t[1] for t in theirs if t):
                return COOKED_IN[method].format(f=f)
        if not cook and all(t[1] for t in theirs if t):
            return f"keeps the {f} raw"
        if all(t[0] != cut for t in theirs if t):
            return f"{'cracks' if food == 'Egg' else 'cuts'} the {f}" if cut else f"keeps the {f} whole"
        if served and all(t[2] not in (None, served) for t in theirs if t):
            return f"serves the {f} {'on a plate' if served == 'Plate' else 'in a bowl'}"
    return None


Treatments = dict[str, tuple[bool, frozenset[str], str | None]]  # food_treatments' answer


def _cooks(food: str, cook: str, t: Treatments) -> bool:
    return food in t and cook in t[food][1]


def _raw(food: str, t: Treatments) -> bool:
    return food not in t or not t[food][1]


def _cuts(food: str, t: Treatments) -> bool:
    return food in t and t[food][0]


def _whole(food: str, t: Treatments) -> bool:
    return food not in t or not t[food][0]


def _serves(food: str, served: str, t: Treatments) -> bool:
    # a rival that puts the food in no dish is not told apart by where this one serves it
    return food in t and t[food][2] in (None, served)


def step_statements(recipe: dict[str, Any]) -> list[tuple[str, Callable[[Treatments], bool]]]:
    """What the recipe's steps do to each food it works with, in plain words ("cooks the egg in the microwave",
    "cuts the tomato", "keeps the bread whole", "serves the lettuce in a bowl"), each with whether it holds
    for another recipe (its food treatments). A recipe without the food does not cook, cut or serve it; one
    that holds for what no step does (kept raw, kept whole) is taken to hold for it too (vacuously), so such
    a statement never tells a recipe from one that lacks the food."""
    out: list[tuple[str, Callable[[Treatments], bool]]] = []
    for food, (cut, cook, served) in sorted(food_treatments(recipe_ops(recipe)).items()):
        f = food.lower()
        for method in sorted(cook):
            if method in COOKED_IN:
                out.append((COOKED_IN[method].format(f=f), functools.partial(_cooks, food, method)))
        if not cook:
            out.append((f"keeps the {f} raw", functools.partial(_raw, food)))
        if cut:
            out.append((f"{'cracks' if food == 'Egg' else 'cuts'} the {f}", functools.partial(_cuts, food)))
        else:
            out.append((f"keeps the {f} whole", functools.partial(_whole, food)))
        if served:
            out.append((f"serves the {f} {'on a plate' if served == 'Plate' else 'in a bowl'}",
                        functools.partial(_serves, food, served)))
    return out


def _asking_ingredients(recipe: dict[str, Any], catalog: Any) -> Iterator[tuple[str, list[dict[str, Any]]]]:
    """The recipe's ingredients that recipes of several names use, with what the site's ingredient filter
    lists for each, where that list does not show the recipe first."""
    for ingredient in sorted({i["name"] for i in recipe["ingredients"]}):
        listed = made_with(ingredient, catalog)
        if len({r["name"] for r in listed}) >= NAME_WORD_MIN_NAMES and listed[0]["id"] != recipe["id"]:
            yield ingredient, listed


# A step-told task asked by a word or ingredient: at most this many of the recipes listed use every food the
# step names and the equipment it names (the site's ingredient and equipment filters narrow the list to
# them); the agent opens and reads each to find the one whose steps do it, within the hard step budget.
MAX_STEP_CANDIDATES = 6
STEP_EQUIPMENT = {"toaster": "Toaster", "microwave": "Microwave", "pan": "Pan", "pot": "Pot", "cuts": "Knife",
                  "plate": "Plate", "bowl": "Bowl"}


def step_candidates(listed: list[dict[str, Any]], step: str) -> list[dict[str, Any]]:
    """The listed recipes that use every food the step names and have the equipment it names: those an agent
    must read, after the site's filters, to find the one whose steps do it."""
    words = re.findall(r"[a-z]+", step.lower())
    foods = {f for f in FOODS if f.lower() in words}
    equipment = {STEP_EQUIPMENT[w] for w in words if w in STEP_EQUIPMENT}
    return [r for r in listed if foods <= {i["name"] for i in r["ingredients"]} and equipment <= set(r["equipment"])]


@functools.cache
def asked_telling_step(recipe_id: str) -> tuple[dict[str, Any], str] | None:
    """Hard, for a recipe with a same-named look-alike: (search, step) where the search is a word of its name
    that the names of several recipes share (``{"q": word}``), else an ingredient that recipes of several
    names use (``{"q": "", "include": [ingredient]}``), whose list does not show the recipe first, and the
    step (what its steps do to a food, else two such things together: "cuts the tomato and cooks the egg in
    the microwave") is true of it and of no other recipe listed; None when none has such a step. Named
    outright, a step-told pair was a choice between two: opening the first listed recipe passed half of
    them (issue 26). Among the several recipes listed only the steps single it out, and where two statements
    are needed, only both together."""
    catalog = load_catalog()
    recipe = catalog.by_id[recipe_id]
    if not any(r["name"] == recipe["name"] and r["id"] != recipe_id for r in catalog.recipes):
        return None
    statements = step_statements(recipe)
    searches: list[tuple[dict[str, Any], list[dict[str, Any]]]] = [
        ({"q": w}, listed) for w, listed in _asking_words(recipe, catalog)]
    searches += [({"q": "", "include": [i]}, listed) for i, listed in _asking_ingredients(recipe, catalog)]
    for size in (1, 2):  # one statement wherever one serves, under any search; else two together
        for search, listed in searches:
            rivals = [food_treatments(recipe_ops(r)) for r in listed if r["id"] != recipe_id]
            for chosen in itertools.combinations(statements, size):
                step = " and ".join(text for text, _ in chosen)
                if (not any(all(holds(r) for _, holds in chosen) for r in rivals)
                        and len(step_candidates(listed, step)) <= MAX_STEP_CANDIDATES):
                    return search, step
    return None


def recipe_web_oracle(recipe: dict[str, Any], filters: dict[str, Any]) -> list[Any]:
    """Search with the constraint's filter, open the recipe, go to its last step.

    The step viewer's URL encodes the step, so the oracle jumps to the last one instead of clicking
    Next n-1 times: same goal, a third of the browser time for a whole-suite run."""
    steps = len(recipe["steps"])
    search = {"q": recipe["name"], **filters}  # a task asking by a word of the name searches that word
    calls = [call("browser_goto", url=site_url("recipes", "/", **search)),
             call("browser_click", element=ref("link", recipe["name"]))]
    if steps > 1:
        calls.append(call("browser_goto", url=site_url("recipes", f"/recipe/{recipe['id']}", step=steps)))
    return calls


def step_web_oracle(recipe: dict[str, Any], filters: dict[str, Any] | None = None) -> list[Any]:
    """Search the name (or the word or ingredient the intent asks by: ``filters``' q and include), then open
    the one recipe whose steps match and go to its last step (no constraint filter tells the look-alikes
    apart; the oracle knows which one it is)."""
    steps = len(recipe["steps"])
    search = {k: v for k, v in (filters or {}).items() if k in ("q", "include")} or {"q": recipe["name"]}
    return [call("browser_goto", url=site_url("recipes", "/", **search)),
            call("browser_goto", url=site_url("recipes", f"/recipe/{recipe['id']}", **({"step": steps} if steps > 1 else {})))]


def delivery_store(products: list[str]) -> tuple[str, str, list[str]] | None:
    """(store id, store name, sizes): the first store that has every product in its first size."""
    sizes = [shop_catalog.get_product(p).sizes[0].label for p in products]
    for store in shop_catalog.load_stores():
        if all(shop_catalog.get_product(p).offer(size, store.id) is not None
               and shop_catalog.stock(p, size, store.id) > 0 for p, size in zip(products, sizes)):
            return store.id, store.name, sizes
    return None


def buy_oracle(products: list[str]) -> list[Any]:
    """Add each product (its first size, from one store that has them all) to the cart, then check out
    for delivery to the kitchen."""
    found = delivery_store(products)
    assert found is not None, f"no store has all of {products}"
    _, store_name, sizes = found
    calls: list[Any] = []
    for product, size in zip(products, sizes):
        calls += [call("browser_goto", url=site_url("shop", f"/product/{product}")),
                  call("browser_type", element=ref("combobox", "Size"), text=size),
                  call("browser_type", element=ref("combobox", "Store"), text=store_name),
                  call("browser_click", element=ref("button", "Add to cart"))]
    return [*calls, call("browser_goto", url=site_url("shop", "/checkout")),
            call("browser_click", element=ref("radio", "Deliver to my kitchen")),
            call("browser_click", element=ref("button", "Place order"))]


def kitchen_steps(recipe: dict[str, Any]) -> dict[str, list[int]]:
    """Which step numbers the kitchen goal covers, and which the recipe page marks as not kitchen steps."""
    return {"kitchen": [n for n, step in enumerate(recipe["steps"], 1) if step.get("kitchen")],
            "not_kitchen": [n for n, step in enumerate(recipe["steps"], 1) if not step.get("kitchen")]}


def kitchen_equipment(recipe: dict[str, Any]) -> set[str]:
    """Every kitchen object type (tool, vessel, appliance, dish) the kitchen steps need: what their ops
    use, and what their kitchen notes name ("fry it in the pan" needs a Pan, even where a Pot would do)."""
    needed: set[str] = set()
    for step in recipe["steps"]:
        if not step.get("kitchen"):
            continue
        for op in step.get("ops", []):
            needed |= required_equipment(op)
        needed |= {EQUIPMENT_WORDS[w] for w in re.findall(r"[a-z]+", step["kitchen"].lower()) if w in EQUIPMENT_WORDS}
    return needed


def missing_equipment(recipe: dict[str, Any], inventory: dict[str, set[str]]) -> set[str]:
    """The equipment the recipe's kitchen steps need that this kitchen lacks (equipment is never delivered)."""
    return kitchen_equipment(recipe) - inventory["tools"] - inventory["receptacles"]


def needed_foods(ops: list[dict[str, Any]]) -> set[str]:
    return {PIECE_SOURCE.get(op.get("object", ""), op.get("object", "")) for op in ops} & FOODS


def kitchen_goals(recipe: dict[str, Any], scene: str, buy: list[str], word: str | None = None,
                  ingredient: str | None = None) -> list[Any]:
    """The recipe's kitchen goals in this kitchen: its outcome, and what tells it from its look-alikes (the
    recipes of the word the intent asks by, when it does) and from doing everything (a food only a
    look-alike uses, when this kitchen has it, stays whole and raw)."""
    ops = recipe_ops(recipe)
    rivals = [recipe_ops(r) for r in look_alikes(recipe, load_catalog(), word, ingredient)]
    present = scene_inventory(scene)["food"] | set(buy)
    return goals_from_ops(ops, [f for f in rival_foods(ops, rivals) if f in present])


def make_task(recipe: dict[str, Any], scene: str, suffix: str, filters: dict[str, Any], n: int,
              buy: list[str] | None = None, kind: str | None = None, step: str | None = None) -> Task | None:
    """One task. ``step`` (hard only): the recipe is told from its look-alikes by this step alone, not by
    ``suffix``'s search filters."""
    buy = list(buy or [])
    kind = kind or ("buy" if buy else "cook")
    ops = recipe_ops(recipe)
    if missing_equipment(recipe, scene_inventory(scene)):
        return None  # the shop sells food only: a kitchen without the steps' pan, bowl, ... cannot do them
    ok, _ = check_recipe_executable(scene, ops, available_extra_types=buy)
    if not ok:
        return None
    products = [KITCHEN_PRODUCTS[food] for food in buy]
    if buy and delivery_store(products) is None:
        return None
    kitchen = [call(c["tool"], **c["args"]) for c in plan_ops(scene, ops, delivered_types=buy)]
    web = recipe_web_oracle(recipe, filters) if step is None else step_web_oracle(recipe, filters)
    web_goals: list[Any] = [RecipeCompleted(recipe_id=recipe["id"])]
    word = filters.get("q")
    # Asked by an ingredient: the filters' first include (the constraint may add another).
    ingredient = filters["include"][0] if not word and "q" in filters else None
    if step is not None and word:
        intent = (f'Cook the dish whose name has the word "{word.capitalize()}". Several recipes have '
                  f'"{word.capitalize()}" in their name: follow the one that {step}.')
    elif step is not None and ingredient:
        intent = f'Cook the dish made with "{ingredient}". Several recipes use {ingredient}: follow the one that {step}.'
    elif step is not None:
        intent = f"Cook {recipe['name']}. More than one recipe has that name: follow the one that {step}."
    elif word:
        intent = (f'Cook the dish whose name has the word "{word.capitalize()}" and that fits this: {suffix}. '
                  f'Several recipes have "{word.capitalize()}" in their name; only one fits.')
    elif ingredient:
        intent = (f'Cook the dish made with "{ingredient}" that fits this: {suffix}. '
                  f'Several recipes use {ingredient}; only one fits.')
    else:
        intent = f"Cook {recipe['name']}." + (f" {suffix}." if suffix else "")
    if buy:
        web += buy_oracle(products)
        web_goals += [OrderPlaced(product_id=product) for product in products]
        if kind == "hard":
            # Hard: the missing foods are not named. The agent reads what the recipe's kitchen steps need,
            # looks in the kitchen for what is there, and orders the rest (web, kitchen, web, kitchen).
            intent += (" Your kitchen lacks some of the foods the recipe's kitchen steps need: find out which, "
                       "and order exactly those from the shop for delivery to your kitchen before you cook.")
        elif len(buy) == 1:
            intent += f" Your kitchen has no {buy[0]}: order it from the shop for delivery to your kitchen first."
        else:
            missing = " and no ".join(buy)
            intent += (f" Your kitchen has no {missing}: order them from the shop for delivery to your kitchen "
                       "first.")
    # The recipe goal takes the last recipe followed to its last step as the agent's choice (principle 2);
    # an agent that reads a rival to its end after its own must be told, as the pantry and two-dish forms say.
    intent += " Follow your recipe on the site to its last step (the last recipe you follow to the end is taken "
    intent += "as your choice)."
    intent += " " + KITCHEN_SCOPE
    oracle = [*web, call("switch_environment", target="embodied", message=f"cook {recipe['name']}"), *kitchen,
              call("finish_episode")]
    steps = kitchen_steps(recipe)
    return Task(
        # Provisional; generate() gives every task an opaque id (the recipe id is the recipe page's URL).
        id=f"cooking-{kind}-{recipe['id']}-{n:02d}",
        domain="cooking",
        difficulty=DIFFICULTY[kind],
        intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="recipes:/"),
                         embodied=KitchenStart(scene=scene)),
        web_goals=web_goals,
        embodied_goals=kitchen_goals(recipe, scene, buy, word or None, ingredient),
        # The budget leaves room for an agent that reads every step (Next, Next, ...), which the oracle skips.
        step_limit=step_budget("cooking", DIFFICULTY[kind], len(oracle) + len(recipe["steps"])),
        oracle=oracle,
        metadata={"recipe_id": recipe["id"], "recipe_name": recipe["name"], "scene": scene,
                  "constraint": (None if step else suffix) or None, "telling_step": step,
                  "pair_id": recipe.get("pair_id"), "name_word": word or None,
                  # only where asked by an ingredient: the other tasks' files stay as they were
                  **({"ingredient": ingredient} if ingredient else {}),
                  "buy": (buy[0] if len(buy) == 1 else buy) if buy else None,
                  "kitchen_steps": steps["kitchen"], "not_kitchen_steps": steps["not_kitchen"]},
    )


def hard_ask(recipe: dict[str, Any], catalog: Any) -> tuple[list[tuple[str, dict[str, Any]]], str | None]:
    """How a hard task asks for the recipe: (constraint pairs with their filters, the telling step or None);
    no pairs when the recipe has no hard form."""
    step = telling_step(recipe, catalog)
    pairs = two_constraints(recipe, catalog)
    if step is None:
        pairs = word_pairs(recipe, catalog) or pairs
    asked = asked_telling_step(recipe["id"]) if catalog is load_catalog() else None
    if asked is not None and (step is not None or not pairs or "q" not in pairs[0][1]):
        search, step = asked
        pairs = [("", search)] if pairs else []
    return pairs, step


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
        # Every template (cook, buy, hard) cooks in a kitchen that has all the steps' equipment.
        scenes = [s for s in scenes if not missing_equipment(recipe, inventories[s])]
        # Hard: two constraints, two needed foods missing (replacing cook tasks, so the suite keeps its size).
        hard = 0
        # Told apart by a step where one is (the steps must be read); else by two constraints together, among
        # the recipes of a word of its name where one serves (several to choose from, not a pair).
        # Among the recipes of a word of its name (else of an ingredient), where a step singles it out there,
        # rather than between the two of its name (a coin toss for an agent that opens the first listed).
        pairs, step = hard_ask(recipe, catalog)
        if pairs and len(foods) >= 2:
            for scene in scenes:
                if hard >= HARD_PER_RECIPE:
                    break
                missing = sorted(foods - inventories[scene]["food"])
                if len(missing) != 2:
                    continue
                suffix, filters = pairs[hard % len(pairs)]
                task = make_task(recipe, scene, suffix, filters, hard, buy=missing, kind="hard", step=step)
                if task is not None:
                    tasks.append(task)
                    hard += 1
        n = 0
        for scene in scenes:
            if n + hard >= TASKS_PER_RECIPE:
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
                    task = make_task(recipe, scene, suffix, filters, 0, buy=missing)
                    if task is not None:
                        tasks.append(task)
                        shopping += 1
                    break
    return with_opaque_ids(tasks)


def with_opaque_ids(tasks: list[Task]) -> list[Task]:
    """Number the tasks of each template in a seeded random order: ``cooking-hard-0007``. An id derived
    from the recipe would hand the agent the recipe page's URL (/recipe/r071) and skip the search."""
    order = list(range(len(tasks)))
    rng_for("cooking", "task-ids").shuffle(order)
    counts: dict[str, int] = {}
    renamed: list[Task | None] = [None] * len(tasks)
    for index in order:
        task = tasks[index]
        kind = task.id.split("-")[1]
        counts[kind] = counts.get(kind, 0) + 1
        renamed[index] = task.model_copy(update={"id": f"cooking-{kind}-{counts[kind]:04d}"})
    return sorted((t for t in renamed if t is not None), key=lambda t: t.id)
