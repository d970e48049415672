"""The outdoor world as one object: the four city graphs, their points of interest, place search,
and walking directions that agree step by step with the embodied street walk.

    from ewa_mcp.outdoor.world import get_world
    w = get_world()
    w.search("350 5th Ave")                       # -> [Place]
    w.directions("poi-manhattan-flatiron-building", "store-target-herald-square")

Graphs are loaded once per process (``get_world`` is cached). Node ids are opaque and stable.
"""

from __future__ import annotations

import gzip
import heapq
import json
import math
import os
import threading
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import networkx as nx

from .address import BLOCK_RULES, loose_street, normalize_street, parse_address
from ..geometry import angle_diff, bearing_deg, cardinal_word, haversine_m

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


@dataclass
class DirectionStep:
    maneuver: str  # depart, continue, slight/turn/sharp left/right, u-turn (walking back), waypoint, arrive
    street: str
    distance_m: float
    instruction: str
    start_node: str = ""
    end_node: str = ""
    heading: float = 0.0  # compass bearing when starting this step


@dataclass
class Directions:
    city: str
    origin: str
    destination: str
    nodes: list[str]
    distance_m: float
    duration_s: float
    steps: list[DirectionStep]


def _fold(text: str) -> str:
    """Case-, accent- and punctuation-insensitive form for matching names."""
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode()
    text = text.lower().replace("&", " and ").replace("'", "").replace("’", "")
    return " ".join("".join(c if c.isalnum() else " " for c in text).split())


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
        self._folded = {pid: _fold(f"{p.name} {p.kind}") for pid, p in self.places.items()}
        self._folded_address = {pid: _fold(p.address) for pid, p in self.places.items()}
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
        folded = _fold(query)
        for pid in sorted(self.places):
            p = self.places[pid]
            if p.city in cities and (self._folded_address[pid] == folded or
                                     _same_address(p.address, number, street, self.cities_by_name[p.city].aliases)):
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
            key = normalize_street(street, g.aliases)
            on_street = g.street_nodes(key)
            rule = BLOCK_RULES.get(c)
            if not on_street or rule is None:
                continue
            block = rule(key, number)
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
            canonical = next(g.streets[s] for _, _, s, _ in g.adj[i] if g.street_key[s] in (key,) or
                             loose_street(g.street_key[s]) == loose_street(key))
            address = f"{number} {canonical}"
            out.append(Place(id=f"{ADDRESS_ID_PREFIX}{c}:{address}", name=address, kind="address", city=c,
                             address=address, lat=g.lat[i], lng=g.lng[i], node=g.ids[i]))
        return out

    def _search_names(self, query: str, cities: list[str]) -> list[Place]:
        q = _fold(query)
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
        steps = _steps(g1, path, dest_place)
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


# ---------------------------------------------------------------- where a place's address is
# A task names a place with its address ("Boston Common (Tremont St & Park St)"), and the walk is graded
# at the place's node: the two must be one spot. A place whose corner label names a corner away from its
# node is moved to that corner when the corner is near the place itself, else relabelled with its node's
# own corner; places sharing one address share one node.
ANCHOR_RADIUS_M = 25.0  # the default arrival radius of a street goal
ANCHOR_MAX_MOVE_M = 320.0  # a named corner farther than this from the place itself is not its corner
ANCHOR_MAX_MOVE_OTHER_M = 225.0  # the same for anything but a park (a park reaches its corners from far)
ANCHOR_KIND_ORDER = ["landmark", "park", "hotel", "museum", "church", "library", "theater", "market", "station"]


def label_streets(graph: CityGraph, label: str) -> tuple[list[set[int]], bool]:
    """The node sets of the streets a corner label names ("A & B", "X (A & B)", "A & B at C",
    "A between B & C"), and whether it names a block rather than a corner."""
    text = label.replace("(", ",").replace(")", ",").replace(" between ", " & ").replace(" at ", " & ")
    parts = [q.strip() for chunk in text.split(",") for q in chunk.replace(" and ", " & ").split("&") if q.strip()]
    found = [nodes for nodes in (graph.street_nodes(normalize_street(q, graph.aliases)) for q in parts) if nodes]
    return found, " between " in label


