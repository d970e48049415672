"""The outdoor world as one object: the four city graphs, their points of interest, place search,
and walking directions that agree step by step with the embodied street walk.

    from ewa_mcp.outdoor.world import get_world
    w = get_world()
    w.search("350 5th Ave")                       # -> [Place]
    w.directions("poi-manhattan-flatiron-building", "store-target-herald-square")

Graphs are loaded once per process (``get_world`` is cached). Node ids are opaque and stable.
Turn-by-turn steps are built in ``directions.py``; places' addresses are tied to their nodes at load
by ``anchoring.py``.
"""

from __future__ import annotations

import gzip
import heapq
import json
import math
import os
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import networkx as nx

from ..geometry import bearing_deg, haversine_m
from .address import BLOCK_RULES, fold, loose_street, normalize_street, parse_address, same_address
from .anchoring import anchor_addresses
from .directions import DirectionStep, Directions, walking_steps

DATA_DIR = Path(__file__).resolve().parent / "data"
PACKAGED_CITIES = ["manhattan", "philadelphia", "boston", "pittsburgh"]
WALKING_SPEED_MPS = 1.4
# A route that changes street pays this many metres in the search (not in the reported length), so
# that among equally short grid routes the one with the fewest turns wins, as a map service would.
TURN_PENALTY_M = 25.0
EXTRA_DATA_ENV = "EWA_STREET_DATA"
# Ids of street-address places: "address:<city>:<number> <street>". An address is its own place: it
# never turns into the name of the building there (a traveling task's address must not name its landmark).
ADDRESS_ID_PREFIX = "address:"


class WorldError(ValueError):
    """A bad id or query; the message names the problem and the fix."""


@dataclass(frozen=True)
class Node:
    id: str
    city: str
    lat: float
    lng: float
    streets: tuple[str, ...]


@dataclass(frozen=True)
class Link:
    """One street segment leaving a node."""

    node: str
    heading: float  # compass bearing from the current node to ``node``
    length_m: float
    street: str


@dataclass
class Place:
    id: str
    name: str
    kind: str  # landmark, store, restaurant, station, park, ..., or intersection / address / street
    city: str
    address: str
    lat: float
    lng: float
    node: str
    facts: dict[str, Any] = field(default_factory=dict)
    description_hint: str = ""
    heading_from_node: float | None = None  # which way the place lies from its street node
    offset_m: float = 0.0
    # An address place: the point of interest at that address, for site records (events) only; pages
    # never show it.
    refers_to: str | None = None


