"""The tour form of hard shopping (issue 26, principle 6), read from the committed suite and checked against
the shop's catalogue and the street map, not the tasks' own metadata: four items no store has all of in
stock, bought at two or three stores (one order at each), within a budget, carried to an end point E on the
shortest whole walk among the plans within the budget."""

from __future__ import annotations

import itertools
import json
from collections import Counter
from pathlib import Path

from ewa_mcp.envs.browser.checks import check_orders_split
from ewa_mcp.envs.browser.goals import OrdersSplit
from ewa_mcp.envs.street.checks import check_passed_place
from ewa_mcp.envs.street.goals import PassedPlace
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.geometry import haversine_m
from ewa_mcp.websites.shop import catalog

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"
TOUR = [t for p in sorted((TASKS_DIR / "shopping").glob("*.json")) for t in json.loads(p.read_text("utf-8"))
        if t["id"].startswith("shopping-pair-") and t["metadata"]["form"] == "tour"]
STORES = [s.id for s in catalog.load_stores()]


def _price(store_id: str, product_id: str, size: str) -> float | None:
    """The price where the store sells the size and has it in stock, else None."""
    offer = catalog.get_product(product_id).offer(size, store_id)
    return offer.price if offer is not None and catalog.stock(product_id, size, store_id) > 0 else None


def _fill(meta: dict, stores: tuple[str, ...]) -> float | None:
    """The least the list costs at these stores with at least one item bought at each (one order per store)."""
    items = list(zip(meta["products"], meta["sizes"], strict=True))
    best = None
    for choice in itertools.product(stores, repeat=len(items)):
        if set(choice) != set(stores):
            continue
        prices = [_price(sid, p, s) for sid, (p, s) in zip(choice, items)]
        if None in prices:
            continue
        total = round(sum(prices), 2)  # type: ignore[arg-type]
        best = total if best is None or total < best else best
    return best


def _world(task: dict) -> tuple[dict[tuple[str, ...], float], dict[tuple[str, ...], float]]:
    """(walk -> cost of its set of stores, walk -> metres) for every order of every set of two or three
    stores that can fill the list."""
    world, meta = get_world(), task["metadata"]
    nodes = meta["store_nodes"]
    start, end = task["start"]["embodied"]["node"], meta["end_node"]

    def m(a: str, b: str) -> float:
        return world.directions(a, b).distance_m

    cost, walk = {}, {}
    for k in (2, 3):
        for stores in itertools.combinations(STORES, k):
            total = _fill(meta, stores)
            if total is None:
                continue
            for order in itertools.permutations(stores):
                way = [start, *(nodes[s] for s in order), end]
                cost[order], walk[order] = total, sum(m(a, b) for a, b in zip(way, way[1:]))
    return cost, walk


def test_tour_form_takes_the_named_forms_place_mostly_over_three_stores() -> None:
    assert len(TOUR) >= 15, len(TOUR)
    assert sum(len(t["metadata"]["stores"]) == 3 for t in TOUR) >= 2 / 3 * len(TOUR)
    assert len({tuple(sorted(t["metadata"]["stores"])) for t in TOUR}) >= 3  # more than one plan answers
    world = get_world()
    for task in TOUR:
        meta = task["metadata"]
        stores = meta["stores"]
        assert len(meta["products"]) == 4 and len(set(meta["products"])) == 4, task["id"]
        for sid in STORES:  # no store fills the list alone
            assert None in [_price(sid, p, s) for p, s in zip(meta["products"], meta["sizes"])], (task["id"], sid)
        (web,) = task["web_goals"]
        assert web["kind"] == "orders_split" and web["store_ids"] == stores, task["id"]
        assert web["max_total"] == meta["budget"] and f"${meta['budget']:.2f}" in task["intent"], task["id"]
        *passed, reached = task["embodied_goals"]
        assert [g["place_id"] for g in passed] == stores and all(g["kind"] == "passed_place" for g in passed)
        assert passed[0].get("after") is None, task["id"]
        assert [g["after"]["place_id"] for g in passed[1:]] == stores[:-1], task["id"]  # each after the one before
        assert reached["kind"] == "reached_place" and reached["place_id"] == meta["end_id"], task["id"]
        assert world.places[meta["end_id"]].name in task["intent"], task["id"]
        assert task["step_limit"] >= len(task["oracle"]) + 60, task["id"]  # room to read and compare


