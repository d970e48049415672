"""Traveling hard in two hops (issue 26, principle 6), played through the real server (Chromium, the street
graph, graded from the run directory): the landmark shares a fact with a named landmark X and stands within the
range; the oracle passes, while going to X instead (its walk, its article, its answer) fails, and so does going
to another landmark sharing the fact that stands outside the range."""

from __future__ import annotations

import shutil

import pytest

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import Task, TaskStore, ToolCall
from ewa_mcp.envs.street.taskgen.traveling import QUESTIONS, cue_value, landmarks_of
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.websites.wiki import store as wiki

from .helpers import play

needs_browser = pytest.mark.skipif(
    not (shutil.which("chromium") or shutil.which("chromium-browser")), reason="no Chromium: apt-get install chromium")


def two_hop_task() -> Task:
    """The first one-fact hard traveling task whose shared fact is a style (the style's own article is a page
    a searcher opens first)."""
    store = TaskStore([tasks_dir()])
    return next(t for t in sorted(store.all("traveling"), key=lambda t: t.id)
                if t.difficulty == "hard" and t.metadata["cue"]["key"] == "architectural_style"
                and not t.metadata.get("pair_cue"))


def go_to(task: Task, place) -> Task:
    """The oracle's plan sent to ``place`` instead: the walk from the corner, its article, its answer to the
    task's question."""
    world = get_world()
    article = wiki.by_poi_id(place.id)
    key = task.metadata["question"]
    answer = QUESTIONS[key][1](place.facts[key]) if key in place.facts else "unknown"
    calls = [c for c in task.oracle if c.tool == "switch_environment"][:1]
    route = world.directions(task.start.embodied.node, place.node)
    calls += [ToolCall(tool="street_move", args={"neighbour": n}) for n in route.nodes[1:]]
    calls += [ToolCall(tool="street_stop", args={}),
              ToolCall(tool="switch_environment", args={"target": "web", "message": "look it up"}),
              ToolCall(tool="browser_goto", args={"url": f"wiki:/wiki/{article.slug}"}),
              ToolCall(tool="finish_episode", args={"answer": answer})]
    return task.model_copy(update={"oracle": calls})


@needs_browser
def test_the_landmark_sharing_xs_style_in_range_passes_x_and_one_out_of_range_fail(tmp_path):
    task = two_hop_task()
    world = get_world()
    cue, start = task.metadata["cue"], task.start.embodied.node
    target, via = world.places[task.metadata["poi_id"]], world.places[cue["via"]]
    farther = [p for p in landmarks_of(world) if p.city == target.city and p.id not in (target.id, via.id)
               and wiki.by_poi_id(p.id) is not None and cue_value(cue["key"], p) == cue["value"]]
    assert farther  # the fact alone does not single the landmark out
    outside = min(farther, key=lambda p: world.directions(start, p.node).distance_m)
    assert world.directions(start, outside.node).distance_m > cue["range_m"]
    assert play(task, tmp_path, "oracle")
    assert not play(go_to(task, via), tmp_path, "the-named-landmark")
    assert not play(go_to(task, outside), tmp_path, "out-of-range")
    assert play(go_to(task, target), tmp_path, "the-plan-to-the-target")  # the altered plan itself can pass


@needs_browser
def test_two_facts_the_place_sharing_both_in_range_passes_one_fact_or_out_of_range_fails(tmp_path):
    """A two-fact task: the place within the range sharing X's fact and Y's passes; the nearest place
    within the range sharing X's fact only fails, so does the one sharing Y's only, and so does the place
    sharing both beyond the range."""
    store = TaskStore([tasks_dir()])
    task = next(t for t in sorted(store.all("traveling"), key=lambda t: t.id)
                if t.difficulty == "hard" and t.metadata.get("pair_cue"))
    world = get_world()
    cue, pair, start = task.metadata["cue"], task.metadata["pair_cue"], task.start.embodied.node
    target = world.places[task.metadata["poi_id"]]
    others = sorted((p for p in world.places.values() if p.city == target.city
                     and p.id not in (target.id, cue["via"], pair["via"]) and wiki.by_poi_id(p.id) is not None),
                    key=lambda p: world.directions(start, p.node).distance_m)
    x_only = next(p for p in others if cue_value(cue["key"], p) == cue["value"])
    y_only = next(p for p in others if cue_value(pair["key"], p) == pair["value"])
    both = next(p for p in others if cue_value(cue["key"], p) == cue["value"]
                and cue_value(pair["key"], p) == pair["value"])
    for decoy in (x_only, y_only):
        assert world.directions(start, decoy.node).distance_m <= cue["range_m"]
    assert world.directions(start, both.node).distance_m > cue["range_m"]
    assert play(task, tmp_path, "oracle")
    assert not play(go_to(task, x_only), tmp_path, "x-fact-only")
    assert not play(go_to(task, y_only), tmp_path, "y-fact-only")
    assert not play(go_to(task, both), tmp_path, "both-out-of-range")
