"""Grading speed on a synthetic run the size of the paper's suite; prints JSON figures.

    python benchmarks/bench_grading.py [--episodes 1500] [--steps 30]

Writes a run directory with the core's own EpisodeRecorder (cooking and navigation episodes with
`steps` trajectory lines each), then times grade_run and the table/JSON rendering.
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import tempfile
import time
from pathlib import Path

from ewa_mcp.graders import grade_run
from ewa_mcp.graders.report_tables import render
from ewa_mcp.core.records import EpisodeRecorder

PLATE = "Plate|+0.00|+0.90|-1.00"


def write_episode(run: Path, n: int, steps: int, rng: random.Random) -> None:
    cooking = n % 3 != 0
    recorder = EpisodeRecorder(run / f"ep-{n:012d}")
    start = {"environment": "web", "web": {"start_url": "recipes:/" if cooking else "map:/"},
             "embodied": {"kind": "kitchen", "scene": "FloorPlan1"} if cooking else
             {"kind": "street", "city": "manhattan", "node": "n-0"}}
    if cooking:
        task = {"id": f"cook-{n}", "domain": "cooking", "intent": "cook", "start": start,
                "web_goals": [{"kind": "recipe_completed", "recipe_id": "r-1"}],
                "embodied_goals": [{"kind": "object_state", "object_type": "Tomato", "prop": "isSliced"},
                                   {"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate"}]}
    else:
        task = {"id": f"nav-{n}", "domain": "navigation", "intent": "walk", "start": start,
                "web_goals": [{"kind": "directions_shown", "origin": "a", "destination": "b"}],
                "embodied_goals": [{"kind": "reached_place", "city": "manhattan", "node": "n-9", "lat": 40.7418,
                                    "lng": -73.9895}], "metadata": {"shortest_path_m": 120.0}}
    recorder.write_task(task)
    env = "web"
    for step in range(1, steps + 1):
        if step == steps // 2:
            env = "embodied"
            tool = "switch_environment"
        else:
            tool = ("browser_click" if env == "web" else ("kitchen_slice" if cooking else "street_move"))
        recorder.step(index=step, tool=tool, args={"ref": f"e{rng.randint(1, 9)}"}, ok=rng.random() > 0.1,
                      error=None, duration_ms=1.0, environment=env, observation=f"obs {rng.random()}", counted=True)
        if env == "web" and step % 5 == 0:
            recorder.event({"site": "recipes", "type": "page_view", "path": f"/r/{rng.randint(1, 4)}"})
    if rng.random() < 0.6:
        recorder.event({"site": "recipes", "type": "recipe_step", "recipe_id": "r-1", "step": 3, "of": 3}
                       if cooking else {"site": "map", "type": "directions", "origin": "a", "destination": "b"})
    if cooking:
        objects = [{"objectId": PLATE, "objectType": "Plate", "parentReceptacles": []}] + [
            {"objectId": f"Tomato|+1|+1|+1|TomatoSliced_{k}", "objectType": "TomatoSliced", "sourceType": "Tomato",
             "parentReceptacles": [PLATE] if rng.random() < 0.3 else []} for k in range(rng.randint(0, 6))]
        embodied = {"name": "kitchen", "objects": objects + [{"objectId": f"Obj{k}|+0|+0|+0", "objectType": f"Obj{k}",
                                                              "parentReceptacles": []} for k in range(60)]}
    else:
        embodied = {"name": "street", "city": "manhattan", "node": "n-5", "lat": 40.7418 + rng.uniform(-4e-4, 4e-4),
                    "lng": -73.9895, "stopped": rng.random() < 0.8, "distance_walked_m": rng.uniform(100, 300)}
    recorder.write_final_state({"episode_id": f"ep-{n:012d}", "status": "finished", "steps": steps, "calls": steps,
                                "switches": 1, "wall_time_s": 60.0, "answer": None,
                                "environments": {"web": {"name": "browser"}, "embodied": embodied}})
    recorder.close()


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--episodes", type=int, default=1500)
    parser.add_argument("--steps", type=int, default=30)
    args = parser.parse_args()
    rng = random.Random(7)
    with tempfile.TemporaryDirectory() as tmp:
        run = Path(tmp) / "run"
        for n in range(args.episodes):
            write_episode(run, n, args.steps, rng)
        timings = []
        for _ in range(3):
            started = time.perf_counter()
            report = grade_run(run)
            timings.append(time.perf_counter() - started)
        started = time.perf_counter()
        render([report], "table")
        table_s = time.perf_counter() - started
        started = time.perf_counter()
        render([report], "json")
        json_s = time.perf_counter() - started
    best = min(timings)
    print(json.dumps({
        "benchmark": "grading",
        "episodes": args.episodes,
        "trajectory_lines_per_episode": args.steps,
        "grade_run_s_median": round(statistics.median(timings), 3),
        "grade_run_s_best": round(best, 3),
        "episodes_per_s": round(args.episodes / best, 1),
        "ms_per_episode": round(1000 * best / args.episodes, 3),
        "render_table_s": round(table_s, 3),
        "render_json_s": round(json_s, 3),
    }))


if __name__ == "__main__":
    main()
