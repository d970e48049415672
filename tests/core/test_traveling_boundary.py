"""Traveling hard decided at the range's edge (issue 26, principle 6), read from the committed suite: the answer's
walk ends just inside the stated range, rivals sharing the fact lie just beyond it (some of them within it as the
crow flies), the stated rule leaves exactly one place, and the step budget holds a careful player who measures
every candidate's walk. benchmarks/bench_traveling_cues.py prints the distributions these bound."""

from __future__ import annotations

import json
from pathlib import Path

from ewa_mcp.envs.street.taskgen.traveling import (
    BOUNDARY_GAP_M,
    BOUNDARY_IN_M,
    BOUNDARY_OUT_M,
    MIN_RIVALS,
    _alike,
    boundary_limit,
    cue_value,
)
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.geometry import haversine_m
from ewa_mcp.taskgen.common import STEP_BUDGETS
from ewa_mcp.websites.wiki import store as wiki

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def hard() -> list[dict]:
    return [t for p in sorted((TASKS_DIR / "traveling").glob("*.json")) for t in json.loads(p.read_text("utf-8"))
            if t["difficulty"] == "hard"]


def walk_m(world, start: str, node: str) -> float:
    try:
        return float(world.directions(start, node).distance_m)
    except ValueError:
        return float("inf")


def crow_m(world, start: str, node: str) -> float:
    a, b = world.node(start), world.node(node)
    return haversine_m(a.lat, a.lng, b.lat, b.lng)


def with_articles(world, city: str, named: set[str]) -> list:
    return [p for p in world.places.values() if p.city == city and p.id not in named
            and wiki.by_poi_id(p.id) is not None]


def test_boundary_limit_puts_the_walk_just_inside_a_round_range() -> None:
    assert boundary_limit(345.0) == 400 and boundary_limit(390.0) == 400 and boundary_limit(320.0) == 350
    assert boundary_limit(395.0) == 450  # 5 m short of 400 is too close to the edge, so the next one
    for walk in (201.0, 333.3, 480.0, 612.5, 899.0):
        limit = boundary_limit(walk)
        assert limit is None or BOUNDARY_GAP_M <= limit - walk <= BOUNDARY_IN_M


def test_the_answer_is_just_inside_and_rivals_just_beyond_the_range() -> None:
    """Every hard task: the answer's walk ends BOUNDARY_GAP_M..BOUNDARY_IN_M inside the range; at least
    MIN_RIVALS other places sharing X's fact (both facts, for a two-fact task) walk at most BOUNDARY_OUT_M
    over it; for one-fact tasks one of them is within the range as the crow flies, and in many tasks one is
    nearer than the answer as the crow flies, so the straight line picks a rival."""
    world = get_world()
    tasks = hard()
    crow_first = 0
    one_fact = [t for t in tasks if not t["metadata"].get("pair_cue")]
    for task in tasks:
        meta, start = task["metadata"], task["start"]["embodied"]["node"]
        cue, pair = meta["cue"], meta.get("pair_cue")
        limit, target = cue["range_m"], world.places[meta["poi_id"]]
        inside = limit - walk_m(world, start, target.node)
        assert BOUNDARY_GAP_M <= inside <= BOUNDARY_IN_M, (task["id"], inside)
        named = {cue["via"], target.id, *([pair["via"]] if pair else [])}
        rivals = [p for p in with_articles(world, target.city, named)
                  if cue_value(cue["key"], p) == cue["value"]
                  and (pair is None or cue_value(pair["key"], p) == pair["value"])
                  and walk_m(world, start, p.node) <= limit + BOUNDARY_OUT_M]
        assert len(rivals) >= MIN_RIVALS, task["id"]
        assert all(walk_m(world, start, p.node) > limit + BOUNDARY_GAP_M for p in rivals), task["id"]
        if pair is None:
            assert any(crow_m(world, start, p.node) <= limit for p in rivals), task["id"]
            crow_first += any(crow_m(world, start, p.node) < crow_m(world, start, target.node) for p in rivals)
    assert crow_first >= 0.4 * len(one_fact), (crow_first, len(one_fact))  # 13 of 27 as generated


def test_the_stated_rule_leaves_exactly_the_answer() -> None:
    """Of the places with an article whose walk is at most the range, X (and Y) aside, exactly one shares
    the fact (both facts), nothing else within the range reads as sharing it, and the answer does."""
    world = get_world()
    for task in hard():
        meta, start = task["metadata"], task["start"]["embodied"]["node"]
        cue, pair = meta["cue"], meta.get("pair_cue")
        target = world.places[meta["poi_id"]]
        named = {cue["via"], *([pair["via"]] if pair else [])}

        def fits(p, alike: bool) -> bool:
            facts = [cue, *([pair] if pair else [])]
            values = [cue_value(f["key"], p) for f in facts]
            if alike:
                return all(v is not None and _alike(f["key"], f["value"], v) for f, v in zip(facts, values))
            return all(v == f["value"] for f, v in zip(facts, values))

        within = [p for p in with_articles(world, target.city, named)
                  if walk_m(world, start, p.node) <= cue["range_m"]]
        assert [p.id for p in within if fits(p, alike=False)] == [target.id], task["id"]
        assert [p.id for p in within if fits(p, alike=True)] == [target.id], task["id"]


def test_the_step_budget_holds_a_careful_player() -> None:
    """A careful player reads X's (and Y's) article, searches the wiki a dozen times, opens the article and
    asks the map's directions for every place of the city sharing the fact, then walks, looks up and answers
    (the oracle's own steps): that fits the budget."""
    world = get_world()
    budget = STEP_BUDGETS[("traveling", "hard")]
    for task in hard():
        meta = task["metadata"]
        cue, target = meta["cue"], world.places[meta["poi_id"]]
        sharing = [p for p in with_articles(world, target.city, {cue["via"]})
                   if cue_value(cue["key"], p) == cue["value"]]
        careful = len(task["oracle"]) + 12 + 2 * len(sharing)
        assert careful <= budget == task["step_limit"], (task["id"], careful, budget)
