"""Goal checks on hand-built episodes, including every defect of the reference grader."""

from __future__ import annotations

import sys
import types
from pathlib import Path
from typing import Any

import pytest
from grading_builders import (
    GOAL,
    EpisodeBuilder,
    item,
    kitchen_state,
    kitchen_task,
    make_task,
    obj,
    offset_north,
    order_event,
    recipe_step,
    street_state,
    street_task,
)

from ewa_mcp.graders import grade_episode

PLATE = "Plate|+0.00|+0.90|-1.00"
COUNTER = "CounterTop|+0.00|+0.90|-1.00"
PAN = "Pan|+0.00|+0.90|-1.00"


def grade_kitchen(tmp_path: Path, goals: list[dict[str, Any]], objects: list[dict[str, Any]]) -> Any:
    ep = EpisodeBuilder(tmp_path, kitchen_task(embodied_goals=goals)).finish(embodied=kitchen_state(objects))
    return grade_episode(ep.directory)


# ------------------------------------------------------------------ receptacles
def test_receptacle_goal_passes_when_met_and_fails_when_not(tmp_path: Path) -> None:
    goal = {"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate"}
    met = grade_kitchen(tmp_path, [goal], [obj("Plate", parents=[COUNTER]), obj("Tomato", parents=[PLATE]),
                                           obj("CounterTop")])
    assert met.embodied_success is True and met.conditions[0].met is True
    unmet = grade_kitchen(tmp_path, [goal], [obj("Plate", parents=[COUNTER]), obj("Tomato", parents=[COUNTER]),
                                             obj("CounterTop")])
    assert unmet.embodied_success is False
    # The reference compared the parent with the object's own type; the expected receptacle must decide.
    assert unmet.conditions[0].detail["where"] == ["CounterTop"]


def test_receptacle_is_the_direct_parent_even_when_ancestors_are_listed(tmp_path: Path) -> None:
    objects = [obj("CounterTop"), obj("Plate", parents=[COUNTER]),
               obj("TomatoSliced", 1, parents=[PLATE, COUNTER], source="Tomato")]
    on_plate = grade_kitchen(tmp_path, [{"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate"}],
                             objects)
    on_counter = grade_kitchen(tmp_path, [{"kind": "object_in", "object_type": "Tomato",
                                           "receptacle_type": "CounterTop"}], objects)
    assert on_plate.embodied_success is True
    assert on_counter.embodied_success is False


def test_receptacle_type_comes_from_the_object_list_for_sink_basins(tmp_path: Path) -> None:
    basin_id = "Sink|+1.00|+0.90|-1.00|SinkBasin"
    objects = [{"objectId": basin_id, "objectType": "SinkBasin", "parentReceptacles": []},
               obj("Apple", parents=[basin_id])]
    result = grade_kitchen(tmp_path, [{"kind": "object_in", "object_type": "Apple", "receptacle_type": "SinkBasin"}],
                           objects)
    assert result.embodied_success is True


def test_receptacle_goal_with_state_needs_the_same_object_in_that_state(tmp_path: Path) -> None:
    goal = {"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Pan", "with_state": {"isCooked": True}}
    raw_in_pan = [obj("Pan"), obj("TomatoSliced", 0, parents=[PAN], source="Tomato"),
                  obj("TomatoSliced", 1, parents=[COUNTER], source="Tomato", isCooked=True), obj("CounterTop")]
    cooked_in_pan = [obj("Pan"), obj("TomatoSliced", 0, parents=[PAN], source="Tomato", isCooked=True)]
    assert grade_kitchen(tmp_path, [goal], raw_in_pan).embodied_success is False
    assert grade_kitchen(tmp_path, [goal], cooked_in_pan).embodied_success is True


