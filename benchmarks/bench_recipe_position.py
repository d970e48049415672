"""Where the cooking target stands in what the site lists (docs/verified.md, "A guess between two"): over
every cooking task, the share whose target is the first recipe listed for what the intent names (the dish's
name, or the word it asks by). That share is the ceiling of an agent that opens the first listed recipe and
cooks it without reading a constraint (`first-recipe`); it reads the task files only, no episode is played.

    .venv/bin/python benchmarks/bench_recipe_position.py                  # tasks/
    .venv/bin/python benchmarks/bench_recipe_position.py --tasks-dir /tmp/tasks-before
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ewa_mcp.core.taskmodel import TaskStore  # noqa: E402
from ewa_mcp.evaluation.heuristics.agents import listed_recipes  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tasks-dir", default=str(ROOT / "tasks"))
    args = parser.parse_args()
    store = TaskStore([Path(args.tasks_dir) / "cooking"])
    tasks = [t for t in store.all() if t.domain == "cooking"]
    total: Counter[str] = Counter()
    first: Counter[str] = Counter()
    alone: Counter[str] = Counter()
    by_word: Counter[str] = Counter()
    for task in tasks:
        listed = listed_recipes(task.intent)
        total[task.difficulty] += 1
        first[task.difficulty] += bool(listed) and listed[0]["id"] == task.metadata["recipe_id"]
        alone[task.difficulty] += len(listed) == 1
        by_word[task.difficulty] += bool(task.metadata.get("name_word") or task.metadata.get("ingredient"))
    print("difficulty  tasks  by a word or ingredient  target listed first  only one recipe listed")
    for difficulty in ("easy", "medium", "hard", "all"):
        n = sum(total.values()) if difficulty == "all" else total[difficulty]
        f = sum(first.values()) if difficulty == "all" else first[difficulty]
        a = sum(alone.values()) if difficulty == "all" else alone[difficulty]
        w = sum(by_word.values()) if difficulty == "all" else by_word[difficulty]
        if n:
            print(f"{difficulty:<10} {n:>6} {w:>25} {f:>10} ({100 * f / n:4.1f} %) {a:>12} ({100 * a / n:4.1f} %)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
