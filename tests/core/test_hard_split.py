"""The hard split of shopping and traveling (issue 16), read from the committed suites."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ewa_mcp.envs.street.world import get_world
from ewa_mcp.websites.wiki import store as wiki

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def suite(domain: str) -> list[dict]:
    return [t for p in sorted((TASKS_DIR / domain).glob("*.json")) for t in json.loads(p.read_text("utf-8"))]


@pytest.mark.parametrize("domain", ["shopping", "traveling"])
def test_at_least_15_percent_hard(domain: str) -> None:
    tasks = suite(domain)
    hard = [t for t in tasks if t.get("difficulty") == "hard"]
    assert len(hard) >= 0.15 * len(tasks), f"{len(hard)} of {len(tasks)} {domain} tasks are hard"


def test_hard_shopping_orders_two_products_at_one_store_within_a_budget() -> None:
    for task in (t for t in suite("shopping") if t["difficulty"] == "hard"):
        orders = [g for g in task["web_goals"] if g["kind"] == "order_placed"]
        assert len(orders) == 2 and orders[0]["store_id"] == orders[1]["store_id"], task["id"]
        assert orders[0]["product_id"] != orders[1]["product_id"], task["id"]
        assert task["embodied_goals"][0]["place_id"] == orders[0]["store_id"], task["id"]
        assert task["embodied_goals"][0]["must_match_order_store"], task["id"]
        assert f"${task['metadata']['budget']:.2f}" in task["intent"], task["id"]


def test_hard_traveling_describes_the_landmark_only_by_its_look() -> None:
    world = get_world()
    for task in (t for t in suite("traveling") if t["difficulty"] == "hard"):
        place = world.places[task["metadata"]["poi_id"]]
        article = wiki.by_poi_id(place.id)
        intent = task["intent"].casefold()
        for giveaway in (place.address, place.name, article.title, *article.aliases):
            assert giveaway.casefold() not in intent, (task["id"], giveaway)
        assert place.description_hint in task["intent"]
