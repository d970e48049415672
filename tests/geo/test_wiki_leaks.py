"""The wiki is an encyclopedia, not a lookup table for the views (issue 16).

For every geolocation task, every distinctive string any of its views shows (shop-sign lines,
whole signs, telephone numbers, plates and plate captions, street-name signs) is searched in
the wiki the way an agent would search it: as a whole, and word by word. The search must
never land on the target city's article or the street's article:

- when every word of the query matched, the target article must not be among the hits at all;
- for a single word, the target must not be among the hits when the word is distinctive
  (it matches at most ``DISTINCTIVE_HITS`` articles) and never be the first hit.

Words that name the country or the city themselves (a plate captioned "DUBAI" or "FIJI", a
sign reading "KAMPALA ROAD") are left out: such a view spells the place by itself, and every
article about a place must name it. Numbers of one or two digits (the groups of a telephone
number) are not distinctive on their own.

So seeing one sign or one phone number and searching for it no longer solves a task; finding
the city takes reasoning over the conventions the articles describe (plate formats, area-code
ranges, languages, architecture, climate).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from ewa_mcp.envs.geo.articles import country_title
from ewa_mcp.envs.geo.graph import build_graph
from ewa_mcp.geometry import FOUR_DIRECTIONS
from ewa_mcp.envs.geo.locations import LOCATIONS_LIST, Location
from ewa_mcp.envs.geo.scene import compose_view
from ewa_mcp.websites.wiki import store
from ewa_mcp.websites.wiki.search import SearchIndex, tokens_of

DISTINCTIVE_HITS = 10


@lru_cache(maxsize=1)
def _index() -> SearchIndex:
    return SearchIndex(store.load_articles())


def view_strings(loc: Location) -> set[str]:
    """Every string a view of this location quotes, as the text observation quotes it."""
    out: set[str] = set()
    for sp in build_graph(loc):
        for heading in FOUR_DIRECTIONS:
            spec = compose_view(loc, sp, heading)
            for sign in spec.shops:
                out.update(t.native for t in sign.lines)
                out.update(t.latin for t in sign.lines)
                out.add(" / ".join(t.native for t in sign.lines))
                if sign.phone:
                    out.add(sign.phone)
            if spec.street_sign is not None:
                out.update(t.native for t in spec.street_sign.lines)
                out.add(" / ".join(t.native for t in spec.street_sign.lines))
            for vehicle in spec.vehicles:
                if vehicle.plate is not None and vehicle.plate.text:
                    out.add(vehicle.plate.text)
                    if vehicle.plate.caption:
                        out.add(vehicle.plate.caption)
    return {s for s in out if s.strip()}


def target_slugs(loc: Location) -> set[str]:
    """The articles that would give the answer away: the city's (or its city-state country's) and the street's."""
    slugs = set()
    for name in (loc.city.name, *loc.city.aliases):
        article = store.find(name)
        if article is not None and article.category != "Countries":
            slugs.add(article.slug)
    city_words = _words(loc.city.name) | set().union(*(_words(a) for a in loc.city.aliases))
    for name in (loc.street, *loc.street_aliases):
        article = store.find(name)  # a street's own article, if it is this city's street
        if article is not None and article.category != "Countries" and city_words & _words(
                store.plain_text(article.body) + " " + " ".join(article.infobox.values())):
            slugs.add(article.slug)
    if store.find(loc.city.name) is None or loc.city.name == country_title(loc.country):
        country = store.find(country_title(loc.country))
        if country is not None and store.normalize_title(country.title) == store.normalize_title(loc.city.name):
            slugs.add(country.slug)  # Singapore, Hong Kong: the country's article is the city's
    return slugs


def _words(text: str) -> set[str]:
    return set(store.normalize_title(text).split())


def place_name_words(loc: Location) -> set[str]:
    """Words of the country's and the city's own names (which a view may spell by itself)."""
    names = [loc.country.name, country_title(loc.country), *loc.country.aliases, loc.city.name, *loc.city.aliases]
    return set().union(*(_words(n) for n in names)) | {"city", "d", "c"}


def leaks(query: str, targets: set[str], names: set[str] = frozenset(), index: SearchIndex | None = None) -> str | None:
    index = index or _index()
    if _words(query) <= names:
        return None
    hits, total, all_words = index.search(query, limit=50)
    slugs = [h.slug for h in hits]
    if all_words and targets & set(slugs):
        return f"{query!r} finds {sorted(targets & set(slugs))} ({total} hits)"
    for token in tokens_of(query):
        if _words(token) <= names or (token.isdigit() and len(token) <= 2):
            continue
        hits, total, _ = index.search(token, limit=DISTINCTIVE_HITS + 1)
        slugs = [h.slug for h in hits]
        if slugs and slugs[0] in targets:
            return f"word {token!r} of {query!r} ranks {slugs[0]} first ({total} hits)"
        if total <= DISTINCTIVE_HITS and targets & set(slugs):
            return f"word {token!r} of {query!r} finds {sorted(targets & set(slugs))} ({total} hits)"
    return None


@pytest.mark.parametrize("loc", LOCATIONS_LIST, ids=lambda loc: loc.id)
def test_no_view_string_finds_the_answer_in_the_wiki(loc):
    targets = target_slugs(loc)
    assert targets, f"{loc.id}: no article for {loc.city.name}"
    names = place_name_words(loc)
    found = [why for s in sorted(view_strings(loc)) if (why := leaks(s, targets, names))]
    assert not found, f"{loc.id} ({loc.city.name}, {loc.street}): " + "; ".join(found[:6])


def test_leak_check_catches_an_article_that_quotes_a_view():
    # The check itself: an article quoting a street sign or an area code is caught; one that
    # quotes neither is not.
    import dataclasses

    loc = next(loc for loc in LOCATIONS_LIST if loc.city.key == "manchester")
    article = store.find(loc.city.name)
    others = [a for a in store.load_articles() if a.slug != article.slug]
    quoting = dataclasses.replace(article, body=article.body + f"\n\nSee {loc.sign[0]}; dial 0161.")
    index = SearchIndex([quoting, *others])
    assert leaks(loc.sign[0], {article.slug}, index=index)
    assert leaks("0161 496 0123", {article.slug}, index=index)
    assert leaks("0161 496 0123", {article.slug}, index=SearchIndex([article, *others])) is None


def test_no_article_repeats_a_view_description_word_for_word():
    """A play-tester found each city's article quoting the sentence its views use for the buildings, so one
    search for that sentence named the city. Articles now summarise the architecture in words of their own."""
    from ewa_mcp.envs.geo.styles import ARCH

    texts = [" ".join(a.body.split()) for a in store.load_articles()]
    for name, arch in ARCH.items():
        sentence = " ".join(arch.description.split())
        assert not any(sentence in text for text in texts), f"an article quotes the {name} buildings sentence"