# ------------------------------------------------------------------ exact types
def test_pot_does_not_match_potato(tmp_path: Path) -> None:
    burner = "StoveBurner|+0.00|+0.90|-1.00"
    objects = [obj("StoveBurner"), obj("Potato", parents=[burner], isCooked=True), obj("Pot", parents=[COUNTER]),
               obj("CounterTop")]
    pot_on_burner = grade_kitchen(tmp_path, [{"kind": "object_in", "object_type": "Pot",
                                              "receptacle_type": "StoveBurner"}], objects)
    assert pot_on_burner.embodied_success is False
    pot_cooked = grade_kitchen(tmp_path, [{"kind": "object_state", "object_type": "Pot", "prop": "isCooked"}], objects)
    assert pot_cooked.embodied_success is False
    potato_cooked = grade_kitchen(tmp_path, [{"kind": "object_state", "object_type": "Potato", "prop": "isCooked"}],
                                  objects)
    assert potato_cooked.embodied_success is True


def test_butterknife_is_not_a_knife(tmp_path: Path) -> None:
    goal = {"kind": "object_state", "object_type": "Knife", "prop": "isPickedUp"}
    butter = grade_kitchen(tmp_path, [goal], [obj("ButterKnife", isPickedUp=True), obj("Knife")])
    knife = grade_kitchen(tmp_path, [goal], [obj("ButterKnife"), obj("Knife", isPickedUp=True)])
    assert butter.embodied_success is False
    assert knife.embodied_success is True


# ------------------------------------------------------------------ False goals and pieces
def test_false_goal_fails_when_one_instance_is_true(tmp_path: Path) -> None:
    goal = {"kind": "object_state", "object_type": "Egg", "prop": "isBroken", "value": False}
    one_broken = grade_kitchen(tmp_path, [goal], [obj("Egg", 0), obj("Egg", 1, isBroken=True)])
    none_broken = grade_kitchen(tmp_path, [goal], [obj("Egg", 0), obj("Egg", 1)])
    assert one_broken.embodied_success is False
    assert "1 of 2" in (one_broken.conditions[0].note or "")
    assert none_broken.embodied_success is True


def test_false_goal_with_no_instance_is_not_met(tmp_path: Path) -> None:
    goal = {"kind": "object_state", "object_type": "Egg", "prop": "isBroken", "value": False}
    assert grade_kitchen(tmp_path, [goal], [obj("Apple")]).embodied_success is False


def test_sliced_and_cracked_pieces_count_for_their_source(tmp_path: Path) -> None:
    objects = [obj("TomatoSliced", 0, source="Tomato"), obj("TomatoSliced", 1, source="Tomato"),
               obj("EggCracked", 0, source="Egg", isCooked=True), obj("Apple")]
    sliced = {"kind": "object_state", "object_type": "Tomato", "prop": "isSliced"}
    not_sliced = {"kind": "object_state", "object_type": "Tomato", "prop": "isSliced", "value": False}
    egg_cooked = {"kind": "object_state", "object_type": "Egg", "prop": "isCooked"}
    apple_sliced = {"kind": "object_state", "object_type": "Apple", "prop": "isSliced"}
    assert grade_kitchen(tmp_path, [sliced], objects).embodied_success is True
    assert grade_kitchen(tmp_path, [not_sliced], objects).embodied_success is False
    assert grade_kitchen(tmp_path, [egg_cooked], objects).embodied_success is True
    assert grade_kitchen(tmp_path, [apple_sliced], objects).embodied_success is False


def test_piece_type_goal_uses_the_pieces_own_state(tmp_path: Path) -> None:
    goal = {"kind": "object_state", "object_type": "BreadSliced", "prop": "isCooked"}
    raw = [obj("BreadSliced", 0, source="Bread"), obj("Bread", isCooked=True)]
    toasted = [obj("BreadSliced", 0, source="Bread"), obj("BreadSliced", 1, source="Bread", isCooked=True)]
    assert grade_kitchen(tmp_path, [goal], raw).embodied_success is False
    assert grade_kitchen(tmp_path, [goal], toasted).embodied_success is True


# ------------------------------------------------------------------ web goals
def _web_episode(tmp_path: Path, web_goals: list[dict[str, Any]], events: list[dict[str, Any]]) -> Any:
    ep = EpisodeBuilder(tmp_path, make_task("w-1", "demo", start={"web": {}}, web_goals=web_goals))
    for event in events:
        ep.event(**event)
    return grade_episode(ep.finish().directory)


