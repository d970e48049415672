"""Navigation tasks: get walking directions on the map site, then walk them in the street graph and
end the walk at the destination. Origins and destinations are landmarks, addresses and intersections
in all four cities; the start heading is drawn from the streets at the origin, never from the route.

Difficulty: a direct route with at most one turn is easy, one with more turns medium. Hard is hard by
composition (issue 26, principle 6): four named stops visited in the order the wiki gives (oldest
building first, by the year built), ending at the newest; the intent lists them in an independent shuffle
(passed_place goals for the first three, each after the one before, reached_place for the last, a wiki
page view of each). Three in four of the hard tasks (slots a seeded shuffle picks) ask instead for the order
that makes the shortest walk on foot past six stops (five or four where a city gives no six), from the map's
walking distances, graded by the same chain."""

from __future__ import annotations

from itertools import permutations
from typing import Any

from ewa_mcp.geometry import haversine_m
from ..world import get_world
from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import DirectionsShown, PageVisited, WebStart
from ewa_mcp.envs.street.goals import PassedPlace, ReachedPlace, StreetStart, Waypoint
from ewa_mcp.websites.map.places import WorldAdapter
from ewa_mcp.websites.wiki import store as wiki
from ewa_mcp.taskgen.common import WALK_RULE, call, rng_for, site_url, step_budget

PER_CITY = {"manhattan": 44, "philadelphia": 36, "boston": 36, "pittsburgh": 36}
# Hard tasks (four stops in the wiki's order) per city: 34 of 186 navigation tasks, 18 %.
PER_CITY_VIA = {"manhattan": 10, "philadelphia": 8, "boston": 8, "pittsburgh": 8}
MIN_M, MAX_M = 250.0, 1300.0
VIA_MIN_LEG_M = 150.0  # the shortest leg between two stops
EASY_MAX_TURNS = 1
TEMPLATES = [
    "Starting at {origin}, guide me step-by-step to {destination}. Get walking directions on the map site, "
    "then walk there. " + WALK_RULE,
    "Show me the fastest walking route from {origin} to {destination} on the map, then follow it on foot. "
    + WALK_RULE,
    "I am at {origin}. Look up how to walk to {destination} online, then walk there. " + WALK_RULE,
]


DIRECTIONS = ("East ", "West ", "North ", "South ")


def corner_phrase(name: str) -> str:
    """An intersection as people say it: "5th Avenue & East 44th Street & West 44th Street" (one street whose
    East and West halves meet at the avenue) is "5th Avenue and 44th Street"; a true three-way corner keeps
    its three streets."""
    streets = name.split(" & ")
    # "South Street" is a name, not the south half of "Street"
    bare = [next((s[len(d):] for d in DIRECTIONS if s.startswith(d) and " " in s[len(d):]), s) for s in streets]
    kept: list[str] = []
    for street, base in zip(streets, bare):
        twins = [s for s, b in zip(streets, bare) if b == base]
        word = base if len(twins) > 1 else street
        if word not in kept:
            kept.append(word)
    return " and ".join(kept if len(kept) > 1 else streets)


def describe(place: Any) -> str:
    """How a task names a place: landmarks by name, addresses and intersections as written on signs."""
    if place.kind == "intersection":
        return f"the corner of {corner_phrase(place.name)}"
    if not place.address or place.address.startswith(place.name):
        # "Market Square (Market St & Forbes Ave)" is already the name with its address
        return place.address or place.name
    return f"{place.name} ({place.address})"


def candidate_places(world: Any, city: str, rng: Any) -> list[Any]:
    pois = [p for p in world.places.values() if p.city == city and p.kind not in ("intersection", "address")]
    graph = world.city(city)
    corners = []
    for node_id in sorted(graph.ids):
        node = world.node(node_id)
        if len(node.streets) >= 2:
            corners.append(node_id)
    rng.shuffle(corners)
    intersections = [world.place(n) for n in corners[: max(20, len(pois))]]
    return sorted(pois, key=lambda p: p.id) + [p for p in intersections if p is not None]


def start_heading(world: Any, node_id: str, rng: Any) -> float:
    links = world.neighbours(node_id)
    return round(rng.choice([link.heading for link in links]), 1) if links else 0.0


def walk_oracle(nodes: list[str]) -> list[Any]:
    return [call("street_move", neighbour=n) for n in nodes[1:]] + [call("street_stop")]


