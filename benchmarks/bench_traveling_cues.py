"""What a single cue of a two-hop traveling hard task gives away (docs/verified.md, "Traveling hard in two hops"),
measured on the committed tasks: how many landmarks the range holds, how often the nearest one is the answer,
how many landmarks share the fact, how often the named landmark X stands within the range; and for the
two-fact tasks (X's fact and Y's together), how often each shortcut lands on the answer: the nearest place
sharing X's fact, the nearest sharing Y's, the nearest place of all, and any place sharing both.

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
from ewa_mcp.geometry import haversine_m  # noqa: E402
from ewa_mcp.envs.street.world import get_world  # noqa: E402
from ewa_mcp.websites.wiki import store as wiki  # noqa: E402
from ewa_mcp.websites.wiki.search import SearchIndex  # noqa: E402


def main() -> int:
    world = get_world()
    every = [t for p in sorted((ROOT / "tasks" / "traveling").glob("*.json")) for t in json.loads(p.read_text("utf-8"))
             if t["difficulty"] == "hard"]
    hard = [t for t in every if not t["metadata"].get("pair_cue")]
    pairs = [t for t in every if t["metadata"].get("pair_cue")]

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
    print(f"one-fact tasks (below): {n}; two-fact tasks: {len(pairs)} of {len(every)}")
    print(f"hard traveling tasks: {n}; shared fact: {dict(Counter(t['metadata']['cue']['key'] for t in hard))}")
    print(f"landmarks with an article within the range (X aside): median {statistics.median(in_range)}, "
          f"min {min(in_range)}, max {max(in_range)}")
    print(f"the nearest of them is the answer: {nearest_hits} of {n} ({100 * nearest_hits / n:.0f} %)")
    print(f"landmarks sharing the fact (the answer included, X aside): median {statistics.median(sharing)}, "
          f"min {min(sharing)}")
    print(f"X itself within the range: {via_in_range} of {n}")
    boundary(world, hard, walk_m)
    if pairs:
        two_facts(world, pairs, walk_m)
    return 0


def local_m(world, a: str, b: str) -> tuple[float, float]:
    """(east, north) metres from node ``a`` to node ``b`` (flat, fine at a walk's scale)."""
    na, nb = world.node(a), world.node(b)
    north = haversine_m(na.lat, na.lng, nb.lat, na.lng) * (1 if nb.lat >= na.lat else -1)
    east = haversine_m(na.lat, na.lng, na.lat, nb.lng) * (1 if nb.lng >= na.lng else -1)
    return east, north


def boundary(world, hard: list[dict], walk_m) -> None:
    """Where the answer and its rivals (other places sharing the fact, X aside) stand against the range
    (docs/verified.md, "Traveling hard: the choice at the range's edge"), and how often each shortcut a
    player could take instead of measuring walks lands on the answer."""
    index = SearchIndex(wiki.load_articles())
    inbound: Counter = Counter()
    for article in wiki.load_articles():
        for target, _ in {(t, "") for t, _ in wiki.links_in(article.body)}:
            found = wiki.find(target)
            if found is not None and found.slug != article.slug:
                inbound[found.slug] += 1
    inside, over, crow_in, crow_first = [], [], 0, 0
    hits: Counter = Counter()
    for task in hard:
        cue, start = task["metadata"]["cue"], task["start"]["embodied"]["node"]
        limit, target = cue["range_m"], world.places[task["metadata"]["poi_id"]]
        places = [p for p in world.places.values() if p.city == target.city and p.id != cue["via"]
                  and wiki.by_poi_id(p.id) is not None]
        sharing = [p for p in places if cue_value(cue["key"], p) == cue["value"]]
        here = world.node(start)

        def crow(p) -> float:
            n = world.node(p.node)
            return haversine_m(here.lat, here.lng, n.lat, n.lng)

        def grid(p) -> float:  # a guess from addresses on a street grid: blocks east-west plus north-south
            east, north = local_m(world, start, p.node)
            return abs(east) + abs(north)

        inside.append(limit - walk_m(start, target.node))
        rivals = [p for p in sharing if p.id != target.id and walk_m(start, p.node) > limit]
        near = [p for p in rivals if walk_m(start, p.node) <= limit + 80]
        over += [walk_m(start, p.node) - limit for p in near]
        crow_in += any(crow(p) <= limit for p in near)
        crow_first += any(crow(p) < crow(target) for p in near)
        hits["nearest sharing the fact as the crow flies"] += min(sharing, key=crow).id == target.id
        hits["nearest sharing the fact by an address (grid) guess"] += min(sharing, key=grid).id == target.id
        hits["place nearest the start as the crow flies"] += min(places, key=crow).id == target.id
        hits["most-linked article sharing the fact"] += \
            max(sharing, key=lambda p: (inbound[wiki.by_poi_id(p.id).slug], p.id)).id == target.id
        ids = {p.id for p in sharing}
        if cue["key"] == "year_built":  # the years of the decade searched one by one, hits read in order
            decade = int(cue["value"][:4])
            queries = [str(year) for year in range(decade, decade + 10)]
        else:
            queries = [f"{cue['value']} {world.city(target.city).name.split(' (')[0].split(',')[0]}"]
        order = [a.poi_id for q in queries for h in index.search(q, 20)[0]
                 if (a := wiki.find(h.slug)) is not None and a.poi_id in ids]
        hits["first hit of a year (or style) search"] += bool(order) and order[0] == target.id
        in_crow = [pid for pid in order if crow(world.places[pid]) <= limit]
        hits["first hit of that search within the range as the crow flies"] += bool(in_crow) and in_crow[0] == target.id
    n = len(hard)
    print(f"the answer's walk ends this far inside the range (m): min {min(inside):.0f}, median "
          f"{statistics.median(inside):.0f}, max {max(inside):.0f}")
    spread = f"min {min(over):.0f}, median {statistics.median(over):.0f}, max {max(over):.0f}" if over else "none"
    print(f"rivals just beyond (walk over the range by at most 80 m): {len(over)} over {n} tasks; over by (m): "
          f"{spread}")
    print(f"tasks with a rival just beyond the walk yet within the range as the crow flies: {crow_in} of {n}; "
          f"nearer than the answer as the crow flies: {crow_first} of {n}")
    for name, hit in hits.items():
        print(f"shortcut '{name}' is the answer: {hit} of {n} ({100 * hit / n:.0f} %)")


def two_facts(world, pairs: list[dict], walk_m) -> None:
    """The shortcuts over the two-fact tasks: which place each picks, among the places with an article
    (stations included: the intent names them) other than X and Y, by the walk from the corner."""
    hits: Counter = Counter()
    in_range_x, in_range_y = [], []
    index = SearchIndex(wiki.load_articles())
    for task in pairs:
        cue, pair, start = task["metadata"]["cue"], task["metadata"]["pair_cue"], task["start"]["embodied"]["node"]
        target = world.places[task["metadata"]["poi_id"]]
        places = sorted((walk_m(start, p.node), p.id, p) for p in world.places.values()
                        if p.city == target.city and p.id not in (cue["via"], pair["via"])
                        and wiki.by_poi_id(p.id) is not None)

        def nearest(keep) -> str | None:
            return next((pid for _, pid, p in places if keep(p)), None)

        shares_x = lambda p: cue_value(cue["key"], p) == cue["value"]  # noqa: E731
        shares_y = lambda p: cue_value(pair["key"], p) == pair["value"]  # noqa: E731
        hits["nearest sharing X's fact"] += nearest(shares_x) == target.id
        hits["nearest sharing Y's fact"] += nearest(shares_y) == target.id
        hits["nearest place of all"] += nearest(lambda p: True) == target.id
        # not a shortcut: both facts read and combined, only the range left unread
        hits["nearest sharing both (both facts read, the range not)"] += \
            nearest(lambda p: shares_x(p) and shares_y(p)) == target.id
        # what a searcher types: the shared style (or architect) and the city, reading hits in order
        text_cue = cue if cue["key"] != "year_built" else pair
        city = world.city(target.city).name.split(" (")[0].split(",")[0]
        found, _, _ = index.search(f"{text_cue['value']} {city}", 20)
        in_range = {pid for m, pid, _ in places if m <= cue["range_m"]}
        first = next((a.poi_id for h in found if (a := wiki.find(h.slug)) is not None and a.poi_id in in_range), None)
        hits["first in range of the wiki's search for the style (or architect) and the city"] += first == target.id
        within = [p for m, _, p in places if m <= cue["range_m"] and p.id != target.id]
        in_range_x.append(sum(1 for p in within if shares_x(p)))
        in_range_y.append(sum(1 for p in within if shares_y(p)))
    n = len(pairs)
    print(f"two-fact tasks: {n}; facts (X, Y): "
          f"{dict(Counter((t['metadata']['cue']['key'], t['metadata']['pair_cue']['key']) for t in pairs))}")
    print(f"other places within the range sharing X's fact: min {min(in_range_x)}, median "
          f"{statistics.median(in_range_x)}; Y's: min {min(in_range_y)}, median {statistics.median(in_range_y)}")
    for name, hit in hits.items():
        print(f"shortcut '{name}' is the answer: {hit} of {n} ({100 * hit / n:.0f} %)")


if __name__ == "__main__":
    raise SystemExit(main())
