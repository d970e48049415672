"""Every constraint a shopping intent states decides the answer (play-test: "nearest store that has it in
stock" was passed by an agent that never looked at stock, because every store had it).

For each committed shopping task, the answer of each strategy that ignores one stated constraint is worked
out from the shop's real catalogue and the street map, and must differ from the task's expected answer.

Strategies that read a position (the store the product page lists first, the first or last listed size) are
checked over the suite instead (issue 26, principle 3): the page lists the stores in one fixed order, so
excluding its first store from every task made that store never a target and another the target of most;
targets and answer positions are balanced, so a position or a favourite store is right about as often as
a guess.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ewa_mcp.envs.street.world import get_world
from ewa_mcp.websites.shop import catalog

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def shopping_tasks() -> list[dict]:
    return [t for p in sorted((TASKS_DIR / "shopping").glob("*.json")) for t in json.loads(p.read_text("utf-8"))]


TASKS = shopping_tasks()


def distance(task: dict, store_id: str) -> float:
    start = task["start"]["embodied"]["node"]
    return get_world().directions(start, task["metadata"]["store_nodes"][store_id]).distance_m


def sellers(product_id: str, size: str) -> list[str]:
    """Stores selling this size, in the product page's order."""
    product = catalog.get_product(product_id)
    return [s.id for s in catalog.load_stores() if product.offer(size, s.id) is not None]


def stocked(product_id: str, size: str) -> list[str]:
    return [s for s in sellers(product_id, size) if catalog.stock(product_id, size, s) > 0]


def nearest(task: dict, store_ids: list[str]) -> str:
    return min(store_ids, key=lambda s: distance(task, s))


def ignore_cheapest(task: dict, product_id: str, size: str) -> dict[str, str]:
    """Where an agent ignoring "cheapest" would walk to: the nearest seller."""
    return {"nearest seller": nearest(task, sellers(product_id, size))}


def wrong_answers(task: dict) -> dict[str, object]:
    """Strategy name -> its answer, for comparison with expected_answer(task)."""
    meta, kind = task["metadata"], task["id"].split("-")[1]
    if kind == "cheapest":
        return ignore_cheapest(task, meta["product_id"], meta["size"])
    if kind == "size":
        # The amount decides the size (test_size_answers_need_the_amount); positions: the suite-level test.
        return dict(ignore_cheapest(task, meta["product_id"], meta["size"]))
    if kind == "calories":
        first = meta["named_products"][0]
        size = catalog.get_product(meta["product_id"]).sizes[0].label
        return {"nearest seller": nearest(task, sellers(meta["product_id"], size)),
                "first listed store": sellers(meta["product_id"], size)[0],
                "cheapest store": catalog.cheapest_store(meta["product_id"], size),
                # Per task, one of the three named products is the answer; across tasks see the balance test.
                "_first named": first}
    if kind == "nearest":
        return {"nearest seller ignoring stock": nearest(task, sellers(meta["product_id"], meta["size"])),
                "cheapest store": catalog.cheapest_store(meta["product_id"], meta["size"])}
    if kind == "pair":
        if meta["form"] in ("split", "tour"):
            return {}  # two or three stores: see the split tests below and tests/core/test_shopping_tour.py
        # Hard by composition: three items in one order at one of three named stores, within a budget. Per
        # task one of the three is the answer, so "the nearest named" or "the cheapest total named" is right
        # in some tasks: across tasks see test_named_stores_cues_only_combine.
        items = list(zip(meta["products"], meta["sizes"], strict=True))
        return {f"the cheapest store of product {i + 1} alone": catalog.cheapest_store(p, size)
                for i, (p, size) in enumerate(items)}
    raise AssertionError(f"unknown shopping template in {task['id']}")


def expected(task: dict, strategy: str) -> object:
    meta = task["metadata"]
    if task["id"].startswith("shopping-size-") and "size" in strategy:
        return meta["size"]
    return meta["store_id"]


