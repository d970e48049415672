"""The street graph of one city and its places: nodes, links, places and shortest walks (``CityGraph``).

``world.py`` loads the graphs and answers searches and directions over them; ``directions.py`` and
``anchoring.py`` read the types declared here, so none of them needs the world.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field
from typing import Any

import networkx as nx

from ewa_mcp.geometry import bearing_deg, haversine_m
from .address import loose_street, normalize_street

WALKING_SPEED_MPS = 1.4
# A route that changes street pays this many metres in the search (not in the reported length), so
# that among equally short grid routes the one with the fewest turns wins, as a map service would.
TURN_PENALTY_M = 25.0
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
                             "python -m ewa_mcp.envs.street.graphgen or the importer")
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