def test_web_success_fails_when_a_different_recipe_was_completed(tmp_path: Path) -> None:
    goal = [{"kind": "recipe_completed", "recipe_id": "tomato-soup-veg"}]
    other = _web_episode(tmp_path, goal, [recipe_step("tomato-soup-veg", 2, 5), recipe_step("tomato-soup-meat", 5, 5)])
    assert other.web_success is False
    assert other.conditions[0].detail["completed_other_recipes"] == ["tomato-soup-meat"]
    assert other.conditions[0].detail["furthest_step"] == 2
    changed = _web_episode(tmp_path, goal, [recipe_step("tomato-soup-veg", 5, 5), recipe_step("tomato-soup-meat", 5, 5)])
    assert changed.web_success is False and changed.conditions[0].detail["chosen_recipe"] == "tomato-soup-meat"
    right = _web_episode(tmp_path, goal, [recipe_step("tomato-soup-veg", k, 5) for k in range(1, 6)])
    assert right.web_success is True


def test_order_goal_checks_product_size_quantity_and_store(tmp_path: Path) -> None:
    goal = [{"kind": "order_placed", "product_id": "p-milk", "size": "1 L", "quantity": 2,
             "store_id": "store-target-herald-square"}]
    store = "store-target-herald-square"
    cases = {
        "exact": (order_event("o1", store, item("p-milk", "1 L", 2)), True),
        "split lines sum": (order_event("o1", store, item("p-milk", "1 l", 1), item("p-milk", "1 L", 1)), True),
        "wrong size": (order_event("o1", store, item("p-milk", "2 L", 2)), False),
        "wrong quantity": (order_event("o1", store, item("p-milk", "1 L", 3)), False),
        "wrong store": (order_event("o1", "store-cvs-midtown", item("p-milk", "1 L", 2)), False),
        "wrong product": (order_event("o1", store, item("p-oat-milk", "1 L", 2)), False),
    }
    for name, (event, expected) in cases.items():
        assert _web_episode(tmp_path, goal, [event]).web_success is expected, name
    nothing = _web_episode(tmp_path, goal, [])
    assert nothing.conditions[0].note == "no order was placed"


def test_directions_and_page_goals(tmp_path: Path) -> None:
    goals = [{"kind": "directions_shown", "origin": "poi-a", "destination": "poi-b"},
             {"kind": "page_visited", "site": "wiki", "path_prefix": "/wiki/flatiron"}]
    good = [{"site": "map", "type": "directions", "origin": "poi-a", "destination": "poi-b", "city": "manhattan"},
            {"site": "wiki", "type": "page_view", "path": "/wiki/flatiron-building"}]
    reversed_route = [{"site": "map", "type": "directions", "origin": "poi-b", "destination": "poi-a"},
                      {"site": "shop", "type": "page_view", "path": "/wiki/flatiron-building"}]
    result = _web_episode(tmp_path, goals, good)
    assert result.web_success is True and result.completion == 1.0
    wrong = _web_episode(tmp_path, goals, reversed_route)
    assert [c.met for c in wrong.conditions] == [False, False]


# ------------------------------------------------------------------ street goals
def _street(tmp_path: Path, state: dict[str, Any], radius: float | None = None, **task_kw: Any) -> Any:
    ep = EpisodeBuilder(tmp_path, street_task(**task_kw)).finish(embodied=state)
    return grade_episode(ep.directory, radius_m=radius)


def test_navigation_success_is_ending_the_walk_within_the_radius(tmp_path: Path) -> None:
    near = offset_north(GOAL["lat"], GOAL["lng"], 20)
    far = offset_north(GOAL["lat"], GOAL["lng"], 30)
    assert _street(tmp_path, street_state(*near)).embodied_success is True
    at_30 = _street(tmp_path, street_state(*far))
    assert at_30.embodied_success is False
    assert at_30.navigation[0].distance_to_goal_m == pytest.approx(30, abs=0.2)
    assert _street(tmp_path, street_state(*far), radius=40).embodied_success is True
    assert _street(tmp_path, street_state(*near), radius=10).embodied_success is False
    # Without a stop the walk ends where the episode finishes: that position is graded.
    walking = _street(tmp_path, street_state(*near, stopped=False))
    assert walking.embodied_success is True and walking.navigation[0].stopped is False
    assert "never stopped" in _street(tmp_path, street_state(*far, stopped=False)).conditions[0].note


