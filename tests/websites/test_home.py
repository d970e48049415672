"""The homepage hub: links to every served site and forwards its search box to the chosen site."""

from __future__ import annotations

import re
from urllib.parse import parse_qs, urlsplit

import pytest
from starlette.testclient import TestClient

from ewa_mcp.websites.common import EPISODE_HEADER, SiteContext
from ewa_mcp.websites.home.app import SEARCH_PATHS, create_app



@pytest.fixture
def client(site_context):
    return TestClient(create_app(site_context), follow_redirects=False)


def test_hub_links_every_served_site_with_a_description(client, site_context):
    page = client.get("/").text
    for name in ("recipes", "shop", "map", "wiki"):
        assert f'<a href="{site_context.urls[name]}/">' in page
    assert len(re.findall(r'<li class="card"><h2>', page)) == 4
    assert '<select id="site" name="site">' in page and '<label for="q">Search</label>' in page


def test_hub_lists_only_sites_that_are_served(event_log):
    ctx = SiteContext(urls={"home": "http://h.test", "recipes": "http://r.test"}, emit=event_log.emit)
    client = TestClient(create_app(ctx), follow_redirects=False)
    page = client.get("/").text
    assert "http://r.test/" in page and "Shop" not in page.split("<main", 1)[1]
    response = client.get("/go?site=wiki&q=Flatiron")
    assert response.status_code == 404 and "not running" in response.text


@pytest.mark.parametrize("site", sorted(SEARCH_PATHS))
def test_search_box_forwards_to_the_sites_search_page(client, site_context, event_log, site):
    response = client.get("/go", params={"site": site, "q": "  tomato   soup "}, headers={EPISODE_HEADER: "ep-h"})
    assert response.status_code == 303
    target = urlsplit(response.headers["location"])
    assert f"{target.scheme}://{target.netloc}" == site_context.urls[site]
    assert target.path == SEARCH_PATHS[site]
    assert parse_qs(target.query) == {"q": ["tomato soup"]}
    assert event_log.for_episode("ep-h", type="search") == [
        {"site": "home", "type": "search", "query": "tomato soup", "target": site}]


def test_empty_search_goes_to_the_sites_front_page(client, site_context):
    response = client.get("/go?site=recipes&q=")
    assert response.status_code == 303 and response.headers["location"] == site_context.urls["recipes"] + "/"


@pytest.mark.parametrize(
    ("query", "status", "phrase"),
    [
        ({"site": "youtube", "q": "x"}, 400, "Unknown site"),
        ({"q": "x"}, 400, "Unknown site"),
        ({"site": "recipes", "q": "x" * 201}, 400, "at most 200"),
    ],
)
def test_bad_forwarding_requests_get_a_clear_error(client, event_log, query, status, phrase):
    response = client.get("/go", params=query, headers={EPISODE_HEADER: "ep-bad"})
    assert response.status_code == status and phrase in response.text
    assert event_log.for_episode("ep-bad") == []


def test_page_view_event(client, event_log):
    client.get("/", headers={EPISODE_HEADER: "ep-view"})
    assert event_log.for_episode("ep-view") == [{"site": "home", "type": "page_view", "path": "/"}]


@pytest.mark.browser
def test_home_to_recipes_in_chromium(site_server, browser_page):
    page, episode = browser_page()
    page.goto(site_server.urls["home"] + "/")
    page.get_by_role("searchbox", name="Search").fill("toast")
    page.get_by_role("combobox", name="in").select_option("recipes")
    page.get_by_role("button", name="Go").click()
    page.wait_for_url(site_server.urls["recipes"] + "/?q=toast")
    assert page.get_by_role("heading", name="Find a recipe").is_visible()
    # Every site links back to the homepage.
    page.get_by_role("navigation", name="Sites").get_by_role("link", name="Homepage").click()
    page.wait_for_url(site_server.urls["home"] + "/")
    events = site_server.events.for_episode(episode)
    assert {"site": "home", "type": "search", "query": "toast", "target": "recipes"} in events
    assert any(e["site"] == "recipes" and e["type"] == "search" and e["query"] == "toast" for e in events)


def test_every_site_is_declared_once_and_everything_else_follows_from_it():
    from ewa_mcp.websites import serve
    from ewa_mcp.websites.common import SITE_TITLES
    from ewa_mcp.websites.home.app import DESCRIPTIONS
    from ewa_mcp.websites.sites import DECLARED

    names = [site.name for site in DECLARED]
    assert len(set(names)) == len(names) and len({site.port for site in DECLARED}) == len(names)
    assert list(serve.DEFAULT_PORTS) == names and list(SITE_TITLES) == names
    assert set(serve.available_sites()) == set(names)  # every declared app imports
    # every site but the homepage itself is listed on the homepage, and each listed one is searchable
    assert list(DESCRIPTIONS) == names[1:] and set(SEARCH_PATHS) <= set(DESCRIPTIONS)
