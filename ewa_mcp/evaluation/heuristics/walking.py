"""Heuristic agents that walk (docs/verified.md, "Walking heuristics"): they ask the map site for
directions and walk the route it lists, so navigation, traveling and shopping can be scored whole.

The route the map site lists is the street graph's shortest walk (``World.directions``, which the site's
directions page renders); these agents read it from the package instead of parsing the page's turn list
street by street, which only saves steps, as the other heuristics read the shop's catalogue. Where a walk
starts is what the street view reports (its node); where it goes is a place the intent names, resolved by
the map site's own resolver. No agent reads a task's goals, oracle or metadata.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any
from urllib.parse import urlencode

from ...websites.shop import catalog
from ...websites.wiki import store as wiki
from ..agents import Session
from .agents import finish, named_products, question_of, visible

# ------------------------------------------------------------------ the map, as its site resolves and routes
@lru_cache(maxsize=1)
def _map() -> Any:
    from ...websites.map.places import WorldAdapter

    return WorldAdapter()


def world() -> Any:
    return _map().world


def as_map_text(phrase: str) -> str:
    """A place as an intent writes it, as the map's search box takes it ("the corner of A and B" -> "A & B")."""
    phrase = phrase.strip().rstrip(".")
    m = re.fullmatch(r"the corner of (.+?) and (.+)", phrase)
    return f"{m.group(1)} & {m.group(2)}" if m else phrase


def resolve(phrase: str, city: str | None = None) -> Any | None:
    """The one place the map site resolves an intent's phrase to, else None. A name that itself ends in
    brackets ("Central Park (Sixth Avenue entrance) (Central Park South & 6th Ave)") is tried without its
    last bracket, then by that bracket (the address) alone, then by what comes before the first bracket."""
    text = as_map_text(phrase)
    tries = [text]
    m = re.fullmatch(r"(.+?)\s*\(([^()]+)\)", text)
    if m:
        tries += [m.group(1), m.group(2)]
    tries.append(text.split(" (")[0])  # an address with brackets of its own: the name before them
    for t in tries:
        place = _map().resolve(t, city).place
        if place is not None:
            return place
    return None


def route_nodes(origin: str, destination: str) -> list[str]:
    """The nodes of the walk the map site lists between two places or nodes."""
    return list(world().directions(origin, destination).nodes)


def walk_m(origin: str, destination: str) -> float:
    return float(world().directions(origin, destination).distance_m)


class Walker:
    """Moves between the browser and the street, remembering where the street view last said it stood."""

    def __init__(self, s: Session):
        self.s = s
        seen = visible(s)
        self.active = str(seen.get("active_environment") or "")
        self.node: str | None = None
        self.city: str | None = None

    async def _note(self, result: Any) -> None:
        obs = (result.structured_content or {}).get("observation") or {}
        if isinstance(obs, dict) and obs.get("node"):
            self.node, self.city = str(obs["node"]), str(obs.get("city") or self.city or "")

    async def to(self, target: str) -> None:
        if self.active != target and not self.s.ended:
            await self._note(await self.s.call("switch_environment", {"target": target, "message": "go on"}))
            self.active = target

    async def here(self) -> str | None:
        """The street node the agent stands on (switching to the street to see it)."""
        await self.to("embodied")
        return self.node

    async def goto(self, url: str) -> Any:
        await self.to("web")
        return None if self.s.ended else await self.s.call("browser_goto", {"url": url})

    async def directions(self, origin: str, destination: str) -> None:
        """Show the map site's directions page (what a person following the map reads)."""
        await self.goto("map:/directions?" + urlencode({"from": origin, "to": destination}))

    async def walk(self, destination: str) -> None:
        """Walk the map's route from here to a place or node id, one street move per edge."""
        start = await self.here()
        if start is None:
            return
        try:
            nodes = route_nodes(start, destination)
        except ValueError:
            return  # no walkable route: the agent stays put
        for node in nodes[1:]:
            if self.s.ended:
                return
            await self._note(await self.s.call("street_move", {"neighbour": node}))

    async def stop(self) -> None:
        await self.to("embodied")
        if not self.s.ended:
            await self.s.call("street_stop", {})


# ------------------------------------------------------------------ reading the intent
_NAV = (r"Starting at (?P<o>.+?), guide me step-by-step to (?P<d>.+?)\. Get walking",
        r"Show me the fastest walking route from (?P<o>.+?) to (?P<d>.+?) on the map",
        r"I am at (?P<o>.+?)\. Look up how to walk to (?P<d>.+?) online")
