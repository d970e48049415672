"""What a cheap walking rule would get over the whole suite (docs/verified.md, "Walking heuristics"), read
from the task files without playing: the share of tasks where the rule's choice is the task's target.

    nice .venv/bin/python benchmarks/bench_walk_priors.py [--tasks DIR]

(``--tasks`` reads another suite, e.g. an older checkout's tasks/, to compare its figures.)

Rules are the walking heuristic agents' choices (ewa_mcp/evaluation/heuristics/walking.py): for a
hard (several-stop) navigation task the stop each rule ends at, or the whole order it walks; for shopping the store (and product or size) each
picks. A ceiling only: the agent must still place the order and walk, which it does (tests/core/
test_walking_heuristics.py). Numbers printed here are measurements, not assertions.
"""

from __future__ import annotations

import sys
from collections import Counter, defaultdict
from itertools import permutations
from math import factorial
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ewa_mcp.core.taskmodel import TaskStore  # noqa: E402
from ewa_mcp.envs.street.taskgen.navigation import nearest_first, shortcut_orders  # noqa: E402
from ewa_mcp.evaluation.heuristics.walking import (  # noqa: E402
    elimination_end,
    named_stores,
    pick_store,
    resolve,
    sellers,
    shopping_items,
    stops_of,
    walk_m,
    world,
)


def family(task_id: str) -> str:
    return task_id.split("-")[1]


def greedy_order(origin: Any, stops: list[Any]) -> list[str]:
    """The stops in the order a walk that always goes to the nearest one not yet seen takes them."""
    here, left, out = origin, list(stops), []
    while left:
        here = min(left, key=lambda p: walk_m(here.node, p.node))
        left.remove(here)
        out.append(here.id)
    return out


def hard_cues(store: TaskStore) -> None:
    """Shopping hard, one cue at a time: the target's distance rank among all four stores, and among the three
    stores a named-stores task names, its rank by walk, by total price, and whether it alone has all in stock."""
    from ewa_mcp.websites.shop import catalog

    cues: Counter[str] = Counter()
    pair = [t for t in store.all("shopping") if t.difficulty == "hard" and t.metadata.get("form") == "named"]
    if not pair:
        return  # the tour form took the named form's numbers (tour_rules)
    for t in pair:
        meta, start = t.metadata, t.start.embodied.node
        by_walk = sorted(meta["store_nodes"], key=lambda sid: walk_m(start, meta["store_nodes"][sid]))
        cues[("nearest", "second nearest", "third nearest", "farthest")[by_walk.index(meta["store_id"])]
             + " of all stores"] += 1
        named = meta.get("named_stores")
        if not named:
            continue
        cues["named-stores tasks"] += 1
        rank = sorted(named, key=lambda sid: walk_m(start, meta["store_nodes"][sid])).index(meta["store_id"])
        cues[("nearest", "middle", "farthest")[rank] + " named"] += 1
        cues["cheapest total named"] += min(named, key=lambda sid: meta["totals"][sid]) == meta["store_id"]
        stocked = [sid for sid in named if all(catalog.stock(p, size, sid) > 0
                                               for p, size in zip(meta["products"], meta["sizes"], strict=True))]
        cues["the only named store with all in stock"] += stocked == [meta["store_id"]]
    n_named = cues.pop("named-stores tasks")
    print(f"\nshopping hard, one store ({len(pair)} tasks, {n_named} naming stores): the cue alone picks the target")
    for cue in [f"{r} of all stores" for r in ("nearest", "second nearest", "third nearest", "farthest")] + [
            f"{r} named" for r in ("nearest", "middle", "farthest", "cheapest total")] + [
            "the only named store with all in stock"]:
        hits, n = cues[cue], (n_named if "named" in cue else len(pair)) or 1
        print(f"  {cue}: {hits} of {n} ({100 * hits / n:.0f} %)")


