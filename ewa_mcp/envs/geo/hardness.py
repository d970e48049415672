"""The hard split: locations where no single cue decides the city.

A city's *shared cues* are what a view shows of it that other cities show too: building style,
climate (sky and trees), street trees, local transport and sign languages. Its *deciding cues*
are the ones that name one city: the telephone area code, the region code or caption on
number plates and a city-specific street-sign style.

A location is hard when it is not a landmark location and its city's shared cues name it only three
or more together (cue_sets.py): every single cue and every pair still fit another city of the
country with a wiki article (the set's or a rival city, rival_cities.py), and all of them together
fit none. Hard locations never show a deciding cue (scene.py):
no area-coded telephone numbers, no legible regional plates, the country's street-sign style;
the street sign is two steps from the start. Finding the city takes several cues together,
read against the wiki's descriptions of the candidate cities.
"""

from __future__ import annotations

from functools import lru_cache

from .cue_sets import hard_city_keys, shared_cues
from .locations import LOCATIONS_LIST, Location

__all__ = ["hard_city_keys", "is_hard", "shared_cues", "task_difficulty"]


@lru_cache(maxsize=1)
def _hard_cities() -> frozenset[str]:
    return hard_city_keys((loc.city for loc in LOCATIONS_LIST),
                          pedestrian={loc.city_key for loc in LOCATIONS_LIST if loc.pedestrian and loc.difficulty != "easy"})


def is_hard(loc: Location) -> bool:
    return loc.difficulty != "easy" and loc.city_key in _hard_cities()


def task_difficulty(loc: Location) -> str:
    """The task's difficulty (Task.difficulty): easy (a landmark), hard (see above) or medium."""
    if loc.difficulty == "easy":
        return "easy"
    return "hard" if is_hard(loc) else "medium"
