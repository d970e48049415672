"""Every cooking task asks for a choice (issue 26, principle 1): an easy or medium task asks for its recipe
by a word of its name that several recipes share (or, where no word serves, by an ingredient several
recipes use), with the constraint that leaves it alone among them. Named outright, a recipe with a name of
its own needed no choosing (the look-alike agent passed half the easy tasks), and one with a same-named
look-alike was a choice between two: opening the first listed recipe passed about 40 % of the tasks."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

import pytest

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.envs.kitchen.taskgen.cooking import NAME_WORD_MIN_NAMES, look_alikes, made_with, named_with
from ewa_mcp.evaluation.heuristics.agents import listed_recipes
from ewa_mcp.websites.recipes.catalog import load_catalog

# Recipes whose every word is shared by too few names for a choice (Welsh Rarebit, Potato Harra, ...) are
# still named outright; their tasks must stay a small share of every difficulty.
MAX_NOTHING_TO_CHOOSE = 0.05
# The share of easy and medium tasks whose target is the first recipe listed for what the intent names: the
# ceiling of the first-recipe agent: the bar (measured 8.3 % easy, 5.0 % medium, 6.5 % hard; about
# 40 % when pairs were named).
MAX_TARGET_FIRST = 0.10


@pytest.fixture(scope="module")
def tasks():
    store = TaskStore([Path(tasks_dir()) / "cooking"])
    # the two-dish form of cooking hard and the recipe the kitchen can make (chosen by what the kitchen holds,
    # not by a constraint) have tests of their own (tests/indoor/test_two_dishes.py, test_pantry.py)
    return [t for t in store.all() if t.domain == "cooking" and t.metadata.get("form") not in ("two_dishes", "pantry")]


def _search_filters(url: str) -> dict[str, object]:
    query = parse_qs(urlsplit(url).query)
    filters: dict[str, object] = {k: v for k, v in query.items() if k in ("include", "exclude", "equipment")}
    filters.update({k: v[0] for k, v in query.items() if k in ("diet", "difficulty", "cuisine")})
    return filters


def test_almost_every_task_has_a_look_alike_to_tell_apart(tasks):
    catalog = load_catalog()
    names = Counter(r["name"] for r in catalog.recipes)
    nothing = Counter()
    per_difficulty = Counter(t.difficulty for t in tasks)
    for task in tasks:
        recipe = catalog.by_id[task.metadata["recipe_id"]]
        word = task.metadata.get("name_word")
        ingredient = task.metadata.get("ingredient")
        if task.metadata.get("telling_step") and (word or ingredient):
            # told apart by a step among what the word or ingredient lists, not by a filter:
            # tests/integration/test_hard_composition.py
            assert recipe["name"] not in task.intent, task.id
            continue
        if ingredient is not None:
            # Asked by an ingredient: the name is not given, recipes of several names use it, and the
            # stated constraint (the oracle's search filters) leaves the target alone among them.
            assert word is None and recipe["name"] not in task.intent, task.id
            assert f'made with "{ingredient}"' in task.intent, task.id
            assert len({r["name"] for r in made_with(ingredient, catalog)}) >= NAME_WORD_MIN_NAMES, task.id
            search = task.oracle[0].args["url"]
            query = parse_qs(urlsplit(search).query)
            assert "q" not in query and ingredient in query["include"], task.id
            left = made_with(ingredient, catalog, _search_filters(search))
            assert [r["id"] for r in left] == [recipe["id"]], (task.id, [r["id"] for r in left])
            continue
        if word is None:
            assert recipe["name"] in task.intent, task.id
            nothing[task.difficulty] += names[recipe["name"]] == 1
            continue
        # Asked by the word: the name is not given, several names share the word ...
        assert recipe["name"] not in task.intent, task.id
        assert f'the word "{word.capitalize()}"' in task.intent, task.id
        listed = named_with(word, catalog)
        assert len({r["name"] for r in listed}) >= NAME_WORD_MIN_NAMES, task.id
        # ... and the stated constraint (the oracle's search filters) leaves the target alone among them.
        search = task.oracle[0].args["url"]
        assert parse_qs(urlsplit(search).query)["q"] == [word], task.id
        left = named_with(word, catalog, _search_filters(search))
        assert [r["id"] for r in left] == [recipe["id"]], (task.id, [r["id"] for r in left])
        for part in task.metadata["constraint"].split(". "):
            assert part in task.intent, task.id
    for difficulty, count in per_difficulty.items():
        assert nothing[difficulty] <= MAX_NOTHING_TO_CHOOSE * count, (difficulty, nothing[difficulty], count)


def test_the_heuristics_read_the_word_and_list_every_recipe_that_has_it(tasks):
    task = next(t for t in tasks if t.metadata.get("name_word"))
    listed = listed_recipes(task.intent)
    assert task.metadata["recipe_id"] in {r["id"] for r in listed}
    assert len({r["name"] for r in listed}) >= NAME_WORD_MIN_NAMES
    assert all(re.search(task.metadata["name_word"], r["name"], re.I) for r in listed)


def test_a_word_task_is_told_from_the_recipes_of_its_word():
    catalog = load_catalog()
    names = Counter(r["name"] for r in catalog.recipes)
    unique = next(r for r in catalog.recipes if names[r["name"]] == 1 and look_alikes(r, catalog))
    rivals = look_alikes(unique, catalog)
    assert unique["id"] not in {r["id"] for r in rivals} and len({r["name"] for r in rivals}) >= 2
    paired = next(r for r in catalog.recipes if names[r["name"]] == 2)
    assert [r["name"] for r in look_alikes(paired, catalog)] == [paired["name"]]


def test_a_guess_at_the_first_listed_recipe_is_seldom_right(tasks):
    """The first-recipe agent's ceiling in every difficulty (hard: a step-told pair is asked by a word or an
    ingredient too, the step singling it out among what that lists); and a task that asks for a recipe with a
    same-named look-alike by a word or an ingredient never lists the target first (named, it would be a
    coin toss; asked that way, a sure pass)."""
    catalog = load_catalog()
    names = Counter(r["name"] for r in catalog.recipes)
    total, first = Counter(), Counter()
    for task in tasks:
        listed = listed_recipes(task.intent)
        target_first = listed[0]["id"] == task.metadata["recipe_id"]
        total[task.difficulty] += 1
        first[task.difficulty] += target_first
        asked_by = task.metadata.get("name_word") or task.metadata.get("ingredient")
        if asked_by and names[task.metadata["recipe_name"]] > 1:
            assert not target_first, task.id
    assert set(total) == {"easy", "medium", "hard"}
    for difficulty, count in total.items():
        assert first[difficulty] <= MAX_TARGET_FIRST * count, (difficulty, first[difficulty], count)


def test_a_pair_asked_by_a_word_is_told_from_every_recipe_of_the_word(tasks):
    catalog = load_catalog()
    names = Counter(r["name"] for r in catalog.recipes)
    task = next(t for t in tasks if t.metadata.get("name_word") and names[t.metadata["recipe_name"]] == 2)
    recipe = catalog.by_id[task.metadata["recipe_id"]]
    rivals = look_alikes(recipe, catalog, task.metadata["name_word"])
    assert recipe["name"] in {r["name"] for r in rivals}  # its same-named look-alike ...
    assert len({r["name"] for r in rivals}) >= NAME_WORD_MIN_NAMES - 1  # ... and the other names of the word
    by_ingredient = next(t for t in tasks if t.metadata.get("ingredient"))
    recipe = catalog.by_id[by_ingredient.metadata["recipe_id"]]
    rivals = look_alikes(recipe, catalog, ingredient=by_ingredient.metadata["ingredient"])
    assert recipe["id"] not in {r["id"] for r in rivals}
    assert all(by_ingredient.metadata["ingredient"] in {i["name"] for i in r["ingredients"]} for r in rivals)


def test_a_food_cooked_in_two_places_is_cooked_in_each_as_a_reader_says() -> None:
    # Mozzarella Potato Stack fries its potato in the pan, then warms it in the microwave: "cooks the potato in
    # a pan on the stove" is true of it, so a step-told task cannot use that statement to rule it out.
    from ewa_mcp.envs.kitchen.taskgen.cooking import food_treatments, load_catalog, recipe_ops, step_statements

    recipe = load_catalog().by_id["r208"]
    treated = food_treatments(recipe_ops(recipe))
    assert treated["Potato"][1] == frozenset({"Pan", "microwave"})
    statements = dict(step_statements(recipe))
    assert statements["cooks the potato in a pan on the stove"](treated)
    assert statements["cooks the potato in the microwave"](treated)
    assert "keeps the potato raw" not in statements
