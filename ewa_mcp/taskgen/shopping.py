"""Shopping tasks: compare products online (price, size, calories, store distance), order one for pickup,
get directions, and walk to that very store (or walk first, then order)."""

from __future__ import annotations

from typing import Any

from ..graders.textnorm import is_number, tokens
from ..outdoor.world import get_world
from ..taskmodel import AnswerNumbers, OrderPlaced, ReachedPlace, StartState, StreetStart, Task, TextAnswer, WebStart
from ..websites.shop import catalog
from .answer_checks import CALORIES, answer_rule, committed_answer
from .common import WALK_RULE, call, ref, rng_for, site_url, step_limit_for

PER_TEMPLATE = 60
MAX_WALK_M = 2200.0


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


def slots(out: list[Task]) -> Any:
    """Task numbers to fill until a template has PER_TEMPLATE tasks; a rejected draw costs a try, not a slot."""
    for _ in range(PER_TEMPLATE * 10):
        if len(out) >= PER_TEMPLATE:
            return
        yield len(out)


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

    def walk(self, start: Any, store_id: str) -> Any:
        return self.world.directions(start.node, self.store_places[store_id].node)


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
        step_limit=step_limit_for(len(oracle), slack=30),
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


def size_answer(product: Any, label: str, context: list[str]) -> TextAnswer:
    """The size asked for, told apart from the product's other sizes and any other amount in its unit."""
    unit = size_unit(label)
    toks = tokens(label)
    aliases: list[str] = []
    units: list[str] = []
    if unit is not None:
        units = [unit, *UNIT_WORDS.get(unit, [])]
        at = next(i for i in range(len(toks)) if " ".join(toks[i:i + len(unit.split())]) == unit and i > 0
                  and is_number(toks[i - 1]))
        quantity = toks[:at]
        aliases = [" ".join([*quantity, u]) for u in units]
    return committed_answer(label, [s.label for s in product.sizes if s.label != label], aliases=aliases,
                            context=[product.name, *context],
                            numbers=AnswerNumbers(units=units, bare=False) if units else None)


def cheapest_tasks(ctx: Context) -> list[Task]:
    out = []
    rng = rng_for("shopping", "cheapest")
    for n in slots(out):
        product = rng.choice(ctx.products)
        size = rng.choice(product.sizes).label
        store_id = catalog.cheapest_store(product.id, size)
        if not in_stock(product, size, store_id):
            continue
        start = rng.choice(ctx.starts)
        walk_first = n % 4 == 3
        intent = (f"Buy me {product.name} ({size}) for pickup at the store that sells it cheapest, "
                  f"then walk there from {start.name} to pick it up. {WALK_RULE}") if not walk_first else (
                  f"Walk from {start.name} to the store that sells {product.name} ({size}) cheapest, "
                  f"and order it online for pickup there once you have arrived. {WALK_RULE}")
        out.append(_task(ctx, f"shopping-cheapest-{n:03d}", intent, start, product, size, store_id, rng,
                         walk_first=walk_first, difficulty="easy"))
    return out