def test_tour_answers_spread_over_the_stores_and_their_sets() -> None:
    """Every store is in some answers and no set of stores answers most tasks. Target, the central store, is
    in nearly every answer: of the generator's pool (183 walks that keep every margin), 178 pass it and every
    three-store one does, and the five without it are pairs, which "the fewest stores" picks (capped at a
    third of the form); docs/verified.md, "Shopping hard: the split form's shortcuts and the tour's store
    sets". It is still not in every answer, and no other store is in more than about three quarters."""
    stores = Counter(s for t in TOUR for s in t["metadata"]["stores"])
    sets = Counter(frozenset(t["metadata"]["stores"]) for t in TOUR)
    (_, most), (_, second) = stores.most_common(2)
    assert len(stores) == len(STORES) and most < len(TOUR) and second <= 0.8 * len(TOUR), stores
    assert max(sets.values()) <= 0.45 * len(TOUR) + 1 and len(sets) >= 4, sets


def test_tour_one_walk_is_shortest_within_the_budget_by_a_small_clear_margin() -> None:
    """Of every walk within the budget (at least 20), the graded one is shortest, by 30 m to 120 m over the
    next; a walk shorter by 30 m or more is over the budget by a few dollars at most (never by less than 5 cents), and the
    answer's cheapest fill is under it by 5 cents or more."""
    for task in TOUR:
        meta = task["metadata"]
        cost, walk = _world(task)
        answer, budget = tuple(meta["stores"]), meta["budget"]
        within = sorted((r for r in walk if cost[r] <= budget), key=walk.__getitem__)
        assert within[0] == answer, (task["id"], within[:2])
        assert len(within) >= 20, (task["id"], len(within))
        assert 30 <= walk[within[1]] - walk[answer] <= 120, (task["id"], walk[within[1]] - walk[answer])
        assert cost[answer] <= budget - 0.05 + 1e-9, task["id"]
        shorter = [r for r in walk if walk[r] <= walk[answer] and r != answer]
        assert all(cost[r] >= budget + 0.05 - 1e-9 for r in shorter), task["id"]
        assert any(walk[r] <= walk[answer] - 30 for r in shorter), task["id"]  # clearly shorter, over the budget
        assert min(cost[r] for r in shorter) - budget <= 3.0, task["id"]  # the budget rules out by small sums
        assert round(walk[answer], 1) == meta["shortest_path_m"], task["id"]


def test_tour_every_rival_plan_fails_the_goals() -> None:
    """Every other plan fails: another set of stores fails the orders (wrong stores, or a store too many or
    too few), and the answer's stores in any other order, on the map's shortest legs, miss the graded order;
    the answer's own order passes both."""
    world = get_world()
    for task in TOUR:
        meta = task["metadata"]
        web = OrdersSplit.model_validate(task["web_goals"][0])
        goals = [PassedPlace.model_validate(g) for g in task["embodied_goals"][:-1]]
        items = [{"product_id": p, "size": s, "quantity": 1} for p, s in zip(meta["products"], meta["sizes"])]
        cost, _walk = _world(task)
        for plan in {tuple(sorted(r)) for r in cost}:
            # each plan's stores, one order at each, the items spread so every store has one
            events = [{"site": "shop", "type": "order_placed",
                       "order": {"store_id": sid, "items": [it for i, it in enumerate(items) if i % len(plan) == j],
                                 "total": 0.0}} for j, sid in enumerate(plan)]
            met = check_orders_split(web, events).met
            assert met is (set(plan) == set(meta["stores"])), (task["id"], plan)
        start, end = task["start"]["embodied"]["node"], meta["end_node"]
        for order in itertools.permutations(meta["stores"]):
            way = [start, *(meta["store_nodes"][s] for s in order), end]
            nodes = [start]
            for a, b in zip(way, way[1:]):
                nodes += world.directions(a, b).nodes[1:]
            state = {"city": "manhattan", "path_points": [[world.node(n).lat, world.node(n).lng] for n in nodes]}
            met = all(check_passed_place(g, state, None).met for g in goals)
            assert met is (list(order) == meta["stores"]), (task["id"], order)


