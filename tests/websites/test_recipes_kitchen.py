"""Every recipe can be cooked: its ops run in at least one kitchen (FloorPlan1–30) through the
kitchen engineer's planner, which executes them in a fresh simulator and checks their effects."""

from __future__ import annotations

import json
from pathlib import Path


from ewa_mcp.envs.kitchen import planner

DATA = json.loads((Path(__file__).resolve().parents[2] / "websites" / "recipes" / "data" / "recipes.json")
                  .read_text(encoding="utf-8"))
SCENES = [f"FloorPlan{i}" for i in range(1, 31)]


def test_every_recipe_is_executable_in_some_kitchen():
    failures = []
    for recipe in DATA:
        ops = [op for step in recipe["steps"] for op in step["ops"]]
        reasons = []
        for scene in SCENES:
            ok, why = planner.check_recipe_executable(scene, ops)
            if ok:
                break
            reasons.append(f"{scene}: {why}")
        else:
            failures.append(f"{recipe['id']} {recipe['name']}: " + "; ".join(reasons[:3]))
    assert not failures, "recipes no kitchen can execute:\n" + "\n".join(failures)


def test_a_broken_op_sequence_is_caught():
    # Guards the test above against a planner that accepts anything.
    ops = [{"op": "cook", "object": "PotatoSliced", "method": "stove"}]  # cooking slices never cut
    assert not any(planner.check_recipe_executable(scene, ops)[0] for scene in SCENES[:5])
