"""The outdoor world as one object: the four city graphs, their points of interest, place search,
and walking directions that agree step by step with the embodied street walk.

    from ewa_mcp.envs.street.world import get_world
    w = get_world()
    w.search("350 5th Ave")                       # -> [Place]
    w.directions("poi-manhattan-flatiron-building", "store-target-herald-square")

Graphs are loaded once per process (``get_world`` is cached). Node ids are opaque and stable.
Turn-by-turn steps are built in ``directions.py``; places' addresses are tied to their nodes at load
by ``anchoring.py``.
"""

from __future__ import annotations

import gzip
import json
import os
import threading
from pathlib import Path
from typing import Any

import networkx as nx

from .address import BLOCK_RULES, fold, loose_street, normalize_street, parse_address, same_address
from .anchoring import anchor_addresses
from .directions import DirectionStep, Directions, walking_steps
from .graph import (  # noqa: F401  (re-exported: the world's types)
    ADDRESS_ID_PREFIX,
    TURN_PENALTY_M,
    WALKING_SPEED_MPS,
    CityGraph,
    Link,
    Node,
    Place,
    WorldError,
)

DATA_DIR = Path(__file__).resolve().parent / "data"
PACKAGED_CITIES = ["manhattan", "philadelphia", "boston", "pittsburgh"]
EXTRA_DATA_ENV = "EWA_STREET_DATA"


