"""A tiny run of the learning demonstration (examples/learn_navigation.py): trained through the gym on train-split
walks with the grader's reward only, the tabular policy learns to take the street toward the destination and to
stop when it is there."""

from __future__ import annotations

import json

import pytest

from ewa_mcp.graders import grade_episode

from .test_llm_agents import load_example

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = [pytest.mark.timeout(600), pytest.mark.slow]


def test_a_short_training_run_learns_to_walk_toward_the_destination(tmp_path):
    demo = load_example("learn_navigation")
    out = tmp_path / "curve.json"
    assert demo.main(["--episodes", "150", "--eval-every", "150", "--eval-tasks", "6", "--cities", "boston",
                      "--no-plot", "--json", str(out), "--run-dir", str(tmp_path / "run")]) == 0
    result = json.loads(out.read_text())
    before, after = result["curve"][0], result["curve"][-1]
    assert before["episodes"] == 0 and after["episodes"] == 150
    assert before["held_out_success"] <= 0.2  # an untrained walker almost never ends at the destination
    assert after["train_success"] > 0.3  # rewards arrived, and only the grader gives them
    move, stop = result["move"], result["stop"]
    # Learned from reward alone: the street most toward the destination beats the one most away from it, and
    # stopping is preferred inside the goal radius over 150-400 m out.
    assert move[0] > move[-1] + 1.0
    assert stop[0] > stop[3]
    # Every episode was a real, recorded, gradable episode: 150 training and 2 x 6 held-out ones.
    episodes = [p.parent for p in (tmp_path / "run").rglob("task.json")]
    assert len(episodes) == 150 + 12
    successes = sum(grade_episode(e).overall_success is True for e in episodes)
    assert successes >= round(after["train_success"] * 150)  # the training successes, judged again by the grader
