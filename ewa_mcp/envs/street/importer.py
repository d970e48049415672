"""Read navigation environments in the paper's released format and build one street graph from them.

The release (``navi_env_merge_v1.json``) is a JSON list of environments. Each environment has a
``source`` and a ``target`` node key and a ``graph`` of panoramas keyed by "lat-lng" strings:

    [{"source": "40.7784-73.9551", "target": "40.7780-73.9542",
      "graph": {"40.7784-73.9551": {"google_pano_id": "...", "lat": 40.7784, "lng": -73.9551,
                                    "links": {"40.7783-73.9550": {"google_pano_id": "...",
                                                                  "heading": 119.0, "text": "E 85th St"}}}}}]

Also accepted: a mapping of name -> environment, one environment per file, ``nodes`` for
``graph``, ``pano_id`` for ``google_pano_id``, ``street`` for a link's ``text``, and links given as
``{key: heading}`` or a list of keys. All environments of one file become one city graph (this
package's format): panoramas shared by several environments are one node, and distinct panoramas
closer than ``MERGE_M`` are merged into one node that keeps every original key and panorama id as
an alias. ``release.py`` turns the environments into tasks.
"""

from __future__ import annotations

import hashlib
import math
import re
from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from .graphgen import FORMAT, FORMAT_VERSION
from ewa_mcp.geometry import haversine_m

KEY_RE = re.compile(r"^\s*(-?\d+(?:\.\d+)?)\s*[-_,;/ ]\s*(-?\d+(?:\.\d+)?)\s*$")
UNNAMED = "unnamed street"
MERGE_M = 1.0  # panoramas closer than this are one place (the release has pairs 0.2-0.8 m apart)
SAME_PANO_M = 15.0  # one panorama id at two positions further apart than this is not merged
NEAR_STREET_M = 60.0  # how far along unnamed links a node looks for the street it is near
SNAP_M = 5.0  # a source/target key missing from its graph may snap to a node this close
MAX_QUOTE = 120


class ImportFormatError(ValueError):
    """The file is not in a supported format; the message says what is missing."""


def quote(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= MAX_QUOTE else text[:MAX_QUOTE] + "…'"


@dataclass
class Environment:
    label: str  # the environment's index in a list file, or its name in a mapping
    source: Any
    target: Any
    nodes: dict[str, dict[str, Any]]


@dataclass
class ImportReport:
    environments_read: int = 0
    panoramas_read: int = 0
    nodes: int = 0
    edges: int = 0
    merged: list[dict[str, Any]] = field(default_factory=list)  # groups of panoramas made one node
    skipped: list[dict[str, str]] = field(default_factory=list)  # environments: label + reason
    notes: list[str] = field(default_factory=list)
    counts: Counter = field(default_factory=Counter)  # dropped nodes / links by reason

    def skip(self, label: str, reason: str) -> None:
        self.skipped.append({"environment": label, "reason": reason})


# ---------------------------------------------------------------- reading the file shapes
def _is_environment(value: Any) -> bool:
    return isinstance(value, dict) and ("graph" in value or "nodes" in value)


def environments(raw: Any, default_label: str) -> list[tuple[str, Any]]:
    """(label, environment) pairs from a list file, a name -> environment mapping or one environment."""
    if isinstance(raw, list):
        return [(str(i), env) for i, env in enumerate(raw)]
    if _is_environment(raw):
        return [(default_label, raw)]
    if isinstance(raw, dict) and raw and all(_is_environment(v) for v in raw.values()):
        return [(str(k), v) for k, v in raw.items()]
    if isinstance(raw, dict):
        raise ImportFormatError(
            f"{default_label}: not a navigation environment file: expected a list of environments, a mapping of "
            f"name -> environment, or one environment with 'source', 'target' and 'graph' (or 'nodes'); "
            f"top-level keys are {quote(sorted(map(str, raw))[:8])}")
    raise ImportFormatError(f"{default_label}: not a navigation environment file: the top level is a "
                            f"{type(raw).__name__}, expected a list or an object")


def _pick(raw: dict[str, Any], *names: str) -> Any:
    for name in names:
        if name in raw:
            return raw[name]
    return None


def _parse_key(key: str) -> tuple[float, float] | None:
    m = KEY_RE.match(key) if isinstance(key, str) else None
    if not m:
        return None
    lat, lng = float(m.group(1)), float(m.group(2))
    # Keys like "40.74-73.98" drop the minus of a western longitude into the separator; the release
    # is all in New York, so a positive longitude from such a key is taken as western.
    if lng > 0 and lat > 0 and "--" not in key and "-" in key[1:]:
        lng = -lng
    return lat, lng


def _number(value: Any) -> float | None:
    try:
        x = float(value)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) else None


