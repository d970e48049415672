"""The heuristic-agent audit (docs/verified.md): each heuristic agent plays a deterministic sample of every
domain and difficulty through the real MCP server; the run is graded and one table printed per agent.

    .venv/bin/python benchmarks/bench_heuristics.py                    # 2 tasks per domain x difficulty
    .venv/bin/python benchmarks/bench_heuristics.py --sample 5 --agent prior --agent geo-lexical

Columns: overall / completion (%) per domain and difficulty, and for geolocation the accuracy per level
beside the best constant guess (the most frequent value of that level among the sampled tasks' answers).
The issue's bar: every heuristic <= 10 % overall everywhere; geolocation no more than 10 points above the
constant guess at any level. Numbers printed here are measurements, not assertions.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ewa_mcp.evaluation.heuristics import NAMES, heuristic_agent  # noqa: E402
from ewa_mcp.evaluation.runner import play, select_tasks  # noqa: E402
from ewa_mcp.graders import grade_run  # noqa: E402
from ewa_mcp.core.taskmodel import Task, TaskStore  # noqa: E402
from ewa_mcp.envs.geo.goals import GeoAnswer

LEVELS = ("continent", "country", "city", "street")
DIFFICULTIES = ("easy", "medium", "hard")


def sample_tasks(store: TaskStore, per_cell: int, domains: list[str] | None,
                 difficulties: list[str] | None = None) -> list[Task]:
    """``per_cell`` tasks of each domain and difficulty, evenly spaced over the sorted ids (as --sample)."""
    tasks: list[Task] = []
    for difficulty in difficulties or DIFFICULTIES:
        try:
            tasks += select_tasks(store, None, per_cell, domains, [difficulty])
        except ValueError:
            continue
    return [t for t in tasks if t.domain != "demo"]


def constant_guess(suite: list[Task], tasks: list[Task]) -> dict[str, float]:
    """Per level, the share of the sampled geolocation tasks that the suite's most frequent value answers."""
    answers = [t.answer for t in tasks if isinstance(t.answer, GeoAnswer)]
    everything = [t.answer for t in suite if isinstance(t.answer, GeoAnswer)]
    if not answers:
        return {}
    modal = {level: Counter(getattr(a, level) for a in everything).most_common(1)[0][0] for level in LEVELS}
    return {level: sum(getattr(a, level) == modal[level] for a in answers) / len(answers) for level in LEVELS}


def table(agent: str, run_dir: Path, tasks: list[Task], suite: list[Task]) -> str:
    report = grade_run(run_dir)
    cells: dict[tuple[str, str], list[tuple[bool, float]]] = {}
    geo: dict[str, list[bool]] = {level: [] for level in LEVELS}
    geo_city: dict[str, list[bool]] = {}  # per difficulty: the hard split must not be easier than the rest
    answers: dict[str, list[bool]] = {}
    for ep in report.episodes:
        cells.setdefault((ep.domain, ep.difficulty or "-"), []).append(
            (ep.overall_success is True, ep.completion or 0.0))
        if ep.answer_checked and ep.domain != "geolocation":
            answers.setdefault(ep.domain, []).append(ep.answer_correct is True)
        if ep.geolocation:
            for level in LEVELS:
                geo[level].append(ep.geolocation.get(level) is True)
            geo_city.setdefault(ep.difficulty or "-", []).append(ep.geolocation.get("city") is True)
    lines = [f"## {agent}", "", "| domain | difficulty | n | overall % | completion % |", "|---|---|---|---|---|"]
    for (domain, difficulty), rows in sorted(cells.items(), key=lambda kv: (kv[0][0], DIFFICULTIES.index(kv[0][1])
                                                                            if kv[0][1] in DIFFICULTIES else 9)):
        overall = 100 * sum(r[0] for r in rows) / len(rows)
        completion = 100 * sum(r[1] for r in rows) / len(rows)
        lines.append(f"| {domain} | {difficulty} | {len(rows)} | {overall:.0f} | {completion:.0f} |")
    if answers:
        lines += ["", "answer accuracy: " + ", ".join(
            f"{d} {100 * sum(v) / len(v):.0f} % (n={len(v)})" for d, v in sorted(answers.items()))]
    if geo["continent"]:
        constant = constant_guess(suite, [t for t in tasks if t.domain == "geolocation"])
        lines += ["", "| geolocation level | agent % | best constant % | margin (points) |", "|---|---|---|---|"]
        for level in LEVELS:
            got = 100 * sum(geo[level]) / len(geo[level])
            base = 100 * constant.get(level, 0.0)
            lines.append(f"| {level} | {got:.0f} | {base:.0f} | {got - base:+.0f} |")
        lines += ["", "| geolocation difficulty | n | city % | best constant city % | margin (points) |",
                  "|---|---|---|---|---|"]
        for difficulty in sorted(geo_city, key=lambda d: DIFFICULTIES.index(d) if d in DIFFICULTIES else 9):
            rows = geo_city[difficulty]
            got = 100 * sum(rows) / len(rows)
            base = 100 * constant_guess(suite, [t for t in tasks if t.domain == "geolocation"
                                                and t.difficulty == difficulty]).get("city", 0.0)
            lines.append(f"| {difficulty} | {len(rows)} | {got:.0f} | {base:.0f} | {got - base:+.0f} |")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--agent", action="append", choices=NAMES, help="an agent (repeatable; default: all)")
    parser.add_argument("--sample", type=int, default=2, help="tasks per domain and difficulty (default 2)")
    parser.add_argument("--domain", action="append", help="restrict to a domain (repeatable)")
    parser.add_argument("--difficulty", action="append", choices=DIFFICULTIES,
                        help="restrict to a difficulty (repeatable)")
    parser.add_argument("--tasks-dir", default=str(ROOT / "tasks"))
    args = parser.parse_args()
    task_dirs = [Path(args.tasks_dir)]
    store = TaskStore(task_dirs)
    tasks = sample_tasks(store, args.sample, args.domain, args.difficulty)
    print(f"{len(tasks)} tasks: {dict(Counter((t.domain, t.difficulty) for t in tasks))}\n")
    for name in args.agent or NAMES:
        with tempfile.TemporaryDirectory(prefix=f"heuristic-{name}-") as tmp:
            started = time.monotonic()
            play(tasks, heuristic_agent(name), run_dir=Path(tmp), task_dirs=task_dirs, progress=False)
            print(table(name, Path(tmp), tasks, store.all()))
            print(f"\n({time.monotonic() - started:.0f} s)\n", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
