"""One choice means one choice (issue 26, principle 2): where the intent asks for one item, at one store,
ordering a rival too, the same item at every store, or every ingredient fails the order goal."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from grading_builders import EpisodeBuilder, item, kitchen_task, make_task, order_event

from ewa_mcp.envs.browser.goals import OrderPlaced
from ewa_mcp.envs.browser.checks import check_order
from ewa_mcp.graders import grade_episode

TASKS = Path(__file__).resolve().parents[2] / "tasks"
CVS, TJ, WF = "store-cvs-midtown", "store-traderjoes-chelsea", "store-wholefoods-union-square"


def _graded(tmp_path: Path, task: dict[str, Any], events: list[dict[str, Any]]) -> Any:
    ep = EpisodeBuilder(tmp_path, task)
    for event in events:
        ep.event(**event)
    return grade_episode(ep.finish().directory)


def _shop_task(web_goals: list[dict[str, Any]]) -> dict[str, Any]:
    return make_task("shop-1", "demo", start={"web": {}}, web_goals=web_goals)


def test_the_target_alone_passes_and_the_target_with_a_rival_fails(tmp_path: Path) -> None:
    # "Which of the two has fewer calories? Order it": the lower one is coconut water.
    goal = [{"kind": "order_placed", "product_id": "p-coconut", "size": "16.9 fl oz", "store_id": CVS}]
    task = _shop_task(goal)
    alone = _graded(tmp_path / "alone", task, [order_event("o1", CVS, item("p-coconut", "16.9 fl oz"))])
    assert alone.web_success is True
    assert "extra_order_lines" not in alone.conditions[0].detail

    one_order = _graded(tmp_path / "one", task, [
        order_event("o1", CVS, item("p-coconut", "16.9 fl oz"), item("p-rice", "2 lb"))])
    two_orders = _graded(tmp_path / "two", task, [
        order_event("o1", CVS, item("p-rice", "2 lb")), order_event("o2", CVS, item("p-coconut", "16.9 fl oz"))])
    for both in (one_order, two_orders):
        assert both.web_success is False
        condition = both.conditions[0]
        assert [line["product_id"] for line in condition.detail["extra_order_lines"]] == ["p-rice"]
        assert condition.note is not None and "order only what was asked" in condition.note


def test_ordering_at_every_store_or_every_size_fails(tmp_path: Path) -> None:
    goal = [{"kind": "order_placed", "product_id": "p-flour", "size": "2 lb", "store_id": WF}]
    task = _shop_task(goal)
    everywhere = [order_event(f"o{k}", store, item("p-flour", "2 lb")) for k, store in enumerate((CVS, TJ, WF))]
    assert _graded(tmp_path / "stores", task, everywhere).web_success is False
    every_size = [order_event("o1", WF, item("p-flour", "2 lb"), item("p-flour", "5 lb"))]
    assert _graded(tmp_path / "sizes", task, every_size).web_success is False
    again = [order_event("o1", WF, item("p-flour", "2 lb")), order_event("o2", WF, item("p-flour", "2 lb"))]
    result = _graded(tmp_path / "again", task, again)
    assert result.web_success is False
    assert result.conditions[0].detail["extra_order_lines"][0]["order_id"] == "o2"


def test_two_items_at_two_stores_pass_and_a_third_order_fails_both(tmp_path: Path) -> None:
    goals = [{"kind": "order_placed", "product_id": "p-chocolate", "size": "10.5 oz", "store_id": TJ},
             {"kind": "order_placed", "product_id": "p-almonds", "size": "6 oz", "store_id": CVS}]
    task = _shop_task(goals)
    asked = [order_event("o1", TJ, item("p-chocolate", "10.5 oz")), order_event("o2", CVS, item("p-almonds", "6 oz"))]
    assert _graded(tmp_path / "asked", task, asked).web_success is True
    more = _graded(tmp_path / "more", task, [*asked, order_event("o3", WF, item("p-almonds", "6 oz"))])
    assert more.web_success is False
    assert [c.met for c in more.conditions] == [False, False]


def test_cooking_buys_the_missing_ingredient_only(tmp_path: Path) -> None:
    # "Your kitchen has no Bread: order it": any size, any store, once.
    goals = [{"kind": "recipe_completed", "recipe_id": "r007"},
             {"kind": "order_placed", "product_id": "prod-bread", "size": None, "quantity": 1, "store_id": None}]
    task = kitchen_task("cook-buy", web_goals=goals)
    missing = [order_event("o1", WF, item("prod-bread", "20 oz loaf"))]
    result = _graded(tmp_path / "missing", task, missing)
    assert [c.met for c in result.conditions if c.kind == "order_placed"] == [True]
    everything = [order_event("o1", WF, item("prod-bread", "20 oz loaf"), item("prod-egg", "12 ct"),
                              item("prod-tomato", "1 lb"), item("prod-potato", "5 lb bag"))]
    result = _graded(tmp_path / "everything", task, everything)
    assert [c.met for c in result.conditions if c.kind == "order_placed"] == [False]
    twice = [order_event("o1", WF, item("prod-bread", "20 oz loaf")), order_event("o2", TJ, item("prod-bread", "1 loaf"))]
    result = _graded(tmp_path / "twice", task, twice)
    assert [c.met for c in result.conditions if c.kind == "order_placed"] == [False]


def _events_for(goals: list[OrderPlaced]) -> list[dict[str, Any]]:
    return [order_event(f"o{k}", g.store_id or WF, item(g.product_id, g.size, g.quantity)) for k, g in enumerate(goals)]


def test_over_the_suite_ordering_everywhere_fails_and_the_asked_orders_pass() -> None:
    """Every task of the suite with an order goal: exactly its orders pass every order goal; the same plus
    the first item at every other store fails them (what `order-everywhere` does)."""
    stores: set[str] = set()
    tasks: list[list[OrderPlaced]] = []
    for path in sorted((TASKS / "shopping").glob("*.json")) + sorted((TASKS / "cooking").glob("*.json")):
        for raw in json.loads(path.read_text()):
            goals = [OrderPlaced.model_validate(g) for g in raw["web_goals"] if g["kind"] == "order_placed"]
            stores.update(g.store_id for g in goals if g.store_id)
            if goals:
                tasks.append(goals)
    # and the split and tour tasks (orders_split): see below and tests/core/test_shopping_tour.py
    assert len(tasks) > 420 and len(stores) >= 4
    for goals in tasks:
        asked = _events_for(goals)
        assert all(check_order(g, asked, goals).met for g in goals)
        first = goals[0]
        elsewhere = [order_event(f"x{s}", s, item(first.product_id, first.size, first.quantity))
                     for s in sorted(stores) if s != first.store_id]
        assert not any(check_order(g, asked + elsewhere, goals).met for g in goals)


def test_over_the_suite_split_orders_pass_and_ordering_everywhere_fails() -> None:
    """Every split task (orders_split): the oracle's two orders, each item where it is cheaper of the two
    stores, pass; the same plus the first item at every other store fails (a third store, the item again)."""
    from ewa_mcp.envs.browser.checks import check_orders_split
    from ewa_mcp.envs.browser.goals import OrdersSplit
    from ewa_mcp.envs.street.taskgen.shopping import split_prices
    from ewa_mcp.websites.shop import catalog

    # Two stores each (the tour form's two or three stores: tests/core/test_shopping_tour.py).
    split = [raw for path in sorted((TASKS / "shopping").glob("*.json")) for raw in json.loads(path.read_text())
             if any(g["kind"] == "orders_split" for g in raw["web_goals"]) and raw["metadata"].get("form") == "split"]
    assert len(split) == 42
    every = [s.id for s in catalog.load_stores()]
    for raw in split:
        (goal,) = [OrdersSplit.model_validate(g) for g in raw["web_goals"]]
        items = [(catalog.get_product(i.product_id), i.size) for i in goal.items]
        prices = split_prices(items, (goal.store_ids[0], goal.store_ids[1]))
        assert prices is not None, raw["id"]
        asked = []
        for sid in goal.store_ids:
            lines = [item(p.id, size) for (p, size), (at, _) in zip(items, prices, strict=True) if at == sid]
            event = order_event(f"o-{sid}", sid, *lines)
            event["order"]["total"] = round(sum(price for at, price in prices if at == sid), 2)
            asked.append(event)
        assert check_orders_split(goal, asked).met, raw["id"]
        first = goal.items[0]
        elsewhere = [order_event(f"x{s}", s, item(first.product_id, first.size)) for s in every
                     if s not in goal.store_ids]
        for event in elsewhere:
            event["order"]["total"] = 0.0
        assert not check_orders_split(goal, asked + elsewhere).met, raw["id"]
