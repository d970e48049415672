"""Content checks: enough articles, unique slugs, every [[link]] resolves, every landmark POI has
an article whose infobox shows its facts, and the Python API the task generator uses."""

from __future__ import annotations

import collections
import sqlite3

from ewa_mcp.websites.wiki import store
from ewa_mcp.websites.wiki.landmarks import LANDMARK_KINDS, fact_label, landmark_pois, load_pois
from ewa_mcp.websites.wiki.search import fts5_available


def test_sqlite_has_fts5():
    assert fts5_available(), f"SQLite {sqlite3.sqlite_version} lacks FTS5"


def test_at_least_300_articles_and_no_problems():
    store.index.cache_clear()
    articles = store.load_articles()
    assert len(articles) >= 300
    assert [str(p) for p in store.check_articles()] == []


def test_slugs_are_unique_across_groups():
    stems = collections.Counter(p.stem for p in store.ARTICLES_DIR.rglob("*.md") if p.name != "README.md")
    assert [s for s, n in stems.items() if n > 1] == []


def test_every_link_resolves_to_an_existing_article():
    articles = store.load_articles()
    slugs = {a.slug for a in articles}
    for article in articles:
        for target, _ in store.links_in(article.body):
            found = store.find(target)
            assert found is not None and found.slug in slugs, f"{article.slug}: [[{target}]]"


def test_every_landmark_poi_has_an_article_showing_its_facts():
    pois = landmark_pois()
    assert pois, "the POI file lists no landmark-like POIs"
    kinds = collections.Counter(p["kind"] for p in pois)
    assert {"landmark", "museum", "park", "station"} <= set(kinds)
    for poi in pois:
        article = store.by_poi_id(poi["id"])
        assert article is not None, f"no article for {poi['id']}"
        assert article.poi_id == poi["id"]
        assert poi["address"] == article.infobox["Address"]
        for key, value in poi["facts"].items():
            shown = article.infobox.get(fact_label(key), "")
            # The grader compares answers with the POI value, so the value must appear verbatim.
            assert str(value) in shown, f"{article.slug}: {key}={value!r} not in {shown!r}"
        assert article.coordinates == {"lat": poi["lat"], "lng": poi["lng"]}


def test_non_landmark_pois_get_no_articles():
    others = [p for p in load_pois() if p["kind"] not in LANDMARK_KINDS]
    assert others and all(store.by_poi_id(p["id"]) is None for p in others)


def test_find_resolves_titles_aliases_and_slugs():
    flatiron = store.find("Flatiron Building")
    assert flatiron is not None
    assert store.find("fuller building") is flatiron
    assert store.find("flatiron-building") is flatiron
    assert store.find("Beaux-Arts").slug == "beaux-arts-architecture"
    assert store.find("no such thing") is None
    assert flatiron.infobox["Year built"] == "1902" and flatiron.category == "Landmarks in Manhattan"


def test_articles_read_like_prose_not_boilerplate():
    articles = [a for a in store.load_articles() if a.group != "geo"]
    paragraphs = collections.Counter(p.strip() for a in articles for p in a.body.split("\n\n") if len(p) > 80)
    assert [p[:60] for p, n in paragraphs.items() if n > 1] == []
    short = [a.slug for a in articles if len(store.plain_text(a.body).split()) < 40]
    assert short == []
