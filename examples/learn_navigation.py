"""A learning demonstration on the CPU: a tabular policy over street moves, trained through the Gymnasium
interface with the grader's reward on navigation tasks of the train split, evaluated on held-out tasks.

    python examples/learn_navigation.py                       # a few minutes; plots docs/learning_curve.png
    python examples/learn_navigation.py --episodes 60 --eval-every 30 --eval-tasks 10 --no-plot   # seconds

The tasks are the walk of each navigation task (``ewa_mcp.task_variants.embodied_only``: the same start and
destination, without the map site), so every episode is street moves only. Training tasks come from the train
split (``generate_split("navigation", "train", seed)``), the held-out ones from the public test split, which shares
no start and goal walk with it.

The policy sees what a walker holding the directions would know: how far the destination is (five distance
bands) and, for each street it can take, the angle between that street and the bearing to the destination (eight
bands of 22.5 degrees). The destination's coordinates come from the task's goal (what the directions would show);
the walker knows where it is by counting its own moves from the start. It is two tables of preferences, one per angle
band for taking a street and one per distance band for stopping, turned into a softmax over the moves on offer
and ``street_stop``. It starts at zero (every choice equally likely) and learns by REINFORCE from the
environment's reward alone: 1.0 when the grader judges the finished episode a success, else 0.0. Nothing else
tells it which move is better.

A random walker almost never ends a whole walk at the destination, so a reward of 1.0 would almost never come.
Training therefore follows a curriculum over the same train-split walks: first their last move or two (started
from a node of the oracle's route), then longer and longer ends of them, up to the whole walk by 60 % of training.
The held-out evaluation always plays whole walks.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import re
import sys
import time
from pathlib import Path
from typing import Any

import gymnasium
import numpy as np

import ewa_mcp.gym  # noqa: F401  (registers the environments)
from ewa_mcp.core.taskmodel import Task
from ewa_mcp.envs.street.goals import ReachedPlace, StreetStart
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.geometry import bearing_deg, haversine_m
from ewa_mcp.task_variants import embodied_only
from ewa_mcp.taskgen.splits import generate_split, public_test_tasks

DISTANCE_BANDS = (25.0, 60.0, 150.0, 400.0)  # metres; below the first is inside the goal radius
ANGLE_BANDS = 8
NEIGHBOUR = re.compile(r"^- [\w-]+: (\S+) along .*?, heading (\d+)°", re.M)


def walk_tasks(tasks: list[Task], prefix: str) -> list[Task]:
    """The walks of plain navigation tasks (one destination, no waypoint), as web-free tasks."""
    out = []
    for task in tasks:
        if len(task.embodied_goals) == 1 and isinstance(task.embodied_goals[0], ReachedPlace):
            out.append(embodied_only(task, f"{prefix}-{task.id}"))
    return out


def last_moves(task: Task, k: int) -> Task:
    """The curriculum: the same walk started ``k`` moves before its end along the oracle's route (a train-split
    walk still; its destination and grader unchanged). k at or past the route's length is the whole walk."""
    moves = [c for c in task.oracle if c.tool == "street_move"]
    if k >= len(moves):
        return task
    assert isinstance(task.start.embodied, StreetStart)
    start = task.start.embodied.model_copy(update={"node": str(moves[-k - 1].args["neighbour"])})
    return task.model_copy(update={"id": f"{task.id}-last{k}", "start": task.start.model_copy(update={"embodied": start}),
                                   "oracle": moves[-k:] + [c for c in task.oracle if c.tool != "street_move"],
                                   "step_limit": max(30, 4 * k + 10)})


def band(distance: float) -> int:
    return sum(distance >= edge for edge in DISTANCE_BANDS)