_STOPS = (r"Starting at (?P<o>.+?), walk to (?P<s>.+?) in the order they were built",
          r"I am at (?P<o>.+?) and want to see (?P<s>.+?), from the oldest building",
          # the shortest-order form: the order is the agent's to find from the map's walking distances
          r"Starting at (?P<o>.+?), visit (?P<s>.+?) in the order that makes the shortest walk",
          r"I am at (?P<o>.+?) and want to see (?P<s>.+?), all (?:four|five|six), in whichever order")


def split_listed(text: str) -> list[str]:
    """"A (x), B (y) (z) and C (w)" -> the three places: a list separator counts only right after a closing
    bracket outside brackets (names may hold commas and "and")."""
    items, depth, start, i = [], 0, 0, 0
    while i < len(text):
        ch = text[i]
        depth += ch == "("
        depth -= ch == ")"
        if ch == ")" and depth == 0:
            for sep in (", and ", ", ", " and "):
                if text.startswith(sep, i + 1):
                    items.append(text[start:i + 1].strip())
                    start = i + 1 + len(sep)
                    i = start - 1
                    break
        i += 1
    return [*items, text[start:].strip()] if text[start:].strip() else items


def route_of(intent: str) -> tuple[str, str] | None:
    """(origin, destination) of a navigation intent, as written."""
    for pattern in _NAV:
        m = re.search(pattern, intent)
        if m:
            return m.group("o"), m.group("d")
    return None


def stops_of(intent: str) -> tuple[str, list[str]] | None:
    """(origin, stops in the order listed) of a hard (several-stop) navigation intent."""
    for pattern in _STOPS:
        m = re.search(pattern, intent)
        if m:
            return m.group("o"), split_listed(m.group("s"))
    return None


def address_of(intent: str) -> tuple[str, str] | None:
    """(corner, address) of a traveling intent that gives the address."""
    m = re.search(r"You are at (the corner of .+?)\. Walk to ([^:]+):", intent)
    return (m.group(1), m.group(2)) if m else None


def corner_of(intent: str) -> str | None:
    m = re.search(r"You are at (the corner of .+?)(?: in [A-Z][a-z]+)?\.", intent)
    return m.group(1) if m else None


async def answer_from_wiki(w: Walker, place: Any, intent: str) -> str | None:
    """Open the wiki article of the place (or of a landmark standing where it is, as an address resolves to
    a point on the street) and read the row the question asks for."""
    if place is None:
        return None
    near = [place, *world().places_near(place.node)]
    article = next((a for a in (wiki.by_poi_id(p.id) for p in near) if a is not None), None)
    if article is None:
        return None
    await w.goto(f"wiki:/wiki/{article.slug}")
    _, row = question_of(intent)  # the infobox row the page shows, read from the article (links as their text)
    value = article.infobox.get(row or "")
    return wiki.plain_text(value) if value else None


def landmarks(city: str) -> list[Any]:
    """The city's landmarks that have a wiki article (what a wiki search can list)."""
    return sorted((p for p in world().places.values() if p.city == city and p.kind not in ("intersection", "address",
                                                                                             "store", "street")
                   and wiki.by_poi_id(p.id) is not None), key=lambda p: p.id)


# ------------------------------------------------------------------ shopping: which store, which item
def store_places() -> dict[str, Any]:
    return {p.id: p for p in world().stores()}


def shopping_items(intent: str) -> tuple[list[tuple[Any, str]], str | None]:
    """The items to order and the answer to give, read the cheap way: the products and sizes the intent
    names; a size question takes the first listed size (and answers it); a calories question takes the
    first named product in its first size (and answers its calories)."""
    m = re.search(r"What size of (.+?) should I buy", intent)
    if m:
        product = next((p for p in catalog.load_products() if p.name == m.group(1)), None)
        return ([(product, product.sizes[0].label)], product.sizes[0].label) if product else ([], None)
    m = re.search(r"How many calories are in (.+?) per serving", intent)
    if m:  # two or three products named ("A and B", "A, B and C"): the first is the one whose name leads
        product = max((p for p in catalog.load_products() if m.group(1).startswith(p.name)),
                      key=lambda p: len(p.name), default=None)
        if product is None or product.nutrition is None:
            return [], None
        return [(product, product.sizes[0].label)], str(product.nutrition.calories)
    return named_products(intent), None


def sellers(items: list[tuple[Any, str]]) -> list[str]:
    """Stores that list every item in its size (stock not read)."""
    stores = [s.id for s in catalog.load_stores()]
    return [sid for sid in stores
            if all(any(o.store_id == sid and o.size == size for o in p.offers) for p, size in items)]


def total_price(items: list[tuple[Any, str]], store_id: str) -> float:
    return sum(next(o.price for o in p.offers if o.store_id == store_id and o.size == size) for p, size in items)


def named_stores(intent: str) -> list[str]:
    """The stores the intent names, in the order it names them."""
    at = [(intent.find(s.name), s.id) for s in catalog.load_stores() if s.name in intent]
    return [sid for _, sid in sorted(at)]


