"""The split form of shopping hard (orders_split): a list bought in exactly one order at each of two stores,
each item once in all, within one budget. Any split of the items between the two stores passes; one store,
the wrong pair, a third order or a total over the budget fails (one choice means one choice, issue 26)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from grading_builders import EpisodeBuilder, item, make_task, order_event

from ewa_mcp.envs.browser.checks import check_orders_split
from ewa_mcp.envs.browser.goals import OrdersSplit
from ewa_mcp.graders import grade_episode

TJ, WF, CVS = "store-traderjoes-chelsea", "store-wholefoods-union-square", "store-cvs-midtown"
GOAL = {"kind": "orders_split", "items": [{"product_id": "p-oats", "size": "18 oz"},
                                          {"product_id": "p-rice", "size": "2 lb"},
                                          {"product_id": "p-milk", "size": "1 gal"}],
        "store_ids": [TJ, WF], "max_total": 20.0}
OATS, RICE, MILK = item("p-oats", "18 oz"), item("p-rice", "2 lb"), item("p-milk", "1 gal")


def placed(order_id: str, store_id: str, total: float, *items: dict[str, Any]) -> dict[str, Any]:
    event = order_event(order_id, store_id, *items)
    event["order"]["total"] = total  # the shop's order_placed event carries the order's total
    return event


def graded(tmp_path: Path, events: list[dict[str, Any]]) -> Any:
    ep = EpisodeBuilder(tmp_path, make_task("shop-split", "demo", start={"web": {}}, web_goals=[GOAL]))
    for event in events:
        ep.event(**event)
    return grade_episode(ep.finish().directory)


def test_two_right_orders_pass_in_either_split(tmp_path: Path) -> None:
    one = graded(tmp_path / "a", [placed("o1", TJ, 9.5, OATS, RICE), placed("o2", WF, 6.0, MILK)])
    assert one.web_success is True, one.conditions[0].note
    # The shared item at the other store: any split within the budget is the buyer's choice.
    other = graded(tmp_path / "b", [placed("o1", WF, 11.0, MILK, RICE), placed("o2", TJ, 4.0, OATS)])
    assert other.web_success is True, other.conditions[0].note
    assert other.conditions[0].detail["spent"] == 15.0


def test_one_store_a_wrong_pair_or_an_extra_order_fails(tmp_path: Path) -> None:
    one_store = graded(tmp_path / "one", [placed("o1", TJ, 12.0, OATS, RICE, MILK)])
    assert one_store.web_success is False and "one order at each of" in one_store.conditions[0].note
    wrong_pair = graded(tmp_path / "pair", [placed("o1", TJ, 9.5, OATS, RICE), placed("o2", CVS, 6.0, MILK)])
    assert wrong_pair.web_success is False and CVS in wrong_pair.conditions[0].note
    third = graded(tmp_path / "third", [placed("o1", TJ, 4.0, OATS), placed("o2", TJ, 5.5, RICE),
                                        placed("o3", WF, 6.0, MILK)])
    assert third.web_success is False  # the same store twice: three orders, not two
    again = graded(tmp_path / "again", [placed("o1", TJ, 9.5, OATS, RICE), placed("o2", WF, 10.0, MILK, RICE)])
    assert again.web_success is False and "more than once" in again.conditions[0].note
    extra = graded(tmp_path / "extra", [placed("o1", TJ, 9.5, OATS, RICE),
                                        placed("o2", WF, 9.0, MILK, item("p-bread", "24 oz"))])
    assert extra.web_success is False and "beyond the list" in extra.conditions[0].note
    missing = graded(tmp_path / "missing", [placed("o1", TJ, 4.0, OATS), placed("o2", WF, 6.0, MILK)])
    assert missing.web_success is False and "not ordered: p-rice" in missing.conditions[0].note


def test_over_the_budget_fails_and_nothing_placed_fails() -> None:
    goal = OrdersSplit.model_validate(GOAL)
    over = check_orders_split(goal, [placed("o1", TJ, 14.5, OATS, RICE), placed("o2", WF, 6.0, MILK)])
    assert over.met is False and "$20.50, over the budget of $20.00" in (over.note or "")
    at_budget = check_orders_split(goal, [placed("o1", TJ, 14.0, OATS, RICE), placed("o2", WF, 6.0, MILK)])
    assert at_budget.met is True  # "at most" includes the budget itself
    none = check_orders_split(goal, [])
    assert none.met is False and "no store" in (none.note or "")


def test_a_split_goal_naming_missing_products_or_stores_is_refused_by_name() -> None:
    """The task-file check names each unknown product and store of an orders_split goal by its place."""
    import json

    from ewa_mcp.core.taskmodel import Task
    from ewa_mcp.taskrefs import ReferenceChecker

    tasks = Path(__file__).resolve().parents[2] / "tasks" / "shopping"
    raw = next(t for p in sorted(tasks.glob("*.json")) for t in json.loads(p.read_text("utf-8"))
               if t["web_goals"] and t["web_goals"][0]["kind"] == "orders_split")
    checker = ReferenceChecker()
    assert checker.missing(Task.model_validate(raw)) == []
    raw["web_goals"][0]["items"][1]["product_id"] = "prod-unicorn"
    raw["web_goals"][0]["store_ids"][0] = "store-nowhere"
    found = checker.missing(Task.model_validate(raw))
    assert [p.split(":")[0] for p in found] == ["web_goals.0.items.1.product_id", "web_goals.0.store_ids.0"]
    assert "'prod-unicorn'" in found[0] and "'store-nowhere'" in found[1]
