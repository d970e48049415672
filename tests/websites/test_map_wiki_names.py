"""The map finds a place by the name and the address its wiki article gives: traveling tasks send the agent
from an article's infobox to the map to measure a walk, so a title or address the map does not know is a
dead end the agent cannot see past."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.street.address import fold
from ewa_mcp.websites.wiki.store import ARTICLES_DIR, read_articles
from ewa_mcp.websites.map.places import WorldAdapter


@pytest.fixture(scope="module")
def adapter() -> WorldAdapter:
    return WorldAdapter()


def _is(place, poi, world) -> bool:
    return place is not None and (place.id == poi or getattr(place, "refers_to", None) == poi
                                  or place.node == world.places[poi].node)


def test_every_wiki_title_and_address_finds_its_place(adapter: WorldAdapter) -> None:
    articles, _ = read_articles(ARTICLES_DIR)
    missed = []
    for article in articles:
        if not article.poi_id or article.poi_id not in adapter.world.places:
            continue
        for text in (article.title, (article.infobox or {}).get("Address")):
            if not text:
                continue
            found = adapter.resolve(text)
            if _is(found.place, article.poi_id, adapter.world) or any(
                    _is(c, article.poi_id, adapter.world) for c in found.choices):
                continue
            if found.place is not None and found.place.kind == "intersection" and "&" in text:
                continue  # a corner the article gives as its address is that corner
            missed.append((text, article.poi_id, getattr(found.place, "id", None), found.error[:40]))
    assert not missed, missed


def test_dashes_part_words_when_names_are_folded() -> None:
    assert fold("14 St–Union Square station") == fold("14 St-Union Square station") == "14 st union square station"


def test_a_place_is_found_at_its_listed_address_after_anchoring_moved_it(adapter: WorldAdapter) -> None:
    paramount = adapter.world.places["poi-manhattan-paramount-building"]
    assert "Broadway" not in paramount.address  # anchored to the street its node stands on
    found = adapter.resolve("1501 Broadway")
    assert _is(found.place, paramount.id, adapter.world)
    penn = adapter.resolve("Pennsylvania Station (New York City)")
    assert penn.place is not None and penn.place.city == "manhattan"