# Moves a shopping oracle makes besides walking: per item the product page, size, store and cart, then the
# checkout, the order, the map's directions, two switches, the stop and the finish.
WEB_CALLS_PER_ITEM, FIXED_CALLS = 4, 7
# How the step limit used to be set (twice the oracle plus a margin): what the limit would say of the walk.
OLD_LIMIT_MARGIN = 15


def implied_moves(step_limit: int, n_items: int) -> float:
    """The walk length (street moves) a step limit of the old rule (2 x oracle + margin) implies."""
    return (step_limit - OLD_LIMIT_MARGIN) / 2 - WEB_CALLS_PER_ITEM * n_items - FIXED_CALLS


def pick_store(rule: str, candidates: list[str], items: list[tuple[Any, str]], start: str,
               step_limit: int) -> str | None:
    """A store by a cheap rule: nearest on foot, cheapest for the items, or the one whose walk best matches
    the step limit (ties to the first in the shop's store list)."""
    if not candidates:
        return None
    places = store_places()
    if rule == "nearest":
        return min(candidates, key=lambda sid: walk_m(start, places[sid].id))
    if rule == "cheapest":
        return min(candidates, key=lambda sid: total_price(items, sid))
    if rule == "step-limit":
        want = implied_moves(step_limit, len(items))
        return min(candidates, key=lambda sid: abs(len(route_nodes(start, places[sid].id)) - 1 - want))
    raise ValueError(f"unknown store rule {rule!r}; choose nearest, cheapest or step-limit")


async def order(w: Walker, items: list[tuple[Any, str]], store_id: str) -> None:
    """One pickup order of the items at the store, through the shop's pages."""
    name = next(s.name for s in catalog.load_stores() if s.id == store_id)
    for product, size in items:
        await w.goto(f"shop:/product/{product.id}")
        for element, text in (("combobox 'Size'", size), ("combobox 'Store'", name)):
            if not w.s.ended:
                await w.s.call("browser_type", {"element": element, "text": text})
        if not w.s.ended:
            await w.s.call("browser_click", {"element": "button 'Add to cart'"})
    await w.goto("shop:/checkout")
    if not w.s.ended:
        await w.s.call("browser_click", {"element": "button 'Place order'"})


# ------------------------------------------------------------------ the agents
class DirectionsWalkerAgent:
    """Following the map: directions from the start to whatever the intent names, walked as listed, then
    stop (and answer from the wiki where asked). Navigation: the destination (several stops: in the order the
    intent lists them); traveling: the address given (a hard task names none: the first landmark in its range
    the wiki lists for the fact's words); shopping: the first store the intent names (the calories and
    two-store forms), with the first named product or both items ordered there."""

    name = "directions-walker"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        domain, intent = seen.get("domain"), str(seen.get("intent", ""))
        w = Walker(s)
        if domain == "navigation":
            await self.navigation(w, intent)
        elif domain == "traveling":
            return await finish(s, await self.traveling(w, intent))
        elif domain == "shopping":
            return await finish(s, await self.shopping(w, intent))
        await finish(s)

    async def navigation(self, w: Walker, intent: str) -> None:
        pair, stops = route_of(intent), stops_of(intent)
        if pair is not None:
            origin, dest = pair
            place, start = resolve(dest), resolve(origin)
            # the names the map resolved: what a person retypes when the intent's full phrase finds nothing
            await w.directions(start.name if start else as_map_text(origin), place.name if place else as_map_text(dest))
            if place is not None:
                await w.walk(place.node)
                await w.stop()
        elif stops is not None:
            origin, listed = stops
            places = [p for p in (resolve(x) for x in listed) if p is not None]
            names = [getattr(resolve(x), "name", as_map_text(x)) for x in (origin, *listed)]
            for a, b in zip(names, names[1:]):
                await w.directions(a, b)
            for p in places:
                await w.walk(p.node)
            await w.stop()

    async def traveling(self, w: Walker, intent: str) -> str | None:
        given = address_of(intent)
        if given is not None:
            corner, address = given
            # a few addresses the map's search does not take ("6th Ave between W 40th St & W 42nd St"): the
            # landmark whose article gives that address
            place = resolve(address) or next((p for city in world().cities for p in landmarks(city)
                                              if p.address == address), None)
        else:
            corner, place = corner_of(intent) or "", await wiki_pick(w, intent)
        if place is None:
            return None
        await w.directions(as_map_text(corner), place.name)
        await w.walk(place.node)
        await w.stop()
        return await answer_from_wiki(w, place, intent)

    async def shopping(self, w: Walker, intent: str) -> str | None:
        items, answer = shopping_items(intent)
        stores = named_stores(intent)
        if not items or not stores:
            return answer
        await order(w, items, stores[0])
        start = await w.here()
        if start is not None:
            await w.directions(start, stores[0])
        await w.walk(stores[0])
        await w.stop()
        return answer