def shortest_form(store: TaskStore) -> None:
    """Navigation hard, the shortest-order form: each tempting shortcut's whole order against the answer (the
    best order on the map's walking distances); the generator keeps each at a third or less."""
    rules: Counter[str] = Counter()
    tasks = [t for t in store.all("navigation") if t.difficulty == "hard" and t.metadata.get("form") == "shortest order"]
    for t in tasks:
        origin_text, listed_text = stops_of(t.intent) or ("", [])
        origin, listed = resolve(origin_text), [resolve(x) for x in listed_text]
        order = t.metadata["stops"]
        for rule, ids in shortcut_orders(world(), lambda a, b: walk_m(a.node, b.node), origin, listed, listed).items():
            rules[f"order: {rule}"] += ids == order
        by_walk = sorted(listed, key=lambda p: walk_m(origin.node, p.node))
        rules["end: farthest from the start on foot"] += by_walk[-1].id == order[-1]
        rules["end: nearest the start on foot"] += by_walk[0].id == order[-1]
        # the end cue combined: the farthest stop last, the others nearest-next before it
        rules["order: greedy nearest-next to the others, then the farthest"] += \
            [*greedy_order(origin, by_walk[:-1]), by_walk[-1].id] == order
        rules["order: reverse of listed"] += [p.id for p in listed][::-1] == order
        rules["order: shortest walk past all (the answer)"] += [p.id for p in min(
            permutations(listed), key=lambda perm: sum(walk_m(a.node, b.node) for a, b in zip([origin, *perm], perm)))] == order
    margins = sorted(t.metadata["margin_m"] for t in tasks)
    sizes = Counter(len(t.metadata["stops"]) for t in tasks)
    print(f"\nnavigation hard, shortest-order form ({len(tasks)} tasks: "
          + ", ".join(f"{n} with {k} stops (chance 1 in {factorial(k)} for an order, 1 in {k} for an end)"
                      for k, n in sorted(sizes.items(), reverse=True))
          + f"; the best order beats the second by {margins[0]:.0f} to {margins[-1]:.0f} m):")
    for rule, hits in rules.items():
        print(f"  {rule}: {hits} ({100 * hits / max(len(tasks), 1):.0f} %)")


def split_rules(store: TaskStore) -> None:
    """Shopping hard, the split form (two orders at two stores): how often each pair rule picks the target pair
    (any order of the two), worked out from the catalogue and the map. The task's own rule (the shortest walk
    past one store to the other, of the pairs within the budget) is printed as a check: 100 %."""
    from ewa_mcp.envs.street.taskgen.shopping import split_costs
    from ewa_mcp.websites.shop import catalog

    stores = [s.id for s in catalog.load_stores()]
    split = [t for t in store.all("shopping") if t.metadata.get("form") == "split"
             and "end_id" not in t.metadata]  # the walk ends at the second store (end points: below)
    rules: Counter[str] = Counter()
    targets: Counter[str] = Counter()
    for t in split:
        meta, start = t.metadata, t.start.embodied.node
        nodes = meta["store_nodes"]
        items = [(catalog.get_product(p), size) for p, size in zip(meta["products"], meta["sizes"], strict=True)]
        costs = {frozenset(k.split("|")): c for k, c in split_costs(items, stores).items()}
        within = [k for k, c in costs.items() if c <= meta["budget"]]
        from_start = {sid: walk_m(start, nodes[sid]) for sid in stores}

        def route(pair: frozenset[str]) -> float:
            a, b = sorted(pair)
            return min(from_start[a] + walk_m(nodes[a], nodes[b]), from_start[b] + walk_m(nodes[b], nodes[a]))

        target = frozenset(meta["store_pair"])
        targets[" & ".join(sorted(target))] += 1
        two_nearest = frozenset(sorted(stores, key=from_start.__getitem__)[:2])
        rules["nearest pair (the two stores nearest the start)"] += two_nearest == target
        rules["nearest pair within the budget (sum of the two walks from the start)"] += \
            min(within, key=lambda k: sum(from_start[s] for s in k)) == target
        rules["cheapest pair (budget and walk not read)"] += min(costs, key=costs.__getitem__) == target
        near = min(stores, key=from_start.__getitem__)
        rules["a pair holding the nearest store"] += near in target
        rest = [(p, size) for p, size in items if not (p.offer(size, near) and catalog.stock(p.id, size, near) > 0)]
        fill = [sid for sid in stores if sid != near and all(
            p.offer(size, sid) and catalog.stock(p.id, size, sid) > 0 for p, size in rest)]
        greedy = frozenset((near, min(fill, key=lambda sid: walk_m(nodes[near], nodes[sid])))) if fill else None
        rules["greedy walk (nearest store, then the nearest to it with the rest)"] += greedy == target
        rules["shortest walk past both, budget not read"] += min(costs, key=route) == target
        rules["shortest walk past both within the budget (the task's rule)"] += min(within, key=route) == target
    n = len(split) or 1
    print(f"\nshopping hard, split form ({len(split)} tasks, {len(targets)} store pairs as targets): "
          "the pair rule picks the target pair")
    for rule, hits in rules.items():
        print(f"  {rule}: {hits} of {len(split)} ({100 * hits / n:.0f} %)")
    print("  targets: " + ", ".join(f"{k} {v}" for k, v in targets.most_common()))