def turns(route: Any) -> int:
    return sum(1 for s in route.steps if s.maneuver not in ("depart", "continue", "arrive", "waypoint"))


def reached(world: Any, city: str, place: Any) -> ReachedPlace:
    end = world.node(place.node)
    return ReachedPlace(city=city, node=place.node, lat=end.lat, lng=end.lng, place_id=place.id)


def start_state(world: Any, city: str, origin: Any, rng: Any) -> StartState:
    return StartState(environment="web", web=WebStart(start_url="map:/"),
                      embodied=StreetStart(city=city, node=origin.node, heading=start_heading(world, origin.node, rng)))


def metadata(world: Any, origin: Any, dest: Any, route: Any, **extra: Any) -> dict[str, Any]:
    return {"shortest_path_m": route.distance_m, "start_lat": world.node(origin.node).lat,
            "start_lng": world.node(origin.node).lng, "origin_node": origin.node, "destination_node": dest.node,
            "route_steps": len(route.steps), "turns": turns(route), **extra}


def resolves_to(resolver: WorldAdapter, place: Any) -> bool:
    """Validation: the map resolves the name the oracle types to exactly this place."""
    found = resolver.resolve(place.name).place
    return found is not None and found.id == place.id


STOPS = 4  # stops per hard task: a guessed order is right 1 time in 24 (3! = 6 with three)
STOPS_NEAR_M = 500.0  # every stop within this of the origin as the crow flies
STOPS_MAX_M = 2200.0  # the longest walk past the stops in ANY order (the hard step budget fits it)
STOPS_TEMPLATES = [
    "Starting at {origin}, walk to {stops} in the order they were built, oldest first, by the year each was "
    "built as the wiki gives it, and end your walk at the newest. Look the years up on the wiki; the map site "
    "gives walking directions. " + WALK_RULE,
    "I am at {origin} and want to see {stops}, from the oldest building to the newest (the wiki gives the year "
    "each was built), ending at the newest. Look the years up on the wiki, get walking directions on the map "
    "site, then walk. " + WALK_RULE,
]


def stop_years(places: list[Any]) -> list[tuple[Any, int]]:
    """Landmarks with a wiki article that states the year they were built."""
    out = []
    for p in places:
        article = wiki.by_poi_id(p.id)
        year = p.facts.get("year_built")
        if article is None or not isinstance(year, int) or str(year) != article.infobox.get("Year built"):
            continue
        out.append((p, year))
    return out


def article_slug(place: Any) -> str:
    article = wiki.by_poi_id(place.id)
    assert article is not None, place.id  # stop_years keeps only landmarks with an article
    return article.slug


def shortest_slots(count: int) -> int:
    """How many of a city's ``count`` hard slots take the shortest-order form."""
    return round(count * SHORTEST_SLOTS)


def stops_tasks(world: Any, resolver: WorldAdapter, city: str, places: list[Any], count: int) -> list[Task]:
    """A city's hard tasks, ids navigation-via-<city>-NNN, in two forms: three in four (the slots a seeded shuffle
    picks, so the id says nothing of the form) ask for the shortest order on foot, the others for the wiki's
    order by year built."""
    slots = list(range(count))
    rng_for("navigation-via-form", city).shuffle(slots)
    cut = shortest_slots(count)
    shortest = shortest_order_tasks(world, resolver, city, places, sorted(slots[:cut]))
    return sorted([*year_order_tasks(world, resolver, city, places, sorted(slots[cut:])), *shortest],
                  key=lambda t: t.id)