async def wiki_pick(w: Walker, intent: str) -> Any | None:
    """A hard traveling task: search the wiki for the fact the intent states; of the landmarks the search
    lists, the first whose walk from the corner is within the intent's range."""
    m = re.search(r"within about (\d+) m of this corner on foot, exactly one (.+?), as its wiki article", intent)
    corner = corner_of(intent)
    start = resolve(corner) if corner else None
    if m is None or start is None:
        return None
    limit, fact = int(m.group(1)), m.group(2)
    query = re.sub(r"^(was|is|has|had)\s+", "", fact)
    page = await w.goto("wiki:/search?" + urlencode({"q": query}))
    text = " ".join(getattr(c, "text", "") for c in (page.content or [])) if page else ""
    for slug in re.findall(r"url: /wiki/([^\s]+)", text):
        article = wiki.find(slug)
        poi = getattr(article, "poi_id", None) if article is not None else None
        place = world().place(poi) if poi else None
        if place is not None and place.city == start.city and walk_m(start.node, place.node) <= limit:
            return place
    return None


class StoreRuleAgent:
    """Shopping by a cheap store rule (``rule``): order the intent's items (a size question: the first
    listed size; a calories question: the first named product) at the store the rule picks among those
    listing them (of the stores the intent names, where it names any), stock and budget not read, walk there
    by the map's route, stop, and answer what was ordered."""

    name = ""
    rule = ""

    async def play(self, s: Session) -> None:
        seen = visible(s)
        if seen.get("domain") != "shopping":
            return await finish(s)
        intent = str(seen.get("intent", ""))
        items, answer = shopping_items(intent)
        w = Walker(s)
        start = await w.here()
        # where the intent names stores (a calories question names one, a two-store order two), only those
        named = named_stores(intent)
        candidates = [sid for sid in sellers(items) if not named or sid in named]
        store = pick_store(self.rule, candidates, items, start, int(seen.get("step_limit") or 0)) \
            if items and start else None
        if store is None or start is None:
            return await finish(s, answer)
        await order(w, items, store)
        await w.directions(start, store)
        await w.walk(store)
        await w.stop()
        await finish(s, answer)


class NearestStoreAgent(StoreRuleAgent):
    """The store nearest the start on foot (by the map's walks)."""

    name, rule = "nearest-store", "nearest"


class CheapestStoreAgent(StoreRuleAgent):
    """The store that sells the items cheapest in all."""

    name, rule = "cheapest-store", "cheapest"


class StepLimitStoreAgent(StoreRuleAgent):
    """The store whose walk from the start best matches what the step limit would imply under the old
    rule (limit = twice the oracle's length plus a margin, less the web calls)."""

    name, rule = "step-limit-store", "step-limit"


def elimination_end(origin: Any, listed: list[Any]) -> Any:
    """The stop the old three-stop generator could have made the newest (it rejected the other draws):
    neither the last one listed nor where a nearest-first walk ends (the first listed of those left, else
    the first listed). Kept as a rule to measure: the generator no longer rejects either draw."""
    from ...envs.street.taskgen.navigation import nearest_first

    greedy = nearest_first(world(), origin, listed)
    left = [p for p in listed if p.id not in (listed[-1].id, greedy)]
    return (left or listed)[0]


class StopEliminationAgent:
    """Several stops, no wiki reading: open each stop's article (unread), then walk past the others in the
    order listed and end at the stop that is neither listed last nor where a nearest-first walk ends."""

    name = "stop-elimination"

    async def play(self, s: Session) -> None:
        seen = visible(s)
        parsed = stops_of(str(seen.get("intent", ""))) if seen.get("domain") == "navigation" else None
        found = [resolve(x) for x in parsed[1]] if parsed else []
        places = [p for p in found if p is not None]
        origin = resolve(parsed[0]) if parsed else None
        if origin is None or len(places) < 3 or len(places) != len(found):
            return await finish(s)
        w = Walker(s)
        for p in places:
            article = wiki.by_poi_id(p.id)
            if article is not None:
                await w.goto(f"wiki:/wiki/{article.slug}")
        end = elimination_end(origin, places)
        order_ = [p for p in places if p.id != end.id] + [end]
        for a, b in zip([origin, *order_], order_):
            await w.directions(a.name, b.name)
        for p in order_:
            await w.walk(p.node)
        await w.stop()
        await finish(s)


WALKING = (DirectionsWalkerAgent, StepLimitStoreAgent, NearestStoreAgent, CheapestStoreAgent, StopEliminationAgent)
