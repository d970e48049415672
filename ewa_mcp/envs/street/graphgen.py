"""Turns the hand-written city specs into the committed street graphs (``data/<city>.json.gz``).

    python -m ewa_mcp.envs.street.graphgen            # all cities
    python -m ewa_mcp.envs.street.graphgen manhattan  # one city

Steps: project each street polyline to local metres; find where streets cross (noding); cut every
street at its crossings and densify the pieces into panorama nodes every <= NODE_SPACING_M metres;
give nodes stable opaque ids; attach the points of interest to the street they are addressed on.
The output is deterministic: the same specs give byte-identical files.
"""

from __future__ import annotations

import argparse
import gzip
import hashlib
import importlib
import json
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

from ewa_mcp.geometry import LocalFrame, bearing_deg, haversine_m
from .address import normalize_street, parse_address
from .specs.base import CitySpec

DATA_DIR = Path(__file__).resolve().parent / "data"
CITIES = ["manhattan", "philadelphia", "boston", "pittsburgh"]
NODE_SPACING_M = 22.0  # Street View panoramas are ~10-25 m apart
SNAP_M = 4.0  # crossings closer than this are one junction
FORMAT = "ewa-street-graph"
FORMAT_VERSION = 1


def opaque_id(prefix: str, lat: float, lng: float) -> str:
    """A stable id from a position rounded to ~1 m, hashed so that the id does not reveal where it is
    (the agent must not be able to decode coordinates from node ids)."""
    key = f"{lat:.5f},{lng:.5f}".encode()
    return f"{prefix}-{hashlib.sha1(key).hexdigest()[:10]}"


@dataclass
class _Way:
    name: str
    xy: list[tuple[float, float]]
    cum: list[float] = field(default_factory=list)  # distance along the polyline at each vertex
    cuts: list[tuple[float, int]] = field(default_factory=list)  # (distance along, junction index)


def _cumulative(xy: list[tuple[float, float]]) -> list[float]:
    out = [0.0]
    for a, b in zip(xy, xy[1:]):
        out.append(out[-1] + math.dist(a, b))
    return out


def _point_at(way: _Way, s: float) -> tuple[float, float]:
    for i in range(len(way.xy) - 1):
        if s <= way.cum[i + 1] or i == len(way.xy) - 2:
            seg = way.cum[i + 1] - way.cum[i]
            f = 0.0 if seg == 0 else max(0.0, min(1.0, (s - way.cum[i]) / seg))
            (x0, y0), (x1, y1) = way.xy[i], way.xy[i + 1]
            return x0 + f * (x1 - x0), y0 + f * (y1 - y0)
    return way.xy[-1]


Point = tuple[float, float]


def _segment_hit(p: Point, p2: Point, q: Point, q2: Point, tol: float) -> tuple[float, float, float, float] | None:
    """Crossing of segments p-p2 and q-q2 (allowing ``tol`` metres of overshoot at the ends, so a
    street that ends on another street makes a T junction). Returns (t, u, x, y) or None."""
    r = (p2[0] - p[0], p2[1] - p[1])
    s = (q2[0] - q[0], q2[1] - q[1])
    cross = r[0] * s[1] - r[1] * s[0]
    lr, ls = math.hypot(*r), math.hypot(*s)
    if lr == 0 or ls == 0 or abs(cross) < 1e-6 * lr * ls:
        return None
    qp = (q[0] - p[0], q[1] - p[1])
    t = (qp[0] * s[1] - qp[1] * s[0]) / cross
    u = (qp[0] * r[1] - qp[1] * r[0]) / cross
    et, eu = tol / lr, tol / ls
    if -et <= t <= 1 + et and -eu <= u <= 1 + eu:
        t, u = min(1.0, max(0.0, t)), min(1.0, max(0.0, u))
        return t, u, p[0] + t * r[0], p[1] + t * r[1]
    return None