def test_tour_shortcuts_each_walk_the_answer_in_a_third_or_less() -> None:
    """Each tempting shortcut, worked out here from the catalogue and the map: the pair within the budget
    nearest E, nearest the start; the cheapest plan; the fewest stores (pairs only); the stores in the order
    the shop lists them; greedy nearest-next until the stores so far fill the list within the budget; the
    best walk by straight lines; the nearest store first; E not read; the budget not read (never right)."""
    world = get_world()
    hits: Counter[str] = Counter()
    for task in TOUR:
        meta = task["metadata"]
        cost, walk = _world(task)
        nodes, budget = meta["store_nodes"], meta["budget"]
        start, end = task["start"]["embodied"]["node"], meta["end_node"]
        within = [r for r in walk if cost[r] <= budget]
        to_end = {s: world.directions(nodes[s], end).distance_m for s in STORES}
        from_start = {s: world.directions(start, nodes[s]).distance_m for s in STORES}
        pairs = {tuple(sorted(r)) for r in within if len(r) == 2}
        pt = {s: world.node(n) for s, n in nodes.items()}
        s0, e0 = world.node(start), world.node(end)

        def line(r: tuple[str, ...]) -> float:
            way = [s0, *(pt[x] for x in r), e0]
            return sum(haversine_m(a.lat, a.lng, b.lat, b.lng) for a, b in zip(way, way[1:]))

        greedy: list[str] = []
        while len(greedy) < 3:
            here = greedy[-1] if greedy else None
            greedy.append(min((s for s in STORES if s not in greedy), key=lambda s: from_start[s] if here is None
                              else world.directions(nodes[here], nodes[s]).distance_m))
            if tuple(greedy) in within:
                break
        fewest = min(len(r) for r in within)
        cheapest = min(cost.values())
        picks = {
            "pair nearest the end": tuple(sorted(min(pairs, key=lambda p: sum(to_end[s] for s in p)),
                                                 key=lambda s: -to_end[s])) if pairs else None,
            "pair nearest the start": tuple(sorted(min(pairs, key=lambda p: sum(from_start[s] for s in p)),
                                                   key=lambda s: from_start[s])) if pairs else None,
            "cheapest plan": min((r for r in walk if cost[r] == cheapest), key=walk.__getitem__),
            "fewest stores": min((r for r in within if len(r) == fewest), key=walk.__getitem__),
            "stores in the listed order": min((r for r in within if list(r) == sorted(r, key=STORES.index)),
                                              key=walk.__getitem__, default=None),
            "greedy nearest next": tuple(greedy) if tuple(greedy) in within else None,
            "straight-line best walk": min(within, key=line),
            "nearest store first": min((r for r in within if r[0] == min({q[0] for q in within},
                                                                        key=from_start.__getitem__)),
                                       key=walk.__getitem__),
            "end point not read": min(within, key=lambda r: walk[r] - to_end[r[-1]]),
            "budget not read": min(walk, key=walk.__getitem__),
        }
        answer = tuple(meta["stores"])
        for rule, pick in picks.items():
            hits[rule] += pick == answer
    print({rule: f"{hits[rule]}/{len(TOUR)}" for rule in picks})
    assert hits["budget not read"] == 0
    for rule, n in hits.items():
        assert n <= len(TOUR) / 3, f"{rule}: {n} of {len(TOUR)}"
