"""Two dishes, two choices (cooking hard, the two-dish form): the recipes_completed goal passes when the two
recipes it names are the last two followed to their end, and fails when a look-alike is finished instead or
after them (docs/grading.md)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from grading_builders import EpisodeBuilder, kitchen_task, recipe_step

from ewa_mcp.envs.browser.checks import check_recipes
from ewa_mcp.envs.browser.goals import RecipesCompleted
from ewa_mcp.graders import grade_episode

GOAL = RecipesCompleted(recipe_ids=["r039", "r130"])


def _ends(*recipe_ids: str) -> list[dict[str, Any]]:
    return [recipe_step(rid, 4, 4) for rid in recipe_ids]


def test_both_recipes_finished_in_either_order_pass() -> None:
    assert check_recipes(GOAL, _ends("r039", "r130")).met is True
    assert check_recipes(GOAL, _ends("r130", "r039")).met is True


def test_look_alikes_read_to_their_end_before_both_are_comparing() -> None:
    result = check_recipes(GOAL, _ends("r038", "r039", "r131", "r130"))
    # a look-alike finished between the two: the last two finished are r131 and r130, r039 is no longer chosen
    assert result.met is False
    assert result.detail["chosen_recipes"] == ["r131", "r130"]
    assert check_recipes(GOAL, _ends("r038", "r131", "r039", "r130")).met is True


def test_a_look_alike_instead_or_after_fails() -> None:
    instead = check_recipes(GOAL, _ends("r038", "r130"))
    assert instead.met is False and "r039" in (instead.note or "")
    after = check_recipes(GOAL, _ends("r039", "r130", "r131"))
    assert after.met is False and after.detail["chosen_recipes"] == ["r130", "r131"]
    assert check_recipes(GOAL, _ends("r039")).met is False
    assert check_recipes(GOAL, [recipe_step("r039", 4, 4), recipe_step("r130", 3, 4)]).met is False


def test_the_grader_routes_the_goal(tmp_path: Path) -> None:
    task = kitchen_task("two-1", web_goals=[{"kind": "recipes_completed", "recipe_ids": ["r039", "r130"]}])
    ep = EpisodeBuilder(tmp_path / "ok", task)
    for event in _ends("r039", "r130"):
        ep.event(**event)
    assert grade_episode(ep.finish().directory).web_success is True
    ep = EpisodeBuilder(tmp_path / "bad", task)
    for event in _ends("r039", "r131"):
        ep.event(**event)
    graded = grade_episode(ep.finish().directory)
    assert graded.web_success is False
    assert graded.conditions[0].kind == "recipes_completed"