def build_graph(spec: CitySpec) -> dict:
    lats = [p[0] for w in spec.ways for p in w.points]
    lngs = [p[1] for w in spec.ways for p in w.points]
    frame = LocalFrame(round((min(lats) + max(lats)) / 2, 5), round((min(lngs) + max(lngs)) / 2, 5))
    ways: list[_Way] = []
    for spec_way in spec.ways:
        xy = [frame.to_xy(*p) for p in spec_way.points]
        ways.append(_Way(spec_way.name, xy, _cumulative(xy)))

    junctions: list[list[float]] = []  # [x, y]

    def junction(x: float, y: float) -> int:
        for i, (jx, jy) in enumerate(junctions):
            if abs(jx - x) < SNAP_M and abs(jy - y) < SNAP_M and math.hypot(jx - x, jy - y) < SNAP_M:
                return i
        junctions.append([x, y])
        return len(junctions) - 1

    # Endpoints first, so a T junction snaps onto the street end rather than beside it.
    for w in ways:
        w.cuts.append((0.0, junction(*w.xy[0])))
        w.cuts.append((w.cum[-1], junction(*w.xy[-1])))
    # Noding: a coarse spatial bucket of segments keeps this near-linear.
    cell = 200.0
    buckets: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for wi, w in enumerate(ways):
        for si in range(len(w.xy) - 1):
            (x0, y0), (x1, y1) = w.xy[si], w.xy[si + 1]
            for cx in range(int(math.floor(min(x0, x1) / cell)) - 1, int(math.floor(max(x0, x1) / cell)) + 2):
                for cy in range(int(math.floor(min(y0, y1) / cell)) - 1, int(math.floor(max(y0, y1) / cell)) + 2):
                    buckets.setdefault((cx, cy), []).append((wi, si))
    seen: set[tuple[int, int, int, int]] = set()
    for members in buckets.values():
        for a in range(len(members)):
            for b in range(a + 1, len(members)):
                (wa, sa), (wb, sb) = members[a], members[b]
                if wa == wb:
                    continue
                key = (wa, sa, wb, sb) if wa < wb else (wb, sb, wa, sa)
                if key in seen:
                    continue
                seen.add(key)
                A, B = ways[wa], ways[wb]
                hit = _segment_hit(A.xy[sa], A.xy[sa + 1], B.xy[sb], B.xy[sb + 1], SNAP_M)
                if hit is None:
                    continue
                t, u, x, y = hit
                j = junction(x, y)
                A.cuts.append((A.cum[sa] + t * (A.cum[sa + 1] - A.cum[sa]), j))
                B.cuts.append((B.cum[sb] + u * (B.cum[sb + 1] - B.cum[sb]), j))

    # Densify every piece between consecutive cuts.
    positions: list[tuple[float, float]] = [(jx, jy) for jx, jy in junctions]
    edges: dict[tuple[int, int], str] = {}
    for w in ways:
        cuts = sorted({(round(s, 3), j) for s, j in w.cuts})
        dedup: list[tuple[float, int]] = []
        for s, j in cuts:
            if dedup and dedup[-1][1] == j:
                continue
            dedup.append((s, j))
        for (s0, j0), (s1, j1) in zip(dedup, dedup[1:]):
            length = s1 - s0
            if length < 0.5:
                continue
            pieces = max(1, math.ceil(length / NODE_SPACING_M))
            prev = j0
            for k in range(1, pieces):
                positions.append(_point_at(w, s0 + length * k / pieces))
                cur = len(positions) - 1
                edges[(prev, cur)] = w.name
                prev = cur
            if prev != j1:
                edges[(prev, j1)] = w.name

    used = sorted({i for e in edges for i in e})
    latlng = {i: frame.to_latlng(*positions[i]) for i in used}
    ids: dict[int, str] = {}
    taken: set[str] = set()
    for i in sorted(used, key=lambda k: (round(latlng[k][0], 6), round(latlng[k][1], 6))):
        nid = opaque_id(spec.code, *latlng[i])
        if nid in taken:
            raise RuntimeError(f"node id collision at {latlng[i]}; nodes closer than ~1 m — check the {spec.city} spec")
        taken.add(nid)
        ids[i] = nid
    order = sorted(used, key=lambda k: ids[k])
    index = {k: n for n, k in enumerate(order)}
    streets = sorted({name for name in edges.values()})
    street_index = {s: n for n, s in enumerate(streets)}
    edge_rows = sorted(
        [min(index[a], index[b]), max(index[a], index[b]), street_index[name]]
        for (a, b), name in edges.items() if a != b
    )
    return {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "city": spec.city,
        "name": spec.name,
        "code": spec.code,
        "streets": streets,
        "aliases": spec.aliases,
        "nodes": [[ids[k], round(latlng[k][0], 6), round(latlng[k][1], 6)] for k in order],
        "edges": edge_rows,
        "fit": spec.fit,
    }


