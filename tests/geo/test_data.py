"""The location set, the generated task files and the wiki articles."""

from __future__ import annotations

import filecmp
import json
import re
from collections import Counter

from ewa_mcp.websites.wiki import store

from ewa_mcp.envs.geo import gazetteer
from ewa_mcp.envs.geo.articles import country_title, write_articles
from ewa_mcp.envs.geo.cities import CITIES
from ewa_mcp.envs.geo.rival_cities import RIVAL_CITIES_LIST
from ewa_mcp.envs.geo.countries import COUNTRIES
from ewa_mcp.envs.geo.taskgen.geolocation import FILE_NAMES, build_task, generate_tasks
from ewa_mcp.geometry import haversine_km
from ewa_mcp.envs.geo.graph import build_graph
from ewa_mcp.envs.geo.languages import LANGUAGES, SHOP_KINDS
from ewa_mcp.envs.geo.locations import DIFFICULTIES, LOCATIONS_LIST
from ewa_mcp.core.paths import REPO_ROOT
from ewa_mcp.core.taskmodel import load_task_file

INHABITED = {"Africa", "Asia", "Europe", "North America", "South America", "Oceania"}


def test_at_least_142_locations_on_every_inhabited_continent_with_a_difficulty_spread():
    assert len(LOCATIONS_LIST) >= 142
    assert len({loc.id for loc in LOCATIONS_LIST}) == len(LOCATIONS_LIST)
    continents = Counter(loc.continent or gazetteer.country_continent(loc.city.iso) for loc in LOCATIONS_LIST)
    assert INHABITED <= set(continents) and min(continents[c] for c in INHABITED) >= 8
    difficulty = Counter(loc.difficulty for loc in LOCATIONS_LIST)
    assert set(difficulty) == set(DIFFICULTIES)
    assert difficulty["easy"] < difficulty["street"] < difficulty["city"]  # some easy, many city-level hard
    assert all((loc.difficulty == "easy") == (loc.landmark is not None) for loc in LOCATIONS_LIST)


def test_locations_lie_in_their_gazetteer_city_and_country():
    for loc in LOCATIONS_LIST:
        record = gazetteer.city(loc.city.geonameid)
        assert record["countrycode"] == loc.city.iso, loc.id
        # Coordinates are on a central street: within 20 km of the gazetteer's city point.
        assert haversine_km(loc.lat, loc.lng, record["latitude"], record["longitude"]) < 20, loc.id
        assert loc.street and loc.sign and 0 <= loc.bearing < 180, loc.id


def test_country_profiles_are_complete():
    for iso, country in COUNTRIES.items():
        assert iso in gazetteer.countries(), iso
        assert country.drive in ("left", "right") and country.langs
        for code in country.langs:
            assert set(LANGUAGES[code].words) == set(SHOP_KINDS)
        if "{a}" not in country.phone:
            assert all(c.area_code is None for c in CITIES.values() if c.iso == iso), iso
    # A few facts that cue a country and are easy to get wrong.
    assert {c.iso for c in COUNTRIES.values() if c.drive == "left"} >= {"GB", "JP", "IN", "AU", "ZA", "KE", "WS", "MZ"}
    assert COUNTRIES["US"].drive == COUNTRIES["FR"].drive == COUNTRIES["CN"].drive == "right"


def test_graph_has_adjacent_and_two_step_standpoints():
    for loc in LOCATIONS_LIST[:20]:
        graph = build_graph(loc)
        assert {sp.steps_from_start for sp in graph.values()} == {0, 1, 2}
        for sp in graph.values():
            for n in sp.neighbours:
                back = [m for m in graph[n.id].neighbours if m.id == sp.id]
                assert back and abs((back[0].bearing - n.bearing) % 360 - 180) < 1e-6
                d = haversine_km(sp.lat, sp.lng, graph[n.id].lat, graph[n.id].lng) * 1000
                assert abs(d - n.distance_m) < 0.5


def test_committed_task_files_are_current(tmp_path):
    count = generate_tasks(tmp_path)
    assert count == 2 * len(LOCATIONS_LIST)
    committed = REPO_ROOT / "tasks" / "geolocation"
    for name in FILE_NAMES.values():
        assert filecmp.cmp(tmp_path / name, committed / name, shallow=False), (
            f"tasks/geolocation/{name} is stale; run python -m ewa_mcp.envs.geo.taskgen.geolocation")
    tasks = load_task_file(committed / FILE_NAMES["embodied"])
    assert tasks[0].start.web is not None and tasks[0].start.web.start_url == "wiki:/"
    baseline = load_task_file(committed / FILE_NAMES["baseline"])
    assert all(t.start.web is None and t.metadata["setting"] == "baseline" for t in baseline)
    assert all(t.id.endswith("-baseline") for t in baseline)


