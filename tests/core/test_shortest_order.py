"""Navigation hard, the shortest-order form (issue 26, principle 6), read from the committed suite: the order
is the agent's to find from the map's walking distances, the answer beats every other order clearly, and
no tempting shortcut gives it in more than a third of the tasks."""

from __future__ import annotations

import json
from collections import Counter
from itertools import permutations
from pathlib import Path

from ewa_mcp.envs.street.taskgen.navigation import (
    PER_CITY_VIA,
    SHORTEST_MARGIN_M,
    SHORTEST_SHARE,
    STOPS_MAX_M,
    chain_passes,
    describe,
    shortcut_orders,
    walk_length,
)
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.taskgen.common import rng_for

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def hard_navigation() -> list[dict]:
    tasks = [t for p in sorted((TASKS_DIR / "navigation").glob("*.json")) for t in json.loads(p.read_text("utf-8"))]
    return [t for t in tasks if t["difficulty"] == "hard"]


def shortest() -> list[dict]:
    return [t for t in hard_navigation() if t["metadata"]["form"] == "shortest order"]


def leg(a, b) -> float:
    return float(get_world().directions(a.id, b.id).distance_m)


def test_about_half_of_each_citys_hard_tasks_ask_for_the_shortest_order_in_slots_a_shuffle_picks() -> None:
    hard = hard_navigation()
    for city, count in PER_CITY_VIA.items():
        ids = sorted(t["id"] for t in hard if t["id"].startswith(f"navigation-via-{city}-"))
        assert ids == [f"navigation-via-{city}-{n:03d}" for n in range(count)]  # ids and counts kept
        slots = list(range(count))
        rng_for("navigation-via-form", city).shuffle(slots)
        picked = {f"navigation-via-{city}-{n:03d}" for n in slots[: count // 2]}
        assert {t["id"] for t in hard if t["id"] in ids and t["metadata"]["form"] == "shortest order"} == picked
    assert len(shortest()) == sum(count // 2 for count in PER_CITY_VIA.values())


def test_the_best_order_is_the_answer_by_a_clear_margin_and_the_shortcuts_are_mostly_wrong() -> None:
    world = get_world()
    tasks = shortest()
    hits: Counter[str] = Counter()
    for task in tasks:
        meta = task["metadata"]
        origin = world.places.get(meta["origin_id"]) or world.place(meta["origin_id"])
        stops = [world.places[p] for p in meta["listed"]]
        ranked = sorted(permutations(stops), key=lambda perm: walk_length(leg, origin, perm))
        best, second = walk_length(leg, origin, ranked[0]), walk_length(leg, origin, ranked[1])
        assert [p.id for p in ranked[0]] == meta["stops"], task["id"]
        assert second - best >= SHORTEST_MARGIN_M and best <= STOPS_MAX_M, task["id"]
        assert meta["shortest_path_m"] == round(best, 1), task["id"]
        # the intent names the stops (with addresses) in the listed order, a shuffle of its own stream
        positions = [task["intent"].index(describe(p)) for p in stops]
        assert positions == sorted(positions), task["id"]
        city, n = task["id"].rsplit("-", 2)[-2], int(task["id"].rsplit("-", 1)[-1])
        shuffled = sorted(meta["stops"])
        rng_for("navigation-shortest-listed", city, n).shuffle(shuffled)
        assert shuffled == meta["listed"], task["id"]
        assert "shortest" in task["intent"] and "walking distances" in task["intent"], task["id"]
        for rule, order in shortcut_orders(world, leg, origin, stops, stops).items():
            hits[rule] += order == meta["stops"]
        goals = task["embodied_goals"]
        assert [g["kind"] for g in goals] == ["passed_place"] * 3 + ["reached_place"], task["id"]
        assert [g["place_id"] for g in goals] == meta["stops"], task["id"]
        assert [(g.get("after") or {}).get("place_id") for g in goals[:3]] == [None, *meta["stops"][:2]], task["id"]
    shares = {rule: hits[rule] / len(tasks) for rule in ("listed", "greedy nearest-next",
                                                          "straight line from the start", "walk from the start")}
    print({rule: f"{100 * s:.0f} %" for rule, s in shares.items()})
    assert hits["greedy nearest-next"] == 0
    assert all(s <= SHORTEST_SHARE for s in shares.values()), shares
    # the answer ends at every listed position somewhere and is not always the stop farthest from the start
    ends = Counter(t["metadata"]["listed"].index(t["metadata"]["stops"][-1]) for t in tasks)
    assert len(ends) >= 3, ends


def test_only_the_best_order_walked_along_the_map_passes_the_chain() -> None:
    """The generator kept only draws where the map's routes past the stops in any of the 23 other orders
    miss the chain; the best order's routes meet it even where a stop is passed early on the way."""
    world = get_world()
    for task in shortest():
        meta, city = task["metadata"], task["start"]["embodied"]["city"]
        origin = world.places.get(meta["origin_id"]) or world.place(meta["origin_id"])
        stops = {p: world.places[p] for p in meta["stops"]}
        answer = [stops[p] for p in meta["stops"]]
        for perm in permutations(answer):
            legs = [world.directions(a.id, b.id).nodes for a, b in zip([origin, *perm], perm)]
            nodes = legs[0] + [n for lg in legs[1:] for n in lg[1:]]
            assert chain_passes(world, city, answer, nodes) is (list(perm) == answer), (task["id"], perm)
