"""Geolocation grading: per-level name matching with alias tables, and great-circle distance.

Levels are matched independently:

- continent: names or codes (Asia, AS); countries whose continent is genuinely debated
  (Turkey, Georgia, Armenia, Cyprus) accept either answer;
- country: names, exonyms, native names and ISO codes (Ivory Coast = Côte d'Ivoire = CI =
  CIV; Hong Kong also accepts China);
- city: the gazetteer's name and alternate names of the answer city plus hand aliases
  (New Delhi = Delhi, Chattogram = Chittagong, Kyiv = Kiev);
- street: the location's name, local-script sign text and aliases, comparing either the
  whole normalised name or its core without type words (Rue/Street/Straße/улица...).

Independently, the distance between the submitted and true coordinates is banded as in
im2gps (street 1 km, city 25 km, region 200 km, country 750 km, continent 2500 km) and
scored GeoGuessr-style: 5000 * exp(-d / 1492.7 km).

``aggregate_geolocation`` and ``render_geolocation_table`` summarise runs like the paper's
Table 3 (baseline vs embodied x levels).
"""

from __future__ import annotations

import math
import statistics
from typing import Any

from ewa_mcp.street_drawing.fonts import script_of
from ewa_mcp.geometry import haversine_km
from ewa_mcp.envs.geo.locations import locations_by_coordinates
from ewa_mcp.envs.geo.names import (
    AMBIGUOUS_CONTINENTS,
    COMPASS_WORDS,
    cities_match,
    countries_match,
    resolve_continent,
    resolve_country,
    street_core,
    streets_match,
)
from ewa_mcp.envs.geo.goals import GeoAnswer

LEVELS = ("continent", "country", "city", "street")
BANDS_KM: dict[str, float] = {"street": 1.0, "city": 25.0, "region": 200.0, "country": 750.0, "continent": 2500.0}
SCORE_MAX = 5000
SCORE_SCALE_KM = 1492.7  # GeoGuessr's world-map decay constant


def geoguessr_score(distance_km: float | None) -> int:
    if distance_km is None:
        return 0
    return int(round(SCORE_MAX * math.exp(-distance_km / SCORE_SCALE_KM)))


def distance_bands(distance_km: float | None) -> dict[str, bool]:
    return {band: distance_km is not None and distance_km <= limit for band, limit in BANDS_KM.items()}


def _coordinate(value: Any, limit: float) -> float | None:
    try:
        x = float(value)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) and -limit <= x <= limit else None


def _text(submission: dict[str, Any], key: str) -> str:
    value = submission.get(key)
    return value.strip() if isinstance(value, str) else ""


def _continent_ok(answer: str, truth: GeoAnswer) -> bool:
    got = resolve_continent(answer) if answer else None
    if got is None:
        return False
    accepted = {resolve_continent(truth.continent) or truth.continent}
    for iso in resolve_country(truth.country):
        accepted |= AMBIGUOUS_CONTINENTS.get(iso, frozenset())
    return got in accepted


def _street_aliases(truth: GeoAnswer) -> tuple[str, ...]:
    loc = locations_by_coordinates().get((round(truth.lat, 4), round(truth.lng, 4)))
    if loc is None or loc.street != truth.street:
        return ()
    # Local-script sign lines are the street's own name (Невский проспект); Latin sign lines
    # may be a district or postcode ("11e Arrt", "Copacabana"), so only aliases cover those.
    native = tuple(line for line in loc.sign if script_of(line) != "latin")
    # A Latin line that shares a name word with the street is the street's own sign, abbreviated as signs
    # are ("JL. JEND. SUDIRMAN"): the agent may copy it as it stands. On a sign that also has a local-script
    # line, every Latin line is that name romanized or translated ("Tian'anmen Guangchang", "NETAJI SUBHASH
    # CHANDRA BOSE ROAD" on Marine Drive): a district line only stands on Latin-only signs.
    words = set(street_core(loc.street)) - COMPASS_WORDS
    signed = tuple(line for line in loc.sign
                   if script_of(line) == "latin" and (native or words & set(street_core(line))))
    return (*loc.street_aliases, *native, *signed)