def angle_band(heading: float, bearing: float) -> int:
    diff = abs((heading - bearing + 180.0) % 360.0 - 180.0)
    return min(ANGLE_BANDS - 1, int(diff // (180.0 / ANGLE_BANDS)))


class TabularPolicy:
    def __init__(self, rng: np.random.Generator):
        # Moving is judged by its angle alone, the same at every distance, so what the short walks of the
        # curriculum teach carries over to long ones; stopping is judged by the distance.
        self.move = np.zeros(ANGLE_BANDS)
        self.stop = np.zeros(len(DISTANCE_BANDS) + 1)
        self.rng = rng

    def choose(self, d: int, angles: list[int], greedy: bool = False) -> tuple[int, np.ndarray]:
        """Index of the choice (len(angles) = stop) and the softmax over the choices."""
        logits = np.array([self.move[a] for a in angles] + [self.stop[d]])
        p = np.exp(logits - logits.max())
        p /= p.sum()
        return (int(p.argmax()) if greedy else int(self.rng.choice(len(p), p=p))), p


def play(env: Any, task: Task, policy: TabularPolicy, greedy: bool = False) -> tuple[float, list[Any]]:
    """One episode through the gym; returns the total reward and the (band, angles, choice, probs) of each step."""
    world = get_world()
    goal = task.embodied_goals[0]
    assert isinstance(goal, ReachedPlace) and isinstance(task.start.embodied, StreetStart)
    node = task.start.embodied.node
    obs, _ = env.reset(options={"task_id": task.id})
    total, trace = 0.0, []
    while True:
        here = world.node(node)
        d = band(haversine_m(here.lat, here.lng, goal.lat, goal.lng))
        bearing = bearing_deg(here.lat, here.lng, goal.lat, goal.lng)
        moves = [(m.group(1), float(m.group(2))) for m in NEIGHBOUR.finditer(obs)]
        angles = [angle_band(h, bearing) for _, h in moves]
        choice, p = policy.choose(d, angles, greedy)
        trace.append((d, angles, choice, p))
        if choice == len(moves):
            obs, reward, terminated, truncated, _ = env.step({"tool": "street_stop", "arguments": {}})
            total += reward
            if not (terminated or truncated):
                obs, reward, terminated, truncated, _ = env.step({"tool": "finish_episode", "arguments": {}})
                total += reward
        else:
            node = moves[choice][0]
            obs, reward, terminated, truncated, _ = env.step({"tool": "street_move",
                                                              "arguments": {"neighbour": node}})
            total += reward
        if terminated or truncated:
            return total, trace


def reinforce(policy: TabularPolicy, trace: list[Any], advantage: float, lr: float) -> None:
    for d, angles, choice, p in trace:
        grad = -p
        grad[choice] += 1.0  # d log softmax / d logits
        for k, a in enumerate(angles):
            policy.move[a] += lr * advantage * grad[k]
        policy.stop[d] += lr * advantage * grad[-1]


def evaluate(env: Any, tasks: list[Task], policy: TabularPolicy) -> float:
    return sum(play(env, t, policy, greedy=False)[0] >= 1.0 for t in tasks) / len(tasks)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--episodes", type=int, default=1000, help="training episodes")
    ap.add_argument("--eval-every", type=int, default=100, help="evaluate on the held-out tasks every N episodes")
    ap.add_argument("--eval-tasks", type=int, default=40, help="held-out tasks (public test split) per evaluation")
    ap.add_argument("--split-seed", type=int, default=0, help="seed of the train split")
    ap.add_argument("--cities", nargs="*", default=["boston", "pittsburgh"], help="cities to draw tasks from")
    ap.add_argument("--lr", type=float, default=0.5)
    ap.add_argument("--seed", type=int, default=0, help="seed of the policy's sampling")
    ap.add_argument("--run-dir", default=None, help="where the episodes are recorded (default: a temp dir)")
    ap.add_argument("--plot", default="docs/learning_curve.png", help="the learning curve (matplotlib)")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--json", metavar="FILE", help="also write the curve as JSON")
    args = ap.parse_args(argv)

    started = time.monotonic()
    train = walk_tasks(generate_split("navigation", "train", args.split_seed, cities=args.cities), "walk")
    held_out = walk_tasks([t for t in public_test_tasks("navigation")
                           if t.start.embodied is not None and getattr(t.start.embodied, "city", None) in args.cities],
                          "walk")
    held_out = random.Random(0).sample(held_out, min(args.eval_tasks, len(held_out)))
    print(f"{len(train)} train walks (train split, seed {args.split_seed}), {len(held_out)} held-out walks "
          f"(public test split), {time.monotonic() - started:.0f} s to draw them", file=sys.stderr)
    import tempfile

    run_dir = args.run_dir or tempfile.mkdtemp(prefix="ewa-learn-")
    longest = max(sum(c.tool == "street_move" for c in t.oracle) for t in train)
    stages = {(t.id, k): last_moves(t, k) for t in train for k in range(1, longest + 1)}
    env = gymnasium.make("ewa_mcp/navigation-v0", extra_tasks=[*{v.id: v for v in stages.values()}.values(), *held_out],
                         tasks=["walk-*"], run_dir=run_dir)
    policy = TabularPolicy(np.random.default_rng(args.seed))
    rng = random.Random(args.seed)
    curve: list[dict[str, float]] = []
    baseline, recent = 0.0, []
    t0 = time.monotonic()
    try:
        for episode in range(args.episodes + 1):
            if episode % args.eval_every == 0:
                rate = evaluate(env, held_out, policy)
                train_rate = sum(recent[-args.eval_every:]) / max(1, len(recent[-args.eval_every:]))
                curve.append({"episodes": episode, "held_out_success": rate, "train_success": train_rate,
                              "seconds": round(time.monotonic() - t0, 1)})
                print(f"episode {episode:5d}  held-out success {rate:.2f}  train success {train_rate:.2f}  "
                      f"{time.monotonic() - t0:6.1f} s", flush=True)
            if episode == args.episodes:
                break
            # The curriculum: walks end k moves from their start, k growing to whole walks by 60 % of training.
            reach = 1 + int(longest * episode / max(1, 0.6 * args.episodes))
            task = stages[(rng.choice(train).id, rng.randint(1, min(reach, longest)))]
            reward, trace = play(env, task, policy)
            recent.append(reward)
            reinforce(policy, trace, reward - baseline, args.lr)
            baseline += 0.05 * (reward - baseline)
    finally:
        env.close()
    if args.json:
        Path(args.json).write_text(json.dumps({"curve": curve, "move": policy.move.tolist(),
                                               "stop": policy.stop.tolist()}, indent=1) + "\n", encoding="utf-8")
    if not args.no_plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot([c["episodes"] for c in curve], [c["held_out_success"] for c in curve], marker="o",
                label="held-out (public test split)")
        ax.plot([c["episodes"] for c in curve][1:], [c["train_success"] for c in curve][1:], ls="--",
                label="training episodes (train split)")
        ax.set_xlabel("training episodes")
        ax.set_ylabel("success rate (grader)")
        ax.set_ylim(-0.02, 1.02)
        ax.set_title(f"Tabular policy over street moves ({curve[-1]['seconds']:.0f} s on the CPU)")
        ax.legend(loc="lower right")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"wrote {args.plot}", file=sys.stderr)
    return 0 if math.isfinite(curve[-1]["held_out_success"]) else 1


if __name__ == "__main__":
    sys.exit(main())