def test_the_walk_is_graded_where_it_ended(tmp_path: Path) -> None:
    # walk_end (where street_stop was called) is what counts, not a position reported beside it.
    near = offset_north(GOAL["lat"], GOAL["lng"], 10)
    far = offset_north(GOAL["lat"], GOAL["lng"], 300)
    stopped_near = {**street_state(*far), "walk_stopped": True,
                    "walk_end": {"node": "n-goal", "lat": near[0], "lng": near[1], "by": "street_stop"}}
    result = _street(tmp_path, stopped_near)
    assert result.embodied_success is True and result.navigation[0].final_node == "n-goal"
    stopped_far = {**street_state(*near), "walk_end": {"node": "n-x", "lat": far[0], "lng": far[1]}}
    assert _street(tmp_path, stopped_far).embodied_success is False


def test_a_waypoint_must_be_passed_before_the_walk_ends(tmp_path: Path) -> None:
    waypoint = offset_north(GOAL["lat"], GOAL["lng"], -200)
    goal = {"kind": "passed_place", "city": "manhattan", "node": "n-way", "lat": waypoint[0], "lng": waypoint[1]}
    near_way = offset_north(*waypoint, 15)

    def run(points: Any) -> Any:
        state = {**street_state(GOAL["lat"], GOAL["lng"]), **({"path_points": points} if points is not None else {})}
        task = street_task()
        task["embodied_goals"].append(goal)
        ep = EpisodeBuilder(tmp_path, task).finish(embodied=state)
        return grade_episode(ep.directory)

    passed = run([list(offset_north(*waypoint, -100)), list(near_way), [GOAL["lat"], GOAL["lng"]]])
    assert passed.embodied_success is True and [c.met for c in passed.conditions] == [True, True]
    skipped = run([list(offset_north(*waypoint, 60)), [GOAL["lat"], GOAL["lng"]]])
    assert skipped.embodied_success is False and "no closer than 60 m" in skipped.conditions[1].note
    assert run(None).conditions[1].met is None


def test_an_ordered_waypoint_must_be_passed_after_the_one_before_it(tmp_path: Path) -> None:
    first = offset_north(GOAL["lat"], GOAL["lng"], -400)
    second = offset_north(GOAL["lat"], GOAL["lng"], -200)
    goal = {"kind": "passed_place", "city": "manhattan", "node": "n-second", "lat": second[0], "lng": second[1],
            "place_id": "second", "after": {"node": "n-first", "lat": first[0], "lng": first[1], "place_id": "first"}}
    far = offset_north(GOAL["lat"], GOAL["lng"], 300)

    def met(*points: tuple[float, float]) -> Any:
        state = {**street_state(GOAL["lat"], GOAL["lng"]), "path_points": [list(p) for p in points]}
        task = street_task()
        task["embodied_goals"].append(goal)
        return grade_episode(EpisodeBuilder(tmp_path, task).finish(embodied=state).directory).conditions[1]

    goal_point = (GOAL["lat"], GOAL["lng"])
    assert met(first, second, goal_point).met is True
    # passing the second stop on the way to the first, then again after it, keeps the order
    assert met(second, first, second, goal_point).met is True
    wrong = met(far, second, first, goal_point)
    assert wrong.met is False and "only before it passed first" in wrong.note and wrong.detail["in_order"] is False
    never = met(second, goal_point)
    assert never.met is False and "never passed first" in never.note