def year_order_tasks(world: Any, resolver: WorldAdapter, city: str, places: list[Any], slots: list[int]) -> list[Task]:
    """Hard by composition (issue 26, principle 6): four stops whose order only the wiki gives (oldest first
    by the year built), ending at the newest. Nothing the agent sees before the work tells the order: the
    intent lists the stops in an independent seeded shuffle (never checked against the answer), and every
    condition a draw must meet (legs of at least VIA_MIN_LEG_M, a walk of at most STOPS_MAX_M) holds for
    the stops in EVERY order, so the geometry of the draw says nothing of which order is the answer."""
    rng = rng_for("navigation-via", city)
    dated = [(p, y) for p, y in stop_years([p for p in places if p.kind not in ("intersection", "address")])
             if resolves_to(resolver, p)]
    tasks: list[Task] = []
    used: set[tuple[str, ...]] = set()
    walks: dict[tuple[str, str], Any] = {}

    def leg(a: Any, b: Any) -> Any:
        if (a.id, b.id) not in walks:
            walks[(a.id, b.id)] = world.directions(a.id, b.id)
        return walks[(a.id, b.id)]

    tries = 0
    count = len(slots)
    while len(tasks) < count and tries < count * 300 and len(dated) >= STOPS:
        tries += 1
        origin = rng.choice(places)
        here = world.node(origin.node)
        near = [(p, y) for p, y in dated if haversine_m(here.lat, here.lng, p.lat, p.lng) <= STOPS_NEAR_M]
        if len(near) < STOPS:
            continue
        chosen = rng.sample(near, STOPS)
        years = sorted(y for _, y in chosen)
        if any(b - a < 5 for a, b in zip(years, years[1:])):
            continue  # the order must be plain from the years
        order = [p for p, _ in sorted(chosen, key=lambda c: c[1])]
        key = (origin.id, *sorted(p.id for p in order))
        if key in used or len({origin.node, *(p.node for p in order)}) < STOPS + 1 \
                or not resolves_to(resolver, origin):
            continue
        try:
            # every leg any order could walk: origin to each stop, each stop to each other
            pairs = [(origin, p) for p in order] + [(a, b) for a in order for b in order if a.id != b.id]
            if min(leg(a, b).distance_m for a, b in pairs) < VIA_MIN_LEG_M:
                continue
            longest = max(sum(leg(a, b).distance_m for a, b in zip([origin, *perm], perm))
                          for perm in permutations(order))
        except ValueError:
            continue
        if longest > STOPS_MAX_M:
            continue
        n = slots[len(tasks)]
        listed = order[:]
        rng_for("navigation-via-listed", city, n).shuffle(listed)  # its own stream: independent of the answer
        used.add(key)
        legs = [leg(a, b) for a, b in zip([origin, *order], order)]
        total = sum(x.distance_m for x in legs)
        nodes = legs[0].nodes + [x for lg in legs[1:] for x in lg.nodes[1:]]
        oracle = [*[call("browser_goto", url=site_url("wiki", f"/wiki/{article_slug(p)}")) for p in listed],
                  *[call("browser_goto", url=site_url("map", "/directions", **{"from": a.name, "to": b.name}))
                    for a, b in zip([origin, *order], order)],
                  call("switch_environment", target="embodied", message="walk past the stops"),
                  *walk_oracle(nodes), call("finish_episode")]
        task_rng = rng_for("navigation-via", city, n)
        stops = ", ".join(describe(p) for p in listed[:-1]) + " and " + describe(listed[-1])
        tasks.append(Task(
            id=f"navigation-via-{city}-{n:03d}",
            domain="navigation",
            difficulty="hard",
            intent=task_rng.choice(STOPS_TEMPLATES).format(origin=describe(origin), stops=stops),
            start=start_state(world, city, origin, task_rng),
            web_goals=[PageVisited(site="wiki", path_prefix=f"/wiki/{article_slug(p)}") for p in order],
            embodied_goals=chain_goals(world, city, order),  # the walk ending at the newest
            step_limit=step_budget("navigation", "hard", len(oracle)),
            oracle=oracle,
            metadata={"shortest_path_m": round(total, 1), "start_lat": world.node(origin.node).lat,
                      "start_lng": world.node(origin.node).lng, "origin_node": origin.node,
                      "destination_node": order[-1].node, "route_steps": sum(len(x.steps) for x in legs),
                      "turns": sum(turns(x) for x in legs), "stops": [p.id for p in order],
                      "listed": [p.id for p in listed], "years": years, "origin_id": origin.id,
                      "form": "year order"},
        ))
    return tasks