def test_size_answers_need_the_amount() -> None:
    """The smallest size that holds the stated amount: the one below it holds less, and it holds enough."""
    for task in (t for t in TASKS if t["id"].startswith("shopping-size-")):
        product, need = catalog.get_product(task["metadata"]["product_id"]), task["metadata"]["need"]["amount"]
        metric = sorted((s for s in product.sizes if s.grams or s.ml), key=lambda s: s.grams or s.ml)
        at = [s.label for s in metric].index(task["metadata"]["size"])
        assert (metric[at].grams or metric[at].ml) >= need, task["id"]
        assert at == 0 or (metric[at - 1].grams or metric[at - 1].ml) < need, task["id"]


def _share(values: list) -> float:
    from collections import Counter

    return Counter(values).most_common(1)[0][1] / len(values)


@pytest.mark.parametrize("family", ["cheapest", "size", "nearest", "pair"])
def test_no_store_is_the_target_of_most_tasks_and_none_never(family: str) -> None:
    tasks = [t for t in TASKS if t["id"].startswith(f"shopping-{family}-")]
    # The split form's target is a pair: its walk's end stands for it here (the pairs: test_split_shortcuts).
    targets = [t["metadata"].get("store_id") or (t["metadata"].get("store_pair") or t["metadata"]["stores"])[-1]
               for t in tasks]
    stores = [s.id for s in catalog.load_stores()]
    assert set(targets) == set(stores), f"{family}: never a target: {set(stores) - set(targets)}"
    assert _share(targets) <= 0.35, f"{family}: one store is the target of {_share(targets):.0%} of the tasks"
    if family != "pair":  # the page's default store is right about as often as a guess
        first = [t["metadata"]["store_id"] == sellers(t["metadata"]["product_id"], t["metadata"]["size"])[0]
                 for t in tasks]
        assert sum(first) / len(first) <= 0.35, f"{family}: the first listed store answers {sum(first)} tasks"


def test_no_position_in_the_size_list_answers_most_size_questions() -> None:
    tasks = [t for t in TASKS if t["id"].startswith("shopping-size-")]
    positions = []
    for t in tasks:
        labels = [s.label for s in catalog.get_product(t["metadata"]["product_id"]).sizes]
        at = labels.index(t["metadata"]["size"])
        positions.append("first" if at == 0 else "last" if at == len(labels) - 1 else "middle")
    assert set(positions) == {"first", "middle", "last"} and _share(positions) <= 0.4, positions


def test_every_template_is_covered() -> None:
    assert {t["id"].split("-")[1] for t in TASKS} == {"cheapest", "size", "calories", "nearest", "pair"}


@pytest.mark.parametrize("task", TASKS, ids=[t["id"] for t in TASKS])
def test_ignoring_any_stated_constraint_gives_a_wrong_answer(task: dict) -> None:
    for strategy, answer in wrong_answers(task).items():
        if strategy.startswith("_"):
            continue
        assert answer != expected(task, strategy), f"{task['id']}: the strategy '{strategy}' also passes"


def test_nearest_store_in_stock_is_not_the_nearest_seller() -> None:
    """The play-tested case itself: the nearest store selling the size has none on the shelf."""
    for task in (t for t in TASKS if t["id"].startswith("shopping-nearest-")):
        meta = task["metadata"]
        near = nearest(task, sellers(meta["product_id"], meta["size"]))
        assert catalog.stock(meta["product_id"], meta["size"], near) == 0, task["id"]
        assert meta["store_id"] == nearest(task, stocked(meta["product_id"], meta["size"])), task["id"]