def test_exact_node_distance_and_spl(tmp_path: Path) -> None:
    at_goal = street_state(GOAL["lat"], GOAL["lng"], node="n-goal", walked=125.0)
    nav = _street(tmp_path, at_goal, metadata={"shortest_path_m": 100.0}).navigation[0]
    assert nav.exact_node is True and nav.distance_to_goal_m == 0.0
    assert nav.spl == pytest.approx(100 / 125)
    # Without a stored shortest path the straight line from the start is used; walking less than it is capped at 1.
    start = offset_north(GOAL["lat"], GOAL["lng"], -200)
    nav2 = _street(tmp_path, street_state(GOAL["lat"], GOAL["lng"], walked=150.0),
                   metadata={"start_lat": start[0], "start_lng": start[1]}).navigation[0]
    assert nav2.shortest_path_source == "straight_line" and nav2.spl == pytest.approx(1.0)
    nav3 = _street(tmp_path, street_state(GOAL["lat"], GOAL["lng"], walked=400.0),
                   metadata={"start_lat": start[0], "start_lng": start[1]}).navigation[0]
    assert nav3.spl == pytest.approx(0.5, abs=0.002)
    away = offset_north(GOAL["lat"], GOAL["lng"], 100)
    failed = _street(tmp_path, street_state(*away), metadata={"shortest_path_m": 100.0}).navigation[0]
    assert failed.spl == 0.0


def test_wrong_city_is_not_an_arrival(tmp_path: Path) -> None:
    result = _street(tmp_path, street_state(GOAL["lat"], GOAL["lng"], city="boston"))
    assert result.embodied_success is False


def test_shopping_walk_must_end_at_the_orders_pickup_store(tmp_path: Path) -> None:
    stores = {"store-target-herald-square": "n-goal", "store-cvs-midtown": "n-cvs"}
    web_goals = [{"kind": "order_placed", "product_id": "p-milk"}]

    def run(store_id: str) -> Any:
        task = street_task("shop-1", "shopping", web_goals=web_goals, metadata={"store_nodes": stores},
                           must_match_order_store=True)
        ep = EpisodeBuilder(tmp_path, task).event(**order_event("o1", store_id, item("p-milk")))
        return grade_episode(ep.finish(embodied=street_state(GOAL["lat"], GOAL["lng"], node="n-goal")).directory)

    right = run("store-target-herald-square")
    assert right.overall_success is True
    wrong = run("store-cvs-midtown")
    assert wrong.web_success is True and wrong.embodied_success is False
    assert "not the pickup store" in (wrong.conditions[1].note or "")


# ------------------------------------------------------------------ answers
@pytest.mark.parametrize(
    ("answer", "must_include", "expected"),
    [
        ("It is 1,454 feet tall.", ["1454"], True),
        ("1454 ft", ["1,454"], True),
        ("It was designed by  DANIEL   burnham.", ["Daniel Burnham"], True),
        ("Côte d’Ivoire", ["Cote d'Ivoire"], True),
        ("Built in 2008", ["2008", "Robert A.M. Stern"], False),
        ("Built in 12008", ["2008"], False),
        ("", ["2008"], False),
    ],
)
def test_text_answers_are_normalised(tmp_path: Path, answer: str, must_include: list[str], expected: bool) -> None:
    task = make_task("q-1", "traveling", answer={"kind": "text", "must_include": must_include})
    result = grade_episode(EpisodeBuilder(tmp_path, task).finish(answer=answer).directory)
    assert result.answer_correct is expected
    assert result.overall_success is expected


def test_exact_text_answer(tmp_path: Path) -> None:
    task = make_task("q-2", "traveling", answer={"kind": "text", "exact": "Beaux-Arts"})
    assert grade_episode(EpisodeBuilder(tmp_path, task).finish(answer="beaux arts").directory).answer_correct is True
    assert grade_episode(
        EpisodeBuilder(tmp_path, task).finish(answer="Beaux-Arts, I think").directory).answer_correct is False


GEO_TASK = {"answer": {"kind": "geolocation", "lat": 48.8584, "lng": 2.2945, "continent": "Europe",
                       "country": "France", "city": "Paris", "street": "Avenue Gustave Eiffel"},
            "start": {"environment": "embodied", "embodied": {"kind": "geo", "location_id": "loc-1",
                                                              "setting": "baseline"}}}


