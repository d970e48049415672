"""Observations describe what is seen; the encyclopedia names conventions in its own words (issue 26, principle 4).

A view says "trees whose bark flakes off in patches"; the wiki says "London plane". When both used the same
distinctive words, matching the words of the views against the articles named the country for half the tasks
without any reasoning (the ``geo-lexical`` heuristic, docs/verified.md). These tests keep the two vocabularies
apart and run that matcher over every task.
"""

from __future__ import annotations

import re
from collections import Counter

from ewa_mcp.envs.geo.cities import CITIES
from ewa_mcp.envs.geo.describe import describe_view
from ewa_mcp.envs.geo.locations import LOCATIONS
from ewa_mcp.envs.geo.scene import compose_view
from ewa_mcp.envs.geo.styles import COLOUR_HEX, TREE_NAMES, TREE_WORDS, VEHICLE_NAMES, VEHICLE_WORDS
from ewa_mcp.envs.geo.taskgen.geolocation import build_tasks
from ewa_mcp.envs.geo.vocabulary import banned_in_articles, distinctive_view_words, words
from ewa_mcp.evaluation.heuristics import agents
from ewa_mcp.geometry import FOUR_DIRECTIONS
from ewa_mcp.websites.wiki import store

_NAMES = re.compile(r"\*\*[^*]+\*\*|\[\[[^\]]+\]\]")


def _allowed(article) -> set[str]:
    """Words an article may share with the views: colours (a plate or a taxi is yellow in both) and the
    colour phrase of the city's vehicles ("black cab")."""
    allowed = set(COLOUR_HEX) | {"cream"}
    for city in CITIES.values():
        if city.name == article.title:
            for feature in city.transport:
                allowed |= words(feature.partition(":")[2])
    return allowed


def test_geo_articles_use_no_word_that_only_some_views_use():
    banned = banned_in_articles()
    assert {"mansard", "shutters", "limestone", "tram", "rickshaw"} & banned  # the view words are known
    found: dict[str, set[str]] = {}
    for article in store.load_articles():
        if article.group != "geo":
            continue
        shared = (words(_NAMES.sub(" ", article.body)) & banned) - _allowed(article)
        if shared:
            found[article.slug] = shared
    assert not found, f"articles reuse the views' distinctive words (say it in the wiki's own words): {found}"


def test_trees_and_vehicles_are_seen_in_other_words_than_the_wiki_names_them():
    assert set(TREE_NAMES) == set(TREE_WORDS) and set(VEHICLE_NAMES) == set(VEHICLE_WORDS)
    for table_seen, table_named in ((TREE_WORDS, TREE_NAMES), (VEHICLE_WORDS, VEHICLE_NAMES)):
        seen_anywhere = set().union(*(words(v) for v in table_seen.values()))
        for key, name in table_named.items():
            shared = words(name.replace("{colour}", "")) & seen_anywhere
            assert not shared, f"{key}: the wiki's name {name!r} uses the views' words {shared}"


def test_views_quote_no_local_vehicle_name():
    # "minibus:trotro" names the vehicle where other cities give a colour: the view must not say it.
    for loc in LOCATIONS.values():
        for feature in loc.city.transport:
            name = feature.partition(":")[2]
            if name and not any(w in COLOUR_HEX for w in name.replace("-", " ").split()):
                for heading in FOUR_DIRECTIONS:
                    text = describe_view(compose_view(loc, "p0", heading))
                    assert name not in text.replace(f"'{name}", ""), (loc.id, name)


def test_word_matching_views_to_the_wiki_beats_the_constant_guess_by_at_most_10_points():
    tasks = build_tasks("embodied") + build_tasks("baseline")
    hits: Counter[str] = Counter()
    for task in tasks:
        start = task.start.embodied
        loc = LOCATIONS[start.location_id]
        headings = ("north",) if start.setting == "baseline" else FOUR_DIRECTIONS
        city = agents.best_city("\n".join(describe_view(compose_view(loc, "p0", h)) for h in headings))
        assert city is not None
        hits["continent"] += city["continent"] == task.answer.continent
        hits["country"] += city["country"] == task.answer.country
        hits["city"] += city["title"] == task.answer.city
    for level in ("continent", "country", "city"):
        modal = Counter(getattr(t.answer, level) for t in tasks).most_common(1)[0][1]
        assert hits[level] - modal <= 0.10 * len(tasks), (level, hits[level], modal, len(tasks))


def test_distinctive_view_words_leave_out_what_every_view_says():
    common = distinctive_view_words()
    assert not {"left", "right", "buildings", "sky", "trees", "signs"} & common