SHORTEST_STOPS = 6  # 720 orders from 21 walking distances; five (120), then four (24), only where six cannot be drawn
SHORTEST_FALLBACK_STOPS = (5, 4)
SHORTEST_NEAR_M = 700.0  # every stop within this of the origin as the crow flies
# The shortest leg between two stops: shorter than the year-order form's (the order is searched, not sorted, and
# a stop passed on the way to another is caught by the chain check below); 150 m left Boston's clustered
# landmarks almost no draw of five.
SHORTEST_MIN_LEG_M = 100.0
# The best order beats the second best by at least SHORTEST_MARGIN_M (the map rounds each leg to 1 m, so a sum
# of six legs is off by 3 m at most: rounding never flips it) but by no more than SHORTEST_MARGIN_MAX_M, so
# an estimate (straight lines, the listed order) or one slipped sum picks a rival; the third best is within
# SHORTEST_THIRD_MAX_M of the best, so a near miss has more than one rival to land on.
SHORTEST_MARGIN_M = 30.0
SHORTEST_MARGIN_MAX_M = 100.0
SHORTEST_THIRD_MAX_M = 160.0
SHORTEST_MAX_M = {4: STOPS_MAX_M, 5: 2600.0, 6: 3000.0}  # the best walk, by stops (the hard step budget fits it)
SHORTEST_TRIES = 4000  # draws for one slot with six stops before it falls back to five (then four)
SHORTEST_SHARE = 1 / 3  # no tempting shortcut (shortcut_orders) may give the answer in more of a city's tasks
# Of a city's hard slots, this share asks for the shortest order, the rest for the wiki's year order (round 9:
# strong agents sort four years without a slip; a search over 720 orders is where care can fail).
SHORTEST_SLOTS = 3 / 4
NUMBER_WORDS = {4: "four", 5: "five", 6: "six"}
FARTHEST_LAST = "ends at the place farthest from the start on foot"
# The end a shortest walk most often has (in three of four kept draws without this cap).
SHORTEST_END_SHARE = 1 / 3
SHORTEST_TEMPLATES = [
    "Starting at {origin}, visit {stops} in the order that makes the shortest walk on foot in all, using the "
    "map's walking distances, and end your walk at the last of them. The order is yours to find: compare the "
    "walking distances the map site gives (from the start to each place and between each two places; walking "
    "distances, not straight lines). " + WALK_RULE,
    "I am at {origin} and want to see {stops}, all {count}, in whichever order makes my whole walk on foot "
    "shortest, using the map's walking distances, ending at the last one I visit. Work the order out from the "
    "walking distances the map site gives between my start and each place and between the places themselves, "
    "then walk it. " + WALK_RULE,
]


def walk_length(leg: Any, origin: Any, order: Any) -> float:
    """Metres of the walk from ``origin`` past ``order`` in turn, leg by leg as the map gives each leg."""
    return float(sum(leg(a, b) for a, b in zip([origin, *order], order)))


def greedy_from(leg: Any, here: Any, left: list[Any]) -> list[Any]:
    """Always the nearest place not yet seen (by ``leg``), from ``here``."""
    left, out = list(left), []
    while left:
        here = min(left, key=lambda p: leg(here, p))
        left.remove(here)
        out.append(here)
    return out


def two_opt(leg: Any, origin: Any, order: list[Any]) -> list[Any]:
    """``order`` improved by reversing a stretch of it while any reversal shortens the walk from ``origin``
    (the start stays first; the best reversal each round, the first of equals)."""
    order = list(order)
    while True:
        now = walk_length(leg, origin, order)
        tries = [order[:i] + order[i:j + 1][::-1] + order[j + 1:]
                 for i in range(len(order)) for j in range(i + 1, len(order))]
        better = min(tries, key=lambda o: walk_length(leg, origin, o))
        if walk_length(leg, origin, better) >= now - 1e-9:
            return order
        order = better


def cheapest_insertion(leg: Any, origin: Any, part: list[Any], rest: Any) -> list[Any]:
    """``part`` with the stop ``rest`` put where it lengthens the walk from ``origin`` least."""
    tries = [part[:i] + [rest] + part[i:] for i in range(len(part) + 1)]
    return min(tries, key=lambda o: walk_length(leg, origin, o))