def test_geolocation_without_geo_grader_is_reported_not_gradable(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ewa_mcp.envs.geo.checks", None)  # behave as if ewa_mcp/envs/geo/checks.py did not exist
    ep = EpisodeBuilder(tmp_path, make_task("geo-1", "geolocation", **GEO_TASK))
    result = grade_episode(ep.finish(submission={"lat": 48.85, "lng": 2.29, "city": "Paris"}).directory)
    assert result.gradable is False and result.answer_correct is None
    assert any("not gradable: geo grader missing" in p for p in result.problems)
    assert result.setting == "baseline"


def test_geolocation_is_delegated_to_the_geo_grader(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[Any] = []

    def grade_geolocation(check: Any, submission: dict[str, Any] | None) -> dict[str, Any]:
        seen.append((check.city, submission))
        city = bool(submission) and submission.get("city") == check.city
        return {"continent": True, "country": True, "city": city, "street": False, "all_levels": False,
                "distance_km": 0.5, "bands": {"street": True}, "score": 4990}

    monkeypatch.setitem(sys.modules, "ewa_mcp.envs.geo.checks",
                        types.SimpleNamespace(grade_geolocation=grade_geolocation))
    ep = EpisodeBuilder(tmp_path, make_task("geo-1", "geolocation", **GEO_TASK))
    result = grade_episode(ep.finish(submission={"lat": 48.85, "lng": 2.29, "city": "Paris"}).directory)
    assert seen == [("Paris", {"lat": 48.85, "lng": 2.29, "city": "Paris"})]
    assert result.gradable is True and result.answer_correct is False
    assert result.geolocation is not None and result.geolocation["city"] is True


def test_geolocation_verdict_names_the_levels_that_missed(tmp_path: Path) -> None:
    task = make_task("geo-2", "geolocation", **GEO_TASK)
    result = grade_episode(EpisodeBuilder(tmp_path, task).finish(submission={
        "lat": 48.85, "lng": 2.29, "continent": "Europe", "country": "France", "city": "Lyon",
        "street": "Rue de Rivoli"}).directory)
    (condition,) = [c for c in result.conditions if c.side == "answer"]
    assert condition.met is False and condition.note == "wrong at: city, street"
    right = grade_episode(EpisodeBuilder(tmp_path, task).finish(submission={
        "lat": 48.85, "lng": 2.29, "continent": "Europe", "country": "France", "city": "Paris",
        "street": "Avenue Gustave Eiffel"}).directory)
    assert [c.note for c in right.conditions if c.side == "answer"] == [None]


def test_geolocation_aggregates_and_table_come_from_the_geo_grader(tmp_path: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    from ewa_mcp.graders import grade_run, render_report

    received: list[list[dict[str, Any]]] = []

    def grade_geolocation(check: Any, submission: dict[str, Any] | None) -> dict[str, Any]:
        ok = bool(submission)
        return {"continent": ok, "country": ok, "city": False, "street": False, "all_levels": False}

    def aggregate_geolocation(rows: list[dict[str, Any]]) -> dict[str, Any]:
        received.append(rows)
        return {"n": len(rows), "continent": sum(r["continent"] for r in rows) / len(rows)}

    def render_geolocation_table(agg_by_run: dict[str, Any]) -> str:
        return "GEO TABLE " + ", ".join(f"{label}: n={agg['n']}" for label, agg in agg_by_run.items())

    monkeypatch.setitem(sys.modules, "ewa_mcp.envs.geo.checks", types.SimpleNamespace(
        grade_geolocation=grade_geolocation, aggregate_geolocation=aggregate_geolocation,
        render_geolocation_table=render_geolocation_table))
    run = tmp_path / "geo-run"
    EpisodeBuilder(run, make_task("geo-1", "geolocation", **GEO_TASK)).finish(submission={"lat": 1.0, "lng": 2.0})
    EpisodeBuilder(run, make_task("geo-2", "geolocation", **GEO_TASK)).finish()
    report = grade_run(run)
    assert report.domains["geolocation"].geolocation == {"n": 2, "continent": 0.5}
    assert sorted(r["setting"] for r in received[0]) == ["baseline", "baseline"]
    assert "GEO TABLE geo-run: n=2" in render_report(report)