def test_position_in_the_intent_never_gives_the_answer_away() -> None:
    """Calories (three products named): the answer is named first, second and third, none of them in more than
    about a third of the tasks (issue 26, principle 3). The hard tasks name no stores (the tour form took the
    named-stores form's numbers)."""
    calories = [t for t in TASKS if t["id"].startswith("shopping-calories-")]
    assert all(len(t["metadata"]["named_products"]) == 3 for t in calories)
    at = [t["metadata"]["named_products"].index(t["metadata"]["product_id"]) for t in calories]
    assert set(at) == {0, 1, 2} and _share(at) <= 0.36, f"the lowest product's places: {at}"
    pairs = [t for t in TASKS if t["id"].startswith("shopping-pair-") and t["metadata"].get("named_stores")]
    assert not pairs, [t["id"] for t in pairs]


def test_the_named_stores_form_is_replaced_by_the_tour_form() -> None:
    """The named-stores form (a store rule passed 10 % of the hard cell) gave its task numbers to the tour
    form, whose plans are many (tests/core/test_shopping_tour.py)."""
    pair = [t for t in TASKS if t["id"].startswith("shopping-pair-")]
    forms = {f: sum(t["metadata"]["form"] == f for t in pair) for f in ("named", "tour", "split")}
    assert forms == {"named": 0, "tour": 18, "split": 42}, forms


# ------------------------------------------------------------------ the split form: two orders at two stores
SPLIT = [t for t in TASKS if t["id"].startswith("shopping-pair-") and t["metadata"]["form"] == "split"]
TO_END = [t for t in SPLIT if "end_id" in t["metadata"]]  # the walk goes on to an end point E
TO_STORE = [t for t in SPLIT if "end_id" not in t["metadata"]]  # the walk ends at the second store


def _store_walk(task: dict, a: str, b: str) -> float:
    nodes = task["metadata"]["store_nodes"]
    return get_world().directions(nodes[a], nodes[b]).distance_m


def _has(store_id: str, product_id: str, size: str) -> bool:
    """The store sells this size and has it in stock."""
    return catalog.get_product(product_id).offer(size, store_id) is not None and \
        catalog.stock(product_id, size, store_id) > 0


def _items(meta: dict) -> list[tuple[str, str]]:
    return list(zip(meta["products"], meta["sizes"], strict=True))


def _pair_cost(meta: dict, a: str, b: str) -> float | None:
    """The least the list costs bought between two stores, each item where it is in stock and cheaper; None
    where neither has some item in stock. Worked out from the catalogue, not the task's metadata."""
    total = 0.0
    for product_id, size in _items(meta):
        product = catalog.get_product(product_id)
        prices = [o.price for sid in (a, b) if (o := product.offer(size, sid)) is not None
                  and _has(sid, product_id, size)]
        if not prices:
            return None
        total += min(prices)
    return round(total, 2)


def _split_world(task: dict) -> tuple[dict[tuple[str, str], float], dict[tuple[str, str], float]]:
    """(pair -> cost, ordered pair -> walk from the start past the first store to the second) for every pair
    of stores that can fill the list."""
    stores = [s.id for s in catalog.load_stores()]
    costs = {(a, b): c for i, a in enumerate(stores) for b in stores[i + 1:]
             if (c := _pair_cost(task["metadata"], a, b)) is not None}
    walks = {(a, b): distance(task, a) + _store_walk(task, a, b) for pair in costs for a, b in (pair, pair[::-1])}
    return costs, walks


