"""Cooking hard, two dishes that share a food (ewa_mcp/envs/kitchen/taskgen/two_dishes.py): about a third of
the hard ids, every one of them audited against the real simulator: the oracle's outcome meets every kitchen
goal; doing everything, either look-alike in place of its dish, and the shared food's two treatments
swapped between the dishes each fail one."""

from __future__ import annotations


import pytest

from ewa_mcp.envs.browser.goals import RecipeCompleted, RecipesCompleted
from ewa_mcp.envs.kitchen.taskgen import two_dishes
from ewa_mcp.envs.kitchen.taskgen.cooking import KITCHEN_SCOPE
from ewa_mcp.envs.kitchen.taskgen.outcomes import grade_kitchen
from ewa_mcp.envs.kitchen.taskgen.recipe_goals import recipe_ops
from ewa_mcp.websites.recipes.catalog import load_catalog




@pytest.fixture(scope="module")
def two(hard: list) -> list:
    return [t for t in hard if t.metadata.get("form") == "two_dishes"]


def test_a_third_of_the_hard_ids_take_the_form_and_the_ids_stay(hard: list, two: list) -> None:
    assert [t.id for t in hard] == [f"cooking-hard-{n:04d}" for n in range(1, 186)]
    assert len(two) == len(hard) // two_dishes.SHARE
    ids = [int(t.id.rsplit("-", 1)[1]) for t in two]
    assert min(ids) < len(ids) < 2 * len(ids) < max(ids)  # spread over the ids (a seeded shuffle), not a block


def test_every_two_dish_task_is_two_recipes_sharing_a_food(two: list) -> None:
    catalog = load_catalog()
    for task in two:
        meta = task.metadata
        raw, cooked = catalog.by_id[meta["recipe_id"]], catalog.by_id[meta["second_recipe_id"]]
        food = meta["shared_food"]
        assert {meta["raw_vessel"], meta["cooked_vessel"]} == {"Plate", "Bowl"}
        assert any(op["op"] == "cook" and op["object"].startswith(food) for op in recipe_ops(cooked))
        assert not any(op["op"] == "cook" and op["object"].startswith(food) for op in recipe_ops(raw))
        recipes = [g for g in task.web_goals if isinstance(g, RecipesCompleted)]
        assert len(recipes) == 1 and sorted(recipes[0].recipe_ids) == sorted([raw["id"], cooked["id"]])
        assert not any(isinstance(g, RecipeCompleted) for g in task.web_goals)
        assert f"Both recipes use {food.lower()}" in task.intent and task.intent.endswith(KITCHEN_SCOPE)
        assert "find out which" in task.intent and meta["buy"]


def test_the_audit_oracle_passes_and_everything_look_alikes_and_the_swap_fail(two: list) -> None:
    counts = two_dishes.audit(two)
    assert counts["tasks"] == len(two) > 0
    assert counts["oracle_fails"] == []
    assert counts["everything_passes"] == []
    assert counts["swap_passes"] == [] and counts["swap_not_doable"] == []
    assert counts["lookalike_passes"] == []
    assert counts["lookalikes"] > counts["lookalike_same_kitchen"] + counts["lookalike_not_doable"]


def test_the_swap_fails_on_the_vessels(two: list) -> None:
    """The swap fails for the reason the form exists: the shared food in each vessel has the other dish's state."""
    catalog = load_catalog()
    task = two[0]
    meta = task.metadata
    raw, cooked = recipe_ops(catalog.by_id[meta["recipe_id"]]), recipe_ops(catalog.by_id[meta["second_recipe_id"]])
    state = two_dishes.two_outcome(task.start.embodied.scene, *two_dishes.swapped_ops(raw, cooked, meta["shared_food"]),
                                   meta["buy"], stop_on_error=False)
    assert state is not None
    failed = {r.description for r in grade_kitchen(task.embodied_goals, state) if not r.met}
    food = meta["shared_food"]
    assert any(d.startswith(f"{food} in {meta['raw_vessel']}") for d in failed)
    assert any(d.startswith(f"{food} in {meta['cooked_vessel']}") for d in failed)


def _piece(n: int, parent: str, cooked: bool) -> dict:
    return {"objectId": f"Bread|+{n}.00|+0.90|-1.00|BreadSliced_{n}", "objectType": "BreadSliced",
            "sourceType": "Bread", "parentReceptacles": [parent], "isCooked": cooked, "isSliced": False}


def test_a_vessel_holding_the_shared_food_both_ways_passes_for_neither_dish() -> None:
    from ewa_mcp.core.taskmodel import DomainGoal
    from ewa_mcp.envs.kitchen import checks

    plate = {"objectId": "Plate|+1.00|+0.90|-1.00", "objectType": "Plate", "parentReceptacles": []}
    raw_dish = DomainGoal(kind="holds_only", receptacle_type="Plate", allowed=["Bread"], cooked={"Bread": False})
    alone = checks.check_holds_only(raw_dish, [plate, _piece(1, plate["objectId"], False)])
    assert alone.met is True
    both = checks.check_holds_only(raw_dish, [plate, _piece(1, plate["objectId"], False),
                                              _piece(2, plate["objectId"], True)])
    assert both.met is False and both.detail["wrong_state"] == ["Bread"] and "both ways" in (both.note or "")
    # without the map the goal is the one-dish holds_only, which does not look at the state
    plain = DomainGoal(kind="holds_only", receptacle_type="Plate", allowed=["Bread"])
    assert checks.check_holds_only(plain, [plate, _piece(1, plate["objectId"], False),
                                           _piece(2, plate["objectId"], True)]).met is True
    bad = DomainGoal(kind="holds_only", receptacle_type="Plate", allowed=["Bread"], cooked={"Bread": "yes"})
    assert checks.check_holds_only(bad, [plate]).met is None


def test_each_vessel_says_how_the_shared_food_is_there(two: list) -> None:
    for task in two:
        meta = task.metadata
        food = meta["shared_food"]
        held = {g.receptacle_type: getattr(g, "cooked", None) for g in task.embodied_goals if g.kind == "holds_only"}
        assert held[meta["raw_vessel"]] == {food: False} and held[meta["cooked_vessel"]] == {food: True}, task.id
