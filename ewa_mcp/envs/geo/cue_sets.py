"""Which cities of a set are hard (hardness.py): a city's shared cues and the rule over them. Needs no
locations, so locations.py can ask it while it builds the list (shared_streets.py), below hardness.py.

The rule (issue 26, principle 6): the country follows from every view, so the city's rivals are the
other cities of its country that have a wiki article: the location set's and the rival cities
(rival_cities.py). A city is hard when every single cue kind its views show, and every pair of them,
still fits at least one rival, and all of them together fit none. Finding it takes three cues or more
put together; the first two that fit leave a real choice.

A rival *fits* what is seen when its article could describe it: the same buildings, a climate whose sky
looks the same (SKY_ALIKE), and every tree, vehicle and sign language seen among its own. Absence is no cue: a city whose views show
no local transport is told apart by what they do show, never by a vehicle it lacks.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from itertools import combinations
from typing import Any

from .cities import City
from .countries import COUNTRIES
from .rival_cities import RIVAL_CITIES
from .styles import CLIMATE

CUE_KINDS = ("arch", "climate", "trees", "transport", "langs")
# Kinds a view shows several of: what is seen must be among what the article lists.
_SET_KINDS = frozenset({"trees", "transport", "langs"})
# A view shows the climate only as its sky (styles.CLIMATE) and an article names it by its seasons; these
# skies read alike (clear and blue; hazy), so a player cannot rule out one climate of a group by the other.
SKY_ALIKE: tuple[frozenset[str], ...] = (
    frozenset({"mediterranean", "semi_arid", "continental"}),
    frozenset({"humid_subtropical", "arid"}),
)


def _same_sky(one: str, other: str) -> bool:
    return one == other or any(one in group and other in group for group in SKY_ALIKE)


def shared_cues(city: City) -> dict[str, Any]:
    country = COUNTRIES[city.iso]
    return {
        "arch": city.arch or country.arch,
        "climate": city.climate,
        "trees": tuple(sorted(city.trees or CLIMATE[city.climate].trees)),
        "transport": tuple(sorted(city.transport)),
        "langs": tuple(city.langs or country.langs),
    }


def seen_kinds(shown: Mapping[str, Any]) -> tuple[str, ...]:
    """The cue kinds that show something (no vehicle of the city's own is nothing to read)."""
    return tuple(kind for kind in CUE_KINDS if shown[kind])


def fits(shown: Mapping[str, Any], other: Mapping[str, Any], kinds: Iterable[str]) -> bool:
    """Whether a city whose article states ``other`` could show what ``shown`` is, in ``kinds``."""
    for kind in kinds:
        if kind in _SET_KINDS:
            if not set(shown[kind]) <= set(other[kind]):
                return False
        elif kind == "climate":
            if not _same_sky(shown[kind], other[kind]):
                return False
        elif shown[kind] != other[kind]:
            return False
    return True


def combination_gaps(shown: Mapping[str, Any], rivals: Mapping[str, Mapping[str, Any]]) -> list[str]:
    """Why ``shown`` breaks the rule against ``rivals`` (key -> cues), or [] when it keeps it: a single cue
    or a pair that no rival fits (it alone names the city), or rivals that fit every cue at once."""
    kinds = seen_kinds(shown)
    gaps = []
    for size in (1, 2):
        for combo in combinations(kinds, size):
            if not any(fits(shown, other, combo) for other in rivals.values()):
                gaps.append(f"{' + '.join(combo)} alone leaves only this city")
    clash = sorted(key for key, other in rivals.items() if fits(shown, other, kinds))
    if clash:
        gaps.append(f"every cue together still fits {', '.join(clash)}")
    return gaps


def candidates(in_set: Iterable[City]) -> dict[str, City]:
    """The cities a player can weigh: the location set's and the rival cities, by key."""
    cities = {city.key: city for city in in_set}
    clash = set(cities) & set(RIVAL_CITIES)
    if clash:
        raise ValueError(f"rival cities {sorted(clash)} have locations: drop them from rival_cities.py")
    return {**cities, **RIVAL_CITIES}


def country_rivals(key: str, pool: Mapping[str, City]) -> dict[str, dict[str, Any]]:
    iso = pool[key].iso
    return {other: shared_cues(city) for other, city in pool.items() if city.iso == iso and other != key}


# What a pedestrian street shows of a city's transport (scene.py: only rail vehicles and bicycles use it).
PEDESTRIAN_VEHICLES = frozenset({"tram", "bicycles"})


def street_cues(city: City, pedestrian: bool = False) -> dict[str, Any]:
    """The city's shared cues as a street of it shows them."""
    cues = shared_cues(city)
    if pedestrian:
        cues["transport"] = tuple(t for t in cues["transport"] if t.partition(":")[0] in PEDESTRIAN_VEHICLES)
    return cues


def hard_city_keys(in_set: Iterable[City], pedestrian: Iterable[str] = ()) -> frozenset[str]:
    """The keys of the hard cities among ``in_set`` (the cities of the location set). ``pedestrian``: keys
    of cities with a non-landmark location on a pedestrian street, which must keep the rule with what such
    a street shows too. Needs no locations, so locations.py can ask it while it builds the list
    (shared_streets.py)."""
    in_set = list(in_set)
    on_foot = set(pedestrian)
    pool = candidates(in_set)
    hard = set()
    for key in {city.key for city in in_set}:
        rivals = country_rivals(key, pool)
        streets = [street_cues(pool[key])] + ([street_cues(pool[key], pedestrian=True)] if key in on_foot else [])
        if rivals and not any(combination_gaps(cues, rivals) for cues in streets):
            hard.add(key)
    return frozenset(hard)


def deciding_sets(shown: Mapping[str, Any], rivals: Mapping[str, Mapping[str, Any]]) -> list[tuple[str, ...]]:
    """The smallest sets of cue kinds that together fit no rival: what a player must put together."""
    kinds = seen_kinds(shown)
    for size in range(1, len(kinds) + 1):
        found = [combo for combo in combinations(kinds, size)
                 if not any(fits(shown, other, combo) for other in rivals.values())]
        if found:
            return found
    return []