def grade_geolocation(answer_check: GeoAnswer | dict[str, Any], submission: dict[str, Any] | None) -> dict[str, Any]:
    truth = answer_check if isinstance(answer_check, GeoAnswer) else GeoAnswer.model_validate(answer_check)
    sub = submission or {}
    continent, country, city, street = (_text(sub, k) for k in LEVELS)
    levels = {
        "continent": _continent_ok(continent, truth),
        "country": bool(country) and countries_match(country, truth.country),
        "city": bool(city) and cities_match(city, truth.city, truth.country, truth.lat, truth.lng),
        "street": bool(street) and streets_match(street, truth.street, _street_aliases(truth)),
    }
    lat, lng = _coordinate(sub.get("lat"), 90), _coordinate(sub.get("lng"), 180)
    distance = None if lat is None or lng is None else round(haversine_km(lat, lng, truth.lat, truth.lng), 3)
    graded = [level for level in LEVELS if truth.graded_levels is None or level in truth.graded_levels]
    return {
        **levels,
        # Success: every level the task asks for (graded_levels; all four unless the views cannot show one).
        "all_levels": all(levels[level] for level in graded),
        "graded_levels": graded,
        # Partial credit: the fraction of those levels right (the episode's completion).
        "completion": sum(levels[level] for level in graded) / len(graded),
        "distance_km": distance,
        "bands": distance_bands(distance),
        "score": geoguessr_score(distance),
        "submitted": submission is not None,
    }


# ------------------------------------------------------------------------------ aggregation
def _wilson(successes: int, n: int, z: float = 1.959964) -> dict[str, Any]:
    if n == 0:
        return {"successes": 0, "n": 0, "value": None, "ci_low": 0.0, "ci_high": 1.0, "method": "wilson"}
    p = successes / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return {"successes": successes, "n": n, "value": p, "ci_low": max(0.0, centre - half),
            "ci_high": min(1.0, centre + half), "method": "wilson"}


def aggregate_geolocation(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """Per setting (baseline/embodied, from each row's "setting"): accuracy per level with a
    Wilson 95 % interval, distance-band rates, median distance and mean score."""
    by_setting: dict[str, dict[str, Any]] = {}
    for setting in sorted({str(r.get("setting") or "unknown") for r in rows}):
        subset = [r for r in rows if str(r.get("setting") or "unknown") == setting]
        n = len(subset)
        distances = [r["distance_km"] for r in subset if isinstance(r.get("distance_km"), int | float)]
        summary: dict[str, Any] = {"n": n}
        for level in (*LEVELS, "all_levels"):
            summary[level] = _wilson(sum(r.get(level) is True for r in subset), n)
        summary["bands"] = {
            band: _wilson(sum(bool((r.get("bands") or {}).get(band)) for r in subset), n) for band in BANDS_KM
        }
        summary["median_distance_km"] = round(statistics.median(distances), 3) if distances else None
        summary["mean_score"] = round(statistics.fmean(r.get("score") or 0 for r in subset), 1) if n else None
        summary["unanswered"] = sum(1 for r in subset if r.get("submitted") is False)
        by_setting[setting] = summary
    return {"by_setting": by_setting, "n": len(rows), "source": "ewa_mcp.envs.geo.checks"}


def _pct(cell: dict[str, Any] | None) -> str:
    if not cell or cell.get("value") is None:
        return "-"
    return f"{100 * cell['value']:.2f}"


SETTING_ORDER = ("baseline", "embodied")


def render_geolocation_table(agg_by_run: dict[str, dict[str, Any]]) -> str:
    """A Markdown table shaped like the paper's Table 3: settings as row groups, one row per
    run, accuracy (%) per level, then distance figures."""
    header = ["Setting / Run", "n", "Continent", "Country", "City", "Street", "All",
              "≤25 km", "Median km", "Mean score"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    settings = sorted({s for agg in agg_by_run.values() for s in (agg.get("by_setting") or {})},
                      key=lambda s: (SETTING_ORDER.index(s) if s in SETTING_ORDER else len(SETTING_ORDER), s))
    for setting in settings:
        lines.append(f"| **{setting.capitalize()}** |" + " |" * (len(header) - 1))
        for run, agg in agg_by_run.items():
            summary = (agg.get("by_setting") or {}).get(setting)
            if summary is None:
                continue
            median = summary.get("median_distance_km")
            cells = [
                f"  {run}",
                str(summary.get("n", 0)),
                *(_pct(summary.get(level)) for level in (*LEVELS, "all_levels")),
                _pct((summary.get("bands") or {}).get("city")),
                "-" if median is None else f"{median:.1f}",
                "-" if summary.get("mean_score") is None else f"{summary['mean_score']:.0f}",
            ]
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)
