"""The method the recipe states is graded (issue 26, principle 1): a fried egg is a cracked egg cooked in the
lit pan (a whole egg fried and then cracked fails), toast is a bread slice from the toaster (a slice fried in
the pan fails, and the reverse), slices the recipe fries are fried as slices (a potato fried whole and then
sliced fails). Every outcome here is a real KitchenSession over the built-in kitchen, driven by the planner."""

from __future__ import annotations

import pytest

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import DomainGoal, TaskStore
from ewa_mcp.envs.kitchen import checks
from ewa_mcp.envs.kitchen.taskgen.outcomes import audit, grade_kitchen, recipe_outcome, union_ops
from ewa_mcp.envs.kitchen.taskgen.recipe_goals import PIECE_SOURCE, goals_from_ops, recipe_ops
from ewa_mcp.websites.recipes.catalog import load_catalog

SCENE = "FloorPlan12"  # holds every food, a Pan, a Pot, a Knife and a Toaster
OFF = {"op": "toggle_off", "object": "StoveBurner"}
FRIED_EGG = [{"op": "crack", "object": "Egg"}, {"op": "cook", "object": "EggCracked", "method": "stove", "vessel": "Pan"},
             OFF, {"op": "put", "object": "EggCracked", "receptacle": "Plate"}]
# the play-tester's way: the whole egg into the hot pan, cracked once it is cooked
WHOLE_EGG_FRIED = [{"op": "cook", "object": "Egg", "method": "stove", "vessel": "Pan"}, {"op": "crack", "object": "Egg"},
                   OFF, {"op": "put", "object": "EggCracked", "receptacle": "Plate"}]
TOAST = [{"op": "slice", "object": "Bread"}, {"op": "cook", "object": "BreadSliced", "method": "toaster"},
         {"op": "put", "object": "BreadSliced", "receptacle": "Plate"}]
PAN_BREAD = [{"op": "slice", "object": "Bread"}, {"op": "cook", "object": "BreadSliced", "method": "stove", "vessel": "Pan"},
             OFF, {"op": "put", "object": "BreadSliced", "receptacle": "Plate"}]
FRIED_SLICES = [{"op": "slice", "object": "Potato"},
                {"op": "cook", "object": "PotatoSliced", "method": "stove", "vessel": "Pan"},
                OFF, {"op": "put", "object": "PotatoSliced", "receptacle": "Plate"}]
FRIED_WHOLE_THEN_SLICED = [{"op": "cook", "object": "Potato", "method": "stove", "vessel": "Pan"},
                           {"op": "slice", "object": "Potato"}, OFF,
                           {"op": "put", "object": "PotatoSliced", "receptacle": "Plate"}]


def _outcome(ops):
    state = recipe_outcome(SCENE, ops)
    assert state is not None, f"the planner could not carry out {ops}"
    return state


def _failed(goals, state):
    return [r for r in grade_kitchen(goals, state) if not r.met]


def test_a_whole_egg_fried_then_cracked_fails_and_a_cracked_egg_in_the_lit_pan_passes():
    goals = goals_from_ops(FRIED_EGG)
    method = [g for g in goals if getattr(g, "kind", "") == "cooked_with"]
    assert [(g.object_type, g.methods, g.as_piece) for g in method] == [("Egg", ["Pan"], True)]
    assert _failed(goals, _outcome(FRIED_EGG)) == []
    whole = _outcome(WHOLE_EGG_FRIED)
    # the final state tells them apart: the cracked egg inherited its cooking from the whole egg
    assert [(o["cookedBy"], o.get("cookedWhole")) for o in whole["objects"] if o["objectType"] == "EggCracked"] \
        == [("Pan", True)]
    failed = _failed(goals, whole)
    # only the method fails: the plate holds a cooked, cracked egg, the stove is off
    assert [r.kind for r in failed] == ["cooked_with"]
    assert "cooked whole" in (failed[0].note or "") and "cracks" in (failed[0].note or "")


def test_an_egg_cooked_whole_and_never_cracked_fails():
    goals = goals_from_ops(FRIED_EGG)
    state = _outcome([WHOLE_EGG_FRIED[0], OFF, {"op": "put", "object": "Egg", "receptacle": "Plate"}])
    kinds = {r.kind for r in _failed(goals, state)}
    assert {"cooked_with", "object_in", "object_state"} <= kinds


def test_pan_fried_bread_fails_a_toaster_recipe_and_toast_fails_a_pan_recipe():
    toast, pan = _outcome(TOAST), _outcome(PAN_BREAD)
    toast_goals, pan_goals = goals_from_ops(TOAST), goals_from_ops(PAN_BREAD)
    assert _failed(toast_goals, toast) == [] and _failed(pan_goals, pan) == []
    wrong = _failed(toast_goals, pan)
    assert [r.kind for r in wrong] == ["cooked_with"] and "not in Toaster" in (wrong[0].note or "")
    wrong = _failed(pan_goals, toast)
    assert [r.kind for r in wrong] == ["cooked_with"] and "not in Pan" in (wrong[0].note or "")


def test_slices_fried_as_slices_pass_and_a_potato_fried_whole_then_sliced_fails():
    goals = goals_from_ops(FRIED_SLICES)
    assert _failed(goals, _outcome(FRIED_SLICES)) == []
    failed = _failed(goals, _outcome(FRIED_WHOLE_THEN_SLICED))
    assert [r.kind for r in failed] == ["cooked_with"]
    assert failed[0].detail["cooked_as_piece"] == [False]


