"""The hard split: locations where no single cue decides the city.

A city's *shared cues* are what a view shows of it that other cities show too: building style,
climate (sky and trees), street trees, local transport and sign languages. Its *deciding cues*
are the ones that name one city: the telephone area code, the region code or caption on
number plates and a city-specific street-sign style.

A location is hard when it is not a landmark location, its country has at least two cities in
the location set, every one of its city's shared cues is also a cue of some other city (so no
single one decides), and their combination differs from every other city of the same country
(so together they pin the city down). Hard locations never show a deciding cue (scene.py):
no area-coded telephone numbers, no legible regional plates, the country's street-sign style;
the street sign is two steps from the start. Finding the city takes several cues together,
read against the wiki's descriptions of the candidate cities.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from .cities import City
from .countries import COUNTRIES
from .styles import CLIMATE

if TYPE_CHECKING:
    from .locations import Location

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


@lru_cache(maxsize=1)
def _hard_cities() -> frozenset[str]:
    from .locations import LOCATIONS_LIST  # locations.py imports this module's answer as it builds the list

    return hard_city_keys(loc.city for loc in LOCATIONS_LIST)


def is_hard(loc: Location) -> bool:
    return loc.difficulty != "easy" and loc.city_key in _hard_cities()


def task_difficulty(loc: Location) -> str:
    """The task's difficulty (Task.difficulty): easy (a landmark), hard (see above) or medium."""
    if loc.difficulty == "easy":
        return "easy"
    return "hard" if is_hard(loc) else "medium"
