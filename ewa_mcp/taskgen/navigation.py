"""Navigation tasks: get walking directions on the map site, then walk them in the street graph and
stop at the destination. Origins and destinations are landmarks, addresses and intersections in all
four cities; the start heading is drawn from the streets at the origin, never from the route."""

from __future__ import annotations

from typing import Any

from ..outdoor.world import get_world
from ..taskmodel import DirectionsShown, ReachedPlace, StartState, StreetStart, Task, WebStart
from ..websites.map.places import WorldAdapter
from .common import call, rng_for, site_url, step_limit_for

PER_CITY = {"manhattan": 44, "philadelphia": 36, "boston": 36, "pittsburgh": 36}
MIN_M, MAX_M = 250.0, 1300.0
TEMPLATES = [
    "Starting at {origin}, guide me step-by-step to {destination}. Get walking directions on the map site, "
    "then walk there and stop when you arrive.",
    "Show me the fastest walking route from {origin} to {destination} on the map, then follow it on foot and "
    "stop at {destination}.",
    "I am at {origin}. Look up how to walk to {destination} online, walk there, and stop when you reach it.",
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


def generate() -> list[Task]:
    world = get_world()
    resolver = WorldAdapter(world)
    tasks: list[Task] = []
    for city, count in PER_CITY.items():
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
            # Validation: the map resolves what the oracle types to exactly these places.
            if resolver.resolve(origin.name).place is None or resolver.resolve(dest.name).place is None:
                continue
            if resolver.resolve(origin.name).place.id != origin.id or resolver.resolve(dest.name).place.id != dest.id:
                continue
            try:
                route = world.directions(origin.id, dest.id)
            except ValueError:
                continue  # no walkable route: never written
            if not MIN_M <= route.distance_m <= MAX_M:
                continue
            used.add((origin.id, dest.id))
            end = world.node(dest.node)
            oracle = [call("browser_goto", url=site_url("map", "/directions", **{"from": origin.name, "to": dest.name})),
                      call("switch_environment", target="embodied", message="walk the route"),
                      *walk_oracle(route.nodes), call("finish_episode")]
            task_rng = rng_for("navigation", city, made)
            tasks.append(Task(
                id=f"navigation-{city}-{made:03d}",
                domain="navigation",
                intent=task_rng.choice(TEMPLATES).format(origin=o_text, destination=d_text),
                start=StartState(environment="web", web=WebStart(start_url="map:/"),
                                 embodied=StreetStart(city=city, node=origin.node,
                                                      heading=start_heading(world, origin.node, task_rng))),
                web_goals=[DirectionsShown(origin=origin.id, destination=dest.id)],
                embodied_goals=[ReachedPlace(city=city, node=dest.node, lat=end.lat, lng=end.lng, place_id=dest.id)],
                step_limit=step_limit_for(len(oracle), slack=30),
                oracle=oracle,
                metadata={"shortest_path_m": route.distance_m, "start_lat": world.node(origin.node).lat,
                          "start_lng": world.node(origin.node).lng, "origin_node": origin.node,
                          "destination_node": dest.node, "route_steps": len(route.steps)},
            ))
            made += 1
    return tasks
