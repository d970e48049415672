"""The oracle through the Gymnasium interface with the dense reward, in any observation mode: does every task
end in success, and do its step rewards sum to its final completion (the dense-reward identity)?

    .venv/bin/python benchmarks/bench_dense_identity.py [--domain cooking ...] [--sample N] [--observation vision]

Without --sample every task of the domains is played (the whole suite: an hour or more on 2 cores with vision
frames). --sample N plays N tasks per domain spread over its id order. Prints JSON per domain: tasks played, oracle
successes, identity holds (|sum of rewards - completion| <= 1e-9), the first violations, seconds, and the load
average (the machine may be shared).
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

import gymnasium

import ewa_mcp.gym  # noqa: F401  (registers the environments)
from ewa_mcp.graders import grade_episode

DOMAINS = ("cooking", "navigation", "shopping", "traveling", "geolocation")


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--domain", action="append", choices=DOMAINS)
    p.add_argument("--sample", type=int, default=None, help="tasks per domain, spread over its id order")
    p.add_argument("--observation", choices=("text", "vision", "both"), default="text")
    args = p.parse_args()
    run_dir = Path(tempfile.mkdtemp(prefix="ewa-dense-"))
    out: dict[str, object] = {"benchmark": "oracle with the dense reward", "observation": args.observation,
                              "run_dir": str(run_dir), "by_domain": {}}
    for domain in args.domain or DOMAINS:
        env = gymnasium.make(f"ewa_mcp/{domain}-v0", run_dir=run_dir, reward="dense", observation=args.observation)
        u = env.unwrapped
        ids = list(u.task_ids)
        if args.sample is not None and args.sample < len(ids):
            ids = [ids[k * len(ids) // args.sample] for k in range(args.sample)]
        successes = holds = 0
        violations: list[dict[str, object]] = []
        t0 = time.monotonic()
        try:
            for task_id in ids:
                env.reset(options={"task_id": task_id})
                rewards = []
                for step in u._runtime.episodes.tasks.get(task_id).oracle:
                    _, reward, terminated, truncated, _ = env.step({"tool": step.tool, "arguments": dict(step.args)})
                    rewards.append(reward)
                    if terminated or truncated:
                        break
                final = grade_episode(u.run_dir / u.episode_id)
                successes += bool(final.overall_success)
                if abs(sum(rewards) - final.completion) <= 1e-9:
                    holds += 1
                elif len(violations) < 10:
                    violations.append({"task": task_id, "sum": sum(rewards), "completion": final.completion})
        finally:
            env.close()
        seconds = time.monotonic() - t0
        out["by_domain"][domain] = {  # type: ignore[index]
            "tasks": len(ids), "oracle_success": successes, "identity_holds": holds,
            "violations": violations, "seconds": round(seconds, 1)}
    out["load_average"] = [round(v, 2) for v in os.getloadavg()]
    out["cpus"] = os.cpu_count()
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
