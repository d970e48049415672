"""Cooking goals tell the target apart (issue 26): the method is checked (the instant cook never meets it),
the dish holds only the recipe's food, what the recipe keeps whole or raw stays so, the stove is off; the
oracle's outcome meets every goal while the look-alike's and doing everything fail; step limits come from
a per-domain, per-difficulty budget."""

from __future__ import annotations

from pathlib import Path

import pytest

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import DomainGoal, Task, TaskStore
from ewa_mcp.envs.kitchen.goals import ObjectState
from ewa_mcp.envs.kitchen import checks
from ewa_mcp.envs.kitchen.taskgen.outcomes import (
    everything_outcome,
    grade_kitchen,
    recipe_outcome,
)
from ewa_mcp.envs.kitchen.taskgen.recipe_goals import goals_from_ops, recipe_ops, rival_foods, telling_goals
from ewa_mcp.evaluation.heuristics.agents import dish_of, missing_foods
from ewa_mcp.taskgen.common import STEP_BUDGETS, step_budget
from ewa_mcp.websites.recipes.catalog import load_catalog

FRY_EGG = [{"op": "crack", "object": "Egg"}, {"op": "cook", "object": "EggCracked", "method": "stove", "vessel": "Pan"},
           {"op": "toggle_off", "object": "StoveBurner"}, {"op": "put", "object": "EggCracked", "receptacle": "Plate"}]


def _met(goals, state):
    return [r.met for r in grade_kitchen(goals, state)]


def test_the_instant_cook_never_meets_a_method_goal():
    instant = [FRY_EGG[0], {"op": "cook", "object": "EggCracked", "method": "any"}, FRY_EGG[3]]
    fried = recipe_outcome("FloorPlan1", FRY_EGG)
    zapped = recipe_outcome("FloorPlan1", instant)
    assert fried is not None and zapped is not None
    pan = DomainGoal(kind="cooked_with", object_type="Egg", methods=["Pan"])
    assert {o.get("cookedBy") for o in fried["objects"] if o.get("isCooked")} == {"Pan"}
    assert {o.get("cookedBy") for o in zapped["objects"] if o.get("isCooked")} == {"CookObject"}
    assert checks.check_cooked_with(pan, fried["objects"]).met is True
    result = checks.check_cooked_with(pan, zapped["objects"])
    assert result.met is False and "instant cook" in (result.note or "")
    # cooked, but not the way asked: a toaster goal is not met by the pan
    assert checks.check_cooked_with(DomainGoal(kind="cooked_with", object_type="Egg", methods=["Toaster"]),
                                    fried["objects"]).met is False


def test_malformed_goal_is_unknown_not_an_error():
    bad = checks.check_cooked_with(DomainGoal(kind="cooked_with", object_type="Egg", methods="Pan"), [])
    assert bad.met is None and "methods" in (bad.note or "")
    bad = checks.check_holds_only(DomainGoal(kind="holds_only", receptacle_type="Plate"), [])
    assert bad.met is None and "allowed" in (bad.note or "")


def test_goals_name_method_negatives_stove_and_dish():
    ops = [{"op": "slice", "object": "Bread"}, {"op": "cook", "object": "BreadSliced", "method": "toaster"},
           {"op": "put", "object": "BreadSliced", "receptacle": "Plate"},
           {"op": "put", "object": "Tomato", "receptacle": "Plate"}, *FRY_EGG]
    goals = telling_goals(ops, untouched=["Lettuce"])
    as_tuples = {(g.kind, getattr(g, "object_type", getattr(g, "receptacle_type", None)),
                  str(getattr(g, "methods", getattr(g, "allowed", getattr(g, "prop", ""))))) for g in goals}
    assert ("cooked_with", "Bread", "['Toaster']") in as_tuples
    assert ("cooked_with", "Egg", "['Pan']") in as_tuples
    assert ("object_state", "Tomato", "isSliced") in as_tuples and ("object_state", "Tomato", "isCooked") in as_tuples
    assert ("object_state", "Lettuce", "isSliced") in as_tuples
    assert ("object_state", "StoveKnob", "isToggled") in as_tuples
    assert ("holds_only", "Plate", "['Bread', 'Tomato', 'Egg']") in as_tuples
    assert all(g.value is False for g in goals if isinstance(g, ObjectState))
    assert rival_foods(FRY_EGG, [ops]) == ["Bread", "Tomato"]


def test_doing_everything_fails_and_the_recipe_passes():
    ops = [{"op": "slice", "object": "Tomato"}, {"op": "put", "object": "TomatoSliced", "receptacle": "Plate"}]
    goals = goals_from_ops(ops)
    done = recipe_outcome("FloorPlan1", ops)
    everything = everything_outcome("FloorPlan1")
    assert done is not None and everything is not None
    assert all(_met(goals, done))
    failed = [r for r in grade_kitchen(goals, everything) if not r.met]
    assert any(r.kind == "holds_only" for r in failed)
    assert any(r.kind == "object_state" and "isCooked" in r.description for r in failed)


@pytest.fixture(scope="module")
def cooking_tasks() -> list[Task]:
    # the two-dish form of cooking hard has its own audit (tests/indoor/test_two_dishes.py)
    return sorted((t for t in TaskStore([Path(tasks_dir()) / "cooking"]).all()
                   if t.domain == "cooking" and t.metadata.get("form") != "two_dishes"), key=lambda t: t.id)