def size_tasks(ctx: Context) -> list[Task]:
    out = []
    rng = rng_for("shopping", "size")
    candidates = [p for p in ctx.products if len([s for s in p.sizes if s.grams or s.ml]) >= 2]
    for n in slots(out):
        product = rng.choice(candidates)
        sizes = sorted([s for s in product.sizes if s.grams or s.ml], key=lambda s: s.grams or s.ml)
        target = sizes[rng.randrange(1, len(sizes))]
        below = sizes[sizes.index(target) - 1]
        amount = (below.grams or below.ml) + max(1, ((target.grams or target.ml) - (below.grams or below.ml)) // 2)
        unit = "g" if target.grams else "ml"
        store_id = catalog.cheapest_store(product.id, target.label)
        if not in_stock(product, target.label, store_id):
            continue
        start = rng.choice(ctx.starts)
        intent = (f"What size of {product.name} should I buy if I need at least {amount} {unit}? Buy the smallest "
                  f"size that is enough, at the store where that size is cheapest, then walk there from "
                  f"{start.name}. {WALK_RULE} Tell me the size. "
                  + answer_rule("Answer with the size as the shop labels it."))
        out.append(_task(ctx, f"shopping-size-{n:03d}", intent, start, product, target.label, store_id, rng,
                         answer=size_answer(product, target.label, [f"{amount} {unit}"])))
    return out


def calorie_tasks(ctx: Context) -> list[Task]:
    out = []
    rng = rng_for("shopping", "calories")
    foods = [p for p in ctx.products if p.nutrition is not None]
    for n in slots(out):
        a, b = rng.sample(foods, 2)
        if a.nutrition.calories == b.nutrition.calories:
            continue
        low = a if a.nutrition.calories < b.nutrition.calories else b
        size = low.sizes[0].label  # not named in the intent: it would tell which product is lower
        stocked = [sid for sid in ctx.stores if in_stock(low, size, sid)]
        if not stocked:
            continue
        store_id = rng.choice(stocked)
        start = rng.choice(ctx.starts)
        high = b if low is a else a
        intent = (f"How many calories are in {a.name} and {b.name} per serving? I need to select the lower one: "
                  f"order it, in the first size the shop lists for it, for pickup at {ctx.stores[store_id].name}, "
                  f"walk there from {start.name}, and tell me its calories per serving. {WALK_RULE} "
                  + answer_rule("Answer with that number of calories."))
        check = committed_answer(str(low.nutrition.calories), [high.name, str(high.nutrition.calories)],
                                 context=[low.name, *(s.label for s in low.sizes), low.nutrition.serving_size],
                                 numbers=CALORIES)
        out.append(_task(ctx, f"shopping-calories-{n:03d}", intent, start, low, size, store_id, rng,
                         answer=check))
    return out


def nearest_tasks(ctx: Context) -> list[Task]:
    out = []
    rng = rng_for("shopping", "nearest")
    for n in slots(out):
        product = rng.choice(ctx.products)
        size = rng.choice(product.sizes).label
        start = rng.choice(ctx.starts)
        stocked = [sid for sid in ctx.stores if in_stock(product, size, sid)]
        if not stocked:
            continue
        dist = {sid: ctx.walk(start, sid).distance_m for sid in stocked}
        ranked = sorted(stocked, key=lambda s: dist[s])
        if len(ranked) > 1 and dist[ranked[1]] - dist[ranked[0]] < 100:
            continue  # too close to call: the answer must be unambiguous
        store_id = ranked[0]
        intent = (f"I am at {start.name}. Buy me {product.name} ({size}) for pickup at the store closest to me "
                  f"on foot that has it in stock, then walk there. {WALK_RULE}")
        out.append(_task(ctx, f"shopping-nearest-{n:03d}", intent, start, product, size, store_id, rng))
    return out


def pair_tasks(ctx: Context) -> list[Task]:
    """Hard: two products, each cheapest at a different store: two orders (one per pickup store, several
    rounds of product page, cart and checkout), then a walk to whichever of the two stores is nearer."""
    out: list[Task] = []
    rng = rng_for("shopping", "pair")
    for n in slots(out):
        a, b = rng.sample(ctx.products, 2)
        size_a, size_b = rng.choice(a.sizes).label, rng.choice(b.sizes).label
        store_a, store_b = catalog.cheapest_store(a.id, size_a), catalog.cheapest_store(b.id, size_b)
        if store_a == store_b or not in_stock(a, size_a, store_a) or not in_stock(b, size_b, store_b):
            continue
        start = rng.choice(ctx.starts)
        walks = {sid: ctx.walk(start, sid) for sid in (store_a, store_b)}
        if abs(walks[store_a].distance_m - walks[store_b].distance_m) < 100:
            continue  # too close to call: which store is nearer must be unambiguous
        near = min(walks, key=lambda sid: walks[sid].distance_m)
        route, place = walks[near], ctx.store_places[near]
        node = ctx.world.node(place.node)
        intent = (f"Buy me {a.name} ({size_a}) and {b.name} ({size_b}), each for pickup at the store that sells "
                  "that item cheapest (one order per store). Then walk from "
                  f"{start.name} to whichever of those two stores is nearer on foot. {WALK_RULE}")
        oracle = [*buy_oracle(a, size_a, ctx.stores[store_a]), *buy_oracle(b, size_b, ctx.stores[store_b]),
                  call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": store_a})),
                  call("browser_goto", url=site_url("map", "/directions", **{"from": start.name, "to": store_b})),
                  call("switch_environment", target="embodied", message="walk to the nearer pickup store"),
                  *[call("street_move", neighbour=x) for x in route.nodes[1:]], call("street_stop"),
                  call("finish_episode")]
        links = ctx.world.neighbours(start.node)
        out.append(Task(
            id=f"shopping-pair-{n:03d}", domain="shopping", difficulty="hard", intent=intent,
            start=StartState(environment="web", web=WebStart(start_url="shop:/"),
                             embodied=StreetStart(city="manhattan", node=start.node,
                                                  heading=round(rng.choice([lk.heading for lk in links]), 1))),
            web_goals=[OrderPlaced(product_id=a.id, size=size_a, quantity=1, store_id=store_a),
                       OrderPlaced(product_id=b.id, size=size_b, quantity=1, store_id=store_b)],
            embodied_goals=[ReachedPlace(city="manhattan", node=place.node, lat=node.lat, lng=node.lng,
                                         place_id=near)],
            step_limit=step_limit_for(len(oracle), slack=40),
            oracle=oracle,
            metadata={"store_nodes": {sid: p.node for sid, p in ctx.store_places.items()},
                      "shortest_path_m": route.distance_m, "start_lat": ctx.world.node(start.node).lat,
                      "start_lng": ctx.world.node(start.node).lng, "products": [a.id, b.id],
                      "sizes": [size_a, size_b], "stores": [store_a, store_b], "nearer_store": near},
        ))
    return out


def generate() -> list[Task]:
    ctx = Context()
    return cheapest_tasks(ctx) + size_tasks(ctx) + calorie_tasks(ctx) + nearest_tasks(ctx) + pair_tasks(ctx)
