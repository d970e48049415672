"""Hard geolocation locations show no deciding cue anywhere the agent can walk, their shared cues name the
city only three or more together, and the near-lane sentence of a view across the street agrees with the
driving side whichever way the view faces.

A deciding cue names one city of the location set: a street or landmark name that only one city has
(Avenida Paulista, Pike Street, a district line such as "Bela Vista"), a city's name, a telephone
number with its area code, a legible regional number plate, a city's own street-sign style.
"""

from __future__ import annotations

import re
from collections import defaultdict
from functools import lru_cache

import pytest

from ewa_mcp.envs.geo.articles import country_title
from ewa_mcp.envs.geo.cities import CITIES
from ewa_mcp.envs.geo.cue_sets import (candidates, combination_gaps, country_rivals, deciding_sets, fits,
                                       shared_cues)
from ewa_mcp.envs.geo.describe import describe_view, describe_view_cues
from ewa_mcp.envs.geo.graph import START, build_graph
from ewa_mcp.envs.geo.hardness import task_difficulty
from ewa_mcp.envs.geo.locations import LOCATIONS_LIST, SURVEYED_LOCATIONS_LIST, Location
from ewa_mcp.envs.geo.names import normalize
from ewa_mcp.envs.geo.scene import compose_view
from ewa_mcp.envs.geo.rival_cities import RIVAL_CITIES
from ewa_mcp.envs.geo.shared_streets import SHARED_STREETS
from ewa_mcp.envs.geo.styles import CLIMATE
from ewa_mcp.envs.geo.taskgen.geolocation import STEP_LIMITS
from ewa_mcp.geometry import FOUR_DIRECTIONS
from ewa_mcp.websites.wiki import store

HARD = [loc for loc in LOCATIONS_LIST if task_difficulty(loc) == "hard"]
SET_CITIES = sorted({loc.city_key for loc in LOCATIONS_LIST})


@lru_cache(maxsize=1)
def owners() -> dict[str, frozenset[str]]:
    """Normalised street, sign and alias text -> the cities of the location set that have it: every
    location's surveyed and played street, and each shared street name for every city of its country."""
    by_text: dict[str, set[str]] = defaultdict(set)
    for loc in (*SURVEYED_LOCATIONS_LIST, *LOCATIONS_LIST):
        for text in (loc.street, *loc.sign, *loc.street_aliases):
            by_text[normalize(text)].add(loc.city_key)
    for iso, pool in SHARED_STREETS.items():
        cities = {key for key in SET_CITIES if CITIES[key].iso == iso}
        for street in pool:
            for text in (street.name, *street.sign, *street.aliases):
                by_text[normalize(text)] |= cities
    return {text: frozenset(cities) for text, cities in by_text.items()}


@lru_cache(maxsize=1)
def city_name_patterns() -> dict[str, re.Pattern[str]]:
    out = {}
    for key in SET_CITIES:
        names = {normalize(n) for n in (CITIES[key].name, *CITIES[key].aliases) if len(normalize(n)) > 2}
        out[key] = re.compile(r"\b(" + "|".join(re.escape(n) for n in sorted(names)) + r")\b")
    return out


def deciding_text(text: str) -> str | None:
    """Why a quoted text (a sign line) names one city, or None when it names none."""
    cities = owners().get(normalize(text), frozenset())
    if len(cities) == 1:
        return f"{text!r} is a street name only {next(iter(cities))} has"
    named = [key for key, pattern in city_name_patterns().items() if pattern.search(normalize(text))]
    if named:
        return f"{text!r} names the city {named[0]}"
    return None


def reachable(loc: Location, steps: int) -> list[str]:
    """The standpoints within ``steps`` moves of the start (each geo_move is one step)."""
    graph = build_graph(loc)
    seen, frontier = {START}, [START]
    for _ in range(steps):
        frontier = [n.id for sp in frontier for n in graph[sp].neighbours if n.id not in seen]
        seen |= set(frontier)
    return sorted(seen)


def deciding_cues(loc: Location) -> list[str]:
    found = []
    country, city = loc.country, loc.city
    for sp in reachable(loc, STEP_LIMITS["embodied"]):
        for heading in FOUR_DIRECTIONS:
            spec = compose_view(loc, sp, heading)
            _, cues = describe_view_cues(spec)
            where = f"{loc.id} {sp} {heading}"
            for cue in sorted(cues):
                kind, _, value = cue.partition(":")
                if kind == "landmark":
                    found.append(f"{where}: a landmark ({value})")
                elif kind == "phone" and "{a}" in country.phone:
                    found.append(f"{where}: a telephone number with the area code ({value})")
                elif kind in ("plate_text", "plate_caption") and country.plate.has_region:
                    found.append(f"{where}: a legible regional plate ({value})")
                elif (kind == "street_sign_style" and city.sign is not None and value == city.sign.words
                      and city.sign.words != country.sign.words):
                    found.append(f"{where}: the city's own street-sign style")
                elif kind in ("sign_text", "street_sign_text") and (why := deciding_text(value)):
                    found.append(f"{where}: {why}")
    return found