def shortcut_orders(world: Any, leg: Any, origin: Any, stops: list[Any], listed: list[Any]) -> dict[str, list[str]]:
    """The orders a shortcut gives instead of working through every order (the ids, first to last): the order
    the intent lists; always the nearest stop not yet seen on foot (greedy nearest-next); the others as listed,
    then an end by elimination (the stop-elimination agent's order); nearest to farthest
    from the start as the crow flies; nearest to farthest from the start on foot; the shortest tour on straight
    lines between the places' points (the answer without reading the map); the best walk past all but one stop
    (the smaller search done right), the one left appended, or put in at its cheapest place (insertion); greedy
    nearest-next improved by reversing stretches while that shortens it (2-opt). ``leg(a, b)`` is the map's
    walking distance in metres."""
    # One answer whatever order the stops come in: the searches below keep the first of equal orders, and the
    # generator (stops as drawn) and a check (stops as listed) must find the same ones.
    stops = sorted(stops, key=lambda p: p.id)
    start = world.node(origin.node)

    def crow(a: Any, b: Any) -> float:
        pa, pb = world.node(a.node), world.node(b.node)
        return haversine_m(pa.lat, pa.lng, pb.lat, pb.lng)

    tour = min(permutations(stops), key=lambda perm: walk_length(crow, origin, perm))
    # the stop-elimination agent's order: the others as listed, then the first listed stop that is neither
    # listed last nor where greedy nearest-next ends
    greedy = greedy_from(leg, origin, stops)
    end = ([p for p in listed if p.id not in (listed[-1].id, greedy[-1].id)] or listed)[0]
    part = min(permutations(stops, len(stops) - 1), key=lambda perm: walk_length(leg, origin, perm))
    rest = [p for p in stops if p not in part]
    return {"listed": [p.id for p in listed],
            "greedy nearest-next": [p.id for p in greedy],
            "the others as listed, then elimination's end": [*(p.id for p in listed if p.id != end.id), end.id],
            "straight line from the start": [p.id for p in sorted(
                stops, key=lambda p: haversine_m(start.lat, start.lng, world.node(p.node).lat,
                                                 world.node(p.node).lng))],
            "walk from the start": [p.id for p in sorted(stops, key=lambda p: leg(origin, p))],
            "straight-line tour": [p.id for p in tour],
            "best walk past all but one, then the last": [p.id for p in [*part, *rest]],
            "best walk past all but one, the last inserted": [p.id for p in cheapest_insertion(
                leg, origin, list(part), rest[0])],
            "2-opt from greedy nearest-next": [p.id for p in two_opt(leg, origin, greedy)]}


def chain_goals(world: Any, city: str, order: list[Any]) -> list[Any]:
    """Each stop passed after the one before it (a chain), the walk ending at the last."""
    return [*[PassedPlace(city=city, node=p.node, lat=world.node(p.node).lat, lng=world.node(p.node).lng,
                          place_id=p.id, after=waypoint(world, order[k - 1]) if k else None)
              for k, p in enumerate(order[:-1])],
            reached(world, city, order[-1])]


def chain_passes(world: Any, city: str, order: list[Any], nodes: list[str]) -> bool:
    """Whether a walk over ``nodes`` (ending at the last) meets the chain of ``order`` as the grader checks it."""
    from ..checks import check_passed_place

    state = {"city": city, "path_points": [[world.node(n).lat, world.node(n).lng] for n in nodes]}
    end = world.node(nodes[-1])
    goals = chain_goals(world, city, order)
    last = goals[-1]
    return all(check_passed_place(g, state, None).met for g in goals[:-1]) and \
        haversine_m(end.lat, end.lng, last.lat, last.lng) <= last.radius_m


