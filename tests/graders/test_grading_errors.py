"""Every error category, each triggered by a hand-built trajectory with a known cause."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from grading_builders import (
    GOAL,
    EpisodeBuilder,
    item,
    kitchen_state,
    kitchen_task,
    obj,
    offset_north,
    order_event,
    recipe_step,
    street_state,
    street_task,
)

from ewa_mcp.graders import grade_episode
from ewa_mcp.graders.errors import CATEGORIES

APPLE_SLICED = [{"kind": "object_state", "object_type": "Apple", "prop": "isSliced"}]
RECIPE = [{"kind": "recipe_completed", "recipe_id": "apple-salad"}]
UNTOUCHED = [obj("Apple"), obj("Lettuce"), obj("Knife")]


def cooking(tmp_path: Path) -> EpisodeBuilder:
    return EpisodeBuilder(tmp_path, kitchen_task(embodied_goals=APPLE_SLICED, web_goals=RECIPE))


def web_done(ep: EpisodeBuilder) -> EpisodeBuilder:
    ep.call("browser_type", {"text": "apple salad"}).event(site="recipes", type="search", query="apple salad")
    ep.call("browser_click", {"ref": "e3"}).event(**recipe_step("apple-salad", 1, 2))
    ep.call("browser_click", {"ref": "e7"}).event(**recipe_step("apple-salad", 2, 2))
    return ep


def classify(ep: EpisodeBuilder, objects: list[dict[str, Any]] | None = None, state: dict[str, Any] | None = None,
             status: str = "finished") -> Any:
    embodied = state if state is not None else kitchen_state(objects if objects is not None else UNTOUCHED)
    result = grade_episode(ep.finish(status=status, embodied=embodied).directory)
    assert result.overall_success is False and result.error is not None
    return result.error


def test_web_page_loop(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    for page in ["/", "/recipe/apple-salad", "/", "/recipe/apple-salad", "/", "/recipe/apple-salad"]:
        ep.call("browser_click", {"ref": page}, observation=f"page {page}").event(site="recipes", type="page_view",
                                                                                  path=page)
    error = classify(ep, status="step_limit")
    assert error.category == "web_page_loop" and error.group == "web_only"
    assert "stuck_in_web" in error.matched  # also true, but the loop is the cause


def test_reloading_one_page_is_not_a_loop(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    for n in range(6):
        ep.call("browser_scroll", {"direction": "down" if n % 2 else "up"}).event(site="recipes", type="page_view",
                                                                                  path="/")
    assert "web_page_loop" not in classify(ep).matched


def test_refining_a_search_is_not_a_loop(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    for n in range(3):
        ep.call("browser_type", {"text": f"apple {n}"}).event(site="wiki", type="page_view", path="/search",
                                                               query=f"apple {n}")
        ep.call("browser_click", {"ref": "e1"}).event(site="wiki", type="page_view", path="/wiki/apple")
    assert "web_page_loop" not in classify(ep).matched


def test_web_repeated_actions(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    for _ in range(3):
        ep.call("browser_click", {"ref": "e5"}, observation="Search results: none")
    error = classify(ep)
    assert error.category == "web_repeated_actions" and error.group == "web_only"


def test_clicking_next_with_changing_pages_is_not_repetition(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    for step in range(1, 5):
        ep.call("browser_click", {"ref": "next"}, observation=f"Step {step} of 9")
    assert "web_repeated_actions" not in classify(ep).matched


def test_stuck_in_web(tmp_path: Path) -> None:
    error = classify(web_done(cooking(tmp_path)).call("browser_scroll", {"direction": "down"}))
    assert error.category == "stuck_in_web" and error.group == "cross_domain"
    assert "no action in the embodied environment" in error.evidence["stuck_in_web"]


def test_stuck_in_web_after_a_short_visit(tmp_path: Path) -> None:
    ep = web_done(cooking(tmp_path)).switch("embodied").call("kitchen_observe").switch("web")
    for n in range(6):
        ep.call("browser_scroll", {"direction": "down"}, observation=f"recipe part {n}")
    error = classify(ep)
    assert error.category == "stuck_in_web"
    assert "the last 6 of" in error.evidence["stuck_in_web"]


def test_stuck_in_embodied(tmp_path: Path) -> None:
    ep = cooking(tmp_path)
    ep.call("browser_click", {"ref": "e3"}).event(**recipe_step("apple-salad", 1, 2)).switch("embodied")
    for tool in ["kitchen_teleport", "kitchen_pickup", "kitchen_put", "kitchen_open", "kitchen_close", "kitchen_drop"]:
        ep.call(tool, {"object": "Fridge"})
    error = classify(ep, status="step_limit")
    assert error.category == "stuck_in_embodied" and error.group == "cross_domain"


def test_switching_without_meaningful_action(tmp_path: Path) -> None:
    ep = cooking(tmp_path).call("browser_type", {"text": "salad"}).call("browser_click", {"ref": "e1"})
    ep.switch("embodied").switch("web").switch("embodied").call("kitchen_observe").switch("web")
    ep.call("browser_click", {"ref": "e2"})
    error = classify(ep)
    assert error.category == "switching_without_action" and error.group == "cross_domain"
    assert error.evidence["switching_without_action"].startswith("3 of 4 switches")


def test_instruction_action_misalignment_in_the_kitchen(tmp_path: Path) -> None:
    ep = web_done(cooking(tmp_path)).switch("embodied")
    ep.call("kitchen_pickup", {"object": "Knife"}).call("kitchen_slice", {"object": "Lettuce"})
    sliced_lettuce = [obj("Apple"), obj("LettuceSliced", 0, source="Lettuce"), obj("Knife", isPickedUp=True)]
    error = classify(ep, sliced_lettuce)
    assert error.category == "instruction_action_misalignment" and error.group == "cross_domain"
    assert "Lettuce" in error.evidence["instruction_action_misalignment"]


def test_instruction_action_misalignment_on_the_street(tmp_path: Path) -> None:
    task = street_task(web_goals=[{"kind": "directions_shown", "origin": "poi-a", "destination": "poi-b"}])
    ep = EpisodeBuilder(tmp_path, task)
    ep.call("browser_click", {"ref": "go"}).event(site="map", type="directions", origin="poi-a", destination="poi-b")
    ep.switch("embodied").call("street_move", {"direction": "left"}).call("street_stop")
    far = offset_north(GOAL["lat"], GOAL["lng"], 200)
    error = classify(ep, state=street_state(*far))
    assert error.category == "instruction_action_misalignment"
    assert "stopped_off_target" in error.matched


def test_walking_to_another_store_than_the_order_is_misalignment(tmp_path: Path) -> None:
    task = street_task("shop-1", "shopping", web_goals=[{"kind": "order_placed", "product_id": "p-milk"}],
                       metadata={"store_nodes": {"store-a": "n-goal", "store-b": "n-b"}}, must_match_order_store=True)
    ep = EpisodeBuilder(tmp_path, task).call("browser_click", {"ref": "buy"})
    ep.event(**order_event("o1", "store-a", item("p-milk"))).switch("embodied").call("street_stop")
    error = classify(ep, state=street_state(*offset_north(GOAL["lat"], GOAL["lng"], 300), node="n-b"))
    assert error.category == "instruction_action_misalignment"
    assert "store-b" in error.evidence["instruction_action_misalignment"]


def test_failed_to_reach_interactable_object(tmp_path: Path) -> None:
    ep = web_done(cooking(tmp_path)).switch("embodied")
    ep.call("kitchen_pickup", {"object": "Knife"}, ok=False, error="Knife|+0.00|+0.90|-1.00 is not visible")
    ep.call("kitchen_move", {"direction": "ahead"})
    ep.call("kitchen_pickup", {"object": "Knife"}, ok=False, error="Knife is out of reach (2.3 m; reach is 1.5 m)")
    error = classify(ep)
    assert error.category == "failed_to_reach_object" and error.group == "embodied_only"


def test_embodied_repeated_actions(tmp_path: Path) -> None:
    ep = web_done(cooking(tmp_path)).switch("embodied")
    for _ in range(4):
        ep.call("kitchen_open", {"object": "Fridge"}, observation="The Fridge is open. You hold nothing.")
    error = classify(ep)
    assert error.category == "embodied_repeated_actions" and error.group == "embodied_only"


def test_never_stopped(tmp_path: Path) -> None:
    task = street_task(web_goals=[{"kind": "directions_shown", "origin": "poi-a", "destination": "poi-b"}])
    ep = EpisodeBuilder(tmp_path, task)
    ep.call("browser_click").event(site="map", type="directions", origin="poi-a", destination="poi-b")
    ep.switch("embodied").call("street_move", {"direction": "forward"}).call("street_move", {"direction": "left"})
    # The walk ended, unstopped, 80 m away when the step limit ended the episode.
    away = offset_north(GOAL["lat"], GOAL["lng"], 80)
    error = classify(ep, state=street_state(*away, stopped=False), status="step_limit")
    assert error.category == "never_stopped" and error.group == "embodied_only"


def test_stopped_off_target_without_directions(tmp_path: Path) -> None:
    task = street_task(web_goals=[{"kind": "directions_shown", "origin": "poi-a", "destination": "poi-b"}])
    ep = EpisodeBuilder(tmp_path, task).call("browser_type", {"text": "poi-b"}).call("browser_click")
    ep.switch("embodied").call("street_move", {"direction": "forward"}).call("street_stop")
    error = classify(ep, state=street_state(*offset_north(GOAL["lat"], GOAL["lng"], 80)))
    assert error.category == "stopped_off_target" and error.group == "embodied_only"


def test_unclassified(tmp_path: Path) -> None:
    ep = cooking(tmp_path).call("browser_type", {"text": "salad"}).call("browser_click", {"ref": "e1"})
    ep.switch("embodied").call("kitchen_pickup", {"object": "Apple"}).call("kitchen_put", {"object": "Bowl"})
    error = classify(ep)
    assert error.category == "unclassified" and error.group == "other"
    assert error.matched == ["unclassified"]


def test_every_category_has_a_group_and_label() -> None:
    assert {group for group, _ in CATEGORIES.values()} == {"cross_domain", "web_only", "embodied_only", "other"}
    assert all(label for _, label in CATEGORIES.values())