def test_the_hard_split_is_large_enough_to_measure():
    assert len(HARD) >= 30


@pytest.mark.parametrize("loc", HARD, ids=lambda loc: f"{loc.id}-{loc.city_key}")
def test_no_hard_location_shows_a_deciding_cue_within_its_step_limit(loc):
    assert reachable(loc, STEP_LIMITS["embodied"]) == sorted(build_graph(loc)), "every standpoint is reachable"
    assert deciding_cues(loc) == []
    # The street sign is still there, read and graded: it names the street, not the city.
    signs = [compose_view(loc, sp, h).street_sign for sp in build_graph(loc) for h in FOUR_DIRECTIONS]
    assert any(s is not None for s in signs)


def test_the_check_catches_the_surveyed_street_names_that_named_the_city():
    # The round-7 play-test read these two moves from the start; each names one city.
    surveyed = {loc.id: loc for loc in SURVEYED_LOCATIONS_LIST}
    assert deciding_text(surveyed["g160"].sign[0]) is not None  # AV. PAULISTA, Sao Paulo
    assert deciding_text(surveyed["g160"].sign[1]) is not None  # Bela Vista, its district
    assert deciding_text(surveyed["g145"].sign[0]) is not None  # Pike St, Seattle
    assert deciding_text("LAGOS ISLAND") is not None  # a city's name
    assert deciding_text("Hauptstraße") is None and deciding_text("Main St") is None


def test_hard_locations_keep_their_coordinates_and_take_a_shared_name_of_their_country():
    surveyed = {loc.id: loc for loc in SURVEYED_LOCATIONS_LIST}
    for loc in HARD:
        before = surveyed[loc.id]
        assert (loc.lat, loc.lng, loc.bearing, loc.city_key) == (before.lat, before.lng, before.bearing,
                                                                  before.city_key)
        assert loc.street in {s.name for s in SHARED_STREETS[loc.city.iso]}
    # A city's hard locations are different tasks with different answers.
    by_city: dict[str, list[str]] = defaultdict(list)
    for loc in HARD:
        by_city[loc.city_key].append(loc.street)
    assert all(len(set(streets)) == len(streets) for streets in by_city.values())
    # Other locations keep their surveyed street.
    assert all(loc == surveyed[loc.id] for loc in LOCATIONS_LIST if loc not in HARD)


def test_every_country_with_shared_names_has_several_cities_in_the_set():
    for iso in SHARED_STREETS:
        cities = {key for key in SET_CITIES if CITIES[key].iso == iso}
        assert len(cities) >= 2, f"{iso}: a shared name of a country with one city in the set names that city"


# ------------------------------------------------------------------ three cues together, never two
def shown_cues(loc: Location) -> dict[str, tuple[str, ...] | str]:
    """What every view within the step limit shows of each shared cue kind, read off the composed views:
    the buildings, the climate (its sky), every tree kind, every vehicle other than a car (with its colour,
    as the city's transport lists it), and the sign languages the shop signs are written in."""
    archs, climates, trees, transport = set(), set(), set(), set()
    climate_key = {id(climate): key for key, climate in CLIMATE.items()}
    for sp in reachable(loc, STEP_LIMITS["embodied"]):
        for heading in FOUR_DIRECTIONS:
            spec = compose_view(loc, sp, heading)
            archs.add(spec.arch_key)
            climates.add(climate_key[id(spec.climate)])
            trees |= {kind for kind, _side, _depth in spec.trees}
            transport |= {f"{v.kind}:{v.colour_words}" if v.colour_words else v.kind
                          for v in spec.vehicles if v.kind != "car"}
            if spec.skytrain:
                transport.add("skytrain")
    assert len(archs) == 1 and len(climates) == 1, (loc.id, archs, climates)
    return {"arch": archs.pop(), "climate": climates.pop(), "trees": tuple(sorted(trees)),
            "transport": tuple(sorted(transport)), "langs": tuple(loc.city.langs or loc.country.langs)}


POOL = candidates(CITIES[key] for key in SET_CITIES)


@lru_cache(maxsize=1)
def wiki_cities() -> dict[str, set[str]]:
    """Country title -> the titles of the wiki's city articles in it (any group: New York City lives in cities/)."""
    out: dict[str, set[str]] = defaultdict(set)
    for article in store.load_articles():
        if article.category == "Cities" and article.infobox.get("Country"):
            out[article.infobox["Country"]].add(article.title)
    return out


@pytest.mark.parametrize("loc", HARD, ids=lambda loc: f"{loc.id}-{loc.city_key}")
def test_every_single_cue_and_every_pair_still_fit_a_rival_with_an_article(loc):
    shown = shown_cues(loc)
    assert fits(shown, shared_cues(loc.city), shown), "the views show what the city's own article states"
    rivals = country_rivals(loc.city_key, POOL)
    # The rivals are the wiki's: each has an article in the country, and the country article lists it.
    titles = wiki_cities()[country_title(loc.country)]
    assert {POOL[key].name for key in rivals} <= titles
    country_article = store.find(country_title(loc.country))
    assert country_article is not None
    assert all(f"[[{POOL[key].name}]]" in country_article.body for key in rivals)
    assert combination_gaps(shown, rivals) == []
    # So what decides is three cues or more, put together.
    assert all(len(kinds) >= 3 for kinds in deciding_sets(shown, rivals))