class World:
    def __init__(self, data_dirs: list[Path] | None = None, pois_path: Path | None = None):
        self.cities_by_name: dict[str, CityGraph] = {}
        for city in PACKAGED_CITIES:
            self._add(CityGraph(_read(DATA_DIR / f"{city}.json.gz")))
        for directory in data_dirs if data_dirs is not None else _extra_dirs():
            for path in sorted(Path(directory).glob("*.json.gz")):
                self._add(CityGraph(_read(path)))
        self.by_code = {g.code: g for g in self.cities_by_name.values()}
        raw_pois = json.loads((pois_path or DATA_DIR / "pois.json").read_text(encoding="utf-8"))
        self.places: dict[str, Place] = {}
        for p in raw_pois:
            graph = self.cities_by_name.get(p["city"])
            link = graph.poi_links.get(p["id"]) if graph else None
            if link is None:
                continue  # a POI of a city that is not loaded (or not yet attached)
            self.places[p["id"]] = Place(
                id=p["id"], name=p["name"], kind=p["kind"], city=p["city"], address=p["address"],
                lat=p["lat"], lng=p["lng"], node=link[0], facts=dict(p.get("facts", {})),
                description_hint=p.get("description_hint", ""), heading_from_node=link[1], offset_m=link[2],
            )
        for graph in self.cities_by_name.values():
            for p in graph.extra_places:
                if p.get("node") in graph.index:
                    self.places[p["id"]] = Place(id=p["id"], name=p["name"], kind=p.get("kind", "address"),
                                                 city=graph.city, address=p.get("address", p["name"]),
                                                 lat=p["lat"], lng=p["lng"], node=p["node"])
        # The address a place is listed at (its wiki article gives it too), before anchoring moves it to the
        # street its node stands on: "1501 Broadway" must still find the Paramount Building.
        listed = {pid: fold(p.address) for pid, p in self.places.items()}
        anchor_addresses(self.places, self.cities_by_name)
        # Other names a place goes by (its wiki article's title, "New York Public Library Main Branch").
        aliases = {p["id"]: tuple(p.get("aliases", ())) for p in raw_pois}
        self._folded = {pid: fold(f"{p.name} {p.kind}") for pid, p in self.places.items()}
        self._folded_aliases = {pid: tuple(fold(f"{a} {p.kind}") for a in aliases.get(pid, ()))
                                for pid, p in self.places.items()}
        self._folded_address = {pid: fold(p.address) for pid, p in self.places.items()}
        self._folded_listed = {pid: text for pid, text in listed.items() if text != self._folded_address[pid]}
        self.places_at: dict[str, list[Place]] = {}
        for p in self.places.values():
            self.places_at.setdefault(p.node, []).append(p)

    def _add(self, graph: CityGraph) -> None:
        if graph.city in self.cities_by_name:
            raise WorldError(f"two street graphs are named {graph.city!r}; rename one (its 'city' field)")
        self.cities_by_name[graph.city] = graph

    # ------------------------------------------------------------ basic access
    @property
    def cities(self) -> list[str]:
        return list(self.cities_by_name)

    def city(self, city: str) -> CityGraph:
        graph = self.cities_by_name.get(city)
        if graph is None:
            raise WorldError(f"unknown city {city!r}; available: {', '.join(self.cities)}")
        return graph

    def graph(self, city: str) -> nx.Graph:
        return self.city(city).to_networkx()

    def locate(self, node_id: str) -> tuple[CityGraph, int]:
        graph = self.by_code.get(node_id.split("-", 1)[0])
        if graph is None or node_id not in graph.index:
            raise WorldError(f"unknown node id {node_id!r}; node ids look like 'mn-0123456789' "
                             "(use search() or a place's node field)")
        return graph, graph.index[node_id]

    def node(self, node_id: str) -> Node:
        graph, i = self.locate(node_id)
        return graph.node(i)

    def neighbours(self, node_id: str) -> list[Link]:
        graph, i = self.locate(node_id)
        return graph.links(i)

    def place(self, place_id: str) -> Place | None:
        if place_id in self.places:
            return self.places[place_id]
        if place_id.startswith(ADDRESS_ID_PREFIX):
            return self._address_place(place_id)
        try:
            graph, i = self.locate(place_id)
        except WorldError:
            return None
        streets = graph.node_streets[i]
        return Place(id=place_id, name=" & ".join(streets), kind="intersection" if len(streets) > 1 else "street",
                     city=graph.city, address=" & ".join(streets), lat=graph.lat[i], lng=graph.lng[i], node=place_id)

    def _address_place(self, place_id: str) -> Place | None:
        city, _, text = place_id[len(ADDRESS_ID_PREFIX):].partition(":")
        if city not in self.cities_by_name or not text:
            return None
        found = self._search_address(text, [city])
        return found[0] if found else None

    def stores(self) -> list[Place]:
        return sorted((p for p in self.places.values() if p.kind == "store"), key=lambda p: p.id)

    def places_near(self, node_id: str) -> list[Place]:
        return list(self.places_at.get(node_id, []))

    # ------------------------------------------------------------ search
    def search(self, query: str, city: str | None = None, limit: int = 10) -> list[Place]:
        """Points of interest by name, addresses ("350 5th Ave") and intersections
        ("W 23rd St & 5th Ave"); case- and punctuation-insensitive."""
        if not isinstance(query, str) or not query.strip():
            raise WorldError("empty search query; give a place name, an address or 'street & street'")
        if city is not None:
            self.city(city)
        cities = [city] if city else self.cities
        results: list[Place] = []
        seen: set[str] = set()

        def add(p: Place) -> None:
            if p.id not in seen:
                seen.add(p.id)
                results.append(p)

        for p in self._search_intersection(query, cities):
            add(p)
        for p in self._search_address(query, cities):
            add(p)
        for p in self._search_names(query, cities):
            add(p)
        return results[:limit]

    def _search_intersection(self, query: str, cities: list[str]) -> list[Place]:
        text = query.replace(" and ", " & ").replace(" AND ", " & ").replace(" at ", " & ").replace("/", " & ")
        parts = [p.strip() for p in text.split("&") if p.strip()]
        if len(parts) != 2:
            return []
        out = []
        for c in cities:
            g = self.cities_by_name[c]
            a = g.street_nodes(normalize_street(parts[0], g.aliases))
            b = g.street_nodes(normalize_street(parts[1], g.aliases))
            both = a & b
            if not both:
                continue
            i = min(both, key=lambda k: g.ids[k])  # several when streets meet twice; stable choice
            names = []
            for part in parts:
                key = normalize_street(part, g.aliases)
                names.append(next((n for n in g.node_streets[i] if g.street_key[g.streets.index(n)] == key), None)
                             or next(n for n in g.node_streets[i]
                                     if loose_street(g.street_key[g.streets.index(n)]) == loose_street(key)))
            name = " & ".join(names)
            out.append(Place(id=g.ids[i], name=name, kind="intersection", city=c, address=name,
                             lat=g.lat[i], lng=g.lng[i], node=g.ids[i]))
        return out

    def _search_address(self, query: str, cities: list[str]) -> list[Place]:
        """Street addresses as address places (named by the address, never by the building there): the
        address of a point of interest stands at its node, any other is interpolated along its block."""
        parsed = parse_address(query)
        if parsed is None:
            return []
        number, street = parsed
        out: list[Place] = []
        seen: set[tuple[str, str]] = set()
        folded = fold(query)
        for pid in sorted(self.places):
            p = self.places[pid]
            if p.city in cities and (self._folded_address[pid] == folded or self._folded_listed.get(pid) == folded or
                                     same_address(p.address, number, street, self.cities_by_name[p.city].aliases)):
                key = (p.city, self._folded_address[pid])
                if key in seen:
                    continue  # two places at one address: one address
                seen.add(key)
                out.append(Place(id=f"{ADDRESS_ID_PREFIX}{p.city}:{p.address}", name=p.address, kind="address",
                                 city=p.city, address=p.address, lat=p.lat, lng=p.lng, node=p.node,
                                 heading_from_node=p.heading_from_node, offset_m=p.offset_m, refers_to=p.id))
        if out:
            return out
        for c in cities:
            g = self.cities_by_name[c]
            street_key = normalize_street(street, g.aliases)
            on_street = g.street_nodes(street_key)
            rule = BLOCK_RULES.get(c)
            if not on_street or rule is None:
                continue
            block = rule(street_key, number)
            if block is None:
                continue
            ends = []
            for cross in block[:2]:
                hits = on_street & g.street_nodes(cross)
                if hits:
                    ends.append(min(hits, key=lambda k: g.ids[k]))
            if len(ends) != 2:
                continue
            f = block[2]
            lat = g.lat[ends[0]] + f * (g.lat[ends[1]] - g.lat[ends[0]])
            lng = g.lng[ends[0]] + f * (g.lng[ends[1]] - g.lng[ends[0]])
            i = g.nearest(lat, lng, on_street)
            canonical = next(g.streets[s] for _, _, s, _ in g.adj[i] if g.street_key[s] in (street_key,) or
                             loose_street(g.street_key[s]) == loose_street(street_key))
            address = f"{number} {canonical}"
            out.append(Place(id=f"{ADDRESS_ID_PREFIX}{c}:{address}", name=address, kind="address", city=c,
                             address=address, lat=g.lat[i], lng=g.lng[i], node=g.ids[i]))
        return out

    def listed_at(self, text: str, city: str | None = None) -> list[Place]:
        """The places whose address, as listed or as anchored, is ``text`` written out in full
        ("Quincy Market, S Market St"), which the address search does not parse."""
        wanted = fold(text)
        return [p for pid, p in sorted(self.places.items()) if (city is None or p.city == city)
                and wanted and wanted in (self._folded_address[pid], self._folded_listed.get(pid))]

    def _search_names(self, query: str, cities: list[str]) -> list[Place]:
        q = fold(query)
        tokens = q.split()
        scored = []
        for pid, name in self._folded.items():
            p = self.places[pid]
            if p.city not in cities:
                continue
            # Name (or another name) and kind only: matching address words would turn an address into the
            # name of what is there.
            best = None
            for text in (name, *self._folded_aliases[pid]):
                words = text.split()
                if q in text:
                    score = 3.0 + (1.0 if text.startswith(q) else 0.0) + len(q) / max(1, len(text))
                elif all(any(w.startswith(t) for w in words) for t in tokens):
                    score = 1.0 + sum(t in words for t in tokens) / len(tokens)
                else:
                    continue
                best = score if best is None else max(best, score)
            if best is not None:
                scored.append((-best, p.name, pid))
        return [self.places[pid] for _, _, pid in sorted(scored)]

    # ------------------------------------------------------------ directions
    def resolve(self, ref: str) -> tuple[CityGraph, int, Place | None]:
        if not isinstance(ref, str) or not ref:
            raise WorldError("empty place reference; pass a place id (poi-..., store-...) or a node id")
        p = self.places.get(ref)
        if p is None and ref.startswith(ADDRESS_ID_PREFIX):
            p = self._address_place(ref)
        if p is not None:
            graph, i = self.locate(p.node)
            return graph, i, p
        try:
            graph, i = self.locate(ref)
        except WorldError:
            raise WorldError(f"unknown place or node id {ref!r}; find ids with search(query)") from None
        return graph, i, None

    def directions(self, origin: str, destination: str) -> Directions:
        g1, a, _ = self.resolve(origin)
        g2, b, dest_place = self.resolve(destination)
        if g1 is not g2:
            raise WorldError(f"{origin!r} is in {g1.city} and {destination!r} is in {g2.city}; walking directions "
                             "need both places in the same city")
        path = g1.route(a, b)
        steps = walking_steps(g1, path, dest_place)
        distance = round(sum(s.distance_m for s in steps), 1)
        return Directions(city=g1.city, origin=origin, destination=destination, nodes=[g1.ids[i] for i in path],
                          distance_m=distance, duration_s=round(distance / WALKING_SPEED_MPS, 1), steps=steps)


