"""Shopping tasks: compare products online (price, size, calories, store distance), order one for pickup,
get directions, and walk to that very store (or walk first, then order)."""

from __future__ import annotations

import itertools
import math
from typing import Any

from ewa_mcp.geometry import haversine_m
from ewa_mcp.graders.textnorm import is_number, tokens
from ..world import get_world
from ewa_mcp.core.taskmodel import AnswerNumbers, StartState, Task, TextAnswer
from ewa_mcp.envs.browser.goals import ItemRef, OrderPlaced, OrdersSplit, WebStart
from ewa_mcp.envs.street.goals import PassedPlace, ReachedPlace, StreetStart, Waypoint
from ewa_mcp.websites.shop import catalog
from ewa_mcp.taskgen.answer_checks import CALORIES, answer_rule, committed_answer
from ewa_mcp.taskgen.common import WALK_RULE, call, ref, rng_for, site_url, step_budget

PER_TEMPLATE = 60
MAX_WALK_M = 2200.0
# Hard basket tasks: no total within this many dollars of the budget, and no tie for "cheapest for the three".
PAIR_MARGIN = 0.25
PAIR_TRIES = 4000
# How the two rival stores of the named-stores form fail: both over the budget (the answer is the cheapest of
# the three), one sold out of an item and cheaper plus one over the budget, both sold out and cheaper (the
# answer is the dearest). Cycled, so "the cheapest total" and "all three in stock" each pick it a third of
# the time.
RIVAL_KINDS = (("budget", "budget"), ("stock", "budget"), ("stock", "stock"))
# The named form's (answer's distance rank among the three named, among all four stores), cycled: nearest of
# all, the middle named one (second or third of all), farthest of all. With the other form's second and third
# of all, no distance rank among all the stores answers more than about a third of the hard tasks.
NAMED_RANKS = ((0, 0), (1, 1), (2, 3), (0, 0), (1, 2), (2, 3))


def buy_oracle(product: Any, size: str, store: Any) -> list[Any]:
    return [call("browser_goto", url=site_url("shop", f"/product/{product.id}")),
            call("browser_type", element=ref("combobox", "Size"), text=size),
            call("browser_type", element=ref("combobox", "Store"), text=store.name),
            call("browser_click", element=ref("button", "Add to cart")),
            call("browser_goto", url=site_url("shop", "/checkout")),
            call("browser_click", element=ref("button", "Place order"))]


def in_stock(product: Any, size: str, store_id: str) -> bool:
    try:
        return catalog.stock(product.id, size, store_id) > 0
    except catalog.CatalogError:  # that store does not sell it
        return False


def first_listed_store(product: Any, size: str, stocked_only: bool = False) -> str | None:
    """The store the product page lists first (its Store menu's default), optionally among those with stock."""
    for store in catalog.load_stores():
        if product.offer(size, store.id) is not None and (not stocked_only or in_stock(product, size, store.id)):
            return store.id
    return None


def seller_ids(product: Any, size: str) -> list[str]:
    """Stores that sell this size (in stock or not), in the order the product page lists them."""
    return [s.id for s in catalog.load_stores() if product.offer(size, s.id) is not None]


def slots(out: list[Task]) -> Any:
    """Task numbers to fill until a template has PER_TEMPLATE tasks; a rejected draw costs a try, not a slot."""
    for _ in range(PER_TEMPLATE * 100):
        if len(out) >= PER_TEMPLATE:
            return
        yield len(out)


def balanced(draw: Any, key: Any, counts: dict[str, int], tries: int = 400) -> Any:
    """Draw candidates (``draw()`` returns one or None) until one whose ``key`` is among the least used so far
    (``counts``, every possible key present); after ``tries`` draws, the least used one seen. Targets spread
    over every store (issue 26: no store the target of most tasks, none never), deterministically."""
    best, best_count = None, None
    for _ in range(tries):
        cand = draw()
        if cand is None:
            continue
        k = key(cand)
        if counts[k] == min(counts.values()):
            best = cand
            break
        if best_count is None or counts[k] < best_count:
            best, best_count = cand, counts[k]
    if best is not None:
        counts[key(best)] += 1
    return best


class Context:
    def __init__(self) -> None:
        self.world = get_world()
        self.products = [p for p in catalog.load_products() if p.offers]
        self.stores = {s.id: s for s in catalog.load_stores()}
        self.store_places = {p.id: p for p in self.world.stores()}
        # Starting points: Manhattan landmarks and stations within walking range of every store.
        starts = []
        for p in sorted(self.world.places.values(), key=lambda p: p.id):
            if p.city != "manhattan" or p.kind not in ("landmark", "station", "park", "museum"):
                continue
            try:
                dists = [self.world.directions(p.node, s.node).distance_m for s in self.store_places.values()]
            except ValueError:
                continue
            if max(dists) <= MAX_WALK_M:
                starts.append(p)
        self.starts = starts
        # Hard pair tasks start from any named place in range (hotels, theaters, restaurants too): from the
        # landmarks alone, a store far from all of them is almost never the nearest within a budget.
        self.pair_starts = [p for p in sorted(self.world.places.values(), key=lambda p: p.id)
                            if p.city == "manhattan" and p.kind not in ("store", "shop", "intersection", "address")
                            and self._in_range(p)]
        self._walks: dict[tuple[Any, str], Any] = {}

    def _in_range(self, place: Any) -> bool:
        try:
            return max(self.world.directions(place.node, s.node).distance_m
                       for s in self.store_places.values()) <= MAX_WALK_M
        except ValueError:
            return False

    def reaches_stores(self, place: Any) -> bool:
        """Every store can be walked to from this place."""
        try:
            return all(self.walk(place, sid) is not None for sid in self.stores)
        except ValueError:
            return False

    def store_counts(self) -> dict[str, int]:
        """A zero count per store (``balanced`` spreads task targets over them)."""
        return {sid: 0 for sid in self.stores}

    def walk(self, start: Any, store_id: str) -> Any:
        key = (start.node, store_id)
        if key not in self._walks:
            self._walks[key] = self.world.directions(start.node, self.store_places[store_id].node)
        return self._walks[key]

    def nearest(self, start: Any, store_ids: list[str]) -> str | None:
        """The nearest on foot of these stores, or None when the two nearest are too close to call (< 100 m)."""
        ranked = sorted(store_ids, key=lambda sid: self.walk(start, sid).distance_m)
        if len(ranked) > 1 and self.walk(start, ranked[1]).distance_m - self.walk(start, ranked[0]).distance_m < 100:
            return None
        return ranked[0] if ranked else None

    def cheapest_is_decisive(self, start: Any, product: Any, size: str, store_id: str) -> bool:
        """Ignoring "cheapest" must fail for the walk: the cheapest store is not the nearest seller. The first
        listed store is not excluded: the product page lists every store in one fixed order, so excluding it
        would make one store never a target; balancing the targets (``balanced``) leaves any one store,
        the first listed included, right for about a quarter of the tasks."""
        return self.nearest(start, seller_ids(product, size)) not in (None, store_id)


class Legs:
    """The map's shortest walks between nodes, each worked out once (the generators price every order of every
    set of stores from several starts and end points, over thousands of drawn lists): ``route`` the walk,
    ``metres`` its length, ``between`` two stores' length by their ids, ``to_end`` a store's to a place."""

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        self._routes: dict[tuple[str, str], Any] = {}

    def route(self, a_node: str, b_node: str) -> Any:
        if (a_node, b_node) not in self._routes:
            self._routes[(a_node, b_node)] = self.ctx.world.directions(a_node, b_node)
        return self._routes[(a_node, b_node)]

    def metres(self, a_node: str, b_node: str) -> float:
        return float(self.route(a_node, b_node).distance_m)

    def between(self, a: str, b: str) -> float:
        return self.metres(self.ctx.store_places[a].node, self.ctx.store_places[b].node)

    def to_end(self, end: Any, sid: str) -> float:
        return self.metres(self.ctx.store_places[sid].node, end.node)


