"""Deterministic task-suite generation (``ewa-mcp tasks generate``).

Each domain module exposes ``generate() -> list[Task]``: seeded, validated (a task whose goals
cannot be reached is not returned), with an oracle solution made of real tool calls. This
module writes them under ``tasks/<domain>/`` in chunks, replacing what was there.
"""

from __future__ import annotations

import importlib
import json
from pathlib import Path

from ..taskmodel import Task

GENERATORS: dict[str, str] = {
    "cooking": "ewa_mcp.taskgen.cooking:generate",
    "navigation": "ewa_mcp.taskgen.navigation:generate",
    "shopping": "ewa_mcp.taskgen.shopping:generate",
    "traveling": "ewa_mcp.taskgen.traveling:generate",
}
CHUNK = 100


def write_tasks(out_dir: Path, domain: str, tasks: list[Task]) -> int:
    folder = out_dir / domain
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob(f"{domain}-*.json"):
        old.unlink()
    tasks = sorted(tasks, key=lambda t: t.id)
    for i in range(0, len(tasks), CHUNK):
        chunk = [t.model_dump(mode="json", exclude_defaults=False) for t in tasks[i : i + CHUNK]]
        path = folder / f"{domain}-{i // CHUNK:03d}.json"
        path.write_text(json.dumps(chunk, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return len(tasks)


def generate_all(out_dir: Path, domains: list[str] | None = None) -> dict[str, int]:
    counts: dict[str, int] = {}
    wanted = domains or [*GENERATORS, "geolocation"]
    for domain in wanted:
        if domain == "geolocation":
            from ..geo.generate import generate_tasks

            counts[domain] = generate_tasks(out_dir / "geolocation")
            continue
        if domain not in GENERATORS:
            raise ValueError(f"unknown domain {domain!r}; choose from {sorted([*GENERATORS, 'geolocation'])}")
        module_name, _, attr = GENERATORS[domain].partition(":")
        tasks = getattr(importlib.import_module(module_name), attr)()
        ids = [t.id for t in tasks]
        if len(ids) != len(set(ids)):
            raise ValueError(f"{domain}: the generator produced duplicate task ids")
        counts[domain] = write_tasks(out_dir, domain, tasks)
    return counts
