"""Nothing in a task id, nor in the order of the task files, predicts the answer (issue 26, principle 3).

The agent sees its task id and list_tasks lists tasks in file order. Geolocation ids once ran continent by
continent (geo-0001 to geo-0040 in Europe), so the id told the continent. Here every family of the suite
(tasks sharing an id prefix) is read in id order, and for each answer key (continent, country, city; target
store, product, size; recipe; destination; the text answer) the share of tasks whose key equals the key of
the task 1 to 8 ids later must stay near the base rate (the chance two random tasks of the family agree):
a run of one continent or a round-robin of stores would stand far above it."""

from __future__ import annotations

import json
import math
import re
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

TASKS = Path(__file__).resolve().parents[2] / "tasks"
MAX_LAG = 8
# z-score of the agreement over the base rate; with about 300 (family, key, lag) comparisons a z of 4.5
# is out of reach by chance, and the geolocation ids of old stood at 24 (continent) and 47 (country).
MAX_Z = 4.5


def family(task_id: str) -> str:
    if task_id.startswith("geo-"):
        return "geo-" + task_id.rsplit("-", 1)[1]  # one family per setting
    return re.sub(r"-\d+$", "", task_id)


def answer_keys(task: dict[str, Any]) -> dict[str, Any]:
    keys: dict[str, Any] = {}
    answer = task.get("answer") or {}
    if answer.get("kind") == "geolocation":
        keys.update(continent=answer["continent"], country=answer["country"], city=answer["city"])
    elif answer.get("kind") == "text":
        keys["answer"] = tuple(answer.get("must_include") or ())
    for i, goal in enumerate(task.get("web_goals") or []):
        if goal["kind"] == "order_placed":
            keys.update({f"store{i}": goal.get("store_id"), f"product{i}": goal["product_id"],
                         f"size{i}": goal.get("size")})
        elif goal["kind"] == "orders_split":
            keys[f"pair{i}"] = tuple(goal["store_ids"])
        elif goal["kind"] == "recipe_completed":
            keys["recipe"] = goal["recipe_id"]
        elif goal["kind"] == "recipes_completed":  # two dishes (the pair), or the one the kitchen can make
            keys["recipe"] = tuple(sorted(goal["recipe_ids"]))
            keys["form"] = "two_dishes" if len(goal["recipe_ids"]) == 2 else "pantry"
        elif goal["kind"] == "page_visited":
            keys["page"] = goal["path_prefix"]
        elif goal["kind"] == "directions_shown":
            keys[f"destination{i}"] = goal["destination"]
    for i, goal in enumerate(task.get("embodied_goals") or []):
        if goal["kind"] == "reached_place":
            keys[f"place{i}"] = goal.get("place_id") or goal.get("node")
    return keys


def families() -> dict[str, list[dict[str, Any]]]:
    found: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for path in sorted(TASKS.glob("*/*.json")):
        raw = json.loads(path.read_text(encoding="utf-8"))
        for task in raw if isinstance(raw, list) else [raw]:
            found[family(task["id"])].append(task)
    return found


def worst_lag(values: list[Any]) -> tuple[int, float, float, float]:
    """(lag, agreement, base rate, z) of the lag whose agreement stands highest above the base rate."""
    n = len(values)
    base = sum((c / n) ** 2 for c in Counter(values).values())
    worst = (0, 0.0, base, -math.inf)
    for lag in range(1, min(MAX_LAG, n - 4) + 1):
        pairs = n - lag
        agree = sum(values[i] == values[i + lag] for i in range(pairs)) / pairs
        sd = math.sqrt(base * (1 - base) / pairs) or 1.0
        z = (agree - base) / sd
        if z > worst[3]:
            worst = (lag, agree, base, z)
    return worst


def leaks() -> list[str]:
    found = []
    for name, tasks in sorted(families().items()):
        tasks = sorted(tasks, key=lambda t: t["id"])
        keyed = [answer_keys(t) for t in tasks]
        for key in sorted(set().union(*keyed)):
            values = [k.get(key) for k in keyed]
            if len(values) < 12 or len(set(values)) < 2:
                continue
            lag, agree, base, z = worst_lag(values)
            if z > MAX_Z:
                found.append(f"{name} {key}: tasks {lag} id(s) apart agree {agree:.0%} (base rate {base:.0%}, z {z:.1f})")
    return found


def test_no_id_order_predicts_the_answer() -> None:
    assert families(), "no tasks found"
    assert leaks() == []


def test_the_check_catches_ids_in_continent_order() -> None:
    """The check itself: the geolocation tasks sorted by continent (the old numbering) are flagged, and a
    round-robin of four stores is too."""
    geo = sorted(families()["geo-baseline"], key=lambda t: (t["answer"]["continent"], t["id"]))
    assert worst_lag([t["answer"]["continent"] for t in geo])[3] > MAX_Z
    assert worst_lag(["a", "b", "c", "d"] * 15)[3] > MAX_Z


def test_geolocation_ids_are_not_in_location_order() -> None:
    from ewa_mcp.envs.geo.locations import LOCATIONS_LIST

    for setting in ("baseline", "embodied"):
        tasks = json.loads((TASKS / "geolocation" / f"geolocation-{setting}.json").read_text(encoding="utf-8"))
        assert [t["id"] for t in tasks] == sorted(t["id"] for t in tasks)  # list_tasks order is id order
        numbers = [int(t["id"].split("-")[1]) for t in tasks]
        assert sorted(numbers) == list(range(1, len(LOCATIONS_LIST) + 1))
        by_location = {t["metadata"]["location_id"]: n for t, n in zip(tasks, numbers, strict=True)}
        in_list_order = [by_location[loc.id] for loc in LOCATIONS_LIST]
        ascending = sum(a < b for a, b in zip(in_list_order, in_list_order[1:], strict=False))
        assert ascending < 0.6 * (len(in_list_order) - 1)  # a shuffle: about half, not all
