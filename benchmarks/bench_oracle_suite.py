"""The whole task suite played by the oracle through the real MCP server, then graded.

    .venv/bin/python benchmarks/bench_oracle_suite.py [--workers 2] [--concurrency 1] [--transport inprocess]
                                                      [--sample N]

Prints JSON: wall time, episodes per minute, and per-domain overall accuracy (acceptance: 100 %).
--workers N runs N processes, each with its own server, browser and sites (evaluation/workers.py), each
playing --concurrency episodes at once; --workers 1 plays in this process.
Target on the 2-core machine with --workers 2: the whole suite in <= 7 minutes (issue 18).
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path

from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.runner import play, select_tasks
from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--concurrency", type=int, default=1)
    p.add_argument("--transport", default="inprocess")
    p.add_argument("--sample", type=int, default=None)
    p.add_argument("--run-dir", default=None)
    args = p.parse_args()
    store = TaskStore([tasks_dir()])
    tasks = [t for t in select_tasks(store, None, args.sample) if t.domain != "demo"]
    run_dir = Path(args.run_dir or tempfile.mkdtemp(prefix="ewa-oracle-suite-"))
    t0 = time.monotonic()
    summary = play(tasks, OracleAgent(), transport=args.transport, workers=args.workers,
                   concurrency=args.concurrency, run_dir=run_dir, task_dirs=[tasks_dir()], progress=True)
    played = time.monotonic() - t0
    t1 = time.monotonic()
    report = grade_run(run_dir)
    graded = time.monotonic() - t1
    by_domain: dict[str, dict[str, int]] = {}
    for e in report.episodes:
        d = by_domain.setdefault(e.domain, {"episodes": 0, "overall_success": 0, "episode_seconds": 0.0})
        d["episodes"] += 1
        d["overall_success"] += bool(e.overall_success)
        d["episode_seconds"] += e.wall_time_s or 0.0
    failures = [{"task": e.task_id, "problems": e.problems[:2],
                 "unmet": [c.description for c in e.conditions if c.met is False][:3]}
                for e in report.episodes if not e.overall_success]
    print(json.dumps({
        "benchmark": "oracle over the task suite",
        "tasks": len(tasks), "workers": args.workers, "concurrency": args.concurrency,
        "transport": args.transport, "load_average_1min": round(os.getloadavg()[0], 2),
        "play_seconds": round(played, 1), "grade_seconds": round(graded, 1),
        "episodes_per_minute": round(len(tasks) / played * 60, 1),
        "could_not_play": [o.task_id for o in summary.outcomes if o.failure][:20],
        # mean_episode_seconds: one episode's own wall time, with the other workers' episodes beside it.
        "by_domain": {d: {"episodes": v["episodes"], "overall_success": v["overall_success"],
                          "accuracy": round(v["overall_success"] / v["episodes"], 4),
                          "mean_episode_seconds": round(v["episode_seconds"] / v["episodes"], 3)}
                      for d, v in sorted(by_domain.items())},
        "by_difficulty": {d: {level: {"episodes": agg.n, "overall_success": agg.overall_accuracy.successes,
                                      "accuracy": agg.overall_accuracy.value}
                              for level, agg in levels.items()}
                          for d, levels in sorted(report.by_difficulty.items())},
        "failures": failures[:20],
        "target": {"minutes": 7, "met": played <= 420},
        "run_dir": str(run_dir),
    }, indent=2))


if __name__ == "__main__":
    main()
