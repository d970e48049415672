"""Small navigation environments in the shapes of the paper's release, written for these tests
(positions on an invented grid in lower Manhattan, outside the packaged Manhattan graph)."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

N = 0.000135  # about 15 m of latitude
E = 0.000178  # about 15 m of longitude at 40.7° N


def key(lat: float, lng: float) -> str:
    return f"{lat}-{abs(lng)}"  # the release's "lat-lng" keys drop the longitude's minus sign


def pos(i: float, j: float) -> tuple[float, float]:
    return round(40.70 + i * N, 7), round(-74.01 + j * E, 7)


def node(p: tuple[float, float], pano: str, links: dict[str, tuple[float, str]]) -> dict[str, Any]:
    return {"google_pano_id": pano, "lat": p[0], "lng": p[1],
            "links": {k: {"google_pano_id": f"link-{k}", "heading": h, "text": text, "elevaionAboveEgm96": 3.0}
                      for k, (h, text) in links.items()}}


P1, P2, P3, P4, P5 = pos(0, 0), pos(1, 0), pos(2, 0), pos(2, 1), pos(2, 2)
P2B = (round(P2[0] + 0.000003, 7), round(P2[1] - 0.000003, 7))  # a second panorama 0.5 m from P2
K1, K2, K2B, K3, K4, K5 = (key(*p) for p in (P1, P2, P2B, P3, P4, P5))
SENORA, BEACON = "Calle Señora", "Beacon Row"

# An L-shaped walk: north on Calle Señora, then east on Beacon Row. P3 -> P4 is a one-way link, P3
# links to a panorama outside the environment, and P2/P2B are near-duplicates.
WALK = {
    "source": K1,
    "target": K5,
    "graph": {
        K1: node(P1, "pano-1", {K2: (0.0, SENORA)}),
        K2: node(P2, "pano-2", {K1: (180.0, SENORA), K3: (0.0, SENORA)}),
        K2B: node(P2B, "pano-2b", {K3: (0.0, SENORA), K1: (180.0, "")}),
        K3: node(P3, "pano-3", {K2: (180.0, SENORA), K4: (90.0, BEACON), "40.8-73.9": (10.0, "Elsewhere St")}),
        K4: node(P4, "pano-4", {K5: (90.0, BEACON)}),
        K5: node(P5, "pano-5", {K4: (270.0, BEACON)}),
    },
}
# start and target are one panorama: nothing to walk
SAME = {"source": K1, "target": K1, "graph": {K1: node(P1, "pano-1", {}), K2: node(P2, "pano-2", {K1: (180.0, "")})}}
# the target has no links at all
CUT = {"source": key(*pos(5, 0)), "target": key(*pos(6, 0)),
       "graph": {key(*pos(5, 0)): node(pos(5, 0), "pano-c1", {}), key(*pos(6, 0)): node(pos(6, 0), "pano-c2", {})}}

RELEASE = [WALK, SAME, CUT]

# The release's annotation file: one entry per environment. The annotated start is the environment's
# target (the walk runs the other way), as in six of the paper's environments.
ANNOTATIONS = [
    {"general": {"task_id": 0, "task_type": "navigation",
                 "startpoint_coordinate": f"({P5[0]}, {P5[1]})", "endpoint_coordinate": f"({P1[0]}, {P1[1]})",
                 "generated_name": "12 Harbor Lane, New York, NY"},
     "embodied": [{"start": "", "end": "", "intent": "Walk there."}],
     "web": [{"sites": ["map"], "intent_template": "Show me a walking route to {{destination1}} from {{destination2}}.",
              "instantiation_dict": {"destination1": "12 Harbor Lane, New York, NY",
                                     "destination2": "40 Beacon Row, New York, NY"}}]},
    {"general": {"task_id": 1, "startpoint_coordinate": "(40.0, -74.0)", "endpoint_coordinate": "(40.0, -74.0)",
                 "generated_name": "Nowhere"}, "embodied": [], "web": []},
    {"general": {"task_id": 2, "startpoint_coordinate": "(40.0, -74.0)", "endpoint_coordinate": "(40.0, -74.0)",
                 "generated_name": "Nowhere"}, "embodied": [], "web": []},
]


def write_release(directory: Path, annotations: bool = False) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "navi_env_test.json"
    path.write_text(json.dumps(RELEASE, ensure_ascii=False), encoding="utf-8")
    if annotations:
        (directory / "navi_anno_test.json").write_text(json.dumps(ANNOTATIONS), encoding="utf-8")
    return path


def legacy_shape() -> dict[str, Any]:
    """The same walk with ``nodes``, ``pano_id``, ``street`` and plain-heading links."""
    env = copy.deepcopy(WALK)
    nodes = {}
    for k, rec in env.pop("graph").items():
        links = {t: ({"heading": v["heading"], "street": v["text"]} if v["text"] else v["heading"])
                 for t, v in rec["links"].items()}
        nodes[k] = {"pano_id": rec["google_pano_id"], "lat": rec["lat"], "lng": rec["lng"], "links": links}
    env["nodes"] = nodes
    return env
