"""Which cities of a set are hard (hardness.py): a city's shared cues and the rule over them. Needs no
locations, so locations.py can ask it while it builds the list (shared_streets.py), below hardness.py."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from typing import Any

from .cities import City
from .countries import COUNTRIES
from .styles import CLIMATE


def shared_cues(city: City) -> dict[str, Any]:
    country = COUNTRIES[city.iso]
    return {
        "arch": city.arch or country.arch,
        "climate": city.climate,
        "trees": tuple(sorted(city.trees or CLIMATE[city.climate].trees)),
        "transport": tuple(sorted(city.transport)),
        "langs": tuple(city.langs or country.langs),
    }


def hard_city_keys(in_set: Iterable[City]) -> frozenset[str]:
    """The keys of the hard cities among ``in_set`` (the cities of the location set). Needs no locations,
    so locations.py can ask it while it builds the list (shared_streets.py)."""
    cities = {city.key: city for city in in_set}
    cues = {key: shared_cues(city) for key, city in cities.items()}
    by_country: dict[str, list[str]] = defaultdict(list)
    for key, city in cities.items():
        by_country[city.iso].append(key)
    hard = set()
    for key, city in cities.items():
        rivals = [other for other in by_country[city.iso] if other != key]
        if not rivals:
            continue
        mine = cues[key]
        each_shared = all(any(cues[o][name] == value for o in cues if o != key)
                          for name, value in mine.items() if value)
        together_unique = all(cues[o] != mine for o in rivals)
        if each_shared and together_unique:
            hard.add(key)
    return frozenset(hard)