def end_point_rules(store: TaskStore) -> None:
    """Shopping hard, the split form with an end point E (S, first store, second store, E): how often each
    shortcut walks the graded order (the pair and its order), over the end-point tasks. The shortcuts are the
    generator's (``split_shortcuts``), worked out again here from each task's prices, walks and the map, so
    an older suite (``--tasks``) is measured by the same rules; tests/core/test_shopping_constraints.py works
    them out from the catalogue and checks they agree with the metadata."""
    from ewa_mcp.envs.street.taskgen.shopping import SPLIT_SHORTCUTS, Context, Legs, pair_key, split_shortcuts
    from ewa_mcp.geometry import haversine_m

    split = [t for t in store.all("shopping") if t.metadata.get("form") == "split"]
    ends = [t for t in split if "end_id" in t.metadata]
    if not ends:
        return
    ctx = Context()
    legs = Legs(ctx)
    rules: Counter[str] = Counter()
    for t in ends:
        meta, start = t.metadata, t.start.embodied.node
        end = ctx.world.places[meta["end_id"]]
        route = {tuple(k.split(">")): m for k, m in meta["walks_m"].items()}
        within = sorted((r for r in route if meta["pair_costs"][pair_key(*r)] <= meta["budget"]), key=route.__getitem__)
        from_start = {sid: legs.metres(start, p.node) for sid, p in ctx.store_places.items()}
        to_end = {sid: legs.to_end(end, sid) for sid in ctx.store_places}
        way_ends = ctx.world.node(start), ctx.world.node(end.node)

        def line(r: tuple[str, str]) -> float:
            way = [way_ends[0], *(ctx.world.node(ctx.store_places[x].node) for x in r), way_ends[1]]
            return sum(haversine_m(a.lat, a.lng, b.lat, b.lng) for a, b in zip(way, way[1:]))

        picks = split_shortcuts(within, meta["pair_costs"], from_start, to_end, legs.between, line)  # type: ignore[arg-type]
        for rule in SPLIT_SHORTCUTS:
            rules[rule] += picks[rule] == tuple(meta["store_pair"])
    margins = sorted(t.metadata["margin_m"] for t in ends)
    pairs = Counter(" & ".join(sorted(t.metadata["store_pair"])) for t in ends)
    print(f"\nshopping hard, split form with an end point ({len(ends)} of {len(split)} split tasks; the answer's "
          f"walk beats the next within the budget by {margins[0]:.0f} to {margins[-1]:.0f} m): the shortcut "
          "walks the graded order")
    for rule in SPLIT_SHORTCUTS:
        print(f"  {rule}: {rules[rule]} of {len(ends)} ({100 * rules[rule] / len(ends):.0f} %)")
    print("  pairs: " + ", ".join(f"{k} {v}" for k, v in pairs.most_common()))


def tour_rules(store: TaskStore) -> None:
    """Shopping hard, the tour form (two or three stores, any order, to an end point E): how often each
    shortcut walks the graded plan (its stores in its order). The picks are the generator's (task metadata);
    tests/core/test_shopping_tour.py works them out again from the catalogue and the map."""
    tours = [t for t in store.all("shopping") if t.metadata.get("form") == "tour"]
    if not tours:
        return
    rules: Counter[str] = Counter()
    for t in tours:
        for rule, pick in t.metadata["shortcuts"].items():
            rules[rule] += pick == t.metadata["stores"]
    margins = sorted(t.metadata["margin_m"] for t in tours)
    within = sorted(t.metadata["walks_within"] for t in tours)
    threes = sum(len(t.metadata["stores"]) == 3 for t in tours)
    print(f"\nshopping hard, tour form ({len(tours)} tasks, {threes} answered by three stores; {within[0]} to "
          f"{within[-1]} walks within the budget; the answer beats the next by {margins[0]:.0f} to "
          f"{margins[-1]:.0f} m): the shortcut walks the graded plan")
    for rule, hits in rules.items():
        print(f"  {rule}: {hits} of {len(tours)} ({100 * hits / len(tours):.0f} %)")
    plans = Counter(" > ".join(t.metadata["stores"]) for t in tours)
    stores = Counter(s for t in tours for s in t.metadata["stores"])
    print(f"  plans: {len(plans)} distinct; stores in the answers: " +
          ", ".join(f"{k} {v}" for k, v in stores.most_common()))


