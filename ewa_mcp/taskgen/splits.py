"""Fresh, seeded task splits (docs/training.md, "Splits").

The public suite under ``tasks/`` is the **test** split. Two more splits are drawn by the same generators:

- **train**, ``generate_split(domain, "train", seed)``: as many seeds as a trainer wants, so an endless stream
  (``stream``);
- **hidden**, ``generate_split(domain, "hidden", seed)``: a private test split for a contamination-free
  leaderboard. Whoever holds the seed regenerates exactly the same tasks; nobody else can.

A split's tasks are the generator's own, drawn with a different random stream (``SPLIT_SALT`` in common.py), so
they are validated and carry an oracle like the public ones. Then two filters make the splits disjoint:

- no task shares an *instance* with a public test task: the same kitchen, recipe and missing ingredients
  (cooking), or the same city, start and goal walk (navigation);
- every instance belongs to one of train and hidden only, by a hash of the instance: a train seed can never
  draw a hidden-split task, whatever the two seeds are.

Geolocation has no split other than test: every location in the world data is already a public test task,
and new locations are made by hand (ewa_mcp/envs/geo/locations.py). A request for one says so.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

from ..core import registry
from ..core.paths import INSTALLED_TASKS, REPO_ROOT
from ..core.taskmodel import Task, TaskStore
from .common import SPLIT_SALT

SPLITS = ("test", "train", "hidden")
# Out of 100 hash buckets of an instance, those below this one are train, the rest hidden.
TRAIN_BUCKETS = 80


def _navigation_key(task: Task) -> tuple[Any, ...]:
    start = task.start.embodied
    goals = tuple((g.kind, getattr(g, "node", None)) for g in task.embodied_goals)
    return ("navigation", getattr(start, "city", None), getattr(start, "node", None), goals)


def _cooking_key(task: Task) -> tuple[Any, ...]:
    buy = task.metadata.get("buy")
    missing = tuple(sorted([buy] if isinstance(buy, str) else buy or []))
    second = task.metadata.get("second_recipe_id")  # the two-dish form of cooking hard: both recipes
    return ("cooking", task.metadata.get("scene"), task.metadata.get("recipe_id"), missing, *([second] if second else []))


# What makes two tasks the same instance, per domain that has fresh splits.
INSTANCE_KEYS: dict[str, Callable[[Task], tuple[Any, ...]]] = {
    "navigation": _navigation_key,
    "cooking": _cooking_key,
}


def split_domains() -> list[str]:
    return sorted(INSTANCE_KEYS)


def instance_key(task: Task) -> tuple[Any, ...]:
    if task.domain not in INSTANCE_KEYS:
        raise ValueError(f"{task.domain} tasks have no instance key; splits exist for {split_domains()}")
    return INSTANCE_KEYS[task.domain](task)


def split_of_instance(key: tuple[Any, ...]) -> str:
    """train or hidden: fixed by the instance alone, so no two seeds of the two splits ever meet."""
    bucket = int.from_bytes(hashlib.sha256(repr(key).encode()).digest()[:4], "big") % 100
    return "train" if bucket < TRAIN_BUCKETS else "hidden"


def public_test_tasks(domain: str, roots: list[Path] | None = None) -> list[Task]:
    """The public test split of a domain: the suite shipped under tasks/."""
    # The shipped suite, never EWA_TASKS_DIR: that may well point at a generated train split.
    store = TaskStore(roots or [INSTALLED_TASKS if INSTALLED_TASKS.is_dir() else REPO_ROOT / "tasks"])
    return [t for t in store.all() if t.domain == domain]


def _check(domain: str, split: str, seed: int) -> None:
    if split not in SPLITS:
        raise ValueError(f"unknown split {split!r}; choose from {', '.join(SPLITS)}")
    if split != "test" and domain not in INSTANCE_KEYS:
        why = (" (every location is already a public test task)" if domain == "geolocation" else "")
        raise ValueError(f"the {split} split exists for {', '.join(split_domains())} only, not {domain}{why}; "
                         "pass --domain with one of those")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ValueError(f"seed must be a non-negative integer, not {seed!r}")


def split_task_id(task_id: str, domain: str, split: str, seed: int) -> str:
    """navigation-boston-000 -> navigation-train7-boston-000: the split and seed are in the id."""
    return f"{domain}-{split}{seed}-{task_id[len(domain) + 1:]}" if task_id.startswith(f"{domain}-") else \
        f"{domain}-{split}{seed}-{task_id}"


def generate_split(domain: str, split: str = "train", seed: int = 0, *, test_tasks: list[Task] | None = None,
                   **generator_args: Any) -> list[Task]:
    """The tasks of ``domain`` in ``split`` drawn with ``seed``. For ``test`` that is the public suite's
    generator unchanged (seed 0 only). ``test_tasks`` (default: the shipped suite) are the instances to avoid;
    ``generator_args`` go to the generator (navigation takes ``cities``)."""
    _check(domain, split, seed)
    declared = registry.domain(domain)
    if declared is None or declared.generator is None:
        raise ValueError(f"unknown domain {domain!r}; choose from {split_domains()}")
    generator = registry.load_object(declared.generator)
    if split == "test":
        if seed:
            raise ValueError("the test split is the public suite and has no seed; use --split hidden --seed N "
                             "for a private test split")
        return list(generator(**generator_args))
    token = SPLIT_SALT.set(f"{split}:{seed}")
    try:
        drawn = list(generator(**generator_args))
    finally:
        SPLIT_SALT.reset(token)
    taken = {instance_key(t) for t in (public_test_tasks(domain) if test_tasks is None else test_tasks)}
    kept: list[Task] = []
    for task in drawn:
        key = instance_key(task)
        if key in taken or split_of_instance(key) != split:
            continue
        taken.add(key)
        kept.append(task.model_copy(update={
            "id": split_task_id(task.id, domain, split, seed),
            "metadata": {**task.metadata, "split": split, "split_seed": seed}}))
    return kept


def stream(domain: str, split: str = "train", seed: int = 0, **generator_args: Any) -> Iterator[Task]:
    """An endless stream of fresh tasks: the split's seeds ``seed``, ``seed + 1``, ... with no instance twice."""
    _check(domain, split, seed)
    if split == "test":
        raise ValueError("the test split is finite (the public suite); stream the train split")
    test_tasks = public_test_tasks(domain)
    seen: set[tuple[Any, ...]] = set()
    while True:
        for task in generate_split(domain, split, seed, test_tasks=test_tasks, **generator_args):
            key = instance_key(task)
            if key not in seen:
                seen.add(key)
                yield task
        seed += 1


def write_split(out_dir: Path, split: str, seed: int, domains: list[str] | None = None) -> dict[str, int]:
    """Write a split's tasks under ``out_dir/<domain>/`` (as ``ewa-mcp tasks generate`` does) for ``domains``
    (default: every domain that has splits). Returns the count per domain."""
    from . import generate_all, write_tasks

    if split == "test":
        if seed:
            raise ValueError("the test split is the public suite and has no seed; use --split hidden --seed N "
                             "for a private test split")
        return generate_all(out_dir, domains)
    chosen = domains or split_domains()
    for domain in chosen:
        _check(domain, split, seed)
    return {domain: write_tasks(out_dir, domain, generate_split(domain, split, seed)) for domain in chosen}
