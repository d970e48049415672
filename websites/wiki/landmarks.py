"""Landmark articles <-> the outdoor POI file (ewa_mcp/envs/street/data/pois.json).

Traveling tasks ask questions answered by POI facts and graders check answers against those
facts, so a landmark article's infobox must show each fact exactly as the POI file has it. The
prose is hand-written; the infobox and coordinates are derived here, never typed by hand:

    python -m ewa_mcp.websites.wiki.landmarks          # report drift and missing articles
    python -m ewa_mcp.websites.wiki.landmarks --write  # rewrite infobox/coordinates of landmark articles
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path
from typing import Any

from .store import ARTICLES_DIR, ArticleIndex, index

POIS_FILE = Path(__file__).resolve().parents[2] / "ewa_mcp" / "envs" / "street" / "data" / "pois.json"
# Kinds a visitor would look up in an encyclopedia; shops, stores and restaurants are not.
LANDMARK_KINDS = frozenset({"landmark", "museum", "park", "church", "theater", "library", "market", "station",
                            "hotel"})
CITY_NAMES = {"manhattan": "Manhattan, New York City", "philadelphia": "Philadelphia", "boston": "Boston",
              "pittsburgh": "Pittsburgh"}
# fact key -> (infobox label, unit appended to numbers)
FACT_LABELS: dict[str, tuple[str, str]] = {
    "architectural_style": ("Architectural style", ""),
    "year_built": ("Year built", ""),
    "architect": ("Architect", ""),
    "designer": ("Designer", ""),
    "height_m": ("Height", " m"),
    "length_m": ("Length", " m"),
    "floors": ("Floors", ""),
    "opening_hours": ("Opening hours", ""),
    "lines": ("Lines", ""),
    "since": ("Since", ""),
    "former_name": ("Former name", ""),
    "former_use": ("Former use", ""),
    "exhibit": ("Exhibit", ""),
    "artist": ("Artist", ""),
    "artwork": ("Artwork", ""),
    "monument": ("Monument", ""),
    "nickname": ("Nickname", ""),
    "access": ("Access", ""),
}


def _poi_path() -> Path:
    try:  # the installed package layout first, the repository layout as fallback
        import ewa_mcp

        candidate = Path(ewa_mcp.__file__).resolve().parent / "envs" / "street" / "data" / "pois.json"
        if candidate.exists():
            return candidate
    except ImportError:
        pass
    return POIS_FILE


def load_pois(path: Path | None = None) -> list[dict[str, Any]]:
    return json.loads((path or _poi_path()).read_text(encoding="utf-8"))


def landmark_pois(pois: list[dict[str, Any]] | None = None) -> list[dict[str, Any]]:
    return [p for p in (pois if pois is not None else load_pois()) if p.get("kind") in LANDMARK_KINDS]


def fact_label(key: str) -> str:
    return FACT_LABELS.get(key, (key.replace("_", " ").capitalize(), ""))[0]


def fact_text(key: str, value: Any) -> str:
    unit = FACT_LABELS.get(key, ("", ""))[1]
    return f"{value}{unit}"


def infobox_for(poi: dict[str, Any]) -> dict[str, str]:
    box = {"Address": str(poi["address"]), "City": CITY_NAMES.get(poi["city"], str(poi["city"]).title())}
    for key, value in poi.get("facts", {}).items():
        box[fact_label(key)] = fact_text(key, value)
    return box


def coordinates_for(poi: dict[str, Any]) -> dict[str, float]:
    return {"lat": float(poi["lat"]), "lng": float(poi["lng"])}


def check_landmarks(wiki: ArticleIndex | None = None, pois: list[dict[str, Any]] | None = None) -> list[str]:
    """Problems: landmark POIs without an article, and infoboxes that disagree with the POI facts."""
    wiki = wiki or index()
    problems = []
    for poi in landmark_pois(pois):
        article = wiki.by_poi.get(poi["id"])
        if article is None:
            problems.append(f"{poi['id']} ({poi['name']}): no article has 'poi_id: {poi['id']}'")
            continue
        for label, text in infobox_for(poi).items():
            if article.infobox.get(label) != text:
                problems.append(f"{article.slug}: infobox '{label}' is {article.infobox.get(label)!r}, "
                                f"the POI says {text!r} (run this module with --write)")
    return problems


def _rewrite_front_matter(text: str, infobox: dict[str, str], coordinates: dict[str, float]) -> str:
    lines = text.split("\n")
    end = next(i for i in range(1, len(lines)) if lines[i].strip() == "---")
    head = [line for line in lines[1:end] if not re.match(r"^(infobox|coordinates):", line)]
    head.append("infobox: " + json.dumps(infobox, ensure_ascii=False))
    head.append("coordinates: " + json.dumps(coordinates))
    return "\n".join(["---", *head, *lines[end:]])


def write_landmarks(root: Path = ARTICLES_DIR, pois: list[dict[str, Any]] | None = None) -> int:
    """Rewrite infobox and coordinates of every article that names a landmark POI; returns files changed.

    Keys a writer added by hand that the POI does not define are kept after the POI's own."""
    index.cache_clear()  # articles may have been added since the index was built
    wiki = index(root)
    changed = 0
    for poi in landmark_pois(pois):
        article = wiki.by_poi.get(poi["id"])
        if article is None or article.path is None:
            continue
        derived = infobox_for(poi)
        derived_labels = {fact_label(k) for k in FACT_LABELS} | {"Address", "City"}
        extra = {k: v for k, v in article.infobox.items() if k not in derived and k not in derived_labels}
        text = article.path.read_text(encoding="utf-8")
        new_text = _rewrite_front_matter(text, {**derived, **extra}, coordinates_for(poi))
        if new_text != text:
            article.path.write_text(new_text, encoding="utf-8")
            changed += 1
    index.cache_clear()
    return changed


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--write", action="store_true", help="rewrite infoboxes from the POI file")
    args = parser.parse_args(argv)
    if args.write:
        print(f"rewrote {write_landmarks()} article(s)")
    problems = check_landmarks()
    for problem in problems:
        print(problem)
    print(f"{len(problems)} problem(s) across {len(landmark_pois())} landmark POIs")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
