"""One real-Chromium pass through the map served by the real SiteServer: type two places, get
walking directions, read them through the accessibility tree as an agent would."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.street.world import get_world

pytestmark = pytest.mark.browser


def test_walking_directions_in_chromium(site_server, browser_page):
    url = site_server.urls["map"]
    route = get_world().directions("poi-manhattan-flatiron-building", "store-cvs-midtown")
    page, episode = browser_page()
    page.goto(url + "/")
    page.get_by_label("From").fill("Flatiron Building")
    page.get_by_label("To").fill("CVS Pharmacy Grand Central")
    page.get_by_role("button", name="Get walking directions").click()
    steps = page.get_by_role("list", name="Turn-by-turn directions").get_by_role("listitem").all_inner_texts()
    assert steps == [s.instruction for s in route.steps]
    image = page.get_by_role("img", name="Walking route from Flatiron Building to CVS Pharmacy Grand Central")
    assert image.is_visible()
    snapshot = page.locator("main").aria_snapshot()
    assert "Turn-by-turn directions" in snapshot and "Arrive at CVS Pharmacy Grand Central" in snapshot
    assert page.url.startswith(url + "/directions?from=Flatiron+Building&via=&to=CVS")  # URL-addressable

    shown = site_server.events.for_episode(episode, type="directions")
    assert shown == [{"site": "map", "type": "directions", "origin": "poi-manhattan-flatiron-building",
                      "destination": "store-cvs-midtown", "city": "manhattan", "distance_m": route.distance_m}]
