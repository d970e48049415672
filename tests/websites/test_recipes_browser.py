"""Real-Chromium smoke test of the recipes site: search, filter, open a recipe, step to the end."""

from __future__ import annotations

import json
from pathlib import Path

import pytest


pytestmark = pytest.mark.browser

DATA = json.loads((Path(__file__).resolve().parents[2] / "websites" / "recipes" / "data" / "recipes.json")
                  .read_text(encoding="utf-8"))


def test_find_and_follow_a_lookalike_recipe_in_chromium(site_server, browser_page):
    # Egg in a Basket comes as a pair; the "Include ingredient: Bacon" constraint picks one.
    target = next(r for r in DATA if r["name"] == "Egg in a Basket"
                  and "Bacon" in {i["name"] for i in r["ingredients"]})
    n = len(target["steps"])
    page, episode = browser_page()
    base = site_server.urls["recipes"]
    page.goto(base + "/")
    page.get_by_role("searchbox", name="Search recipes").fill("egg in a basket")
    page.get_by_role("combobox", name="Include ingredient").select_option("Bacon")
    page.get_by_role("button", name="Apply filters").click()
    page.wait_for_url(base + "/?q=egg+in+a+basket&include=Bacon")
    results = page.get_by_role("list", name="Recipes").get_by_role("link")
    assert results.all_inner_texts() == ["Egg in a Basket"]
    # The URL holds the state: a reload keeps the search text and the filter.
    page.reload()
    assert page.get_by_role("searchbox", name="Search recipes").input_value() == "egg in a basket"
    assert page.get_by_role("combobox", name="Include ingredient").input_value() == "Bacon"

    results.first.click()
    page.wait_for_url(base + f"/recipe/{target['id']}")
    image = page.get_by_role("img", name=f"Illustration of {target['name']}", exact=False)
    assert image.evaluate("img => img.complete && img.naturalWidth > 0")
    for k in range(1, n):
        assert page.get_by_role("heading", name=f"Step {k} of {n}").is_visible()
        page.get_by_role("link", name="Next step").click()
    snapshot = page.locator("main").aria_snapshot()
    assert f"Step {n} of {n}" in snapshot
    assert page.get_by_role("button", name="Next step").is_disabled()

    steps = site_server.events.for_episode(episode, type="recipe_step")
    assert [(e["recipe_id"], e["step"], e["of"]) for e in steps] == [(target["id"], k, n) for k in range(1, n + 1)]


def test_step_links_land_on_the_step_in_chromium(site_server, browser_page):
    """Next step, Previous step and Start over open the page scrolled to the step box: the new step's text is
    on the first screen, with no scroll needed (the recipe's picture and lists fill the top of the page)."""
    recipe = DATA[0]
    steps = [s["text"] for s in recipe["steps"]]
    page, _ = browser_page()
    page.set_viewport_size({"width": 1280, "height": 720})
    base = site_server.urls["recipes"]
    page.goto(base + f"/recipe/{recipe['id']}")
    text = page.locator(".step-text")

    def on_first_screen() -> bool:
        box = text.bounding_box()
        assert box is not None
        return 0 <= box["y"] and box["y"] + box["height"] <= page.viewport_size["height"]

    # The page as a link from the index opens it: at the top, with the step box below the fold here.
    assert page.evaluate("window.scrollY") == 0 and not on_first_screen()
    for label, expected in [("Next step", 2), ("Next step", 3), ("Previous step", 2), ("Start over", 1)]:
        page.get_by_role("link", name=label).click()
        page.wait_for_url(base + f"/recipe/{recipe['id']}?step={expected}#step")
        assert text.inner_text() == steps[expected - 1]
        assert page.evaluate("window.scrollY") > 0 and on_first_screen(), label
        assert page.get_by_role("heading", name=f"Step {expected} of {len(steps)}").is_visible()