def test_split_lists_no_single_store_fills_and_the_goals_name_the_pair() -> None:
    assert len(SPLIT) == 42
    assert {len(t["metadata"]["products"]) for t in SPLIT} == {3, 4}
    for task in SPLIT:
        meta = task["metadata"]
        assert len(set(meta["products"])) == len(meta["products"]), task["id"]
        for store in catalog.load_stores():
            assert not all(_has(store.id, p, s) for p, s in _items(meta)), (task["id"], store.id)
        first, second = meta["store_pair"]
        (web,) = task["web_goals"]
        assert web["kind"] == "orders_split" and web["store_ids"] == [first, second], task["id"]
        assert web["max_total"] == meta["budget"] and f"${meta['budget']:.2f}" in task["intent"], task["id"]
        assert [(i["product_id"], i["size"]) for i in web["items"]] == _items(meta), task["id"]
        if "end_id" in meta:  # past the first store, then the second (graded after the first), ending at E
            passed, then, reached = task["embodied_goals"]
            assert then["kind"] == "passed_place" and then["place_id"] == second, task["id"]
            assert then["after"]["place_id"] == first and then["after"]["node"] == passed["node"], task["id"]
            assert reached["place_id"] == meta["end_id"] and not reached["must_match_order_store"], task["id"]
            assert get_world().places[meta["end_id"]].address in task["intent"], task["id"]
        else:
            passed, reached = task["embodied_goals"]
            assert reached["place_id"] == second and reached["must_match_order_store"], task["id"]
        assert passed["kind"] == "passed_place" and passed["place_id"] == first, task["id"]
        assert passed.get("after") is None and reached["kind"] == "reached_place", task["id"]


def test_split_exactly_one_pair_within_the_budget_walks_shortest() -> None:
    """The target pair fills the list within the budget (by 25 cents or more) and its walk, in the order
    graded, is the shortest of every pair within it: 100 m or more shorter than any other pair's, 150 m or more
    shorter than its own the other way round. A pair with a shorter walk is over the budget (by 25 cents or
    more), and another pair within the budget walks farther. (The tasks without an end point.)"""
    for task in TO_STORE:
        meta, pair = task["metadata"], tuple(task["metadata"]["store_pair"])
        costs, walks = _split_world(task)
        key = pair if pair in costs else pair[::-1]
        budget, target = meta["budget"], walks[pair]
        assert costs[key] <= budget - 0.25, task["id"]
        assert walks[pair[::-1]] - target >= 150, task["id"]
        shorter = [k for k in costs if k != key and min(walks[k], walks[k[::-1]]) < target]
        assert shorter and all(costs[k] >= budget + 0.25 for k in shorter), task["id"]
        rivals = [k for k in costs if k != key and costs[k] <= budget]
        assert rivals and all(min(walks[k], walks[k[::-1]]) - target >= 100 for k in rivals), task["id"]


def test_split_shortcuts_pick_the_target_pair_in_a_third_or_less() -> None:
    """The tempting shortcuts, each worked out here from the catalogue and the map: the pair holding the
    nearest store, the pair that fills the list cheapest, the greedy walk (nearest store first, then the store
    nearest it with the rest in stock) and the pair within the budget nearest the start by the sum of the two
    walks. None picks the target pair in more than about a third of the split tasks; the targets spread over
    every pair of stores, none the target of more than about a third."""
    from collections import Counter

    hits: Counter[str] = Counter()
    targets = [frozenset(t["metadata"]["store_pair"]) for t in SPLIT]
    for task in TO_STORE:
        meta = task["metadata"]
        costs, _walks = _split_world(task)
        target = frozenset(meta["store_pair"])
        stores = [s.id for s in catalog.load_stores()]
        near = min(stores, key=lambda sid: distance(task, sid))
        within = [k for k in costs if costs[k] <= meta["budget"]]
        hits["pair holding the nearest store"] += near in target
        hits["cheapest pair"] += frozenset(min(costs, key=lambda k: costs[k])) == target
        rest = [(p, s) for p, s in _items(meta) if not _has(near, p, s)]
        fill = [sid for sid in stores if sid != near and all(_has(sid, p, s) for p, s in rest)]
        greedy = frozenset((near, min(fill, key=lambda sid: _store_walk(task, near, sid)))) if fill else None
        hits["greedy walk"] += greedy == target
        hits["straight sum"] += frozenset(min(within, key=lambda k: distance(task, k[0]) + distance(task, k[1]))) == target
    for rule in ("pair holding the nearest store", "cheapest pair", "greedy walk", "straight sum"):
        assert hits[rule] <= 0.4 * len(TO_STORE), f"{rule}: {hits[rule]} of {len(TO_STORE)}"
    # the central pair (Target and Trader Joe's) has the shortest walks to most end points: 17 of 42
    assert len(set(targets)) == 6 and _share(targets) <= 0.41, Counter(targets)