def directions_via(world: "World", origin: str, via: str, destination: str) -> Directions:
    """Walking directions from origin to destination that pass a waypoint: the two shortest legs joined,
    the first leg's arrival becoming a 'Pass ...' step (maneuver 'waypoint')."""
    first, second = world.directions(origin, via), world.directions(via, destination)
    g, _, via_place = world.resolve(via)
    arrive = first.steps[-1]
    name = via_place.name if via_place is not None else "the waypoint"
    side = arrive.instruction.removeprefix(f"Arrive at {name}").removesuffix(".")
    passing = DirectionStep("waypoint", arrive.street, 0.0, f"Pass {name}{side}, then go on.", arrive.start_node,
                            arrive.end_node, arrive.heading)
    legs = first.steps[:-1] + [passing] + second.steps
    distance = round(first.distance_m + second.distance_m, 1)
    return Directions(city=first.city, origin=origin, destination=destination, nodes=first.nodes + second.nodes[1:],
                      distance_m=distance, duration_s=round(distance / WALKING_SPEED_MPS, 1), steps=legs)


def _read(path: Path) -> dict[str, Any]:
    try:
        with gzip.open(path, "rt", encoding="utf-8") as fh:
            return json.load(fh)
    except FileNotFoundError:
        raise WorldError(f"street graph {path} is missing; run python -m ewa_mcp.envs.street.graphgen") from None


def _extra_dirs() -> list[Path]:
    from ewa_mcp.settings import load_settings  # the street_data setting; re-read: use_street_data extends it

    return list(load_settings().street_data)


def use_street_data(dirs: list[Path]) -> None:
    """Add directories of street graph files to the world ($EWA_STREET_DATA, so server processes
    started from here see them too); a world already loaded is reloaded on next use."""
    global _world
    current = [str(p) for p in _extra_dirs()]
    new = [str(d) for d in dirs if Path(d).is_dir() and str(d) not in current]
    if not new:
        return
    os.environ[EXTRA_DATA_ENV] = os.pathsep.join(current + new)
    with _lock:
        _world = None


_lock = threading.Lock()
_world: World | None = None


def get_world() -> World:
    """The process-wide world (loaded on first use; a few hundred milliseconds)."""
    global _world
    if _world is None:
        with _lock:
            if _world is None:
                _world = World()
    return _world