def shortest_order_tasks(world: Any, resolver: WorldAdapter, city: str, places: list[Any],
                         slots: list[int]) -> list[Task]:
    """Hard by composition and discrimination (issue 26, principle 6): six named stops (five, then four, where
    the city's data gives no six), visited in the order that makes the shortest walk on foot, ending at the
    last. The order is the agent's to find from the map's walking distances (21 of them: the start to each
    stop, each two stops), working through the 720 orders; each distance is stated plainly, but only all of
    them together give the order. Kept draws: the best order beats the second best by SHORTEST_MARGIN_M to
    SHORTEST_MARGIN_MAX_M (clear of the map's rounding, small enough that an estimate or one slipped sum picks
    a rival) and the third by at most SHORTEST_THIRD_MAX_M; no shortcut (shortcut_orders) gives it in more than SHORTEST_SHARE of the city's tasks, greedy
    nearest-next never, and no draw is given by two shortcuts at once; and a walk that follows the map past the
    stops in any other order fails the chain (the grader passes only the best order, even though a stop passed
    early on the way to another does not count against a walk)."""
    rng = rng_for("navigation-shortest", city)
    # one bracket: an address that holds one ("Madison Square Park (E 23rd St & Madison Ave)") reads as a
    # place named twice in a list of five
    stops_pool = [p for p in places if p.kind not in ("intersection", "address")
                  and describe(p).endswith(")") and describe(p).count("(") == 1 and resolves_to(resolver, p)]
    tasks: list[Task] = []
    used: set[tuple[str, ...]] = set()
    hits: dict[str, int] = {}
    walks: dict[tuple[str, str], Any] = {}

    def route(a: Any, b: Any) -> Any:
        if (a.id, b.id) not in walks:
            walks[(a.id, b.id)] = world.directions(a.id, b.id)
        return walks[(a.id, b.id)]

    def leg(a: Any, b: Any) -> float:
        return float(route(a, b).distance_m)

    def joined(origin: Any, perm: Any) -> list[str]:
        walk = [route(a, b) for a, b in zip([origin, *perm], perm)]
        return list(walk[0].nodes + [x for lg in walk[1:] for x in lg.nodes[1:]])

    for n in slots:
        sizes = [SHORTEST_STOPS, *SHORTEST_FALLBACK_STOPS]
        size, tries = sizes.pop(0), 0
        task: Task | None = None
        while task is None:
            tries += 1
            if tries > SHORTEST_TRIES * (3 if not sizes else 1):  # the smallest size: the slot's last chance
                if not sizes:
                    break  # a slot left empty, as with any draw that finds too little (a train split's seed)
                size, tries = sizes.pop(0), 0
            origin = rng.choice(places)
            here = world.node(origin.node)
            near = [p for p in stops_pool if haversine_m(here.lat, here.lng, p.lat, p.lng) <= SHORTEST_NEAR_M]
            if len(near) < size:
                continue
            chosen = sorted(rng.sample(near, size), key=lambda p: p.id)
            key = (origin.id, *(p.id for p in chosen))
            if key in used or len({origin.node, *(p.node for p in chosen)}) < size + 1 \
                    or not resolves_to(resolver, origin):
                continue
            try:
                pairs = [(origin, p) for p in chosen] + [(a, b) for a in chosen for b in chosen if a.id != b.id]
                if min(leg(a, b) for a, b in pairs) < SHORTEST_MIN_LEG_M:
                    continue
                ranked = sorted(permutations(chosen), key=lambda perm: walk_length(leg, origin, perm))
            except ValueError:
                continue
            order = list(ranked[0])
            best, second = walk_length(leg, origin, order), walk_length(leg, origin, ranked[1])
            third = walk_length(leg, origin, ranked[2])
            if not SHORTEST_MARGIN_M <= second - best <= SHORTEST_MARGIN_MAX_M or best > SHORTEST_MAX_M[size] \
                    or third - best > SHORTEST_THIRD_MAX_M:
                continue
            listed = list(chosen)
            rng_for("navigation-shortest-listed", city, n).shuffle(listed)  # its own stream, never redrawn
            target = [p.id for p in order]
            matched = [name for name, ids in shortcut_orders(world, leg, origin, chosen, listed).items()
                       if ids == target]
            # the end alone: the place farthest from the start on foot last cuts the search to the orders of
            # the others (120 of 720), so a six- or five-stop answer ends there in at most SHORTEST_END_SHARE of
            # a city's tasks (the four-stop fallback, which only clustered Boston needs, is left uncapped)
            if size >= 5 and max(chosen, key=lambda p: leg(origin, p)) is order[-1]:
                matched.append(FARTHEST_LAST)
            if {"greedy nearest-next", "the others as listed, then elimination's end"} & set(matched) or \
                    len(set(matched) - {FARTHEST_LAST}) > 1 or \
                    any(hits.get(name, 0) + 1 > (SHORTEST_END_SHARE if name == FARTHEST_LAST else SHORTEST_SHARE)
                        * len(slots) for name in matched):
                continue
            nodes = joined(origin, order)
            if not chain_passes(world, city, order, nodes) or \
                    any(chain_passes(world, city, order, joined(origin, perm)) for perm in ranked[1:]):
                continue
            for name in matched:
                hits[name] = hits.get(name, 0) + 1
            used.add(key)
            task = shortest_task(world, city, n, origin, order, listed, nodes, route, best, second, third)
        if task is not None:
            tasks.append(task)
    return tasks


