"""Every cooking task asks for a choice (issue 26, principle 1): a recipe whose name no other recipe has
is asked for by a word of its name that several recipes share, with the constraint that leaves it alone
among them. Named outright, following the only recipe of that name was the whole task, and the
look-alike agent (open the recipes of the name, cook the first) passed half the easy tasks."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

import pytest

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.envs.kitchen.taskgen.cooking import NAME_WORD_MIN_NAMES, look_alikes, named_with
from ewa_mcp.evaluation.heuristics.agents import listed_recipes
from ewa_mcp.websites.recipes.catalog import load_catalog

# Recipes whose every word is shared by too few names for a choice (Welsh Rarebit, Potato Harra, ...) are
# still named outright; their tasks must stay a small share of every difficulty.
MAX_NOTHING_TO_CHOOSE = 0.05


@pytest.fixture(scope="module")
def tasks():
    store = TaskStore([Path(tasks_dir()) / "cooking"])
    return [t for t in store.all() if t.domain == "cooking"]


def _search_filters(url: str) -> dict[str, object]:
    query = parse_qs(urlsplit(url).query)
    filters: dict[str, object] = {k: v for k, v in query.items() if k in ("include", "exclude", "equipment")}
    filters.update({k: v[0] for k, v in query.items() if k in ("diet", "difficulty")})
    return filters


def test_almost_every_task_has_a_look_alike_to_tell_apart(tasks):
    catalog = load_catalog()
    names = Counter(r["name"] for r in catalog.recipes)
    nothing = Counter()
    per_difficulty = Counter(t.difficulty for t in tasks)
    for task in tasks:
        recipe = catalog.by_id[task.metadata["recipe_id"]]
        word = task.metadata.get("name_word")
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
