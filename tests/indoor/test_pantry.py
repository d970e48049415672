"""Cooking hard, the recipe the kitchen can make (ewa_mcp/envs/kitchen/taskgen/pantry.py): a share of the
one-dish hard ids ask for the one recipe of a word that the kitchen can make with what it holds. Every task is
checked against the recipe site's data and the real simulator: the choice is true (exactly one recipe of the
word needs only foods the kitchen holds, and it is not listed first), the rivals lack different foods, the
oracle passes, and doing everything and each rival's outcome fail the kitchen goals."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.envs.browser.goals import OrderPlaced, RecipeCompleted, RecipesCompleted
from ewa_mcp.envs.kitchen.planner import scene_inventory
from ewa_mcp.envs.kitchen.taskgen import pantry
from ewa_mcp.envs.kitchen.taskgen.cooking import KITCHEN_SCOPE, named_with
from ewa_mcp.envs.kitchen.taskgen.outcomes import grade_kitchen, recipe_outcome
from ewa_mcp.envs.kitchen.taskgen.recipe_goals import recipe_ops
from ewa_mcp.websites.recipes.catalog import load_catalog

TASKS = Path(__file__).resolve().parents[2] / "tasks"



@pytest.fixture(scope="module")
def chosen(hard: list) -> list:
    return [t for t in hard if t.metadata.get("form") == "pantry"]


def test_the_form_takes_a_share_of_the_hard_ids_and_both_old_forms_stay(hard: list, chosen: list) -> None:
    assert [t.id for t in hard] == [f"cooking-hard-{n:04d}" for n in range(1, 186)]
    forms = Counter(t.metadata.get("form") for t in hard)
    assert forms["two_dishes"] > 0 and forms[None] > 0
    assert 15 <= len(chosen) <= forms[None] // 2
    ids = [int(t.id.rsplit("-", 1)[1]) for t in chosen]
    assert len({(i - 1) * 4 // len(hard) for i in ids}) == 4  # in every quarter of the ids (a seeded shuffle)
    assert len({t.metadata["name_word"] for t in chosen}) >= 8
    assert max(Counter(t.metadata["name_word"] for t in chosen).values()) <= pantry.PER_WORD
    # never the same dish in the same kitchen twice (asked by another word of its name)
    assert len({(t.metadata["recipe_id"], t.start.embodied.scene) for t in chosen}) == len(chosen)


def test_exactly_one_recipe_of_the_word_needs_only_foods_the_kitchen_holds(chosen: list) -> None:
    catalog = load_catalog()
    for task in chosen:
        meta = task.metadata
        held = scene_inventory(task.start.embodied.scene)["food"]
        listed = named_with(meta["name_word"], catalog)
        makeable = [r["id"] for r in listed if pantry.page_foods(r) <= held]
        assert makeable == [meta["recipe_id"]], task.id
        assert listed[0]["id"] != meta["recipe_id"]  # never the first listed: position does not pass
        # the dish's own name has the word whole (the search also lists "Crisp" for "crisps")
        assert re.search(rf"\b{meta['name_word']}\b", meta["recipe_name"].lower()), task.id
        assert set(meta["rivals_lack"]) == {r["id"] for r in listed} - {meta["recipe_id"]}
        for rival_id, missing in meta["rivals_lack"].items():
            assert missing and set(missing) == pantry.page_foods(catalog.by_id[rival_id]) - held


def test_what_the_rivals_lack_is_balanced(chosen: list) -> None:
    for task in chosen:  # within a task, more than one food rules rivals out: each must be looked for
        lacked = {f for missing in task.metadata["rivals_lack"].values() for f in missing}
        assert len(lacked) >= pantry.MIN_LACKED, task.id
    over_all = Counter(f for t in chosen for missing in t.metadata["rivals_lack"].values() for f in missing)
    assert len(over_all) >= 5 and max(over_all.values()) < 0.4 * sum(over_all.values())


def test_the_intent_states_the_choice_and_the_goals_take_the_last_recipe_followed(chosen: list) -> None:
    for task in chosen:
        word = task.metadata["name_word"].capitalize()
        assert task.intent.startswith(f'Cook the dish whose name has the word "{word}" that your kitchen can make')
        assert "Exactly one of them needs only foods your kitchen holds" in task.intent
        assert "nothing needs ordering" in task.intent and task.intent.endswith(KITCHEN_SCOPE)
        assert task.web_goals == [RecipesCompleted(recipe_ids=[task.metadata["recipe_id"]])]
        assert not any(isinstance(g, (RecipeCompleted, OrderPlaced)) for g in task.web_goals)
        assert not any(c.tool.startswith("browser_") and "shop:" in str(c.args) for c in task.oracle)


def test_the_audit_oracle_passes_and_everything_and_every_rival_fail(chosen: list) -> None:
    counts = pantry.audit(chosen)
    assert counts["tasks"] == len(chosen) > 0
    assert counts["oracle_fails"] == []
    assert counts["everything_passes"] == []
    assert counts["rival_passes"] == []
    assert counts["rivals"] > counts["rival_not_doable"]  # most rivals were played out, not just skipped


def test_a_rival_cooked_with_its_missing_foods_fails_a_named_goal() -> None:
    """One task's rival, played out in the real simulator, fails its goals, and the failed goal is reported."""
    catalog = load_catalog()
    task = next(t for t in TaskStore([TASKS]).all() if t.metadata.get("form") == "pantry")
    scene = task.start.embodied.scene
    played = [(rid, recipe_outcome(scene, recipe_ops(catalog.by_id[rid]), missing))
              for rid, missing in task.metadata["rivals_lack"].items()]
    played = [(rid, state) for rid, state in played if state is not None]
    assert played
    for rid, state in played:
        failed = [r for r in grade_kitchen(task.embodied_goals, state) if not r.met]
        assert failed, rid
    own = recipe_outcome(scene, recipe_ops(catalog.by_id[task.metadata["recipe_id"]]))
    assert own is not None and all(r.met for r in grade_kitchen(task.embodied_goals, own))