def shortest_task(world: Any, city: str, n: int, origin: Any, order: list[Any], listed: list[Any],
                  nodes: list[str], route: Any, best: float, second: float, third: float) -> Task:
    """The task of a kept shortest-order draw: every distance the order needs, looked up as an agent would
    (the start to each stop, each two stops), then the walk."""
    legs = [route(a, b) for a, b in zip([origin, *order], order)]
    lookups = [(origin, p) for p in listed] + [(a, b) for i, a in enumerate(listed) for b in listed[i + 1:]]
    oracle = [*[call("browser_goto", url=site_url("map", "/directions", **{"from": a.name, "to": b.name}))
                for a, b in lookups],
              call("switch_environment", target="embodied", message="walk the shortest order"),
              *walk_oracle(nodes), call("finish_episode")]
    task_rng = rng_for("navigation-shortest", city, n)
    stops = ", ".join(describe(p) for p in listed[:-1]) + " and " + describe(listed[-1])
    here = world.node(origin.node)
    return Task(
        id=f"navigation-via-{city}-{n:03d}",
        domain="navigation",
        difficulty="hard",
        intent=task_rng.choice(SHORTEST_TEMPLATES).format(origin=describe(origin), stops=stops,
                                                          count=NUMBER_WORDS[len(order)]),
        start=start_state(world, city, origin, task_rng),
        web_goals=[PageVisited(site="map", path_prefix="/directions")],
        embodied_goals=chain_goals(world, city, order),
        step_limit=step_budget("navigation", "hard", len(oracle)),
        oracle=oracle,
        metadata={"shortest_path_m": round(best, 1), "start_lat": here.lat, "start_lng": here.lng,
                  "origin_node": origin.node, "destination_node": order[-1].node,
                  "route_steps": sum(len(x.steps) for x in legs), "turns": sum(turns(x) for x in legs),
                  "stops": [p.id for p in order], "listed": [p.id for p in listed], "origin_id": origin.id,
                  "form": "shortest order", "second_best_m": round(second, 1),
                  "margin_m": round(second - best, 1), "third_margin_m": round(third - best, 1)},
    )


def waypoint(world: Any, place: Any) -> Waypoint:
    node = world.node(place.node)
    return Waypoint(node=place.node, lat=node.lat, lng=node.lng, place_id=place.id)


def nearest_first(world: Any, origin: Any, stops: list[Any]) -> str:
    """Where a walk that always goes to the nearest stop not yet seen ends (the stop's id)."""
    here, left = origin, list(stops)
    while left:
        here = min(left, key=lambda p: world.directions(here.id, p.id).distance_m)
        left.remove(here)
    return str(here.id)


def generate(cities: list[str] | None = None) -> list[Task]:
    """The navigation tasks of every city, or of ``cities`` only (a quicker draw of a training split)."""
    unknown = sorted(set(cities or ()) - set(PER_CITY))
    if unknown:
        raise ValueError(f"unknown cities {unknown}; choose from {sorted(PER_CITY)}")
    world = get_world()
    resolver = WorldAdapter(world)
    tasks: list[Task] = []
    for city, count in PER_CITY.items():
        if cities and city not in cities:
            continue
        rng = rng_for("navigation", city)
        places = candidate_places(world, city, rng)
        made, tries = 0, 0
        used: set[tuple[str, str]] = set()
        while made < count and tries < count * 60:
            tries += 1
            origin, dest = rng.sample(places, 2)
            if origin.node == dest.node or (origin.id, dest.id) in used:
                continue
            o_text, d_text = describe(origin), describe(dest)
            if not resolves_to(resolver, origin) or not resolves_to(resolver, dest):
                continue
            try:
                route = world.directions(origin.id, dest.id)
            except ValueError:
                continue  # no walkable route: never written
            if not MIN_M <= route.distance_m <= MAX_M:
                continue
            used.add((origin.id, dest.id))
            oracle = [call("browser_goto", url=site_url("map", "/directions", **{"from": origin.name, "to": dest.name})),
                      call("switch_environment", target="embodied", message="walk the route"),
                      *walk_oracle(route.nodes), call("finish_episode")]
            task_rng = rng_for("navigation", city, made)
            level = "easy" if turns(route) <= EASY_MAX_TURNS else "medium"
            tasks.append(Task(
                id=f"navigation-{city}-{made:03d}",
                domain="navigation",
                difficulty=level,
                intent=task_rng.choice(TEMPLATES).format(origin=o_text, destination=d_text),
                start=start_state(world, city, origin, task_rng),
                web_goals=[DirectionsShown(origin=origin.id, destination=dest.id)],
                embodied_goals=[reached(world, city, dest)],
                step_limit=step_budget("navigation", level, len(oracle)),
                oracle=oracle,
                metadata=metadata(world, origin, dest, route),
            ))
            made += 1
        tasks.extend(stops_tasks(world, resolver, city, places, PER_CITY_VIA[city]))
    return tasks