class CityGraph:
    """One city's graph in compact arrays (fast moves and routing) plus a lazily built networkx view."""

    def __init__(self, data: dict[str, Any]):
        if data.get("format") != "ewa-street-graph":
            raise WorldError("not an ewa street graph file (format field missing); regenerate it with "
                             "python -m ewa_mcp.outdoor.generate or the importer")
        self.city: str = data["city"]
        self.name: str = data.get("name", self.city)
        self.code: str = data["code"]
        self.streets: list[str] = data["streets"]
        self.aliases: dict[str, str] = data.get("aliases", {})
        self.fit: dict[str, Any] = data.get("fit", {})
        self.ids: list[str] = [n[0] for n in data["nodes"]]
        self.lat: list[float] = [n[1] for n in data["nodes"]]
        self.lng: list[float] = [n[2] for n in data["nodes"]]
        self.index: dict[str, int] = {nid: i for i, nid in enumerate(self.ids)}
        # adjacency: per node a list of (neighbour index, length m, street index, heading)
        self.adj: list[list[tuple[int, float, int, float]]] = [[] for _ in self.ids]
        for a, b, s in data["edges"]:
            length = haversine_m(self.lat[a], self.lng[a], self.lat[b], self.lng[b])
            self.adj[a].append((b, length, s, bearing_deg(self.lat[a], self.lng[a], self.lat[b], self.lng[b])))
            self.adj[b].append((a, length, s, bearing_deg(self.lat[b], self.lng[b], self.lat[a], self.lng[a])))
        self.node_streets: list[tuple[str, ...]] = [
            tuple(sorted({self.streets[s] for _, _, s, _ in links})) for links in self.adj
        ]
        self.poi_links: dict[str, list] = data.get("pois", {})
        # Imported graphs carry their own named places (a task's start and destination addresses).
        self.extra_places: list[dict[str, Any]] = data.get("places", [])
        self.street_key: list[str] = [normalize_street(s, self.aliases) for s in self.streets]
        self.nodes_by_key: dict[str, set[int]] = {}
        self.nodes_by_loose: dict[str, set[int]] = {}
        for i, links in enumerate(self.adj):
            for _, _, s, _ in links:
                self.nodes_by_key.setdefault(self.street_key[s], set()).add(i)
                self.nodes_by_loose.setdefault(loose_street(self.street_key[s]), set()).add(i)
        self._nx: nx.Graph | None = None

    # ------------------------------------------------------------ lookups
    def node(self, i: int) -> Node:
        return Node(self.ids[i], self.city, self.lat[i], self.lng[i], self.node_streets[i])

    def links(self, i: int) -> list[Link]:
        return [Link(self.ids[j], round(h, 1), round(length, 1), self.streets[s]) for j, length, s, h in self.adj[i]]

    def nearest(self, lat: float, lng: float, candidates: set[int] | None = None) -> int:
        pool = candidates if candidates is not None else range(len(self.ids))
        return min(pool, key=lambda i: (self.lat[i] - lat) ** 2 + ((self.lng[i] - lng) * 0.76) ** 2)

    def street_nodes(self, key: str) -> set[int]:
        """Nodes on a street given by a normalised key; without a direction it matches either side."""
        found = self.nodes_by_key.get(key)
        if found:
            return found
        return self.nodes_by_loose.get(loose_street(key), set())

    def to_networkx(self) -> nx.Graph:
        if self._nx is None:
            g = nx.Graph(city=self.city, name=self.name)
            for i, nid in enumerate(self.ids):
                g.add_node(nid, lat=self.lat[i], lng=self.lng[i], streets=list(self.node_streets[i]))
            for a, links in enumerate(self.adj):
                for b, length, s, h in links:
                    if a < b:
                        back = (h + 180.0) % 360.0
                        g.add_edge(self.ids[a], self.ids[b], length=length, street=self.streets[s],
                                   heading={self.ids[a]: round(h, 2), self.ids[b]: round(back, 2)})
            self._nx = g
        return self._nx

    # ------------------------------------------------------------ routing
    def route(self, src: int, dst: int) -> list[int]:
        """A* over (node, street arrived on) with a small turn penalty; haversine heuristic."""
        if src == dst:
            return [src]
        lat_d, lng_d = self.lat[dst], self.lng[dst]
        coslat = math.cos(math.radians(lat_d))
        k = 111_195.0

        def h(i: int) -> float:
            # Equirectangular distance: within 0.1 % of haversine at city scale, and an
            # admissible lower bound once scaled down by that margin.
            return 0.998 * k * math.hypot(self.lat[i] - lat_d, (self.lng[i] - lng_d) * coslat)

        start = (src, -1)
        best: dict[tuple[int, int], float] = {start: 0.0}
        parent: dict[tuple[int, int], tuple[int, int]] = {}
        heap = [(h(src), 0.0, src, -1)]
        while heap:
            _, g, i, s_in = heapq.heappop(heap)
            if i == dst:
                path = [i]
                state = (i, s_in)
                while state in parent:
                    state = parent[state]
                    path.append(state[0])
                return path[::-1]
            if g > best.get((i, s_in), math.inf):
                continue
            for j, length, s, _ in self.adj[i]:
                ng = g + length + (TURN_PENALTY_M if s_in not in (-1, s) else 0.0)
                key = (j, s)
                if ng < best.get(key, math.inf):
                    best[key] = ng
                    parent[key] = (i, s_in)
                    heapq.heappush(heap, (ng + h(j), ng, j, s))
        raise WorldError(f"no walking route in {self.city} between these nodes (the graph is disconnected there)")

    def edge(self, a: int, b: int) -> tuple[float, int, float]:
        for j, length, s, h in self.adj[a]:
            if j == b:
                return length, s, h
        raise WorldError(f"nodes {self.ids[a]} and {self.ids[b]} are not neighbours")


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
        anchor_addresses(self.places, self.cities_by_name)
        self._folded = {pid: fold(f"{p.name} {p.kind}") for pid, p in self.places.items()}
        self._folded_address = {pid: fold(p.address) for pid, p in self.places.items()}
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
            if p.city in cities and (self._folded_address[pid] == folded or
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

    def _search_names(self, query: str, cities: list[str]) -> list[Place]:
        q = fold(query)
        tokens = q.split()
        scored = []
        for pid, text in self._folded.items():
            p = self.places[pid]
            if p.city not in cities:
                continue
            # Name and kind only: matching address words would turn an address into the name of what is there.
            words = text.split()
            if q in text:
                score = 3.0 + (1.0 if text.startswith(q) else 0.0) + len(q) / max(1, len(text))
            elif all(any(w.startswith(t) for w in words) for t in tokens):
                score = 1.0 + sum(t in words for t in tokens) / len(tokens)
            else:
                continue
            scored.append((-score, p.name, pid))
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
        raise WorldError(f"street graph {path} is missing; run python -m ewa_mcp.outdoor.generate") from None


def _extra_dirs() -> list[Path]:
    from ..settings import load_settings  # the street_data setting; re-read: use_street_data extends it

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
