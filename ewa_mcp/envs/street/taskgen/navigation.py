"""Navigation tasks: get walking directions on the map site, then walk them in the street graph and
end the walk at the destination. Origins and destinations are landmarks, addresses and intersections
in all four cities; the start heading is drawn from the streets at the origin, never from the route.

Difficulty: a direct route with at most one turn is easy, one with more turns medium; a walk that
must pass a named waypoint on the way (directions via it, graded with a passed_place goal) is hard."""

from __future__ import annotations

from typing import Any

from ..world import directions_via, get_world
from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import DirectionsShown, WebStart
from ewa_mcp.envs.street.goals import PassedPlace, ReachedPlace, StreetStart
from ewa_mcp.websites.map.places import WorldAdapter
from ewa_mcp.taskgen.common import WALK_RULE, call, rng_for, site_url, step_budget

PER_CITY = {"manhattan": 44, "philadelphia": 36, "boston": 36, "pittsburgh": 36}
# Hard tasks (via a waypoint) per city: 34 of 186 navigation tasks, 18 %.
PER_CITY_VIA = {"manhattan": 10, "philadelphia": 8, "boston": 8, "pittsburgh": 8}
MIN_M, MAX_M = 250.0, 1300.0
VIA_MIN_LEG_M, VIA_MAX_M = 150.0, 1600.0
EASY_MAX_TURNS = 1
TEMPLATES = [
    "Starting at {origin}, guide me step-by-step to {destination}. Get walking directions on the map site, "
    "then walk there. " + WALK_RULE,
    "Show me the fastest walking route from {origin} to {destination} on the map, then follow it on foot. "
    + WALK_RULE,
    "I am at {origin}. Look up how to walk to {destination} online, then walk there. " + WALK_RULE,
]
VIA_TEMPLATES = [
    "Starting at {origin}, walk to {destination}, passing {waypoint} on the way. Get walking directions via "
    "{waypoint} on the map site, then walk that route. " + WALK_RULE,
    "I am at {origin} and want to see {waypoint} on my way to {destination}. Look up a walking route that passes "
    "it on the map, then follow it on foot. " + WALK_RULE,
]


def describe(place: Any) -> str:
    """How a task names a place: landmarks by name, addresses and intersections as written on signs."""
    if place.kind == "intersection":
        return f"the corner of {place.name.replace(' & ', ' and ')}"
    return f"{place.name} ({place.address})" if place.address else place.name


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


def via_tasks(world: Any, resolver: WorldAdapter, city: str, places: list[Any], count: int) -> list[Task]:
    """Hard tasks: origin -> named waypoint -> destination, the waypoint off the direct route."""
    rng = rng_for("navigation-via", city)
    named = [p for p in places if p.kind not in ("intersection", "address")]
    tasks: list[Task] = []
    used: set[tuple[str, str, str]] = set()
    tries = 0
    while len(tasks) < count and tries < count * 300:
        tries += 1
        origin, dest = rng.sample(places, 2)
        waypoint = rng.choice(named)
        ids = (origin.id, waypoint.id, dest.id)
        if len({origin.node, waypoint.node, dest.node}) < 3 or ids in used:
            continue
        if not all(resolves_to(resolver, p) for p in (origin, waypoint, dest)):
            continue
        try:
            direct = world.directions(origin.id, dest.id)
            first, second = world.directions(origin.id, waypoint.id), world.directions(waypoint.id, dest.id)
        except ValueError:
            continue
        if min(first.distance_m, second.distance_m) < VIA_MIN_LEG_M or first.distance_m + second.distance_m > VIA_MAX_M:
            continue
        # The waypoint must be a detour: the direct route never comes near it, so passing it is a choice.
        if waypoint.node in direct.nodes or first.distance_m + second.distance_m < direct.distance_m + 100:
            continue
        route = directions_via(world, origin.id, waypoint.id, dest.id)
        if len(set(route.nodes)) < len(route.nodes):
            continue  # the walk would double back on itself after the waypoint
        used.add(ids)
        n = len(tasks)
        oracle = [call("browser_goto", url=site_url("map", "/directions", **{"from": origin.name, "via": waypoint.name,
                                                                              "to": dest.name})),
                  call("switch_environment", target="embodied", message="walk the route"),
                  *walk_oracle(route.nodes), call("finish_episode")]
        task_rng = rng_for("navigation-via", city, n)
        way = world.node(waypoint.node)
        tasks.append(Task(
            id=f"navigation-via-{city}-{n:03d}",
            domain="navigation",
            difficulty="hard",
            intent=task_rng.choice(VIA_TEMPLATES).format(origin=describe(origin), destination=describe(dest),
                                                         waypoint=describe(waypoint)),
            start=start_state(world, city, origin, task_rng),
            web_goals=[DirectionsShown(origin=origin.id, destination=waypoint.id),
                       DirectionsShown(origin=waypoint.id, destination=dest.id)],
            embodied_goals=[PassedPlace(city=city, node=waypoint.node, lat=way.lat, lng=way.lng, place_id=waypoint.id),
                            reached(world, city, dest)],
            step_limit=step_budget("navigation", "hard", len(oracle)),
            oracle=oracle,
            metadata=metadata(world, origin, dest, route, waypoint_node=waypoint.node,
                              direct_route_m=direct.distance_m),
        ))
    return tasks


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
        tasks.extend(via_tasks(world, resolver, city, places, PER_CITY_VIA[city]))
    return tasks