def label_corner(graph: CityGraph, label: str, lat: float, lng: float) -> int | None:
    """The corner a label names (the one nearest the place when streets meet twice); None if it names none."""
    streets, _ = label_streets(graph, label)
    corners = {i for a in range(len(streets)) for b in range(a + 1, len(streets)) for i in streets[a] & streets[b]}
    return graph.nearest(lat, lng, corners) if corners else None


def label_fits(graph: CityGraph, label: str, node: int) -> bool:
    """Whether a corner label describes this node: its corner within the arrival radius, or (a block
    label, "A between B & C") the node on A between the two corners."""
    streets, block = label_streets(graph, label)
    if block and len(streets) == 3:
        ends = [streets[0] & streets[k] for k in (1, 2)]
        if node not in streets[0] or not all(ends):
            return False
        e1, e2 = (min(e, key=lambda i: haversine_m(graph.lat[i], graph.lng[i], graph.lat[node], graph.lng[node]))
                  for e in ends)
        span = haversine_m(graph.lat[e1], graph.lng[e1], graph.lat[e2], graph.lng[e2])
        return (haversine_m(graph.lat[e1], graph.lng[e1], graph.lat[node], graph.lng[node]) +
                haversine_m(graph.lat[e2], graph.lng[e2], graph.lat[node], graph.lng[node])) <= span + ANCHOR_RADIUS_M
    corner = label_corner(graph, label, graph.lat[node], graph.lng[node])
    return corner is not None and haversine_m(graph.lat[corner], graph.lng[corner], graph.lat[node],
                                              graph.lng[node]) <= ANCHOR_RADIUS_M


def _attach(p: Place, graph: CityGraph, i: int) -> None:
    p.node = graph.ids[i]
    p.offset_m = round(haversine_m(graph.lat[i], graph.lng[i], p.lat, p.lng), 1)
    p.heading_from_node = round(bearing_deg(graph.lat[i], graph.lng[i], p.lat, p.lng), 1)


def node_label(graph: CityGraph, i: int) -> str:
    """A label derived from the node itself: its corner, or its street between the corners either side."""
    if len(graph.node_streets[i]) >= 2:
        return " & ".join(graph.node_streets[i])
    street = graph.node_streets[i][0] if graph.node_streets[i] else ""
    ends = []
    for j, _, s, _ in graph.adj[i]:
        prev, cur = i, j
        for _ in range(50):
            if len(graph.node_streets[cur]) >= 2:
                ends.append(next(n for n in graph.node_streets[cur] if n != street))
                break
            nxt = [k for k, _, s2, _ in graph.adj[cur] if k != prev and graph.streets[s2] == street]
            if not nxt:
                break
            prev, cur = cur, nxt[0]
    ends = sorted(set(ends))
    return f"{street} between {ends[0]} & {ends[1]}" if len(ends) == 2 else street


def anchor_addresses(places: dict[str, Place], graphs: dict[str, CityGraph]) -> None:
    """Make every point of interest's address name the spot of its node (see ANCHOR_* above)."""
    for p in sorted(places.values(), key=lambda p: p.id):
        graph = graphs[p.city]
        if p.refers_to or p.kind in ("address", "intersection") or parse_address(p.address) is not None:
            continue
        i = graph.index[p.node]
        corner = None if label_streets(graph, p.address)[1] else label_corner(graph, p.address, p.lat, p.lng)
        reach = ANCHOR_MAX_MOVE_M if p.kind == "park" else ANCHOR_MAX_MOVE_OTHER_M
        if corner is not None and haversine_m(graph.lat[corner], graph.lng[corner], p.lat, p.lng) <= reach:
            if corner != i:
                _attach(p, graph, corner)  # at the corner itself: places named by one corner share its node
        elif not label_fits(graph, p.address, i):
            p.address = node_label(graph, i)
    groups: dict[tuple[str, str], list[Place]] = {}
    for p in places.values():
        if parse_address(p.address) is not None:
            groups.setdefault((p.city, _fold(p.address)), []).append(p)
    for group in groups.values():
        if len({p.node for p in group}) > 1:  # one address, one spot: the main building's node
            rank = {k: n for n, k in enumerate(ANCHOR_KIND_ORDER)}
            main = min(group, key=lambda p: (rank.get(p.kind, len(rank)), p.id))
            graph = graphs[main.city]
            for p in group:
                if p.node != main.node:
                    _attach(p, graph, graph.index[main.node])


