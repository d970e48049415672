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
    name = catalog.get_store(store_id).name
    assert other.get_by_label(name, exact=False).is_checked()
    price = catalog.price("prod-cheddar-cheese", "16 oz", store_id)
    assert f"Total at {name}: ${2 * price:,.2f}" in other.locator("main").inner_text()
    # Another store is looked at by choosing it and asking for its prices: the page then shows that
    # store's figures only (the comparison across stores is the buyer's to make).
    elsewhere = next(s for s in catalog.load_stores() if s.id != store_id)
    other.get_by_label(elsewhere.name, exact=False).check()
    other.get_by_role("button", name="Show prices at this store").click()
    other.wait_for_url(f"**/checkout?store_id={elsewhere.id}*")
    shown = other.locator("main").inner_text()
    assert f"at {elsewhere.name}" in shown and f"Total at {name}" not in shown
    other.get_by_label(name, exact=False).check()
    other.get_by_role("button", name="Place order").click()
    assert other.get_by_role("heading", level=1).inner_text() == "Order EWA-1001"
    assert "Thank you" in other.locator("main").aria_snapshot()

    [placed] = site_server.events.for_episode(episode, type="order_placed")
    order = placed["order"]
    assert order["store_id"] == store_id
    assert [(i["product_id"], i["size"], i["quantity"]) for i in order["items"]] == [
        ("prod-cheddar-cheese", "16 oz", 2)]
