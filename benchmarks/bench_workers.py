"""Episodes per minute with 1 and with N worker processes (`ewa-mcp eval --workers`), oracle agent, graded.

    .venv/bin/python benchmarks/bench_workers.py [--sample 20] [--workers 2] [--concurrency 1] [--rounds 1]

Both sides go through the same worker-process driver (evaluation/workers.py), so each pays for its
processes' start (Python, the MCP SDK, Chromium, the sites) inside its wall time. Rounds alternate the order
(1, N, N, 1, ...) so a change in the machine's other load does not favour one side. Prints JSON: per run the
wall time, episodes/min, accuracy, the 1-minute load average before and after, and the CPU the run's
processes used (cores used; CPU seconds per episode); then the ratio of the summed rates. Target (issue 18): 2 workers >= 1.7x one worker on a 2-core machine. Each run also prints
the whole suite's minutes at its pace (its wall time scaled by the suite's episode time per domain over the
sample's; target: <= 7 with 2 workers).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import tempfile
import time
from pathlib import Path

from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.runner import select_tasks
from ewa_mcp.evaluation.workers import play_in_processes
from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore


def cpu_seconds() -> float:
    own, reaped = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + reaped.ru_utime + reaped.ru_stime


def suite_minutes(summary, seconds: float, suite: dict[str, int]) -> float:
    """The whole suite's wall time at this run's pace: the run's wall time scaled by how much more episode time
    the suite holds, domain by domain (a sample has 20 of each domain; the suite is half cooking)."""
    busy: dict[str, list[float]] = {}
    for o in summary.outcomes:
        busy.setdefault(o.domain, []).append(o.seconds)
    sample_work = sum(sum(v) for v in busy.values())
    suite_work = sum(suite[d] * sum(v) / len(v) for d, v in busy.items())
    return seconds * suite_work / sample_work / 60


def one(tasks, workers: int, concurrency: int, suite: dict[str, int]) -> dict:
    run_dir = Path(tempfile.mkdtemp(prefix=f"ewa-bench-workers{workers}-"))
    load_before = os.getloadavg()[0]
    cpu_before = cpu_seconds()
    t0 = time.monotonic()
    summary = play_in_processes(tasks, OracleAgent(), workers=workers, concurrency=concurrency, run_dir=run_dir,
                                task_dirs=[tasks_dir()], progress=False)
    seconds = time.monotonic() - t0
    cpu = cpu_seconds() - cpu_before
    load_after = os.getloadavg()[0]
    report = grade_run(run_dir)
    solved = sum(bool(e.overall_success) for e in report.episodes)
    shutil.rmtree(run_dir, ignore_errors=True)
    return {"workers": workers, "concurrency": concurrency, "episodes": len(report.episodes),
            "could_not_play": sum(o.failure is not None for o in summary.outcomes),
            "solved": solved, "seconds": round(seconds, 1),
            "episodes_per_minute": round(len(tasks) / seconds * 60, 1),
            "whole_suite_minutes_at_this_pace": round(suite_minutes(summary, seconds, suite), 1),
            # CPU of the driver, the workers and what they reaped (Playwright's node, Chromium): how many cores
            # the run got, and what one episode costs whatever else runs on the machine.
            "cores_used": round(cpu / seconds, 2), "cpu_seconds_per_episode": round(cpu / len(tasks), 3),
            "load_average_1min": [round(load_before, 2), round(load_after, 2)]}


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--sample", type=int, default=20, help="tasks per domain (default 20)")
    p.add_argument("--domain", action="append", help="restrict to a domain (repeatable)")
    p.add_argument("--workers", type=int, default=2, help="the N compared with 1 (default 2)")
    p.add_argument("--concurrency", type=int, default=1, help="episodes at once in each worker")
    p.add_argument("--rounds", type=int, default=1, help="pairs of runs, order alternating")
    args = p.parse_args()
    store = TaskStore([tasks_dir()])
    tasks = [t for t in select_tasks(store, None, args.sample, args.domain) if t.domain != "demo"]
    suite = {d: len(store.all(d)) for d in {t.domain for t in tasks}}
    runs = []
    for r in range(args.rounds):
        order = (1, args.workers) if r % 2 == 0 else (args.workers, 1)
        for n in order:
            runs.append(one(tasks, n, args.concurrency, suite))
            print(json.dumps(runs[-1]), flush=True)
    rate = {n: sum(x["episodes_per_minute"] for x in runs if x["workers"] == n) / args.rounds
            for n in (1, args.workers)}
    print(json.dumps({"benchmark": "eval worker processes", "tasks": len(tasks), "cpus": os.cpu_count(),
                      "episodes_per_minute": {str(n): round(v, 1) for n, v in rate.items()},
                      f"ratio_{args.workers}_to_1": round(rate[args.workers] / rate[1], 2),
                      "runs": runs}, indent=2))


if __name__ == "__main__":
    main()