def test_sampled_tasks_oracle_passes_lookalike_and_everything_fail(cooking_tasks):
    """Every 25th task (the full audit: python -m ewa_mcp.envs.kitchen.taskgen.outcomes)."""
    catalog = load_catalog()
    checked_rivals = 0
    for task in cooking_tasks[::25]:
        recipe = catalog.by_id.get(task.metadata["recipe_id"])
        buy = task.metadata.get("buy") or []
        delivered = [buy] if isinstance(buy, str) else list(buy)
        scene = task.start.embodied.scene
        own = recipe_outcome(scene, recipe_ops(recipe), delivered)
        assert own is not None and all(_met(task.embodied_goals, own)), task.id
        for other in catalog.recipes:
            if other["name"] == recipe["name"] and other["id"] != recipe["id"] \
                    and recipe_ops(other) != recipe_ops(recipe):
                state = recipe_outcome(scene, recipe_ops(other), delivered)
                if state is not None:
                    checked_rivals += 1
                    assert not all(_met(task.embodied_goals, state)), (task.id, other["id"])
        everything = everything_outcome(scene, delivered)
        assert everything is not None
        assert not all(_met(task.embodied_goals, everything)) or task.id == "cooking-cook-0847", task.id
    assert checked_rivals >= 10


def test_step_limits_are_the_budget_of_the_cell_and_fit_the_oracle():
    store = TaskStore([Path(tasks_dir())])
    seen: set[tuple[str, str]] = set()
    for task in store.all():
        key = (task.domain, task.difficulty)
        if key not in STEP_BUDGETS:
            continue
        seen.add(key)
        assert task.step_limit == STEP_BUDGETS[key], task.id
        assert len(task.oracle) <= task.step_limit, task.id
    assert {d for d, _ in seen} == {"cooking", "navigation", "shopping", "traveling"}


def test_step_budget_refuses_what_it_cannot_fit():
    with pytest.raises(ValueError, match="exceeds the budget"):
        step_budget("cooking", "easy", 10_000)
    with pytest.raises(ValueError, match="STEP_BUDGETS"):
        step_budget("cooking", "impossible", 1)


def test_heuristics_read_the_dish_and_the_missing_foods_from_the_intent():
    name = load_catalog().recipes[0]["name"]
    intent = f"Cook {name}. Diet type: Vegan. Your kitchen has no Egg and no Potato: order them from the shop."
    assert dish_of(intent) == name
    assert missing_foods(intent) == ["Egg", "Potato"]
    assert missing_foods(f"Cook {name}.") == []


def test_following_every_same_named_recipe_fails_the_recipe_goal():
    from ewa_mcp.envs.browser.goals import RecipeCompleted
    from ewa_mcp.envs.browser.checks import check_recipe

    def step(rid: str, n: int, of: int) -> dict:
        return {"site": "recipes", "type": "recipe_step", "recipe_id": rid, "step": n, "of": of}

    goal = RecipeCompleted(recipe_id="r004")
    assert check_recipe(goal, [step("r004", 7, 7)]).met is True
    assert check_recipe(goal, [step("r003", 2, 6), step("r004", 7, 7)]).met is True  # compared, then chose
    # a look-alike read to its end to compare it (a step-told task asks for that), then the choice followed
    compared = check_recipe(goal, [*(step("r003", k, 6) for k in range(1, 7)), *(step("r004", k, 7) for k in range(1, 8))])
    assert compared.met is True and compared.detail["completed_other_recipes"] == ["r003"]
    both = check_recipe(goal, [step("r004", 7, 7), step("r003", 6, 6)])
    assert both.met is False and "the last recipe followed to its end is the one chosen" in (both.note or "")
    assert both.detail["chosen_recipe"] == "r003"
    assert check_recipe(goal, [step("r003", 6, 6)]).met is False


def test_the_kitchen_heuristics_fail_through_the_real_tools(tmp_path, cooking_tasks):
    """Both cooking heuristics play one task whose first listed same-named recipe is the look-alike (with
    other kitchen steps) through the MCP server, browser and kitchen; the grader fails both, the kitchen
    goals included (not only the recipe goal)."""
    from ewa_mcp.evaluation.heuristics import heuristic_agent
    from ewa_mcp.evaluation.heuristics.agents import same_named
    from ewa_mcp.evaluation.runner import play
    from ewa_mcp.graders import grade_run

    catalog = load_catalog()
    task = next(t for t in cooking_tasks if t.difficulty == "easy"
                and (first := same_named(t.metadata["recipe_name"])[0])["id"] != t.metadata["recipe_id"]
                and recipe_ops(first) != recipe_ops(catalog.by_id.get(t.metadata["recipe_id"]))
                and recipe_outcome(t.start.embodied.scene, recipe_ops(first)) is not None)
    for name in ("look-alike", "cook-everything"):
        run_dir = tmp_path / name
        play([task], heuristic_agent(name), run_dir=run_dir, task_dirs=[Path(tasks_dir())], progress=False)
        (episode,) = grade_run(run_dir).episodes
        assert episode.overall_success is False, name
        assert episode.embodied_success is False, name
