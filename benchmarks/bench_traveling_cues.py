"""What a single cue of a two-hop traveling hard task gives away (docs/verified.md, "Traveling hard in two hops"),
measured on the committed tasks: how many landmarks the range holds, how often the nearest one is the answer,
how many landmarks share the fact, how often the named landmark X stands within the range.

    .venv/bin/python benchmarks/bench_traveling_cues.py

Numbers printed here are measurements, not assertions (the properties every task must have are tested in
tests/core/test_hard_split.py and tests/core/test_traveling_concepts.py).
"""

from __future__ import annotations

import json
import statistics
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ewa_mcp.envs.street.taskgen.traveling import cue_value, landmarks_of  # noqa: E402
from ewa_mcp.envs.street.world import get_world  # noqa: E402
from ewa_mcp.websites.wiki import store as wiki  # noqa: E402


def main() -> int:
    world = get_world()
    hard = [t for p in sorted((ROOT / "tasks" / "traveling").glob("*.json")) for t in json.loads(p.read_text("utf-8"))
            if t["difficulty"] == "hard"]

    def walk_m(start: str, node: str) -> float:
        try:
            return float(world.directions(start, node).distance_m)
        except ValueError:
            return float("inf")

    in_range, nearest_hits, sharing, via_in_range = [], 0, [], 0
    for task in hard:
        cue, start = task["metadata"]["cue"], task["start"]["embodied"]["node"]
        target = world.places[task["metadata"]["poi_id"]]
        peers = [p for p in landmarks_of(world) if p.city == target.city and p.id != cue["via"]
                 and wiki.by_poi_id(p.id) is not None]
        within = sorted((walk_m(start, p.node), p.id) for p in peers if walk_m(start, p.node) <= cue["range_m"])
        in_range.append(len(within))
        nearest_hits += bool(within) and within[0][1] == target.id
        sharing.append(sum(1 for p in peers if cue_value(cue["key"], p) == cue["value"]))
        via_in_range += walk_m(start, world.places[cue["via"]].node) <= cue["range_m"]
    n = len(hard)
    print(f"hard traveling tasks: {n}; shared fact: {dict(Counter(t['metadata']['cue']['key'] for t in hard))}")
    print(f"landmarks with an article within the range (X aside): median {statistics.median(in_range)}, "
          f"min {min(in_range)}, max {max(in_range)}")
    print(f"the nearest of them is the answer: {nearest_hits} of {n} ({100 * nearest_hits / n:.0f} %)")
    print(f"landmarks sharing the fact (the answer included, X aside): median {statistics.median(sharing)}, "
          f"min {min(sharing)}")
    print(f"X itself within the range: {via_in_range} of {n}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