def _task(ctx: Context, tid: str, intent: str, start: Any, product: Any, size: str, store_id: str,
          rng: Any, answer: TextAnswer | None = None, walk_first: bool = False,
          difficulty: str = "medium") -> Task:
    store = ctx.stores[store_id]
    place = ctx.store_places[store_id]
    route = ctx.walk(start, store_id)
    node = ctx.world.node(place.node)
    web = [*buy_oracle(product, size, store),
           call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": store_id}))]
    walk = [call("street_move", neighbour=n) for n in route.nodes[1:]] + [call("street_stop")]
    finish = call("finish_episode", **({"answer": answer.must_include[0]} if answer else {}))
    if walk_first:
        oracle = [call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": store_id})),
                  call("switch_environment", target="embodied", message="walk to the store"), *walk,
                  call("switch_environment", target="web", message="order for pickup"),
                  *buy_oracle(product, size, store), finish]
    else:
        oracle = [*web, call("switch_environment", target="embodied", message="walk to the pickup store"), *walk,
                  finish]
    links = ctx.world.neighbours(start.node)
    return Task(
        id=tid, domain="shopping", difficulty=difficulty, intent=intent,
        start=StartState(environment="embodied" if walk_first else "web", web=WebStart(start_url="shop:/"),
                         embodied=StreetStart(city="manhattan", node=start.node,
                                              heading=round(rng.choice([lk.heading for lk in links]), 1))),
        web_goals=[OrderPlaced(product_id=product.id, size=size, quantity=1, store_id=store_id)],
        embodied_goals=[ReachedPlace(city="manhattan", node=place.node, lat=node.lat, lng=node.lng,
                                     place_id=store_id, must_match_order_store=True)],
        answer=answer,
        step_limit=step_budget("shopping", difficulty, len(oracle)),
        oracle=oracle,
        metadata={"store_nodes": {sid: p.node for sid, p in ctx.store_places.items()},
                  "shortest_path_m": route.distance_m, "start_lat": ctx.world.node(start.node).lat,
                  "start_lng": ctx.world.node(start.node).lng, "product_id": product.id, "size": size,
                  "store_id": store_id, "walk_first": walk_first},
    )


# Other ways of writing a size unit, accepted in answers ("1 litre" for "1 L").
UNIT_WORDS = {"l": ["litre", "liter", "litres", "liters"], "oz": ["ounce", "ounces"], "fl oz": ["fluid ounces"],
              "lb": ["pound", "pounds"], "gal": ["gallon", "gallons"], "qt": ["quart", "quarts"],
              "pt": ["pint", "pints"], "ct": ["count"], "ml": ["millilitres", "milliliters"], "g": ["grams"]}


def size_unit(label: str) -> str | None:
    """The unit written after a size label's last number: "oz" in "24 oz loaf", "fl oz" in "33.8 fl oz"."""
    toks = tokens(label)
    numbers = [i for i, t in enumerate(toks) if is_number(t)]
    if not numbers or numbers[-1] + 1 >= len(toks):
        return None
    unit = toks[numbers[-1] + 1: numbers[-1] + 3]
    return " ".join(unit) if unit[0] in ("fl", "sq") and len(unit) == 2 else unit[0]


def size_aliases(label: str) -> tuple[list[str], list[str]]:
    """(aliases, units) of a size label: "29 ounces" for "29 oz", "1 litre" for "1 L"."""
    unit = size_unit(label)
    if unit is None:
        return [], []
    toks = tokens(label)
    units = [unit, *UNIT_WORDS.get(unit, [])]
    at = next(i for i in range(len(toks)) if " ".join(toks[i:i + len(unit.split())]) == unit and i > 0
              and is_number(toks[i - 1]))
    quantity = toks[:at]
    return [" ".join([*quantity, u]) for u in units], units


def size_answer(product: Any, label: str, context: list[str]) -> TextAnswer:
    """The size asked for, told apart from the product's other sizes (in every wording) and any other
    amount in its unit."""
    aliases, units = size_aliases(label)
    others = [s.label for s in product.sizes if s.label != label]
    rivals = [*others, *(a for o in others for a in size_aliases(o)[0])]
    return committed_answer(label, rivals, aliases=aliases, context=[product.name, *context],
                            numbers=AnswerNumbers(units=units, bare=False) if units else None)


def cheapest_tasks(ctx: Context) -> list[Task]:
    out: list[Task] = []
    rng = rng_for("shopping", "cheapest")
    counts = ctx.store_counts()

    def draw() -> Any:
        product = rng.choice(ctx.products)
        size = rng.choice(product.sizes).label
        store_id = catalog.cheapest_store(product.id, size)
        start = rng.choice(ctx.starts)
        if not in_stock(product, size, store_id) or not ctx.cheapest_is_decisive(start, product, size, store_id):
            return None
        return product, size, store_id, start

    for n in slots(out):
        picked = balanced(draw, lambda c: c[2], counts)
        if picked is None:
            continue
        product, size, store_id, start = picked
        walk_first = n % 4 == 3
        intent = (f"Buy me {product.name} ({size}) for pickup at the store that sells it cheapest, "
                  f"then walk there from {start.name} to pick it up. {WALK_RULE}") if not walk_first else (
                  f"Walk from {start.name} to the store that sells {product.name} ({size}) cheapest, "
                  f"and order it online for pickup there once you have arrived. {WALK_RULE}")
        out.append(_task(ctx, f"shopping-cheapest-{n:03d}", intent, start, product, size, store_id, rng,
                         walk_first=walk_first, difficulty="easy"))
    return out


def _amount(size: Any) -> int:
    """A size's grams or millilitres (the sizes compared here have one of them)."""
    return int(size.grams or size.ml or 0)


def _nutrition(product: Any) -> Any:
    """A food's nutrition (the products compared here have it)."""
    assert product.nutrition is not None
    return product.nutrition


def size_tasks(ctx: Context) -> list[Task]:
    out: list[Task] = []
    rng = rng_for("shopping", "size")
    candidates = [p for p in ctx.products if len([s for s in p.sizes if s.grams or s.ml]) >= 2]
    counts = ctx.store_counts()
    position = ["first"]

    def draw() -> Any:
        # The answer's place in the size list rotates (first, last, a middle one where a product has three
        # sizes), so neither "the first listed" nor "the last listed" size answers most questions.
        where = position[0]
        pool = [p for p in candidates if len([s for s in p.sizes if s.grams or s.ml]) >= 3] if where == "middle" \
            else candidates
        product = rng.choice(pool)
        sizes = sorted([s for s in product.sizes if s.grams or s.ml], key=_amount)
        index = 0 if where == "first" else len(sizes) - 1 if where == "last" else rng.randrange(1, len(sizes) - 1)
        target = sizes[index]
        if index == 0:  # the smallest is enough: ask for a little less than it holds
            amount = max(1, int(_amount(target) * rng.uniform(0.5, 0.9)))
        else:
            below = sizes[index - 1]
            amount = _amount(below) + max(1, (_amount(target) - _amount(below)) // 2)
        store_id = catalog.cheapest_store(product.id, target.label)
        start = rng.choice(ctx.starts)
        # The cheapest store decides the walk: it is not the nearest seller.
        if not in_stock(product, target.label, store_id) or not ctx.cheapest_is_decisive(
                start, product, target.label, store_id):
            return None
        return product, target, amount, store_id, start

    for n in slots(out):
        position[0] = ("first", "last", "middle")[n % 3]
        picked = balanced(draw, lambda c: c[3], counts)
        if picked is None:
            continue
        product, target, amount, store_id, start = picked
        unit = "g" if target.grams else "ml"
        intent = (f"What size of {product.name} should I buy if I need at least {amount} {unit}? Buy the smallest "
                  f"size that is enough, at the store where that size is cheapest, then walk there from "
                  f"{start.name}. {WALK_RULE} Tell me the size. "
                  + answer_rule("Answer with the size as the shop labels it."))
        if any(t.intent == intent for t in out):
            counts[store_id] -= 1
            continue  # the same question twice
        task = _task(ctx, f"shopping-size-{n:03d}", intent, start, product, target.label, store_id, rng,
                     answer=size_answer(product, target.label, [f"{amount} {unit}"]))
        task.metadata["need"] = {"amount": amount, "unit": unit}
        out.append(task)
    return out


def calorie_tasks(ctx: Context) -> list[Task]:
    out: list[Task] = []
    rng = rng_for("shopping", "calories")
    counts = ctx.store_counts()
    foods = [p for p in ctx.products if p.nutrition is not None]
    for n in slots(out):
        # Three products, so "the first named" (or any one place) answers about a third of the questions.
        three = rng.sample(foods, 3)
        if len({_nutrition(p).calories for p in three}) < 3:
            continue
        low, *higher = sorted(three, key=lambda p: _nutrition(p).calories)
        # The lowest product is named first, second or third in turn, so no place in the question answers
        # without reading the calories.
        rng.shuffle(higher)
        named = [*higher]
        named.insert(n % 3, low)
        size = low.sizes[0].label  # not named in the intent: it would tell which product is lower
        start = rng.choice(ctx.starts)
        # The named store decides too: it is not the store an agent ignoring the name would pick (the
        # nearest seller, the first listed, the cheapest for that size).
        sellers = seller_ids(low, size)
        ignored = {ctx.nearest(start, sellers), first_listed_store(low, size), catalog.cheapest_store(low.id, size)}
        stocked = [sid for sid in sellers if in_stock(low, size, sid) and sid not in ignored]
        if not stocked or None in ignored:
            continue
        store_id = min(rng.sample(stocked, len(stocked)), key=lambda sid: counts[sid])  # the least used so far
        intent = (f"How many calories are in {named[0].name}, {named[1].name} and {named[2].name} per serving? "
                  f"I need to select the lowest one: "
                  f"order it, in the first size the shop lists for it, for pickup at {ctx.stores[store_id].name}, "
                  f"walk there from {start.name}, and tell me its calories per serving. {WALK_RULE} "
                  + answer_rule("Answer with that number of calories."))
        check = committed_answer(str(_nutrition(low).calories),
                                 [r for p in higher for r in (p.name, str(_nutrition(p).calories))],
                                 context=[low.name, *(s.label for s in low.sizes), _nutrition(low).serving_size],
                                 numbers=CALORIES)
        if any(t.intent == intent for t in out):
            continue  # the same question twice
        counts[store_id] += 1
        task = _task(ctx, f"shopping-calories-{n:03d}", intent, start, low, size, store_id, rng, answer=check)
        task.metadata["named_products"] = [p.id for p in named]
        out.append(task)
    return out


# The released suite has 51 "nearest" tasks (the pool was exhausted when the first listed store was excluded);
# task ids are kept, so the family keeps that size now that the pool is larger.
NEAREST_TASKS = 51


def nearest_tasks(ctx: Context) -> list[Task]:
    out: list[Task] = []
    rng = rng_for("shopping", "nearest")
    sold_out = [(p, o.size) for p in ctx.products for o in p.offers if o.stock == 0
                and any(q.size == o.size and q.stock > 0 for q in p.offers)]
    seen: set[tuple[str, str, str]] = set()
    counts = ctx.store_counts()

    def draw() -> Any:
        # "that has it in stock" must decide: the nearest store selling this size has none on the shelf.
        product, size = rng.choice(sold_out)
        start = rng.choice(ctx.starts)
        if (product.id, size, start.id) in seen:
            return None  # few product sizes are sold out somewhere: do not ask the same thing twice
        sellers = seller_ids(product, size)
        stocked = [sid for sid in sellers if in_stock(product, size, sid)]
        nearest_seller, store_id = ctx.nearest(start, sellers), ctx.nearest(start, stocked)
        if nearest_seller is None or store_id is None or in_stock(product, size, nearest_seller):
            return None  # too close to call, or the nearest seller has stock
        # "closest to me" must decide too: the answer is not the cheapest store in stock. (The first listed
        # store is not excluded: targets are balanced over the stores instead, see ``balanced``.)
        if store_id == catalog.cheapest_store(product.id, size):
            return None
        return product, size, start, store_id

    for n in slots(out):
        if len(out) >= NEAREST_TASKS:
            break
        picked = balanced(draw, lambda c: c[3], counts)
        if picked is None:
            continue
        product, size, start, store_id = picked
        seen.add((product.id, size, start.id))
        intent = (f"I am at {start.name}. Buy me {product.name} ({size}) for pickup at the store closest to me "
                  f"on foot that has it in stock, then walk there. {WALK_RULE}")
        out.append(_task(ctx, f"shopping-nearest-{n:03d}", intent, start, product, size, store_id, rng))
    return out


# Items in one hard order: three prices at each of the four stores, added by the agent (the checkout shows
# the chosen store's total only, so the comparison across stores is the agent's arithmetic).
BASKET_ITEMS = 3


def basket_total(items: list[tuple[Any, str]], store_id: str) -> float | None:
    """What the items cost together at one store, or None when it does not sell every one."""
    offers = [product.offer(size, store_id) for product, size in items]
    return None if any(o is None for o in offers) else round(sum(o.price for o in offers if o is not None), 2)


def pair_budget(total: float, over: list[float]) -> float | None:
    """A round budget (whole or half dollars) that the answer's total fits with a margin and that every total
    in ``over`` exceeds with a margin, or None when none fits (the budget must decide, never by a cent)."""
    for step in (1.0, 0.5):
        budget = math.ceil((total + PAIR_MARGIN) / step) * step
        if all(t >= budget + PAIR_MARGIN for t in over):
            return budget
    return None


def _listing(items: list[tuple[Any, str]]) -> str:
    """ "A (s), B (s) and C (s)" as the intent names them; with semicolons where a name holds a comma
    ("Fluoride Toothpaste, Fresh Mint" read as two items in a comma list)."""
    named = [f"{p.name} ({size})" for p, size in items]
    sep = "; " if any("," in p.name for p, _ in items) else ", "
    return sep.join(named[:-1]) + (";" if sep == "; " else "") + " and " + named[-1]


# The split form of the hard pair tasks (issue 26, principle 6): a list no single store has in stock, bought in
# two orders at two stores within one budget, on the shortest walk from the start past one store to the other.
SPLIT_ITEMS = (4, 3)  # four items where the stock allows (more splits per pair to price), else three
SPLIT_MAX_WALK_M = 3500.0  # the whole walk, start past both stores to the end point: about 175 moves, which
# leaves the hard step budget (280) room for some 60 steps of reading prices and routes beyond the oracle's
SPLIT_PLACE_TRIES = 6  # starts and end points tried for one list
SPLIT_SINGLE_SHARE = 0.8  # of the four items, each lacking at one store: this share lack it there alone
SPLIT_GAP_M = 40.0  # the answer's walk beats every other walk within the budget (other pairs, its own pair the
# other way round) by at least this much: clear on the map's rounding (to 10 m)
SPLIT_GAP_MAX_M = 150.0  # and by at most this much: close enough that estimating the sums can pick a rival
SPLIT_END_GAP_M = 60.0  # the end point stands this far or more from both stores of the answer (straight line)
SPLIT_END_MAX_WALK_M = 4200.0  # with an end point: about 210 moves, as the tour form's (the hard step budget is
# 320 since that form): walks over the outer stores (CVS, Whole Foods) fit, so the answers are not mostly the
# central pair (Target and Trader Joe's), which the pair rules (nearest E, stores nearest each other) pick
SPLIT_END_TASKS = 33  # of the 42 split numbers, those with an end point (the rest end at the second store)
SPLIT_PAIR_SHARE = 0.36  # no pair of stores the answer of more than this share of split tasks
SPLIT_LAST_SHARE = 0.4  # no store the last before E in more than this share of the end-point tasks
SPLIT_SHORTCUT_SHARE = 0.33  # each tempting shortcut picks the answer's walk in at most this share of the
# end-point tasks; the pick takes the lowest cap that still fills SPLIT_END_TASKS (``split_choose``)
SPLIT_PAIR_GAP_M = 100.0  # without an end point: the target walk beats every other pair within the budget by this
SPLIT_ORDER_GAP_M = 150.0  # and its own pair visited the other way round by this much: the order is graded
SPLIT_V9_SHARE = 0.3  # and each of its shortcuts picks the target pair in at most this share of those tasks
SPLIT_ROUNDS = 8
SPLIT_SHORTCUTS_RIGHT = 2  # of them, at most this many pick the answer in any one task: the shares stay even
SPLIT_POOL_DRAWS = 30000  # lists drawn (of four items, then of three) for the pool the suite is picked from
SPLIT_SHORTCUTS = ("nearest store first", "pair nearest the start", "pair nearest the end", "cheapest pair",
                   "end point not read", "budget not read", "straight-line best walk", "stores nearest each other",
                   "greedy nearest next")
# Named-stores tasks (the rest are the split form). A store rule picks among the three stores named, right in a
# third of them by construction (positions and ranks are cycled), and wrong in every split task: 18 of 60 keeps
# any such rule at 10 % of the hard tasks (the bar for heuristics), and six full cycles of the named
# form's cells (NAMED_RANKS, RIVAL_KINDS, the answer's place in the sentence).
NAMED_TASKS = 18


def pair_key(a: str, b: str) -> str:
    """A pair of stores, unordered, as metadata names it ("a|b", ids sorted)."""
    return "|".join(sorted((a, b)))


def split_prices(items: list[tuple[Any, str]], pair: tuple[str, str]) -> list[tuple[str, float]] | None:
    """Where each item is cheapest between the pair's two stores among those with it in stock, and its price
    there; None when neither has some item in stock."""
    out = []
    for product, size in items:
        offers = [(sid, o.price) for sid in pair if (o := product.offer(size, sid)) is not None
                  and in_stock(product, size, sid)]
        if not offers:
            return None
        out.append(min(offers, key=lambda x: x[1]))
    return out


def split_costs(items: list[tuple[Any, str]], store_ids: list[str]) -> dict[str, float]:
    """Every pair of stores that can fill the list between them (``pair_key``), with the least it costs there."""
    costs = {}
    for i, a in enumerate(store_ids):
        for b in store_ids[i + 1:]:
            prices = split_prices(items, (a, b))
            if prices is not None:
                costs[pair_key(a, b)] = round(sum(p for _, p in prices), 2)
    return costs


def split_shortcuts(within: list[tuple[str, str]], costs: dict[str, float], from_start: dict[str, float],
                    to_end: dict[str, float], between: Any, line: Any) -> dict[str, tuple[str, str] | None]:
    """The walk (first store, second store) each tempting shortcut picks, or None where it picks none.
    ``within`` is every order of visiting every pair that fills the list within the budget; ``costs`` every
    pair that fills it at all (``pair_key``). The shortcuts: the store nearest the start first, then the
    partner that makes the rest of the walk shortest; the pair nearest the start (sum of the two walks from
    it), nearer store first; the pair nearest the end point, ending at the store nearer it; the cheapest
    pair, in its shorter order; the shortest walk from the start past both stores, the end point not read
    (the rule before the end point was added); the shortest whole walk over every pair, the budget not read;
    the shortest walk within the budget by straight lines (``line``, a walk's straight-line metres S, first,
    second, E); the pair within the budget whose two stores are nearest each other on foot, in its shorter
    order; greedy nearest-next (the store nearest the start among those in a pair within the budget, then
    the partner within the budget nearest it, E not read)."""
    route = {(a, b): from_start[a] + between(a, b) + to_end[b] for k in costs for a, b in
             (k.split("|"), k.split("|")[::-1])}
    pairs = sorted({pair_key(a, b) for a, b in within})

    def best_order(k: str) -> tuple[str, str]:
        a, b = k.split("|")
        return min(((a, b), (b, a)), key=lambda r: route[r])

    out: dict[str, tuple[str, str] | None] = {name: None for name in SPLIT_SHORTCUTS}
    if not within:
        return out
    nearest = min({a for a, _ in within}, key=lambda sid: from_start[sid])
    out["nearest store first"] = min((r for r in within if r[0] == nearest),
                                     key=lambda r: between(*r) + to_end[r[1]])
    near_start = min(pairs, key=lambda k: sum(from_start[s] for s in k.split("|")))
    out["pair nearest the start"] = tuple(sorted(near_start.split("|"), key=lambda s: from_start[s]))  # type: ignore[assignment]
    near_end = min(pairs, key=lambda k: sum(to_end[s] for s in k.split("|")))
    out["pair nearest the end"] = tuple(sorted(near_end.split("|"), key=lambda s: -to_end[s]))  # type: ignore[assignment]
    out["cheapest pair"] = best_order(min(costs, key=lambda k: costs[k]))
    out["end point not read"] = min(within, key=lambda r: from_start[r[0]] + between(*r))
    out["budget not read"] = min(route, key=lambda r: route[r])
    out["straight-line best walk"] = min(within, key=line)
    out["stores nearest each other"] = best_order(min(pairs, key=lambda k: min(
        between(*k.split("|")), between(*k.split("|")[::-1]))))
    out["greedy nearest next"] = min((r for r in within if r[0] == nearest), key=lambda r: between(*r))
    return out


def _near_in_order(world: Any, nodes: list[str], first: Any, second: Any, radius: float = 25.0) -> bool:
    """A walk along these nodes passes ``first`` and, at that moment or later, ``second`` (as the grader's
    ``passed_place`` with ``after`` reads it)."""
    points = [world.node(n) for n in nodes]
    near = [[haversine_m(p.lat, p.lng, q.lat, q.lng) <= radius for p in points] for q in (first, second)]
    at = next((i for i, hit in enumerate(near[0]) if hit), None)
    return at is not None and any(near[1][at:])


def lacking_sets(ctx: Context, store_ids: list[str]) -> tuple[dict[frozenset[str], list[tuple[Any, str]]],
                                                                list[frozenset[str]]]:
    """Items (product, size) by the set of stores that lack them (sold out or not sold), and those sets in a
    fixed order. A split list is drawn set by set, each as likely as the next: drawn item by item, nearly
    every list of three or four has a store with all of them."""
    lacking: dict[frozenset[str], list[tuple[Any, str]]] = {}
    for product in ctx.products:
        for size in product.sizes:
            missing = frozenset(sid for sid in store_ids if not in_stock(product, size.label, sid))
            if missing and len(missing) < len(store_ids):
                lacking.setdefault(missing, []).append((product, size.label))
    return lacking, sorted(lacking, key=sorted)


def walk_places(ctx: Context) -> list[Any]:
    """Every named Manhattan place a walk to the stores can start (or end) at, in id order."""
    return [p for p in sorted(ctx.world.places.values(), key=lambda p: p.id) if p.city == "manhattan"
            and p.kind not in ("store", "shop", "intersection", "address") and ctx.reaches_stores(p)]


def split_tasks(ctx: Context, numbers: list[int]) -> dict[int, Task]:
    """The split form for the task numbers given: four items where stock allows (else three), no store with
    all of them in stock, so two orders at two stores; then the goods are carried to an end point E. Every
    pair of stores that can fill the list is a candidate, priced at the cheaper store of the two for each item,
    and each pair can be visited in two orders: up to 12 walks from the start S past the first store and the
    second to E. The answer is the shortest whole walk among the pairs within the budget. Each part decides:
    some walk shorter than the answer's is over the budget; the next walk within it (another pair, or the same
    pair the other way round) is longer by SPLIT_GAP_M to SPLIT_GAP_MAX_M (clear on the map's rounding, close
    enough that estimating can pick it); the shortcuts (``split_shortcuts``) each pick the answer's walk in at
    most about a third of the tasks. Answers spread over the six pairs."""
    rng = rng_for("shopping", "pair-split")
    store_ids = list(ctx.stores)
    legs = Legs(ctx)
    leg, between, to_end = legs.route, legs.between, legs.to_end

    pairs = {pair_key(a, b): 0 for i, a in enumerate(store_ids) for b in store_ids[i + 1:]}
    lacking, kinds = lacking_sets(ctx, store_ids)
    # Starts and ends between stores far apart are where the walks rank the pairs and orders differently
    # from the shortcuts.
    places = walk_places(ctx)
    by_store: dict[str, list[Any]] = {}
    by_pair: dict[str, list[Any]] = {}
    for place in places:
        near = {sid: ctx.walk(place, sid).distance_m for sid in store_ids}
        by_store.setdefault(min(store_ids, key=near.__getitem__), []).append(place)
        by_pair.setdefault(min(pairs, key=lambda k: sum(near[sid] for sid in k.split("|"))), []).append(place)
    pair_cap = int(SPLIT_PAIR_SHARE * len(numbers))
    want = {"items": SPLIT_ITEMS[0]}

    def draw() -> list[Any] | None:
        if want["items"] == len(store_ids):
            # One item missing at each store (most often there alone): no store fills the list, and most
            # pairs of stores fill it between them, so up to 12 walks are candidates.
            sets = [frozenset([sid]) if rng.random() < SPLIT_SINGLE_SHARE or not (
                    wider := [k for k in kinds if sid in k and len(k) > 1]) else rng.choice(wider)
                    for sid in store_ids]
            items = [rng.choice(lacking[k]) for k in sets]
            rng.shuffle(items)
        else:
            items = [rng.choice(lacking[rng.choice(kinds)]) for _ in range(want["items"])]
        if len({p.id for p, _ in items}) < len(items):
            return None  # one product twice
        if any(all(in_stock(p, size, sid) for p, size in items) for sid in store_ids):
            return None  # some store fills the list alone
        costs = split_costs(items, store_ids)
        found = []  # every walk that can be the answer, from every start and end point tried
        for _ in range(SPLIT_PLACE_TRIES):  # the list is the rare part: try it from several places
            # Starts drawn evenly by their nearest store, end points by their nearest pair of stores: drawn
            # uniformly, most places lie nearest the central stores, and "go to the nearest" would answer.
            start = rng.choice(by_store[rng.choice(sorted(by_store))])
            end = rng.choice(by_pair[rng.choice(sorted(by_pair))])
            if start.node == end.node or start.id == end.id:
                continue
            from_start = {sid: ctx.walk(start, sid).distance_m for sid in store_ids}
            ends = {sid: to_end(end, sid) for sid in store_ids}
            route = {(a, b): from_start[a] + between(a, b) + ends[b] for k in costs
                     for a, b in (k.split("|"), k.split("|")[::-1])}
            ranked = sorted(route, key=lambda r: route[r])
            for at in range(1, len(ranked)):  # never the shortest walk: the budget must decide
                target = ranked[at]
                key = pair_key(*target)
                if any(pair_key(*r) == key for r in ranked[:at]):
                    continue  # its own pair the other way round is shorter
                budget = pair_budget(costs[key], [costs[pair_key(*r)] for r in ranked[:at]])
                if budget is None:
                    continue
                within = [r for r in ranked if costs[pair_key(*r)] <= budget]
                gap = route[within[1]] - route[target]
                if len({pair_key(*r) for r in within}) < 2 or not SPLIT_GAP_M <= gap <= SPLIT_GAP_MAX_M:
                    continue  # another pair within the budget, and the next walk close but clear of the answer
                if route[target] > SPLIT_END_MAX_WALK_M:
                    continue  # the walk must fit the step budget
                first, second = target
                at_end = ctx.world.node(end.node)
                if any(haversine_m(at_end.lat, at_end.lng, q.lat, q.lng) < SPLIT_END_GAP_M
                       for q in (ctx.world.node(ctx.store_places[sid].node) for sid in target)):
                    continue  # E no store's doorstep: ending there is not ending at a store
                back = [*leg(start.node, ctx.store_places[second].node).nodes,
                        *leg(ctx.store_places[second].node, ctx.store_places[first].node).nodes[1:],
                        *leg(ctx.store_places[first].node, end.node).nodes[1:]]
                if _near_in_order(ctx.world, back, ctx.world.node(ctx.store_places[first].node),
                                  ctx.world.node(ctx.store_places[second].node)):
                    continue  # the pair walked the other way round would pass both in the graded order too
                s_at = ctx.world.node(start.node)

                def line(r: tuple[str, str]) -> float:
                    way = [s_at, *(ctx.world.node(ctx.store_places[x].node) for x in r), at_end]
                    return sum(haversine_m(a.lat, a.lng, b.lat, b.lng) for a, b in zip(way, way[1:]))

                picked = split_shortcuts(within, costs, from_start, ends, between, line)
                if sum(r == target for r in picked.values()) > SPLIT_SHORTCUTS_RIGHT:
                    continue  # too many shortcuts right at once: their shares could not stay even
                found.append((items, start, end, target, budget, costs, route, picked, gap))
        return found

    # A pool of drawn tasks, then the suite picked from it: among the candidates that keep every shortcut
    # within its share and every pair within its cap, each task number takes the one with the fewest
    # shortcuts right, then the least used pair (the pairs with the shortest walks would gather most
    # answers), then the least used end point and start.
    pool: list[Any] = []
    for want["items"] in SPLIT_ITEMS:  # four items where the stock allows, else three
        for _ in range(SPLIT_POOL_DRAWS):
            pool.extend(draw() or [])
    picks = split_choose(pool, numbers, pairs, places)
    out: dict[int, Task] = {}
    for n, pick in zip(numbers, picks):
        items, start, end, (first, second), budget, costs, route, shortcuts, gap = pool[pick]
        out[n] = _split_task(ctx, rng, n, items, start, end, first, second, budget, costs, route, shortcuts, gap)
    if len(out) < len(numbers):
        # The numbers past SPLIT_END_TASKS (and any the shares leave open) keep the form without an end
        # point (the walk ends at the second store).
        return {**out, **store_to_store_tasks(ctx, numbers[len(out):], pairs, pair_cap)}
    return out


def split_choose(pool: list[Any], numbers: list[int], pairs: dict[str, int], places: list[Any]) -> list[int]:
    """The pool entries the end-point tasks take (SPLIT_END_TASKS of ``numbers``, fewer where the shares leave
    none open), in order. Each shortcut walks the answer's graded order in at most ``cap`` of them: the lowest
    cap (from two up to a third of the tasks) that fills them all, so every rule stays as near chance as the
    pool allows. ``pairs`` counts each pair's answers (updated here, for the form without an end point)."""
    want = min(len(numbers), SPLIT_END_TASKS)
    pair_cap = int(SPLIT_PAIR_SHARE * len(numbers))
    picked: tuple[list[int], dict[str, int]] = ([], dict(pairs))
    for cap in range(2, int(SPLIT_SHORTCUT_SHARE * want) + 1):
        picked = _split_choose_under(pool, want, dict(pairs), pair_cap, cap, places)
        if len(picked[0]) == want:
            break
    pairs.update(picked[1])
    return picked[0]


def _split_choose_under(pool: list[Any], want: int, pairs: dict[str, int], pair_cap: int, cap: int,
                        places: list[Any]) -> tuple[list[int], dict[str, int]]:
    """Up to ``want`` pool entries, no shortcut right in more than ``cap`` and no pair the answer of more than
    ``pair_cap`` (``pairs`` counting): each takes the entry whose right shortcuts have been right least so far
    (none right first), then the least used last store (the walk's last store before E: Target, the central
    store, would end most walks), then the least used pair (the pairs with the shortest walks would gather
    most answers), then the least used end point and start, four items before three."""
    hits = {name: 0 for name in SPLIT_SHORTCUTS}
    lasts: dict[str, int] = {}
    out: list[int] = []
    used: set[int] = set()
    places_used = {p.id: 0 for p in places}

    def right(i: int) -> list[str]:
        return [name for name, r in pool[i][7].items() if r == pool[i][3]]

    while len(out) < want:
        open_ = [i for i, c in enumerate(pool) if i not in used and pairs[pair_key(*c[3])] < pair_cap
                 and lasts.get(c[3][1], 0) < SPLIT_LAST_SHARE * want and all(hits[name] < cap for name in right(i))]
        if not open_:
            break
        pick = min(open_, key=lambda i: (sum(hits[name] + 1 for name in right(i)), lasts.get(pool[i][3][1], 0),
                                         pairs[pair_key(*pool[i][3])], places_used[pool[i][2].id],
                                         places_used[pool[i][1].id], len(pool[i][0]) != SPLIT_ITEMS[0], i))
        items, start, end, (first, second) = pool[pick][:4]
        # the same list from the same start twice would be the same question
        used.update(i for i, c in enumerate(pool) if c[0] == items and c[1] is start)
        pairs[pair_key(first, second)] += 1
        lasts[second] = lasts.get(second, 0) + 1
        places_used[start.id] += 1  # starts and end points spread too: the same two places share every walk
        places_used[end.id] += 1
        for name in right(pick):
            hits[name] += 1
        out.append(pick)
    return out, pairs


def place_label(place: Any) -> str:
    """A place as the intent names it: its name with its street address."""
    if not place.address or place.address.startswith(place.name):
        return place.address or place.name
    return f"{place.name} ({place.address})"


def _split_list_words(items: list[tuple[Any, str]], budget: float) -> str:
    """The split list's opening, the same in both forms: the items, two orders, the budget and how to split."""
    money, count = f"${budget:.2f}", {3: "three", 4: "four"}[len(items)]
    return (f"Buy me {_listing(items)}. No single store has all {count} in stock, so buy them in two orders for "
            f"pickup at two different stores, each item in exactly one of the orders, spending at most {money} "
            f"in all (the two orders' totals added together). Where both stores have an item in stock, buy it at "
            f"either one, as long as the two totals stay within {money}.")


def _two_orders_oracle(ctx: Context, items: list[tuple[Any, str]], first: str, second: str) -> list[Any]:
    """The oracle's two orders, each item at the store of the pair where it is cheaper."""
    prices = split_prices(items, (first, second))
    assert prices is not None
    at = {sid: [(p, size) for (p, size), (where, _) in zip(items, prices) if where == sid] for sid in (first, second)}
    oracle: list[Any] = []
    for sid in (first, second):  # one order per store: the checkout prices the cart at one pickup store
        oracle += [c for product, size in at[sid] for c in buy_oracle(product, size, ctx.stores[sid])[:4]]
        oracle += [call("browser_goto", url=site_url("shop", "/checkout")),
                   call("browser_click", element=ref("button", "Place order"))]
    return oracle


def _split_common(ctx: Context, rng: Any, n: int, items: list[tuple[Any, str]], start: Any, first: str,
                  second: str, budget: float) -> dict[str, Any]:
    """What both split forms' tasks share: the id, the start and the two-order web goal."""
    links = ctx.world.neighbours(start.node)
    return {"id": f"shopping-pair-{n:03d}", "domain": "shopping", "difficulty": "hard",
            "start": StartState(environment="web", web=WebStart(start_url="shop:/"),
                                embodied=StreetStart(city="manhattan", node=start.node,
                                                     heading=round(rng.choice([lk.heading for lk in links]), 1))),
            "web_goals": [OrdersSplit(items=[ItemRef(product_id=p.id, size=size) for p, size in items],
                                      store_ids=[first, second], max_total=budget)]}


def _split_metadata(ctx: Context, items: list[tuple[Any, str]], start: Any, first: str, second: str, budget: float,
                    costs: dict[str, float], route: dict[tuple[str, str], float]) -> dict[str, Any]:
    """The metadata both split forms open with (the end-point form adds its end and walks)."""
    return {"form": "split", "store_nodes": {sid: p.node for sid, p in ctx.store_places.items()},
            "shortest_path_m": round(route[(first, second)], 1), "start_lat": ctx.world.node(start.node).lat,
            "start_lng": ctx.world.node(start.node).lng, "products": [p.id for p, _ in items],
            "sizes": [size for _, size in items], "store_pair": [first, second], "budget": budget,
            "pair_costs": costs, "reverse_path_m": round(route[(second, first)], 1)}


def _split_task(ctx: Context, rng: Any, n: int, items: list[tuple[Any, str]], start: Any, end: Any, first: str,
                second: str, budget: float, costs: dict[str, float], route: dict[tuple[str, str], float],
                shortcuts: dict[str, tuple[str, str] | None], gap: float) -> Task:
    money = f"${budget:.2f}"
    goal = place_label(end)
    intent = (f"{_split_list_words(items, budget)} Then walk from {start.name} to pick up "
              f"both orders, one store after the other, and carry everything to {goal}. Of the pairs of stores "
              f"that can fill the list within {money} this way, each visited in either order, pick the shortest "
              f"whole walk: from {start.name} to the first store, plus from there to the second store, plus from "
              f"there to {end.name}. Walk that route: past the first store, then the second, ending at "
              f"{end.name}. {WALK_RULE}")
    oracle = _two_orders_oracle(ctx, items, first, second)
    stops = [ctx.store_places[first], ctx.store_places[second]]
    legs = [ctx.world.directions(a, b) for a, b in zip([start.node, stops[0].node, stops[1].node],
                                                        [stops[0].node, stops[1].node, end.node])]
    nodes = [legs[0].nodes[0], *(x for lg in legs for x in lg.nodes[1:])]
    oracle += [call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": first})),
               call("browser_goto", url=site_url("map", "/directions", **{"from": first, "to": second})),
               call("browser_goto", url=site_url("map", "/directions", **{"from": second, "to": end.name})),
               call("switch_environment", target="embodied",
                    message="walk past the first store and the second to the end point"),
               *[call("street_move", neighbour=x) for x in nodes[1:]], call("street_stop"), call("finish_episode")]
    at_first, at_second, at_end = (ctx.world.node(p.node) for p in (*stops, end))
    return Task(
        **_split_common(ctx, rng, n, items, start, first, second, budget), intent=intent,
        embodied_goals=[PassedPlace(city="manhattan", node=stops[0].node, lat=at_first.lat, lng=at_first.lng,
                                    place_id=first),
                        PassedPlace(city="manhattan", node=stops[1].node, lat=at_second.lat, lng=at_second.lng,
                                    place_id=second,
                                    after=Waypoint(node=stops[0].node, lat=at_first.lat, lng=at_first.lng,
                                                   place_id=first)),
                        ReachedPlace(city="manhattan", node=end.node, lat=at_end.lat, lng=at_end.lng,
                                     place_id=end.id)],
        step_limit=step_budget("shopping", "hard", len(oracle)),
        oracle=oracle,
        metadata={**_split_metadata(ctx, items, start, first, second, budget, costs, route),
                  "end_id": end.id, "end_node": end.node, "margin_m": round(gap, 1),
                  "walks_m": {f"{a}>{b}": round(m, 1) for (a, b), m in sorted(route.items())},
                  "shortcuts": {name: (None if r is None else list(r)) for name, r in shortcuts.items()}},
    )


def _pair_shortcuts(items: list[tuple[Any, str]], store_ids: list[str], from_start: dict[str, float],
                    between: Any, costs: dict[str, float], budget: float) -> dict[str, str | None]:
    """The pair each tempting shortcut picks (``pair_key``, or None where it picks none): the pair holding the
    nearest store (of the pairs within the budget, the shortest walk among those holding it), the pair that
    fills the list cheapest, the greedy walk (the nearest store first, then the store nearest to it that has
    the rest in stock, budget unread) and the pair within the budget whose two stores are nearest the start
    by the sum of the two walks from it (not the walk past one to the other)."""
    within = [k for k, c in costs.items() if c <= budget]
    walks = {k: min(from_start[a] + between(a, b) for a, b in (k.split("|"), k.split("|")[::-1])) for k in within}
    nearest = min(store_ids, key=lambda sid: from_start[sid])
    holding = [k for k in within if nearest in k.split("|")]
    rest = [(p, size) for p, size in items if not in_stock(p, size, nearest)]
    fill = [sid for sid in store_ids if sid != nearest and all(in_stock(p, size, sid) for p, size in rest)]
    return {
        "nearest store": min(holding, key=lambda k: walks[k]) if holding else None,
        "cheapest pair": min(costs, key=lambda k: costs[k]) if costs else None,
        "greedy walk": pair_key(nearest, min(fill, key=lambda sid: between(nearest, sid))) if fill else None,
        "straight sum": min(within, key=lambda k: sum(from_start[sid] for sid in k.split("|"))) if within else None,
    }


def store_to_store_tasks(ctx: Context, numbers: list[int], used: dict[str, int] | None = None,
                         most: int | None = None) -> dict[int, Task]:
    """The split form without an end point, for the task numbers the end-point form cannot fill (``split_tasks``):
    three or four items, no store with all of them in stock, so
    two orders at two stores. Every pair of stores that can fill the list is a candidate, priced at the cheaper
    store of the two for each item; the answer is the pair within the budget with the shortest walk from the
    start past one of its stores to the other, visited in that order. Each part decides: some pair with a
    shorter walk is over the budget, some other pair within it is longer (by 100 m or more), the same pair the
    other way round is 150 m or more longer, and the shortcuts (``split_shortcuts``) each pick the answer in
    at most about a third of the tasks. Answers spread over the six pairs."""
    rng = rng_for("shopping", "pair-split")
    store_ids = list(ctx.stores)
    between = Legs(ctx).between

    pairs = {pair_key(a, b): 0 for i, a in enumerate(store_ids) for b in store_ids[i + 1:]}
    lacking, kinds = lacking_sets(ctx, store_ids)
    # Starts between two stores far apart are where the walk past one store to the other and the two walks
    # from the start rank the pairs differently.
    starts = walk_places(ctx)
    hits = {name: 0 for name in ("nearest store", "cheapest pair", "greedy walk", "straight sum")}
    cap = int(SPLIT_V9_SHARE * len(numbers)) + 1  # a few tasks: a third rounded down would be too tight
    pair_cap = int(SPLIT_V9_SHARE * len(numbers)) + 1
    if used is not None and most is not None:  # after the end-point form: the least used pairs over both
        pairs.update(used)  # forms come first; the few left may exceed its cap by this form's own share
        pair_cap = most + pair_cap
    want = {"items": SPLIT_ITEMS[0]}

    def draw() -> Any:
        items = [rng.choice(lacking[rng.choice(kinds)]) for _ in range(want["items"])]
        if len({p.id for p, _ in items}) < len(items):
            return None  # one product twice
        if any(all(in_stock(p, size, sid) for p, size in items) for sid in store_ids):
            return None  # some store fills the list alone
        start = rng.choice(starts)
        costs = split_costs(items, store_ids)
        from_start = {sid: ctx.walk(start, sid).distance_m for sid in store_ids}
        route = {(a, b): from_start[a] + between(a, b) for k in costs for a, b in (k.split("|"), k.split("|")[::-1])}
        best = {k: min(((a, b), (b, a)), key=lambda r: route[r]) for k in costs for a, b in [k.split("|")]}
        ranked = sorted(costs, key=lambda k: route[best[k]])
        for at in range(1, len(ranked)):  # never the pair with the shortest walk: the budget must decide
            target = ranked[at]
            budget = pair_budget(costs[target], [costs[k] for k in ranked[:at]])
            if budget is None:
                continue
            within = [k for k in ranked if costs[k] <= budget]
            first, second = best[target]
            if len(within) < 2 or route[(first, second)] > SPLIT_MAX_WALK_M:
                return None  # a pair within the budget must be longer; the walk must fit the step budget
            if route[(second, first)] - route[(first, second)] < SPLIT_ORDER_GAP_M \
                    or route[best[within[1]]] - route[(first, second)] < SPLIT_PAIR_GAP_M:
                return None  # the order of the walk, and the next pair within the budget, by a clear margin
            if pairs[target] >= pair_cap:
                return None  # the central pairs have the shortest walks most often: no pair the target of most
            picked = _pair_shortcuts(items, store_ids, from_start, between, costs, budget)
            if any(hits[name] >= cap for name, k in picked.items() if k == target):
                return None  # that shortcut has picked the answer in its share of the tasks already
            return items, start, (first, second), budget, costs, route, picked
        return None

    out: dict[int, Task] = {}
    for cell, n in enumerate(numbers):
        want["items"] = SPLIT_ITEMS[cell % len(SPLIT_ITEMS)]
        while True:
            for _ in range(SPLIT_ROUNDS):  # late in the suite few draws are open to a shortcut: try longer
                picked = balanced(draw, lambda c: pair_key(*c[2]), pairs, tries=PAIR_TRIES)
                if picked is not None:
                    break
            else:
                raise RuntimeError(f"no split task could be drawn for shopping-pair-{n:03d}")
            items, start, (first, second), budget, costs, route, shortcuts = picked
            task = _store_to_store_task(ctx, rng, n, items, start, first, second, budget, costs, route, between, shortcuts)
            if all(t.intent != task.intent for t in out.values()):
                break
            pairs[pair_key(first, second)] -= 1  # the same question twice
        for name, k in shortcuts.items():
            hits[name] += k == pair_key(first, second)
        out[n] = task
    return out


def _store_to_store_task(ctx: Context, rng: Any, n: int, items: list[tuple[Any, str]], start: Any, first: str, second: str,
                budget: float, costs: dict[str, float], route: dict[tuple[str, str], float], between: Any,
                shortcuts: dict[str, str | None]) -> Task:
    money = f"${budget:.2f}"
    intent = (f"{_split_list_words(items, budget)} Of the pairs of stores that can fill "
              f"the list within {money} this way, pick the pair with the shortest walk from {start.name} to one "
              f"of its stores and on to the other (count both ways round for each pair: the walk from "
              f"{start.name} to the first store plus the walk from there to the second). Then walk that route "
              f"from {start.name}: past the first store, ending at the second. {WALK_RULE}")
    oracle = _two_orders_oracle(ctx, items, first, second)
    legs = [ctx.walk(start, first), ctx.world.directions(ctx.store_places[first].node, ctx.store_places[second].node)]
    nodes = [*legs[0].nodes, *legs[1].nodes[1:]]
    oracle += [call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": first})),
               call("browser_goto", url=site_url("map", "/directions", **{"from": first, "to": second})),
               call("switch_environment", target="embodied", message="walk past the first store to the second"),
               *[call("street_move", neighbour=x) for x in nodes[1:]], call("street_stop"), call("finish_episode")]
    places = [ctx.store_places[first], ctx.store_places[second]]
    ends = [ctx.world.node(p.node) for p in places]
    return Task(
        **_split_common(ctx, rng, n, items, start, first, second, budget), intent=intent,
        embodied_goals=[PassedPlace(city="manhattan", node=places[0].node, lat=ends[0].lat, lng=ends[0].lng,
                                    place_id=first),
                        ReachedPlace(city="manhattan", node=places[1].node, lat=ends[1].lat, lng=ends[1].lng,
                                     place_id=second, must_match_order_store=True)],
        step_limit=step_budget("shopping", "hard", len(oracle)),
        oracle=oracle,
        metadata={**_split_metadata(ctx, items, start, first, second, budget, costs, route),
                  "shortcuts": shortcuts},
    )


def pair_tasks(ctx: Context) -> list[Task]:
    """Hard by composition (issue 26, principle 6), in forms over a seeded shuffle of the ids. 18 of the 60
    (``TOUR_TASKS``) are the tour form (``tour_tasks``): a list of four bought at two or three stores within a
    budget, on the shortest walk past them to an end point. Numbers the tour pool cannot fill (none now) name
    three stores (``NAMED_TASKS``): three products bought together in one order at one pickup store, the one
    of the three that has all three in stock within a budget for the three (``named_draw``). The other
    42 are the split form (``split_tasks``): a list no single store has in stock, two orders at two stores
    within one budget, on the shortest walk past one store to the other. Every number the agent needs is on
    the product pages and the map (the checkout shows one chosen store's total at a time). Ids keep the
    family's name, ``shopping-pair-*``."""
    out: list[Task] = []
    rng = rng_for("shopping", "pair")
    counts = ctx.store_counts()

    want: dict[str, Any] = {"rank": 0, "rank_all": 0, "kinds": RIVAL_KINDS[0], "position": 0}

    def rank_among_all(start: Any, store_id: str) -> int:
        return sorted(ctx.stores, key=lambda sid: ctx.walk(start, sid).distance_m).index(store_id)

    def draw() -> Any:
        products = rng.sample(ctx.products, BASKET_ITEMS)
        items = [(p, rng.choice(p.sizes).label) for p in products]
        start = rng.choice(ctx.pair_starts)
        totals = {sid: basket_total(items, sid) for sid in ctx.stores}
        stocked = sorted((sid for sid, t in totals.items() if t is not None
                          and all(in_stock(p, size, sid) for p, size in items)),
                         key=lambda sid: ctx.walk(start, sid).distance_m)
        cheapest_each = {catalog.cheapest_store(p.id, size) for p, size in items}
        if len(cheapest_each) < 2:
            return None  # one store cheapest for every item would answer "cheapest" item by item
        return named_draw(items, start, totals, stocked, cheapest_each)

    def named_draw(items: list[tuple[Any, str]], start: Any, totals: dict[str, float | None],
                   stocked: list[str], cheapest_each: set[str]) -> Any:
        """Three stores named, one of which has all three in stock and sells them within the
        budget. Each rival fails by one thing: stock (it lists all three, one is sold out there, and the three
        cost less there than at the answer) or the budget (all three in stock, over it by a margin). The kinds
        of failure and the answer's place by distance among the three are cycled over the tasks, so that
        neither the nearest, the middle, the farthest, the cheapest total nor "all three in stock" alone picks
        the answer in more than about a third of them; only reading both stock and the sum does. The answer is
        no item's cheapest store (picking by any one price fails). Any store can be the answer this way, which
        spreads the pickup stores where prices favour some stores (issue 26)."""
        kinds: tuple[str, str] = want["kinds"]
        choices = [sid for sid in stocked if sid not in cheapest_each]
        if not choices:
            return None
        # The least used store so far: prices favour some stores, which would gather the answers there.
        answer: str = min(rng.sample(choices, len(choices)), key=lambda sid: counts[sid])
        total = totals[answer]
        assert total is not None
        sold_out = [sid for sid in ctx.stores if sid != answer and totals[sid] is not None and sid not in stocked
                    and totals[sid] <= total - PAIR_MARGIN]  # type: ignore[operator]
        over = [sid for sid in stocked if sid != answer]
        pools = [sold_out if kind == "stock" else over for kind in kinds]
        pairs = [(a, b) for a in pools[0] for b in pools[1] if a != b]
        if not pairs:
            return None
        rivals = list(rng.choice(pairs))
        budget = pair_budget(total, [totals[sid] for sid, kind in zip(rivals, kinds) if kind == "budget"])  # type: ignore[misc]
        if budget is None:
            return None
        by_distance = sorted([answer, *rivals], key=lambda sid: ctx.walk(start, sid).distance_m)
        gaps = [ctx.walk(start, b).distance_m - ctx.walk(start, a).distance_m
                for a, b in zip(by_distance, by_distance[1:])]
        if by_distance.index(answer) != want["rank"] or rank_among_all(start, answer) != want["rank_all"] \
                or min(gaps) < 100:
            return None  # the answer's distance rank as cycled, and no two named stores too close to call
        rng.shuffle(rivals)
        named = [*rivals]
        named.insert(want["position"], answer)  # the answer is named first, second or third in turn
        return items, start, answer, budget, totals, named

    # Which tasks name stores, and which cell of its form's cycles each takes, come from a seeded shuffle of
    # the task numbers: any pattern in the ids (every eighth task named, cells in id order) lets tasks some
    # ids apart agree on the answer (tests/core/test_id_order.py).
    order = rng_for("shopping-pair-forms").sample(range(PER_TEMPLATE), PER_TEMPLATE)
    # The tour form first, for the first TOUR_TASKS numbers of the shuffle (the named form's numbers among
    # them): as many as the stock and the map allow within its shares; the numbers it leaves keep the
    # older forms.
    tours = tour_tasks(ctx, order[:TOUR_TASKS])
    named_ids = set(order[:NAMED_TASKS]) - set(tours)
    cells = {m: i for i, m in enumerate(m for m in order if m in named_ids)}
    split = split_tasks(ctx, [m for m in order if m not in named_ids and m not in tours])  # in the shuffle's order
    for n in slots(out):
        # 18 tasks name three stores, the others are the split form. The named tasks cycle through every
        # pair of (answer's distance rank, rivals' failures), the answer's rank among all four stores spread
        # over all four (NAMED_RANKS).
        if n in tours:
            out.append(tours[n])
            continue
        if n not in named_ids:
            out.append(split[n])
            continue
        cell = cells[n]
        want["rank"], want["rank_all"] = NAMED_RANKS[cell % 6]
        want["kinds"] = RIVAL_KINDS[(cell % 3 + cell // 3) % 3]
        want["position"] = (cell // 2) % 3
        picked = balanced(draw, lambda c: c[2], counts, tries=PAIR_TRIES)  # the pickup store spreads over the stores
        if picked is None:
            continue
        items, start, store_id, budget, totals, named = picked
        store = ctx.stores[store_id]
        route, place = ctx.walk(start, store_id), ctx.store_places[store_id]
        node = ctx.world.node(place.node)
        money = f"${budget:.2f}"
        first, second, third = (ctx.stores[sid].name for sid in named)
        intent = (f"Buy me {_listing(items)} together, in one order for pickup at {first}, {second} or "
                  f"{third}: whichever of the three has all three items in stock and sells them for {money} "
                  f"or less in all. Then walk there from {start.name} to pick them up. {WALK_RULE}")
        if any(t.intent == intent for t in out):
            counts[store_id] -= 1
            continue  # the same question twice
        oracle = [*[c for product, size in items for c in buy_oracle(product, size, store)[:4]],
                  call("browser_goto", url=site_url("shop", "/checkout")),
                  call("browser_click", element=ref("button", "Place order")),
                  call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": store_id})),
                  call("switch_environment", target="embodied", message="walk to the pickup store"),
                  *[call("street_move", neighbour=x) for x in route.nodes[1:]], call("street_stop"),
                  call("finish_episode")]
        links = ctx.world.neighbours(start.node)
        out.append(Task(
            id=f"shopping-pair-{n:03d}", domain="shopping", difficulty="hard", intent=intent,
            start=StartState(environment="web", web=WebStart(start_url="shop:/"),
                             embodied=StreetStart(city="manhattan", node=start.node,
                                                  heading=round(rng.choice([lk.heading for lk in links]), 1))),
            web_goals=[OrderPlaced(product_id=p.id, size=size, quantity=1, store_id=store_id) for p, size in items],
            embodied_goals=[ReachedPlace(city="manhattan", node=place.node, lat=node.lat, lng=node.lng,
                                         place_id=store_id, must_match_order_store=True)],
            step_limit=step_budget("shopping", "hard", len(oracle)),
            oracle=oracle,
            metadata={"form": "named", "store_nodes": {sid: p.node for sid, p in ctx.store_places.items()},
                      "shortest_path_m": route.distance_m, "start_lat": ctx.world.node(start.node).lat,
                      "start_lng": ctx.world.node(start.node).lng, "products": [p.id for p, _ in items],
                      "sizes": [size for _, size in items], "store_id": store_id, "budget": budget,
                      "named_stores": named, "totals": {sid: t for sid, t in totals.items() if t is not None}},
        ))
    return out



# The tour form of the hard pair tasks (issue 26, principle 6): four items no single store has in stock, bought
# at two OR three of the four stores (one order at each store walked to, every item once), within one budget,
# then carried to an end point. Each set of stores that can fill the list is a plan, priced at its cheapest
# fill that buys something at every one of its stores, and walked in any order of its stores: up to 12 walks
# over pairs and 24 over three stores. The answer is the shortest whole walk among the plans within the budget.
TOUR_SIZES = (2, 3)  # stores in a plan
TOUR_TASKS = 18  # of the 60: the numbers the named form had (its store rule passed 10 % of the cell)
TOUR_ITEMS = 4
TOUR_SINGLE_SHARE = 0.5  # of the lists drawn, this share has one item lacking at each store
TOUR_MONEY_MARGIN = 0.05  # the answer's fill is this much under the budget, every plan over it this much over
TOUR_MIN_WITHIN = 20  # walks (store orders) among the plans within the budget: too many to check one by one
TOUR_GAP_M = 30.0  # the answer's walk beats every other walk within the budget by at least this (map rounds to 10 m)
TOUR_GAP_MAX_M = 120.0  # and by at most this: estimating, or one slip in the sums, picks a rival
TOUR_OVER_MAX = 3.0  # some shorter walk is over the budget by this many dollars or less: the sums must be exact
TOUR_MAX_WALK_M = 4200.0  # the whole walk: about 210 moves, within the hard step budget with the reading
TOUR_SHARE = 0.33  # each shortcut walks the answer's plan in at most this share of the tour tasks
TOUR_SET_SHARE = 0.45  # no set of stores the answer of more than this share (three-store answers are
# possible for few sets: the stock lets few sets need all three of their stores)
TOUR_POOL_DRAWS = 12000  # lists drawn for the pool the suite is picked from
TOUR_SHORTCUTS_RIGHT = 2  # at most this many shortcuts right in any one task
TOUR_SHORTCUTS = ("pair nearest the end", "pair nearest the start", "cheapest plan", "fewest stores",
                  "stores in the listed order", "greedy nearest next", "straight-line best walk",
                  "nearest store first", "end point not read", "budget not read")


def set_key(stores: Any) -> str:
    """A set of stores, unordered, as metadata names it ("a|b|c", ids sorted)."""
    return "|".join(sorted(stores))


def plan_fill(items: list[tuple[Any, str]], stores: tuple[str, ...]) -> tuple[float, list[str]] | None:
    """The cheapest way to buy every item once at these stores, each store selling it in stock, with at least
    one item bought at every one of them (one order per store walked to): (total, the store of each item), or
    None when no such fill exists."""
    best: tuple[float, list[str]] | None = None
    options = [[(sid, o.price) for sid in stores if (o := product.offer(size, sid)) is not None
                and in_stock(product, size, sid)] for product, size in items]
    for choice in itertools.product(*options):
        if {sid for sid, _ in choice} != set(stores):
            continue
        total = round(sum(p for _, p in choice), 2)
        if best is None or total < best[0]:
            best = (total, [sid for sid, _ in choice])
    return best


def tour_budget(total: float, over: list[float]) -> float | None:
    """The roundest budget (dollars, halves, quarters, dimes, nickels) that the answer's fill fits and every
    total in ``over`` exceeds, each by TOUR_MONEY_MARGIN or more, or None. Prices are in cents and the budget
    is stated exactly, so a few cents decide fairly; the three-store plans cost only a little less than their
    pairs, so the budget must be fine to rule the pairs out."""
    for step in (1.0, 0.5, 0.25, 0.1, 0.05):
        budget = round(math.ceil(round((total + TOUR_MONEY_MARGIN) / step, 6)) * step, 2)
        if all(t >= budget + TOUR_MONEY_MARGIN - 1e-9 for t in over):
            return budget
    return None


def passes_in_order(world: Any, nodes: list[str], stops: list[Any], radius: float = 25.0) -> bool:
    """A walk along these nodes meets the graded order of ``stops`` as the grader reads ``passed_place`` with
    ``after``: each stop passed, and each one last passed at or after the moment the one before was first
    passed."""
    points = [world.node(n) for n in nodes]
    near = [[i for i, p in enumerate(points) if haversine_m(p.lat, p.lng, q.lat, q.lng) <= radius] for q in stops]
    if any(not hits for hits in near):
        return False
    return all(max(near[k]) >= min(near[k - 1]) for k in range(1, len(stops)))


def tour_shortcuts(ctx: Context, routes: dict[tuple[str, ...], float], costs: dict[str, float], budget: float,
                   from_start: dict[str, float], legs: Any, start: Any, end: Any) -> dict[str, tuple[str, ...] | None]:
    """The plan (store order) each tempting shortcut walks, or None where it picks none. ``routes`` is every
    order of every set of stores that can fill the list, with its whole walk; ``costs`` each set's cheapest
    fill. The shortcuts: the pair within the budget nearest the end point (sum of its two walks to it), ending
    at the store nearer it; the pair within the budget nearest the start, nearer store first; the cheapest set,
    in its shortest order; the shortest walk among the plans with the fewest stores (three-store plans not
    considered); the shortest walk visiting its stores in the order the shop lists them; the greedy walk (the
    nearest store, then the nearest store not yet visited, until the stores so far fill the list within the
    budget); the shortest walk by straight lines; the shortest walk starting at the nearest store; the
    shortest walk from the start past the stores, the end point not read; the shortest walk, the budget not
    read."""
    within = {r: m for r, m in routes.items() if costs[set_key(r)] <= budget}
    out: dict[str, tuple[str, ...] | None] = {name: None for name in TOUR_SHORTCUTS}
    if not within:
        return out

    def shortest(rs: Any, key: Any = None) -> tuple[str, ...] | None:
        rs = list(rs)
        return min(rs, key=key or (lambda r: routes[r])) if rs else None

    to_end = {sid: legs(ctx.store_places[sid].node, end.node) for sid in ctx.stores}
    pairs = [r for r in within if len(r) == 2]
    if pairs:
        near_end = min(sorted({set_key(r) for r in pairs}), key=lambda k: sum(to_end[s] for s in k.split("|")))
        out["pair nearest the end"] = tuple(sorted(near_end.split("|"), key=lambda s: -to_end[s]))
        near_start = min(sorted({set_key(r) for r in pairs}), key=lambda k: sum(from_start[s] for s in k.split("|")))
        out["pair nearest the start"] = tuple(sorted(near_start.split("|"), key=lambda s: from_start[s]))
    cheapest = min(costs, key=lambda k: (costs[k], k))
    out["cheapest plan"] = shortest(r for r in routes if set_key(r) == cheapest)
    fewest = min(len(r) for r in within)
    out["fewest stores"] = shortest(r for r in within if len(r) == fewest)
    listed = list(ctx.stores)
    out["stores in the listed order"] = shortest(r for r in within if list(r) == sorted(r, key=listed.index))
    walked: list[str] = []
    here = None
    while len(walked) < max(TOUR_SIZES):
        ahead = [sid for sid in ctx.stores if sid not in walked]
        nxt = min(ahead, key=lambda sid: from_start[sid] if here is None else legs(ctx.store_places[here].node,
                                                                                   ctx.store_places[sid].node))
        walked.append(nxt)
        here = nxt
        if tuple(walked) in within:
            out["greedy nearest next"] = tuple(walked)
            break
    pts = {sid: ctx.world.node(p.node) for sid, p in ctx.store_places.items()}
    s, e = ctx.world.node(start.node), ctx.world.node(end.node)

    def line(r: tuple[str, ...]) -> float:
        way = [s, *(pts[x] for x in r), e]
        return sum(haversine_m(a.lat, a.lng, b.lat, b.lng) for a, b in zip(way, way[1:]))

    out["straight-line best walk"] = shortest(within, key=line)
    nearest = min(sorted({r[0] for r in within}), key=lambda sid: from_start[sid])
    out["nearest store first"] = shortest(r for r in within if r[0] == nearest)
    out["end point not read"] = shortest(within, key=lambda r: routes[r] - to_end[r[-1]])
    out["budget not read"] = shortest(routes)
    return out


def tour_tasks(ctx: Context, numbers: list[int]) -> dict[int, Task]:
    """The tour form for as many of the task numbers given as the data allows, in their order (the rest are
    left to the other forms). A list of four items, one lacking at each store (no store fills it alone); every
    set of two or three stores that can fill it is a plan (``plan_fill``), each order of its stores a walk
    from the start S past them to the end point E. The answer is the shortest walk within the budget. Each
    part decides: some shorter walk is over the budget, by a few dollars at most; at least TOUR_MIN_WITHIN
    walks are within it, and the next of them is longer by TOUR_GAP_M to TOUR_GAP_MAX_M; every other order of
    the answer's stores misses the graded order; the shortcuts (``tour_shortcuts``) each walk the answer in at
    most about a third of the tasks; answers spread over the sets of stores."""
    rng = rng_for("shopping", "pair-tour")
    store_ids = list(ctx.stores)
    legs = Legs(ctx)
    leg, leg_m = legs.route, legs.metres

    node = {sid: p.node for sid, p in ctx.store_places.items()}
    lacking, kinds = lacking_sets(ctx, store_ids)
    places = walk_places(ctx)
    by_store: dict[str, list[Any]] = {}
    for place in places:
        near = {sid: ctx.walk(place, sid).distance_m for sid in store_ids}
        by_store.setdefault(min(store_ids, key=near.__getitem__), []).append(place)
    sets = [tuple(c) for k in TOUR_SIZES for c in itertools.combinations(store_ids, k)]

    def draw() -> list[Any]:
        # Each item lacking at one store or more (a set of stores drawn evenly among those the stock has): an
        # item only some stores keep rules some sets of stores out, which is where three stores are needed.
        if rng.random() < TOUR_SINGLE_SHARE:  # one item lacking at each store: every set fills, prices decide
            items = [rng.choice(lacking[k]) for k in kinds if len(k) == 1]
            rng.shuffle(items)
        else:
            items = [rng.choice(lacking[rng.choice(kinds)]) for _ in range(TOUR_ITEMS)]
        if len({p.id for p, _ in items}) < len(items):
            return []
        if any(all(in_stock(p, size, sid) for p, size in items) for sid in store_ids):
            return []  # some store fills the list alone
        fills = {set_key(c): f for c in sets if (f := plan_fill(items, c)) is not None}
        costs = {k: f[0] for k, f in fills.items()}
        found = []
        for _ in range(SPLIT_PLACE_TRIES):
            start = rng.choice(by_store[rng.choice(sorted(by_store))])
            end = rng.choice(places)
            if start.id == end.id or start.node == end.node:
                continue
            from_start = {sid: ctx.walk(start, sid).distance_m for sid in store_ids}
            routes = {}
            for k in costs:
                for r in itertools.permutations(k.split("|")):
                    routes[r] = from_start[r[0]] + sum(leg_m(node[a], node[b]) for a, b in zip(r, r[1:])) \
                        + leg_m(node[r[-1]], end.node)
            ranked = sorted(routes, key=lambda r: (routes[r], r))
            for at in range(1, len(ranked)):
                target = ranked[at]
                key = set_key(target)
                shorter = [r for r in ranked if r != target and routes[r] <= routes[target]]
                if not any(routes[r] <= routes[target] - TOUR_GAP_M for r in shorter) \
                        or any(set_key(r) == key for r in shorter):
                    continue  # a clearly shorter walk for the budget to rule out; its own stores no shorter
                budget = tour_budget(costs[key], [costs[set_key(r)] for r in shorter])
                if budget is None:
                    continue
                within = [r for r in ranked if costs[set_key(r)] <= budget]
                over = min(costs[set_key(r)] for r in shorter) - budget
                gap = routes[within[1]] - routes[target] if len(within) > 1 else 0.0
                if len(within) < TOUR_MIN_WITHIN or not TOUR_GAP_M <= gap <= TOUR_GAP_MAX_M or over > TOUR_OVER_MAX:
                    continue
                if routes[target] > TOUR_MAX_WALK_M:
                    continue  # the walk must fit the step budget
                at_end = ctx.world.node(end.node)
                if any(haversine_m(at_end.lat, at_end.lng, q.lat, q.lng) < SPLIT_END_GAP_M
                       for q in (ctx.world.node(node[sid]) for sid in target)):
                    continue  # E no store's doorstep
                stops = [ctx.world.node(node[sid]) for sid in target]
                rivals = [r for r in itertools.permutations(target) if r != target]
                if any(passes_in_order(ctx.world, tour_nodes(leg, start.node, [node[x] for x in r], end.node), stops)
                       for r in rivals):
                    continue  # another order of the same stores would pass them in the graded order too
                picked = tour_shortcuts(ctx, routes, costs, budget, from_start, leg_m, start, end)
                if sum(r == target for r in picked.values()) > TOUR_SHORTCUTS_RIGHT:
                    continue
                found.append((items, start, end, target, budget, costs, fills[key][1], routes, picked, gap, over,
                              len(within)))
        return found

    pool: list[Any] = []
    for _ in range(TOUR_POOL_DRAWS):
        pool.extend(draw())
    out: dict[int, Task] = {}
    for n, pick in zip(numbers, tour_choose(ctx, pool, numbers, sets, places)):
        out[n] = _tour_task(ctx, rng, n, leg, *pool[pick])
    return out


def tour_choose(ctx: Context, pool: list[Any], numbers: list[int], sets: list[tuple[str, ...]],
                places: list[Any]) -> list[int]:
    """The pool entries the tour tasks take, in the order of ``numbers`` (fewer where the shares leave none
    open): each takes the entry with the fewest shortcuts right, then the least used set of stores, then the
    least used stores, then the least used start and end point. Target is in nearly every entry (docs/verified.md,
    "Shopping hard: the split form's shortcuts and the tour's store sets"): a pick that spreads the stores first
    fills fewer numbers or none better."""
    hits = {name: 0 for name in TOUR_SHORTCUTS}
    cap = int(TOUR_SHARE * len(numbers))
    set_counts = {set_key(c): 0 for c in sets}
    set_cap = int(TOUR_SET_SHARE * len(numbers)) + 1
    store_counts = ctx.store_counts()
    places_used = {p.id: 0 for p in places}
    out: list[int] = []
    used: set[int] = set()
    for _ in numbers:
        open_ = [i for i, c in enumerate(pool) if i not in used and set_counts[set_key(c[3])] < set_cap
                 and all(hits[name] < cap for name, r in c[8].items() if r == c[3])]
        if not open_:
            break
        pick = min(open_, key=lambda i: (sum(r == pool[i][3] for r in pool[i][8].values()),
                                         set_counts[set_key(pool[i][3])], sum(store_counts[s] for s in pool[i][3]),
                                         places_used[pool[i][2].id] + places_used[pool[i][1].id], i))
        c = pool[pick]
        out.append(pick)
        used.update(i for i, d in enumerate(pool) if d[0] == c[0] or (d[1] is c[1] and d[2] is c[2]))
        set_counts[set_key(c[3])] += 1
        for sid in c[3]:
            store_counts[sid] += 1
        places_used[c[1].id] += 1
        places_used[c[2].id] += 1
        for name, r in c[8].items():
            hits[name] += r == c[3]
    return out


def tour_nodes(leg: Any, start: str, stops: list[str], end: str) -> list[str]:
    """The nodes of the shortest walk from ``start`` past ``stops`` in order to ``end``."""
    way = [start, *stops, end]
    nodes = [start]
    for a, b in zip(way, way[1:]):
        nodes += leg(a, b).nodes[1:]
    return nodes


def _tour_task(ctx: Context, rng: Any, n: int, leg: Any, items: list[tuple[Any, str]], start: Any, end: Any,
               target: tuple[str, ...], budget: float, costs: dict[str, float], fill: list[str],
               routes: dict[tuple[str, ...], float], shortcuts: dict[str, tuple[str, ...] | None], gap: float,
               over: float, n_within: int) -> Task:
    money = f"${budget:.2f}"
    intent = (f"Buy me {_listing(items)}. No single store has all four in stock, so buy them at two or three "
              f"different stores: one order for pickup at each store you will walk to, each item in exactly one "
              f"order, at a store that has it in stock, spending at most {money} in all (the orders' totals added "
              f"together). Then walk from {start.name} to pick up every order, one store after another, and carry "
              f"everything to {place_label(end)}. Of all the ways to do this within {money} (which two or three "
              f"stores, and in which order you visit them), pick the one with the shortest whole walk: from "
              f"{start.name} to the first store, from each store to the next, and from the last store to "
              f"{end.name}. Walk that route: past the stores in that order, ending at {end.name}. {WALK_RULE}")
    oracle: list[Any] = []
    for sid in target:  # one order per store: the checkout prices the cart at one pickup store
        oracle += [c for (product, size), where in zip(items, fill) if where == sid
                   for c in buy_oracle(product, size, ctx.stores[sid])[:4]]
        oracle += [call("browser_goto", url=site_url("shop", "/checkout")),
                   call("browser_click", element=ref("button", "Place order"))]
    way = [start.name, *target, end.name]
    oracle += [call("browser_goto", url=site_url("map", "/directions", **{"from": a, "to": b}))
               for a, b in zip(way, way[1:])]
    stops = [ctx.store_places[sid] for sid in target]
    nodes = tour_nodes(leg, start.node, [p.node for p in stops], end.node)
    oracle += [call("switch_environment", target="embodied", message="walk past the stores in order to the end point"),
               *[call("street_move", neighbour=x) for x in nodes[1:]], call("street_stop"), call("finish_episode")]
    at = [ctx.world.node(p.node) for p in stops]
    goals: list[Any] = []
    for k, (sid, p, q) in enumerate(zip(target, stops, at)):
        before = None if k == 0 else Waypoint(node=stops[k - 1].node, lat=at[k - 1].lat, lng=at[k - 1].lng,
                                               place_id=target[k - 1])
        goals.append(PassedPlace(city="manhattan", node=p.node, lat=q.lat, lng=q.lng, place_id=sid, after=before))
    at_end = ctx.world.node(end.node)
    goals.append(ReachedPlace(city="manhattan", node=end.node, lat=at_end.lat, lng=at_end.lng, place_id=end.id))
    links = ctx.world.neighbours(start.node)
    return Task(
        id=f"shopping-pair-{n:03d}", domain="shopping", difficulty="hard", intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="shop:/"),
                         embodied=StreetStart(city="manhattan", node=start.node,
                                              heading=round(rng.choice([lk.heading for lk in links]), 1))),
        web_goals=[OrdersSplit(items=[ItemRef(product_id=p.id, size=size) for p, size in items],
                               store_ids=list(target), max_total=budget)],
        embodied_goals=goals,
        step_limit=step_budget("shopping", "hard", len(oracle)),
        oracle=oracle,
        metadata={"form": "tour", "store_nodes": {sid: p.node for sid, p in ctx.store_places.items()},
                  "shortest_path_m": round(routes[target], 1), "start_lat": ctx.world.node(start.node).lat,
                  "start_lng": ctx.world.node(start.node).lng, "products": [p.id for p, _ in items],
                  "sizes": [size for _, size in items], "stores": list(target), "budget": budget,
                  "plan_costs": costs, "fill": fill, "end_id": end.id, "end_node": end.node,
                  "margin_m": round(gap, 1), "over_budget_by": round(over, 2), "walks_within": n_within,
                  "walks_m": {">".join(r): round(m, 1) for r, m in sorted(routes.items())},
                  "shortcuts": {name: (None if r is None else list(r)) for name, r in shortcuts.items()}},
    )


def generate() -> list[Task]:
    ctx = Context()
    return cheapest_tasks(ctx) + size_tasks(ctx) + calorie_tasks(ctx) + nearest_tasks(ctx) + pair_tasks(ctx)