def _end_walks(task: dict) -> tuple[dict[tuple[str, str], float], dict[tuple[str, str], float]]:
    """(pair -> cost, ordered pair -> the whole walk S -> first store -> second store -> E) for every pair of
    stores that can fill the list, from the catalogue and the map (not the task's metadata)."""
    world, meta = get_world(), task["metadata"]
    costs, _ = _split_world(task)
    end = world.places[meta["end_id"]].node
    walks = {(a, b): distance(task, a) + _store_walk(task, a, b)
             + world.directions(meta["store_nodes"][b], end).distance_m
             for pair in costs for a, b in (pair, pair[::-1])}
    return costs, walks


def test_split_to_an_end_point_is_most_of_the_form_and_mostly_four_items() -> None:
    assert len(TO_END) >= 30 and len(TO_END) + len(TO_STORE) == 42
    assert sum(len(t["metadata"]["products"]) == 4 for t in TO_END) >= 0.8 * len(TO_END)
    ends = [t["metadata"]["end_id"] for t in TO_END]
    assert len(set(ends)) >= 15 and _share(ends) <= 0.25  # end points spread, not one place


def test_split_to_an_end_point_one_walk_is_shortest_within_the_budget_by_a_margin() -> None:
    """Of every pair that fills the list within the budget, each visited in either order, the graded walk
    (S, first store, second store, E) is the shortest, by 40 m to 150 m over the next (another pair, or the
    same pair the other way round); a shorter walk exists whose pair is over the budget (by 25 cents)."""
    sizes = []
    for task in TO_END:
        meta = task["metadata"]
        costs, walks = _end_walks(task)
        sizes.append(len(walks))
        key = lambda r: r if r in costs else r[::-1]  # noqa: E731
        budget, answer = meta["budget"], tuple(meta["store_pair"])
        within = sorted((r for r in walks if costs[key(r)] <= budget), key=walks.__getitem__)
        assert within[0] == answer, (task["id"], within[:2])
        gap = walks[within[1]] - walks[answer]
        assert 40 <= gap <= 150, (task["id"], gap)
        assert costs[key(answer)] <= budget - 0.25, task["id"]
        shorter = [r for r in walks if walks[r] < walks[answer]]
        assert shorter and all(costs[key(r)] >= budget + 0.25 for r in shorter), task["id"]
        assert len({key(r) for r in within}) >= 2, task["id"]  # more than one pair to choose among
    assert sum(n == 12 for n in sizes) >= len(sizes) / 2  # most lists: every pair fills, 12 walks


