"""Import navigation environments in the paper's released format so they run in this server.

That format has, per environment, a source node, a target node and the nodes keyed by
"lat-lng" strings, each with a panorama id, lat, lng and links {neighbour key: heading}:

    {"source": "40.7411-73.9897", "target": "40.7416-73.9893",
     "nodes": {"40.7411-73.9897": {"pano_id": "...", "lat": 40.7411, "lng": -73.9897,
                                   "links": {"40.7413-73.9895": 29.1}}, ...}}

Each environment becomes a street graph file (this package's format, loaded by the world from the
directories in $EWA_STREET_DATA) and a navigation task whose goal is the target node:

    python -m ewa_mcp.outdoor.importer env1.json env2.json --data-dir imported/graphs --task-dir imported/tasks
    EWA_STREET_DATA=imported/graphs ewa-mcp --tasks imported/tasks ...

Panorama images are not part of the format (they were Street View photographs); views are
rendered like every other node, without points of interest.
"""

from __future__ import annotations

import argparse
import gzip
import hashlib
import json
import re
import sys
from pathlib import Path
from typing import Any

from .generate import FORMAT, FORMAT_VERSION
from .geo import bearing_deg, haversine_m, opaque_id

KEY_RE = re.compile(r"^\s*(-?\d+(?:\.\d+)?)\s*[-_,]\s*(-?\d+(?:\.\d+)?)\s*$")
UNNAMED = "unnamed street"


class ImportFormatError(ValueError):
    """The file is not in the expected format; the message says what is missing."""


def _coords(key: str, record: dict[str, Any]) -> tuple[float, float]:
    lat = record.get("lat", record.get("latitude"))
    lng = record.get("lng", record.get("lon", record.get("longitude")))
    if lat is not None and lng is not None:
        return float(lat), float(lng)
    m = KEY_RE.match(key)
    if not m:
        raise ImportFormatError(f"node {key!r} has no lat/lng fields and its key is not 'lat-lng'")
    lat_v, lng_v = float(m.group(1)), float(m.group(2))
    # Keys like "40.74-73.98" drop the minus of a western longitude into the separator.
    if lng_v > 0 and "--" not in key and lat_v > 0:
        lng_v = -lng_v
    return lat_v, lng_v


def _pick(raw: dict[str, Any], *names: str) -> Any:
    for name in names:
        if name in raw:
            return raw[name]
    return None


def convert(raw: dict[str, Any], name: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """Returns (graph file payload, navigation task) for one environment."""
    nodes = _pick(raw, "nodes", "graph")
    if nodes is None:
        nodes = {k: v for k, v in raw.items() if isinstance(v, dict) and ("links" in v or "neighbors" in v)}
    if not isinstance(nodes, dict) or not nodes:
        raise ImportFormatError(f"{name}: no nodes found; expected a 'nodes' object keyed by 'lat-lng'")
    source = _pick(raw, "source", "source_node", "start", "start_node")
    target = _pick(raw, "target", "target_node", "goal", "goal_node", "destination")
    if source not in nodes or target not in nodes:
        raise ImportFormatError(f"{name}: source {source!r} and target {target!r} must both be node keys")
    slug = re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-") or "env"
    city = f"import-{slug}"
    code = "x" + hashlib.sha1(city.encode()).hexdigest()[:5]
    pos = {key: _coords(key, rec) for key, rec in nodes.items()}
    ids: dict[str, str] = {}
    for key, (lat, lng) in pos.items():
        nid = opaque_id(code, lat, lng)
        if nid in ids.values():
            raise ImportFormatError(f"{name}: two nodes within a metre of each other at {lat},{lng}")
        ids[key] = nid
    order = sorted(ids, key=lambda k: ids[k])
    index = {k: i for i, k in enumerate(order)}
    streets = [UNNAMED]
    street_index = {UNNAMED: 0}
    edges: set[tuple[int, int, int]] = set()
    for key, rec in nodes.items():
        links = rec.get("links", rec.get("neighbors", {}))
        if isinstance(links, list):
            links = {n: None for n in links}
        for other, value in links.items():
            if other not in nodes:
                continue  # links leaving the environment's subgraph
            street = value.get("street") if isinstance(value, dict) else None
            s = street_index.setdefault(street or UNNAMED, len(streets))
            if s == len(streets):
                streets.append(street)
            a, b = index[key], index[other]
            if a != b:
                edges.add((min(a, b), max(a, b), s))
    lat0, lng0 = pos[source]
    lat1, lng1 = pos[target]
    graph = {
        "format": FORMAT, "version": FORMAT_VERSION, "city": city, "name": f"Imported environment {name}",
        "code": code, "streets": streets, "aliases": {},
        "nodes": [[ids[k], round(pos[k][0], 7), round(pos[k][1], 7)] for k in order],
        "edges": sorted([list(e) for e in edges]), "pois": {},
        "fit": {"method": "imported", "pano_ids": {ids[k]: nodes[k].get("pano_id") for k in order if nodes[k].get("pano_id")}},
    }
    heading = raw.get("heading")
    if heading is None:
        heading = 0.0  # never derived from the route: that leaked the goal direction in the original
    task = {
        "id": f"nav-import-{slug}",
        "domain": "navigation",
        "intent": raw.get("intent") or "Walk to the destination of this imported route and stop there.",
        "start": {"environment": "embodied",
                  "embodied": {"kind": "street", "city": city, "node": ids[source], "heading": float(heading)}},
        "embodied_goals": [{"kind": "reached_place", "city": city, "node": ids[target], "lat": lat1, "lng": lng1,
                            "radius_m": 10.0}],
        "step_limit": 80,
        "metadata": {"source": "imported", "original_source": source, "original_target": target,
                     "start_goal_distance_m": round(haversine_m(lat0, lng0, lat1, lng1), 1),
                     "start_goal_bearing": round(bearing_deg(lat0, lng0, lat1, lng1), 1)},
    }
    return graph, task


def write(graph: dict[str, Any], task: dict[str, Any], data_dir: Path, task_dir: Path) -> tuple[Path, Path]:
    data_dir.mkdir(parents=True, exist_ok=True)
    task_dir.mkdir(parents=True, exist_ok=True)
    gpath = data_dir / f"{graph['city']}.json.gz"
    with open(gpath, "wb") as fh, gzip.GzipFile(fileobj=fh, mode="wb", mtime=0) as gz:
        gz.write(json.dumps(graph, separators=(",", ":"), sort_keys=True).encode())
    tpath = task_dir / f"{task['id']}.json"
    tpath.write_text(json.dumps(task, indent=2) + "\n", encoding="utf-8")
    return gpath, tpath


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Import navigation environments in the paper's format.")
    parser.add_argument("files", nargs="+", type=Path)
    parser.add_argument("--data-dir", type=Path, required=True, help="where graph files go ($EWA_STREET_DATA)")
    parser.add_argument("--task-dir", type=Path, required=True, help="where task files go")
    args = parser.parse_args(argv)
    for path in args.files:
        try:
            raw = json.loads(path.read_text(encoding="utf-8"))
            items = raw.items() if isinstance(raw, dict) and "nodes" not in raw and all(
                isinstance(v, dict) and "nodes" in v for v in raw.values()) else [(path.stem, raw)]
            for name, env in items:
                graph, task = convert(env, str(name))
                g, t = write(graph, task, args.data_dir, args.task_dir)
                print(json.dumps({"environment": name, "graph": str(g), "task": str(t),
                                  "nodes": len(graph["nodes"]), "edges": len(graph["edges"])}))
        except (OSError, json.JSONDecodeError, ImportFormatError) as exc:
            print(f"{path}: {exc}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
