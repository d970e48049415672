"""One real-Chromium pass through the shop served by the real SiteServer: search, product page,
add to cart, checkout in a second tab, order page.

Proves the forms work in a browser (labels, selects, POST-redirect-GET) and that the episode
header a browser context sends keys the state and the events."""

from __future__ import annotations

import pytest

from ewa_mcp.websites.shop import catalog

pytestmark = pytest.mark.browser


def test_buy_cheddar_in_chromium(site_server, browser_page):
    url = site_server.urls["shop"]
    store_id = catalog.cheapest_store("prod-cheddar-cheese", "16 oz")
    page, episode = browser_page()
    page.goto(url + "/")
    page.get_by_label("Search products").fill("cheddar")
    page.get_by_role("button", name="Search", exact=True).first.click()
    page.get_by_role("link", name="Sharp Cheddar Cheese").click()
    assert page.get_by_role("heading", level=1).inner_text() == "Sharp Cheddar Cheese"
    page.get_by_label("Size", exact=True).select_option("16 oz")
    page.get_by_label("Store", exact=True).select_option(store_id)
    page.get_by_label("Quantity", exact=True).fill("2")
    page.get_by_role("button", name="Add to cart").click()
    assert "Added to cart" in page.get_by_role("status").inner_text()
    # A second tab of the same episode sees the same server-side cart.
    other = page.context.new_page()
    other.goto(url + "/checkout")
    assert other.get_by_label(catalog.get_store(store_id).name, exact=False).is_checked()
    other.get_by_role("button", name="Place order").click()
    assert other.get_by_role("heading", level=1).inner_text() == "Order EWA-1001"
    assert "Thank you" in other.locator("main").aria_snapshot()

    [placed] = site_server.events.for_episode(episode, type="order_placed")
    order = placed["order"]
    assert order["store_id"] == store_id
    assert [(i["product_id"], i["size"], i["quantity"]) for i in order["items"]] == [
        ("prod-cheddar-cheese", "16 oz", 2)]