def node_position(key: str, rec: dict[str, Any]) -> tuple[float, float] | None:
    lat = _number(_pick(rec, "lat", "latitude"))
    lng = _number(_pick(rec, "lng", "lon", "longitude"))
    if lat is None or lng is None:
        parsed = _parse_key(key)
        if parsed is None:
            return None
        lat, lng = parsed
    if not (-90 <= lat <= 90 and -180 <= lng <= 180):
        return None
    return lat, lng


def parse_environment(label: str, raw: Any) -> Environment:
    if not isinstance(raw, dict):
        raise ImportFormatError(f"environment {label} is a {type(raw).__name__}, not an object")
    nodes = _pick(raw, "graph", "nodes")
    if isinstance(nodes, list):  # a list of node records carrying their own key
        nodes = {str(_pick(n, "key", "id", "google_pano_id", "pano_id")): n for n in nodes if isinstance(n, dict)}
    if not isinstance(nodes, dict) or not nodes:
        raise ImportFormatError(f"environment {label} has no panoramas: expected a non-empty 'graph' object "
                                f"keyed by 'lat-lng'")
    source = _pick(raw, "source", "source_node", "start", "start_node")
    target = _pick(raw, "target", "target_node", "goal", "goal_node", "destination")
    if source is None or target is None:
        raise ImportFormatError(f"environment {label} has no 'source' and 'target' node keys")
    return Environment(label, source, target, {str(k): v for k, v in nodes.items()})


def _links(rec: dict[str, Any]) -> list[tuple[str, str | None, str | None]]:
    """(neighbour key, street name, neighbour panorama id) for each link of a node record."""
    links = _pick(rec, "links", "neighbors", "neighbours")
    if isinstance(links, list):
        out = []
        for item in links:
            if isinstance(item, dict):
                key = _pick(item, "key", "id", "node")
                if key is not None:
                    out.append((str(key), _street(item), _pano(item)))
            elif isinstance(item, str):
                out.append((item, None, None))
        return out
    if not isinstance(links, dict):
        return []
    return [(str(k), _street(v) if isinstance(v, dict) else None, _pano(v) if isinstance(v, dict) else None)
            for k, v in links.items()]


def _street(rec: dict[str, Any]) -> str | None:
    value = _pick(rec, "text", "street", "street_name", "name")
    if not isinstance(value, str):
        return None
    value = " ".join(value.split())[:80]
    return value or None


def _pano(rec: Any) -> str | None:
    if not isinstance(rec, dict):
        return None
    value = _pick(rec, "google_pano_id", "pano_id", "pano")
    return str(value) if isinstance(value, str | int) and str(value) else None


# ---------------------------------------------------------------- building the city graph
class _UnionFind:
    def __init__(self, n: int):
        self.parent = list(range(n))

    def find(self, i: int) -> int:
        while self.parent[i] != i:
            self.parent[i] = self.parent[self.parent[i]]
            i = self.parent[i]
        return i

    def union(self, a: int, b: int) -> None:
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[max(ra, rb)] = min(ra, rb)  # the earliest panorama represents the group


def city_code(city: str) -> str:
    return "x" + hashlib.sha1(city.encode()).hexdigest()[:5]


def node_id(code: str, lat: float, lng: float) -> str:
    # Hashed, so an id does not reveal where the node is; 7 decimals keep merged-away neighbours apart.
    return f"{code}-{hashlib.sha1(f'{lat:.7f},{lng:.7f}'.encode()).hexdigest()[:10]}"