def main() -> int:
    tasks = Path(sys.argv[sys.argv.index("--tasks") + 1]) if "--tasks" in sys.argv else ROOT / "tasks"
    store = TaskStore([tasks])
    shortest_form(store)
    nav: Counter[str] = Counter()
    for t in store.all("navigation"):
        if t.difficulty != "hard" or t.metadata.get("form") != "year order":
            continue
        origin_text, listed_text = stops_of(t.intent) or ("", [])
        origin, listed = resolve(origin_text), [resolve(x) for x in listed_text]
        order, end = t.metadata["stops"], t.metadata["stops"][-1]
        ids = [p.id for p in listed]
        nav["tasks"] += 1
        nav["end: elimination (neither listed last nor the nearest-first end)"] += elimination_end(origin, listed).id == end
        for k in range(len(listed)):
            nav[f"end: listed {k + 1} of {len(listed)}"] += ids[k] == end
        nav["end: the nearest-first walk's end"] += nearest_first(world(), origin, listed) == end
        by_walk = sorted(listed, key=lambda p: walk_m(origin.node, p.node))
        nav["end: nearest the start on foot"] += by_walk[0].id == end
        nav["end: farthest from the start on foot"] += by_walk[-1].id == end
        nav["order: as listed (directions-walker)"] += ids == order
        eliminated = elimination_end(origin, listed).id
        nav["order: the others as listed, then elimination's end (stop-elimination)"] += \
            [i for i in ids if i != eliminated] + [eliminated] == order
        nav["order: reverse of listed"] += ids[::-1] == order
        nav["order: greedy nearest-next (the nearest stop not yet seen, on foot)"] += greedy_order(origin, listed) == order
        nav["order: shortest walk past all"] += [p.id for p in min(
            permutations(listed), key=lambda perm: sum(walk_m(a.node, b.node) for a, b in zip([origin, *perm], perm)))] == order
    n = nav.pop("tasks")
    print(f"navigation hard, year-order form ({n} tasks): the rule's last stop is the newest (end; chance 1 in 4) / its whole order is "
          "the wiki's (order; chance 1 in 24, and only the whole order passes: each stop is graded after the one before)")
    for rule, hits in nav.items():
        print(f"  {rule}: {hits} ({100 * hits / n:.0f} %)")

    cells: dict[tuple[str, str], Counter[str]] = defaultdict(Counter)
    for t in store.all("shopping"):
        items, answer = shopping_items(t.intent)
        key = (t.difficulty or "-", family(t.id))
        cell = cells[key]
        cell["tasks"] += 1
        named = named_stores(t.intent)  # the store agents choose among the stores the intent names, if any
        start, candidates = t.start.embodied.node, [sid for sid in sellers(items) if not named or sid in named]
        right_items = (answer is None or t.answer is None or answer in t.answer.must_include) and (
            "product_id" not in t.metadata or items[0][0].id == t.metadata["product_id"])
        target = t.metadata.get("store_id")  # none for the split form: one store cannot meet two orders' goal
        for rule in ("nearest", "cheapest", "step-limit"):
            picked = pick_store(rule, candidates, items, start, t.step_limit)
            cell[f"{rule}-store"] += right_items and target is not None and picked == target
        cell["first named store (directions-walker)"] += right_items and bool(named) and named[0] == target
    print("\nshopping: the rule's store (and, for a question, its guess of product or size) is the target")
    for (difficulty, fam), cell in sorted(cells.items()):
        n = cell.pop("tasks")
        print(f"  {difficulty} {fam} ({n} tasks): " + ", ".join(f"{r} {h} ({100 * h / n:.0f} %)" for r, h in cell.items()))
    hard_cues(store)
    split_rules(store)
    end_point_rules(store)
    tour_rules(store)
    sizes = Counter(t.difficulty or "-" for t in store.all("shopping"))
    for difficulty in ("easy", "medium", "hard"):
        rows = [c for (d, _), c in cells.items() if d == difficulty]
        if rows:
            hits, rule = max((sum(c[r] for c in rows), r) for r in rows[0])
            print(f"  {difficulty}: best rule {rule}: {hits} of {sizes[difficulty]} "
                  f"({100 * hits / sizes[difficulty]:.0f} %)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