def test_a_recipe_that_cooks_a_food_whole_does_not_ask_for_pieces():
    ops = [FRIED_WHOLE_THEN_SLICED[0], OFF, {"op": "put", "object": "Potato", "receptacle": "Plate"}]
    method = [g for g in goals_from_ops(ops) if getattr(g, "kind", "") == "cooked_with"]
    assert [(g.object_type, getattr(g, "as_piece", None)) for g in method] == [("Potato", None)]
    assert _failed(goals_from_ops(ops), _outcome(ops)) == []


def test_as_piece_false_asks_for_the_food_cooked_whole():
    goal = DomainGoal(kind="cooked_with", object_type="Potato", methods=["Pan"], as_piece=False)
    assert checks.check_cooked_with(goal, _outcome(FRIED_WHOLE_THEN_SLICED)["objects"]).met is True
    result = checks.check_cooked_with(goal, _outcome(FRIED_SLICES)["objects"])
    assert result.met is False and "cut before it was cooked" in (result.note or "")


def test_a_malformed_as_piece_is_unknown_not_an_error():
    bad = DomainGoal(kind="cooked_with", object_type="Egg", methods=["Pan"], as_piece="yes")
    result = checks.check_cooked_with(bad, _outcome(FRIED_EGG)["objects"])
    assert result.met is None and "as_piece" in (result.note or "")


def test_every_cooking_task_asks_for_pieces_where_its_recipe_cooks_pieces():
    """Every task file, every difficulty (two dishes included): a food the recipe cracks or slices and then
    cooks has a cooked_with goal with as_piece; a food it cooks whole has none."""
    by_id = {r["id"]: r for r in load_catalog().recipes}
    tasks = [t for t in TaskStore([tasks_dir()]).all() if t.domain == "cooking"]
    assert len(tasks) == 1080
    checked = 0
    for task in tasks:
        ids = [task.metadata["recipe_id"], *([task.metadata["second_recipe_id"]]
                                             if task.metadata.get("form") == "two_dishes" else [])]
        as_pieces = {PIECE_SOURCE[op["object"]] for rid in ids for op in recipe_ops(by_id[rid])
                     if op["op"] == "cook" and op["object"] in PIECE_SOURCE}
        for goal in task.embodied_goals:
            if getattr(goal, "kind", "") != "cooked_with":
                continue
            checked += 1
            assert (getattr(goal, "as_piece", None) is True) == (goal.object_type in as_pieces), (task.id, goal)
    assert checked > 1000


def test_the_audit_on_a_sample_cooking_whole_what_the_recipe_cuts_first_fails():
    """Every 20th single-dish task (the full audit: python -m ewa_mcp.envs.kitchen.taskgen.outcomes): the
    oracle passes, and the recipe done with each cut-then-cooked food cooked whole first fails."""
    tasks = sorted((t for t in TaskStore([tasks_dir()]).all()
                    if t.domain == "cooking" and t.metadata.get("form") != "two_dishes"), key=lambda t: t.id)
    counts = audit(tasks[::20], over_acting=False)  # the over-acting half: the slow test below
    assert counts["oracle_fails"] == []
    assert counts["whole_first_passes"] == []
    assert counts["whole_first_played"] >= 20


@pytest.mark.slow
def test_over_acting_among_the_candidates_rarely_meets_the_kitchen_goals():
    """Every 5th single-dish task: doing every cut and cooking of every recipe the intent's name lists, the
    plate holding what all of them serve (or what any serves), meets the kitchen goals in at most 3 % of
    the tasks (measured about 2 %: candidates whose kitchen steps differ only where no goal looks)."""
    tasks = sorted((t for t in TaskStore([tasks_dir()]).all()
                    if t.domain == "cooking" and t.metadata.get("form") != "two_dishes"), key=lambda t: t.id)[::5]
    counts = audit(tasks)
    for plate in ("common", "all"):
        assert len(counts[f"union_{plate}_passes"]) <= 0.03 * len(tasks), (plate, counts[f"union_{plate}_passes"])


def test_union_ops_does_every_cut_and_cooking_and_plates_what_all_serve():
    toast = [{"op": "slice", "object": "Bread"}, {"op": "cook", "object": "BreadSliced", "method": "toaster"},
             {"op": "put", "object": "BreadSliced", "receptacle": "Plate"}]
    pan = [{"op": "slice", "object": "Bread"}, {"op": "cook", "object": "BreadSliced", "method": "stove", "vessel": "Pan"},
           {"op": "toggle_off", "object": "StoveBurner"}, {"op": "slice", "object": "Tomato"},
           {"op": "put", "object": "BreadSliced", "receptacle": "Plate"},
           {"op": "put", "object": "TomatoSliced", "receptacle": "Plate"}]
    common = union_ops([toast, pan])
    assert [op["op"] for op in common] == ["slice", "cook", "cook", "slice", "put", "toggle_off"]
    assert {op.get("method") for op in common if op["op"] == "cook"} == {"toaster", "stove"}
    assert [op["object"] for op in common if op["op"] == "put"] == ["BreadSliced"]
    assert [op["object"] for op in union_ops([toast, pan], plate="all") if op["op"] == "put"] == [
        "BreadSliced", "TomatoSliced"]
    assert union_ops([toast]) == toast  # no stove used: nothing to turn off