@dataclass
class CityBuild:
    graph: dict[str, Any]  # the street graph file payload
    node_of: dict[tuple[str, str], str]  # (environment label, original key) -> node id
    position: dict[str, tuple[float, float]]  # node id -> (lat, lng)
    street_at: dict[str, str]  # node id -> the main street through it


def build_city(envs: list[Environment], city: str, name: str, report: ImportReport) -> CityBuild:
    """One street graph from all environments' panoramas (merged by panorama id and by distance)."""
    code = city_code(city)
    recs: list[tuple[str, str, float, float, str | None]] = []  # (env label, key, lat, lng, pano id)
    index: dict[tuple[str, str], int] = {}
    for env in envs:
        for key, rec in env.nodes.items():
            report.panoramas_read += 1
            pos = node_position(key, rec) if isinstance(rec, dict) else None
            if pos is None:
                report.counts["panoramas without a usable lat/lng (dropped)"] += 1
                continue
            index[(env.label, key)] = len(recs)
            recs.append((env.label, key, pos[0], pos[1], _pano(rec)))
    uf = _UnionFind(len(recs))
    by_pano: dict[str, int] = {}
    for i, (_, _, lat, lng, pano) in enumerate(recs):
        if pano is None:
            continue
        j = by_pano.setdefault(pano, i)
        if j != i:
            if haversine_m(lat, lng, recs[j][2], recs[j][3]) <= SAME_PANO_M:
                uf.union(i, j)
            else:
                report.counts["panorama ids found at two places over 15 m apart (kept apart)"] += 1
    # near-duplicates: a grid of ~1.1 m cells, compared with the neighbouring cells
    cells: dict[tuple[int, int], list[int]] = {}
    for i, (_, _, lat, lng, _) in enumerate(recs):
        cells.setdefault((int(math.floor(lat * 1e5)), int(math.floor(lng * 1e5))), []).append(i)
    for (cy, cx), members in cells.items():
        for dy in (-1, 0, 1):
            for dx in (-2, -1, 0, 1, 2):
                for j in cells.get((cy + dy, cx + dx), []):
                    for i in members:
                        if i < j and haversine_m(recs[i][2], recs[i][3], recs[j][2], recs[j][3]) < MERGE_M:
                            uf.union(i, j)
    groups: dict[int, list[int]] = {}
    for i in range(len(recs)):
        groups.setdefault(uf.find(i), []).append(i)
    rep_id: dict[int, str] = {}
    position: dict[str, tuple[float, float]] = {}
    aliases: dict[str, list[str]] = {}
    panos: dict[str, list[str]] = {}
    for root, members in groups.items():
        lat, lng = recs[root][2], recs[root][3]
        nid = node_id(code, lat, lng)
        if nid in position:  # two groups at the same 7-decimal position: merged by MERGE_M already
            raise ImportFormatError(f"two panorama groups share the position {lat},{lng}")
        rep_id[root] = nid
        position[nid] = (lat, lng)
        keys = sorted({recs[m][1] for m in members})
        pano_ids = sorted({pano for m in members if (pano := recs[m][4])})
        aliases[nid] = keys
        panos[nid] = pano_ids
        if len(keys) > 1 or len(pano_ids) > 1:
            spread = max(haversine_m(recs[a][2], recs[a][3], recs[b][2], recs[b][3]) for a in members for b in members)
            report.merged.append({"node": nid, "keys": keys, "pano_ids": pano_ids, "spread_m": round(spread, 2)})
    node_of = {(label, key): rep_id[uf.find(i)] for (label, key), i in index.items()}
    # links -> undirected edges, named by the first street name either direction gives
    for env in envs:
        if not any(street for rec in env.nodes.values() if isinstance(rec, dict) for _, street, _ in _links(rec)):
            report.counts["environments whose links name no street (their streets read 'unnamed street')"] += 1
    edge_street: dict[tuple[str, str], str | None] = {}
    directed: set[tuple[str, str]] = set()
    pano_node = {p: nid for nid, ps in panos.items() for p in ps}
    for env in envs:
        for key, rec in env.nodes.items():
            a = node_of.get((env.label, key))
            if a is None or not isinstance(rec, dict):
                continue
            for other, street, pano in _links(rec):
                b = node_of.get((env.label, other)) or (pano_node.get(pano) if pano else None)
                if b is None:
                    report.counts["links to panoramas outside their environment (dropped)"] += 1
                    continue
                if a == b:
                    report.counts["links between merged duplicate panoramas (dropped)"] += 1
                    continue
                directed.add((a, b))
                pair = (min(a, b), max(a, b))
                if edge_street.get(pair) is None:
                    edge_street[pair] = street
    one_way = sum(1 for a, b in directed if (b, a) not in directed)
    if one_way:
        report.counts["one-way links (walkable both ways here)"] += one_way
    # unnamed edges take the street their endpoints are otherwise on, when that is unambiguous
    named_at: dict[str, Counter] = {}
    for (a, b), street in edge_street.items():
        if street:
            named_at.setdefault(a, Counter())[street] += 1
            named_at.setdefault(b, Counter())[street] += 1
    for pair, street in list(edge_street.items()):
        if street is None:
            common = set(named_at.get(pair[0], {})) & set(named_at.get(pair[1], {}))
            edge_street[pair] = sorted(common)[0] if len(common) == 1 else None
    order = sorted(position)
    idx = {nid: i for i, nid in enumerate(order)}
    streets = [UNNAMED]
    street_index = {UNNAMED: 0}
    edges = []
    for (a, b), street in sorted(edge_street.items()):
        s = street_index.setdefault(street or UNNAMED, len(streets))
        if s == len(streets):
            streets.append(street or UNNAMED)
        edges.append([idx[a], idx[b], s])
    street_at = _streets_at(order, edge_street, position)
    report.nodes, report.edges = len(order), len(edges)
    graph = {
        "format": FORMAT, "version": FORMAT_VERSION, "city": city, "name": name, "code": code,
        "streets": streets, "aliases": {},
        "nodes": [[nid, round(position[nid][0], 7), round(position[nid][1], 7)] for nid in order],
        "edges": edges, "pois": {}, "places": [],
        "fit": {"method": "imported",
                "node_aliases": {nid: aliases[nid] for nid in order},
                "pano_ids": {nid: panos[nid] for nid in order if panos[nid]}},
    }
    return CityBuild(graph=graph, node_of=node_of, position=position, street_at=street_at)