def _same_address(address: str, number: int, street: str, aliases: dict[str, str]) -> bool:
    parsed = parse_address(address)
    if parsed is None or parsed[0] != number:
        return False
    a, b = normalize_street(parsed[1], aliases), normalize_street(street, aliases)
    return a == b or loose_street(a) == loose_street(b) and (a.split()[0] not in ("west", "east") or
                                                             b.split()[0] not in ("west", "east"))


def _maneuver(turn: float, reverses: bool = False) -> str:
    """The instruction for a change of heading. A U-turn is only ever walking back the way one came;
    a street leaving at a very sharp angle (a diagonal crossing a grid) is a sharp turn."""
    if reverses:
        return "u-turn"
    a = abs(turn)
    if a < 25:
        return "continue"
    side = "right" if turn > 0 else "left"
    if a < 60:
        return f"slight {side}"
    if a <= 135:
        return f"turn {side}"
    return f"sharp {side}"


def _round_m(d: float) -> int:
    return int(round(d / 10.0) * 10) if d >= 15 else int(round(d))


def _steps(g: CityGraph, path: list[int], dest: Place | None) -> list[DirectionStep]:
    if len(path) == 1:
        name = dest.name if dest else "your destination"
        return [DirectionStep("arrive", g.node_streets[path[0]][0] if g.node_streets[path[0]] else "",
                              0.0, f"You are already at {name}.", g.ids[path[0]], g.ids[path[0]], 0.0)]
    segments: list[dict[str, Any]] = []
    for k, (a, b) in enumerate(zip(path, path[1:])):
        length, s, h = g.edge(a, b)
        reverses = k > 0 and path[k - 1] == b  # walking straight back along the edge just walked
        if segments and segments[-1]["street"] == s and not reverses:
            seg = segments[-1]
            seg["length"] += length
            seg["end"] = b
            seg["last_heading"] = h
        else:
            segments.append({"street": s, "length": length, "start": a, "end": b, "heading": h, "last_heading": h,
                             "reverses": reverses})
    steps: list[DirectionStep] = []
    prev_heading = None
    for k, seg in enumerate(segments):
        street = g.streets[seg["street"]]
        dist = round(seg["length"], 1)
        if k == 0:
            maneuver = "depart"
            text = f"Head {cardinal_word(seg['heading'])} on {street} for {_round_m(dist)} m."
        else:
            maneuver = _maneuver(angle_diff(seg["heading"], prev_heading), seg["reverses"])
            if maneuver == "continue":
                text = f"Continue onto {street} for {_round_m(dist)} m."
            elif maneuver == "u-turn":
                text = f"Make a U-turn and walk back along {street} for {_round_m(dist)} m."
            elif maneuver.startswith("sharp"):
                text = f"Turn {maneuver} onto {street} and walk {_round_m(dist)} m."
            else:
                text = f"{maneuver.capitalize()} onto {street} and walk {_round_m(dist)} m."
        steps.append(DirectionStep(maneuver, street, dist, text, g.ids[seg["start"]], g.ids[seg["end"]],
                                   round(seg["heading"], 1)))
        prev_heading = seg["last_heading"]
    end = path[-1]
    where = dest.name if dest else "your destination"
    side = ""
    if dest is not None and dest.heading_from_node is not None and dest.offset_m > 5 and prev_heading is not None:
        rel = angle_diff(dest.heading_from_node, prev_heading)
        side = " on your right" if rel > 20 else " on your left" if rel < -20 else " ahead"
    steps.append(DirectionStep("arrive", g.streets[segments[-1]["street"]], 0.0, f"Arrive at {where}{side}.",
                               g.ids[end], g.ids[end], round(prev_heading or 0.0, 1)))
    return steps


def _read(path: Path) -> dict[str, Any]:
    try:
        with gzip.open(path, "rt", encoding="utf-8") as fh:
            return json.load(fh)
    except FileNotFoundError:
        raise WorldError(f"street graph {path} is missing; run python -m ewa_mcp.outdoor.generate") from None


def _extra_dirs() -> list[Path]:
    value = os.environ.get(EXTRA_DATA_ENV, "")
    return [Path(p) for p in value.split(os.pathsep) if p]


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
