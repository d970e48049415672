"""One real-Chromium pass through the wiki served by the real SiteServer: search from the main
page, land on the article through an alias, read the infobox through the accessibility tree,
follow an internal link, open a random article; events are keyed by the browser's episode."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser


def test_search_read_and_wander_in_chromium(site_server, browser_page):
    url = site_server.urls["wiki"]
    page, episode = browser_page()
    page.goto(url + "/")
    page.get_by_label("Search the wiki").fill("Fuller Building")
    page.keyboard.press("Enter")
    page.wait_for_url("**/wiki/flatiron-building*")
    assert page.get_by_role("heading", level=1).inner_text() == "Flatiron Building"

    infobox = page.get_by_role("table", name="Infobox: Flatiron Building")
    outline = infobox.aria_snapshot()
    assert 'rowheader "Year built"' in outline and "1902" in outline
    assert 'rowheader "Height"' in outline and "87 m" in outline

    page.get_by_role("link", name="Daniel Burnham").first.click()
    assert page.get_by_role("heading", level=1).inner_text() == "Daniel Burnham"

    page.get_by_role("link", name="Random article").click()
    page.wait_for_url("**/wiki/*")
    assert page.get_by_role("heading", level=1).inner_text()

    events = site_server.events.for_episode(episode, site="wiki")
    [search] = [e for e in events if e["type"] == "search"]
    assert search["went_to"] == "flatiron-building"
    viewed = [e["slug"] for e in events if e["type"] == "page_view" and e.get("slug")]
    [random] = [e for e in events if e["type"] == "random"]
    assert viewed == ["flatiron-building", "daniel-burnham", random["slug"]]