def test_tasks_reveal_nothing_in_their_public_fields():
    for loc in LOCATIONS_LIST:
        task = build_task(loc, "embodied")
        public = json.dumps({"id": task.id, "intent": task.intent}, ensure_ascii=False).lower()
        assert loc.city.name.lower() not in public and loc.country.name.lower() not in public


def test_every_country_and_city_has_a_wiki_article():
    index = store.index()
    assert not index.problems, [str(p) for p in index.problems[:5]]
    for loc in LOCATIONS_LIST:
        city_article = index.find(loc.city.name)
        assert city_article is not None, loc.city.name
        assert index.find(country_title(loc.country)) is not None, loc.country.name
    # A geo city article describes conventions (an area-code block, a plate format) and never
    # quotes what a view shows (the street sign, the area code itself): tests/geo/test_wiki_leaks.py.
    chattogram = index.find("Chittagong")
    assert chattogram is not None and chattogram.title == "Chattogram"
    assert "CDA Avenue" not in chattogram.body and "031" not in chattogram.body
    assert "area code of the 03x block" in chattogram.body and "region's name, in the local script" in chattogram.body
    assert index.find("Côte d'Ivoire").title == "Ivory Coast"


def test_committed_articles_are_current(tmp_path):
    out = tmp_path / "geo"
    written = write_articles(out, articles_root=store.ARTICLES_DIR)
    committed = store.ARTICLES_DIR / "geo"
    assert written == len(list(committed.glob("*.md")))
    for path in out.glob("*.md"):
        assert filecmp.cmp(path, committed / path.name, shallow=False), (
            f"{path.name} is stale; run python -m ewa_mcp.envs.geo.articles")


def test_a_city_article_names_only_the_sign_languages_its_views_show():
    # Yogyakarta's article said its street signs also show Javanese script while every view showed Indonesian
    # in Latin letters only, and a play-tester ruled the right city out on it: the article's words about signs
    # must agree with the languages the views draw (the city's own, else its country's).
    every_name = {lang.name for lang in LANGUAGES.values()}
    for city in [*CITIES.values(), *RIVAL_CITIES_LIST]:
        shown = {LANGUAGES[code].name for code in (city.langs or COUNTRIES[city.iso].langs)}
        named = {m.group(1) for m in re.finditer(r"([A-Z][a-z]+) script", city.about)}
        if "sign" in city.about:
            named |= {name for name in every_name if re.search(rf"\b{name}\b", city.about)}
        assert named <= shown, (city.name, named - shown, city.about)


def test_every_city_article_links_its_climate_to_an_article_that_lists_the_city():
    # A view shows the climate as its sky; the climate article says how that climate's weather looks, so an
    # agent telling two cities apart by the sky reads the link in the wiki rather than guessing it.
    index = store.index()
    for city in [*CITIES.values(), *RIVAL_CITIES_LIST]:
        article = index.find(city.name)
        assert article is not None, city.name
        if article.group != "geo" or article.category != "Cities":
            continue  # a city-state's country article, or an article of the street world's own
        link = re.search(r"- Climate: \[\[([^]|]+)\|", article.body)
        assert link is not None, city.name
        climate = index.find(link.group(1))
        assert climate is not None and climate.category == "Climates", (city.name, link.group(1))
        assert f"[[{city.name}]]" in climate.body, (city.name, climate.title)
        assert "## What the weather looks like" in climate.body


def test_a_city_whose_article_is_not_the_geo_groups_still_states_its_conventions():
    # New York City's article comes from the street world's wiki; its geo location is hard, so without
    # the conventions block (trees, climate, yellow taxicabs) the answer could not be read from the wiki.
    from ewa_mcp.envs.geo.articles import TAKEN_HEADING, taken_city_sections

    blocks = taken_city_sections(store.ARTICLES_DIR)
    assert any(path.name == "new-york-city.md" for path in blocks)
    for path, block in blocks.items():
        assert block.startswith(TAKEN_HEADING) and "Street trees:" in block
        assert path.read_text(encoding="utf-8").endswith("\n\n" + block), (
            f"{path} lacks its city's conventions; run python -m ewa_mcp.envs.geo.articles")