def attach_pois(graph: dict, pois: list[dict]) -> dict:
    """For each POI of this city: the nearest node on the street its address names (else the nearest
    node), the compass heading from that node to the POI (which side of the street it is on) and
    the offset in metres. Returns {poi_id: [node_id, heading, offset_m]}."""
    nodes = graph["nodes"]
    streets = graph["streets"]
    node_streets: dict[int, set[str]] = {}
    for a, b, s in graph["edges"]:
        node_streets.setdefault(a, set()).add(streets[s])
        node_streets.setdefault(b, set()).add(streets[s])
    norm_cache = {s: normalize_street(s, graph.get("aliases", {})) for s in streets}
    out: dict[str, list] = {}
    for poi in pois:
        if poi["city"] != graph["city"]:
            continue
        wanted = _address_streets(poi["address"], graph.get("aliases", {}))
        best, best_d = None, float("inf")
        fallback, fallback_d = None, float("inf")
        for i, (_, lat, lng) in enumerate(nodes):
            if abs(lat - poi["lat"]) > 0.01 or abs(lng - poi["lng"]) > 0.013:
                continue
            d = haversine_m(lat, lng, poi["lat"], poi["lng"])
            if d < fallback_d:
                fallback, fallback_d = i, d
            if wanted and any(norm_cache[s] in wanted for s in node_streets.get(i, ())) and d < best_d:
                best, best_d = i, d
        # Prefer the addressed street unless it is implausibly far (a bad address parse).
        chosen = best if best is not None and best_d <= fallback_d + 60.0 else fallback
        if chosen is None:
            raise RuntimeError(f"POI {poi['id']} is outside the {graph['city']} graph; fix its coordinates")
        nid, lat, lng = nodes[chosen]
        d = haversine_m(lat, lng, poi["lat"], poi["lng"])
        heading = bearing_deg(lat, lng, poi["lat"], poi["lng"]) if d > 1.0 else 0.0
        out[poi["id"]] = [nid, round(heading, 1), round(d, 1)]
    return out


def _address_streets(address: str, aliases: dict[str, str]) -> set[str]:
    parsed = parse_address(address)
    if parsed is not None:
        return {normalize_street(parsed[1], aliases)}
    parts = [p for p in address.replace(" and ", " & ").replace(" at ", " & ").split("&") if p.strip()]
    return {normalize_street(p.split("(")[0].split(" between ")[0], aliases) for p in parts}


def load_pois() -> list[dict]:
    return json.loads((DATA_DIR / "pois.json").read_text(encoding="utf-8"))


def write_city(city: str, data_dir: Path = DATA_DIR) -> dict:
    spec: CitySpec = importlib.import_module(f"ewa_mcp.envs.street.specs.{city}").build()
    graph = build_graph(spec)
    graph["pois"] = attach_pois(graph, load_pois())
    payload = json.dumps(graph, separators=(",", ":"), sort_keys=True).encode()
    path = data_dir / f"{city}.json.gz"
    with open(path, "wb") as fh:
        # mtime=0 keeps the gzip bytes identical between runs.
        with gzip.GzipFile(fileobj=fh, mode="wb", mtime=0, compresslevel=9) as gz:
            gz.write(payload)
    return {"city": city, "nodes": len(graph["nodes"]), "edges": len(graph["edges"]),
            "pois": len(graph["pois"]), "bytes": path.stat().st_size}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cities", nargs="*", default=CITIES, help=f"cities to build (default: {' '.join(CITIES)})")
    args = parser.parse_args(argv)
    for city in args.cities:
        if city not in CITIES:
            print(f"unknown city {city!r}; choose from {', '.join(CITIES)}", file=sys.stderr)
            return 2
        print(json.dumps(write_city(city)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
