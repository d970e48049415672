"""Writes the example replays from the committed tasks: one per domain, each a readable JSONL of tool
calls with a documented outcome (some succeed, some fail on purpose so the grader's verdicts show).

    .venv/bin/python examples/replays/make_replays.py   # rewrites examples/replays/*.jsonl
"""

from __future__ import annotations

import json
from pathlib import Path

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore

HERE = Path(__file__).resolve().parent


def lines(task_id: str, calls: list[tuple[str, dict]]) -> str:
    return "".join(json.dumps({"task_id": task_id, "tool": tool, "args": args}) + "\n" for tool, args in calls)


def oracle(task) -> list[tuple[str, dict]]:
    return [(c.tool, dict(c.args)) for c in task.oracle]


def main() -> None:
    store = TaskStore([tasks_dir()])
    first = {d: sorted(store.all(d), key=lambda t: t.id)[0] for d in
             ["cooking", "navigation", "shopping", "traveling", "geolocation"]}
    replays: dict[str, str] = {}
    # cooking: the perfect run
    replays["cooking"] = lines(first["cooking"].id, oracle(first["cooking"]))
    # navigation: directions right, but the walk stops four panoramas short of the destination
    nav = oracle(first["navigation"])
    moves = [i for i, (tool, _) in enumerate(nav) if tool == "street_move"]
    replays["navigation"] = lines(first["navigation"].id, nav[: moves[-4]] + nav[moves[-1] + 1:])
    # shopping: the perfect run
    replays["shopping"] = lines(first["shopping"].id, oracle(first["shopping"]))
    # traveling: walked and looked it up, then answered wrongly
    trav = oracle(first["traveling"])
    trav[-1] = ("finish_episode", {"answer": "I could not find it"})
    replays["traveling"] = lines(first["traveling"].id, trav)
    # geolocation: right country, wrong city (and coordinates ~390 km off)
    geo = oracle(first["geolocation"])
    tool, args = geo[-1]
    geo[-1] = (tool, {**args, "city": "Lyon", "lat": 45.7640, "lng": 4.8357, "street": "Rue de la République"})
    replays["geolocation"] = lines(first["geolocation"].id, geo)
    for domain, text in replays.items():
        (HERE / f"{domain}.jsonl").write_text(text, encoding="utf-8")
        print(f"wrote {domain}.jsonl ({text.count(chr(10))} calls)")


if __name__ == "__main__":
    main()
