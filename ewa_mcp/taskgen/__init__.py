"""Deterministic task-suite generation (``ewa-mcp tasks generate``).

Each domain names its generator in the registry (ewa_mcp/core/registry.py): ``Domain.generator``, a function
``generate() -> list[Task]`` (seeded, validated: a task whose goals cannot be reached is not returned, with
an oracle solution made of real tool calls), whose tasks this module writes under ``tasks/<domain>/`` in
chunks, replacing what was there; or ``Domain.writer``, a function ``(out_dir) -> int`` that writes its own
files (geolocation keeps one file per setting).
"""

from __future__ import annotations

import json
from pathlib import Path

from ..core import registry
from ewa_mcp.core.taskmodel import Task

CHUNK = 100


def generated_domains() -> list[str]:
    """The domains that have a generator, in the registry's order."""
    return [d.name for d in registry.domains() if d.generator or d.writer]


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


def generate_domain(out_dir: Path, domain: str) -> int:
    declared = registry.domain(domain)
    if declared is None or not (declared.generator or declared.writer):
        raise ValueError(f"unknown domain {domain!r}; choose from {sorted(generated_domains())}")
    if declared.writer:
        return int(registry.load_object(declared.writer)(out_dir / domain))
    assert declared.generator is not None
    tasks = registry.load_object(declared.generator)()
    ids = [t.id for t in tasks]
    if len(ids) != len(set(ids)):
        raise ValueError(f"{domain}: the generator produced duplicate task ids")
    wrong = sorted({t.domain for t in tasks} - {domain})
    if wrong:
        raise ValueError(f"{domain}: the generator produced tasks of another domain ({', '.join(wrong)})")
    return write_tasks(out_dir, domain, tasks)


def generate_all(out_dir: Path, domains: list[str] | None = None) -> dict[str, int]:
    return {domain: generate_domain(out_dir, domain) for domain in domains or generated_domains()}