def test_split_to_an_end_point_shortcuts_are_wrong_in_most_tasks() -> None:
    """Each tempting shortcut, worked out here from the catalogue and the map, walks the graded order in about
    a third of the end-point tasks or less: the nearest store first (then the partner that makes the rest
    shortest), the pair nearest the start, the pair nearest E, the cheapest pair, the shortest walk past both
    with E not read, the shortest whole walk with the budget not read (never: the budget decides), the best
    walk by straight lines, the pair whose stores are nearest each other, greedy nearest-next (the nearest
    store, then its nearest partner within the budget)."""
    from collections import Counter

    from ewa_mcp.geometry import haversine_m

    world = get_world()
    hits: Counter[str] = Counter()
    for task in TO_END:
        meta = task["metadata"]
        costs, walks = _end_walks(task)
        key = lambda r: r if r in costs else r[::-1]  # noqa: E731
        end = world.places[meta["end_id"]].node
        to_end = {s: world.directions(meta["store_nodes"][s], end).distance_m for p in costs for s in p}
        within = [r for r in walks if costs[key(r)] <= meta["budget"]]
        answer = tuple(meta["store_pair"])
        near = min({r[0] for r in within}, key=lambda s: distance(task, s))
        picks = {
            "nearest store first": min((r for r in within if r[0] == near),
                                       key=lambda r: _store_walk(task, *r) + to_end[r[1]]),
            "pair nearest the start": tuple(sorted(min({key(r) for r in within}, key=lambda p: sum(
                distance(task, s) for s in p)), key=lambda s: distance(task, s))),
            "pair nearest the end": tuple(sorted(min({key(r) for r in within}, key=lambda p: sum(
                to_end[s] for s in p)), key=lambda s: -to_end[s])),
            "cheapest pair": min((r for r in walks if key(r) == min(costs, key=costs.__getitem__)),
                                 key=walks.__getitem__),
            "end point not read": min(within, key=lambda r: distance(task, r[0]) + _store_walk(task, *r)),
            "budget not read": min(walks, key=walks.__getitem__),
            "straight-line best walk": min(within, key=lambda r: sum(
                haversine_m(a.lat, a.lng, b.lat, b.lng) for a, b in zip(
                    [world.node(task["start"]["embodied"]["node"]),
                     *(world.node(meta["store_nodes"][s]) for s in r), world.node(end)],
                    [*(world.node(meta["store_nodes"][s]) for s in r), world.node(end)]))),
            "stores nearest each other": min((r for r in walks if key(r) == min(
                {key(q) for q in within}, key=lambda p: min(_store_walk(task, *p), _store_walk(task, *p[::-1])))),
                key=walks.__getitem__),
            "greedy nearest next": min((r for r in within if r[0] == near), key=lambda r: _store_walk(task, *r)),
        }
        for rule, pick in picks.items():
            hits[rule] += pick == answer
        assert meta["shortcuts"] == {k: list(v) for k, v in picks.items()}, task["id"]  # as the generator saw
    print(dict(hits), len(TO_END), len(SPLIT))
    assert hits["budget not read"] == 0
    for rule, n in hits.items():  # each a third of the end-point tasks or less (chance: about one in ten)
        assert n <= len(TO_END) / 3, f"{rule}: {n} of {len(TO_END)}"


def test_split_to_an_end_point_the_other_order_misses_the_graded_order() -> None:
    """The answer's pair walked the other way round (S, second store, first store, E, on the map's shortest
    legs) never passes the first store and then the second: the order the grader checks is the choice."""
    from ewa_mcp.envs.street.checks import check_passed_place
    from ewa_mcp.envs.street.goals import PassedPlace

    world = get_world()
    for task in TO_END:
        meta = task["metadata"]
        first, second = (meta["store_nodes"][s] for s in meta["store_pair"])
        end = world.places[meta["end_id"]].node
        for order, met in (((first, second), True), ((second, first), False)):
            nodes = [task["start"]["embodied"]["node"]]
            for a, b in zip([nodes[0], *order], [*order, end]):
                nodes += world.directions(a, b).nodes[1:]
            state = {"city": "manhattan", "path_points": [[world.node(n).lat, world.node(n).lng] for n in nodes]}
            goal = PassedPlace.model_validate(task["embodied_goals"][1])
            assert check_passed_place(goal, state, None).met is met, (task["id"], order)


def test_a_list_whose_product_name_holds_a_comma_reads_as_its_items() -> None:
    """"Fluoride Toothpaste, Fresh Mint" in a comma list read as two items (a play-tester counted four of
    three): such a list is separated by semicolons, and every item is named whole with its size."""
    checked = 0
    for task in TASKS:
        meta = task["metadata"]
        if "products" not in meta:
            continue
        names = [catalog.get_product(p).name for p in meta["products"]]
        named = [f"{name} ({size})" for name, size in zip(names, meta["sizes"], strict=True)]
        assert all(item in task["intent"] for item in named), task["id"]
        if any("," in name for name in names):
            checked += 1
            listing = "; ".join(named[:-1]) + "; and " + named[-1]
            assert listing in task["intent"], task["id"]
    assert checked > 0