def test_the_rule_catches_a_pair_that_names_the_city():
    berlin = shown_cues(next(loc for loc in HARD if loc.city_key == "berlin"))
    rivals = country_rivals("berlin", POOL)
    assert combination_gaps(berlin, rivals) == []
    # Without Munich (the same sky and trees, trams of another colour), sky and trees alone name Berlin.
    gaps = combination_gaps(berlin, {k: v for k, v in rivals.items() if k != "munich"})
    assert "climate + trees alone leaves only this city" in gaps
    # The location set alone (round 8): the trams decided Lisbon against Porto at once.
    lisbon = shown_cues(next(loc for loc in HARD if loc.city_key == "lisbon"))
    set_only = {k: shared_cues(CITIES[k]) for k in SET_CITIES if CITIES[k].iso == "PT" and k != "lisbon"}
    assert "transport alone leaves only this city" in combination_gaps(lisbon, set_only)
    # A rival that fits every cue leaves two answers: no longer hard.
    twin = dict(shared_cues(CITIES["lisbon"]))
    assert combination_gaps(lisbon, {**rivals, "twin": twin})[-1] == "every cue together still fits twin"


def test_absence_is_no_cue_and_what_is_seen_must_be_listed():
    shown = {"arch": "a", "climate": "c", "trees": ("plane",), "transport": (), "langs": ("de",)}
    with_trams = {"arch": "a", "climate": "c", "trees": ("linden", "plane"), "transport": ("tram:blue",),
                  "langs": ("de",)}
    # No vehicle seen: a city with trams still fits (the street may simply have none).
    assert fits(shown, with_trams, ("trees", "transport"))
    # A yellow tram seen: a city whose article lists blue ones does not.
    assert not fits({**shown, "transport": ("tram:yellow",)}, with_trams, ("transport",))
    # The climate shows only as the sky: a clear Mediterranean sky rules out no semi-arid city, while a grey
    # oceanic one rules out a continental city (clear blue) and a highland horizon shows its mountains.
    assert fits({**shown, "climate": "mediterranean"}, {**shown, "climate": "semi_arid"}, ("climate",))
    assert not fits({**shown, "climate": "oceanic"}, {**shown, "climate": "continental"}, ("climate",))
    assert not fits({**shown, "climate": "highland"}, {**shown, "climate": "semi_arid"}, ("climate",))


def test_rival_cities_have_no_location_and_a_real_gazetteer_record():
    from ewa_mcp.envs.geo import gazetteer

    assert not set(RIVAL_CITIES) & set(SET_CITIES)
    for city in RIVAL_CITIES.values():
        record = gazetteer.city(city.geonameid)
        assert record["countrycode"] == city.iso, city.key
        assert store.find(city.name) is not None, f"{city.name} has no wiki article"


# ------------------------------------------------------------------ the near lane of a view across the street
_LANES = re.compile(r"In the lane nearer to you traffic moves from your (left|right) to your (left|right) "
                    r"\((\w+)ward\); in the far lane from your (left|right) to your (left|right) \((\w+)ward\)\.")


def _turn(heading: str, quarter_turns: int) -> str:
    return FOUR_DIRECTIONS[(FOUR_DIRECTIONS.index(heading) + quarter_turns) % 4]


def _facade_pair(drive: str) -> tuple[Location, str, str]:
    """A location of that driving side with views across the street facing both ways at the start."""
    for loc in LOCATIONS_LIST:
        if loc.country.drive != drive or loc.pedestrian or loc.landmark is not None:
            continue
        facades = [h for h in FOUR_DIRECTIONS if compose_view(loc, START, h).composition == "facade"]
        for h in facades:
            if _turn(h, 2) in facades:
                return loc, h, _turn(h, 2)
    raise AssertionError(f"no {drive}-hand location with opposite views across the street")


@pytest.mark.parametrize("drive", ["right", "left"])
def test_near_lane_moves_with_the_driving_side_in_both_facings_at_one_standpoint(drive):
    loc, one, other = _facade_pair(drive)
    seen = {}
    for heading in (one, other):
        m = _LANES.search(describe_view(compose_view(loc, START, heading)))
        assert m is not None, heading
        near_from, near_to, near_compass, far_from, far_to, far_compass = m.groups()
        # The view looks across from the kerb behind the viewer, so the near lane is the viewer's side of the
        # road; traffic keeps that kerb on its right (right-hand traffic) or left, so it moves a quarter
        # turn clockwise (or anticlockwise) from the facing.
        expected = _turn(heading, 1 if drive == "right" else 3)
        assert near_compass == expected, (heading, m.group(0))
        assert near_to == ("right" if drive == "right" else "left") and near_from != near_to
        assert far_compass == _turn(expected, 2) and (far_from, far_to) == (near_to, near_from)
        seen[heading] = near_compass
    # Turned round at one standpoint, the near lane is the other lane: its traffic goes the other way.
    assert seen[one] == _turn(seen[other], 2)
