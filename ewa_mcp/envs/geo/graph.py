"""The explorable standpoint graph of a location.

Five standpoints on the street's axis: the start p0, one step each way (p1 ahead along the
street's bearing, p2 behind) and two steps each way (p3 beyond p1, p4 beyond p2):

    p4 — p2 — p0 — p1 — p3

Spacing is 22–38 m (a few house fronts), fixed per location.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from ewa_mcp.geometry import destination
from .locations import Location
from .seeding import rng_for


@dataclass(frozen=True)
class Neighbour:
    id: str
    bearing: float  # absolute heading from this standpoint, degrees
    distance_m: float


@dataclass(frozen=True)
class Standpoint:
    id: str
    lat: float
    lng: float
    offset_m: float  # signed distance from the start along the street's bearing
    steps_from_start: int
    neighbours: tuple[Neighbour, ...]


START = "p0"


@lru_cache(maxsize=512)
def build_graph(loc: Location) -> dict[str, Standpoint]:
    rng = rng_for("graph", loc.id)
    d1, d2, d3, d4 = (round(rng.uniform(22, 38), 1) for _ in range(4))
    offsets = {"p0": 0.0, "p1": d1, "p2": -d2, "p3": d1 + d3, "p4": -(d2 + d4)}
    steps = {"p0": 0, "p1": 1, "p2": 1, "p3": 2, "p4": 2}
    edges = [("p0", "p1"), ("p0", "p2"), ("p1", "p3"), ("p2", "p4")]
    ahead, behind = float(loc.bearing), float((loc.bearing + 180) % 360)

    adjacency: dict[str, list[Neighbour]] = {k: [] for k in offsets}
    for a, b in edges:
        dist = round(abs(offsets[b] - offsets[a]), 1)
        a_to_b = ahead if offsets[b] > offsets[a] else behind
        b_to_a = behind if a_to_b == ahead else ahead
        adjacency[a].append(Neighbour(b, a_to_b, dist))
        adjacency[b].append(Neighbour(a, b_to_a, dist))

    graph: dict[str, Standpoint] = {}
    for sid, off in offsets.items():
        bearing = ahead if off >= 0 else behind
        lat, lng = destination(loc.lat, loc.lng, bearing, abs(off) / 1000.0) if off else (loc.lat, loc.lng)
        graph[sid] = Standpoint(sid, lat, lng, off, steps[sid], tuple(sorted(adjacency[sid], key=lambda n: n.id)))
    return graph