def _streets_at(order: list[str], edge_street: dict[tuple[str, str], str | None],
                position: dict[str, tuple[float, float]]) -> dict[str, str]:
    """Each node's main street; a node on unnamed links only says which named street is nearest
    along the links ("near 5th Ave"), within NEAR_STREET_M."""
    adj: dict[str, list[tuple[str, str | None]]] = {}
    for (a, b), street in edge_street.items():
        adj.setdefault(a, []).append((b, street))
        adj.setdefault(b, []).append((a, street))
    out: dict[str, str] = {}
    for nid in order:
        names = Counter(s for _, s in adj.get(nid, []) if s)
        if names:
            out[nid] = max(names, key=lambda s: (names[s], s))
            continue
        out[nid] = UNNAMED
        seen, frontier = {nid}, [(0.0, nid)]
        while frontier:  # Dijkstra over the unnamed links, stopping at the first named one
            frontier.sort()
            dist, cur = frontier.pop(0)
            found = sorted(s for _, s in adj.get(cur, []) if s)
            if found:
                out[nid] = f"near {found[0]}"
                break
            for nxt, _ in adj.get(cur, []):
                step = haversine_m(*position[cur], *position[nxt])
                if nxt not in seen and dist + step <= NEAR_STREET_M:
                    seen.add(nxt)
                    frontier.append((dist + step, nxt))
    return out


def endpoint_node(build: CityBuild, env: Environment, key: Any) -> str | None:
    """The node of a source/target key; a key missing from its graph snaps to a node within SNAP_M."""
    if isinstance(key, str | int):
        found = build.node_of.get((env.label, str(key)))
        if found:
            return found
        parsed = _parse_key(str(key))
        if parsed is not None:
            cands = {build.node_of[(env.label, k)] for k in env.nodes if (env.label, k) in build.node_of}
            best = min(cands, key=lambda n: haversine_m(*parsed, *build.position[n]), default=None)
            if best is not None and haversine_m(*parsed, *build.position[best]) <= SNAP_M:
                return best
    return None
