"""Set-of-Marks badges never hide what they mark, and the recipe site's step links land on the step: both on
the real embedded sites in a real Chromium, through the browser environment an agent drives."""

from __future__ import annotations

import io
from collections.abc import AsyncIterator
from typing import Any

import pytest
from PIL import Image

from ewa_mcp.core.services import Services
from ewa_mcp.envs.browser.chromium import chromium_service
from ewa_mcp.envs.browser.observation import capture, draw_marks
from ewa_mcp.envs.browser.som import REMOVE_MARKS_JS
from ewa_mcp.envs.browser.tabs import take_snapshot
from ewa_mcp.settings import load_settings
from ewa_mcp.websites.recipes.catalog import load_recipes
from ewa_mcp.websites.shop import catalog

from .helpers import open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]

BOXES_JS = """(selector) => [...document.querySelectorAll(selector)].map((e) => {
  const r = e.getBoundingClientRect();
  return {id: e.id, checked: !!e.checked, box: [r.x, r.y, r.width, r.height]};
})"""


@pytest.fixture(scope="module")
async def site_services(chromium_path: str, anyio_backend: str) -> AsyncIterator[Services]:
    """The real embedded sites (started by the first episode, as the server does) and one Chromium."""
    services = Services(load_settings({}))
    await services.get("chromium", chromium_service)
    yield services
    await services.aclose()


def _meet(a: list[float], b: list[float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


def _on_screen(box: list[float], width: int, height: int) -> bool:
    return box[0] >= 0 and box[1] >= 0 and box[0] + box[2] <= width and box[1] + box[3] <= height


def _region(image: Image.Image, box: list[float]) -> bytes:
    x, y, w, h = box
    return image.crop((round(x), round(y), round(x + w), round(y + h))).tobytes()


async def _badges(env: Any) -> tuple[list[list[int]], Any]:
    """Where the observation's drawing step puts the badges on the page as it is now (then taken off)."""
    session = env.session
    tab = session.current()
    info = await take_snapshot(session, tab, boxes=True)
    try:
        return await draw_marks(session, tab, info), info
    finally:
        await session.main_world(tab, f"({REMOVE_MARKS_JS})()")


async def test_checkout_badges_leave_every_radio_button_and_its_checked_state_visible(site_services):
    store_id = catalog.cheapest_store("prod-cheddar-cheese", "16 oz")
    env = await open_env(site_services, "shop:/product/prod-cheddar-cheese", episode_id="ep-marks-checkout",
                         options={"observation": "vision"})
    try:
        page = env.session.current().page
        await page.get_by_label("Size", exact=True).select_option("16 oz")
        await page.get_by_label("Store", exact=True).select_option(store_id)
        await page.get_by_role("button", name="Add to cart").click()
        await page.wait_for_url("**/cart?added=*")
        shown = await env.goto("shop:/checkout")
        assert "Pre-selected: " in await page.inner_text("main")

        radios = [r for r in await page.evaluate(BOXES_JS, "input[type=radio]")
                  if _on_screen(r["box"], 1280, 720)]
        assert {r["checked"] for r in radios} == {True, False}, radios  # a chosen store and others on screen
        badges, info = await _badges(env)
        assert len(badges) == shown.data["marks"] >= len(radios)
        for radio in radios:
            covering = [b for b in badges if _meet(b[1:], radio["box"])]
            assert covering == [], f"badges {covering} cover radio {radio}"
        for i, a in enumerate(badges):  # there is room on this page: no badge hides another
            assert _on_screen(a[1:], info[3], info[4]), a
            assert not any(_meet(a[1:], b[1:]) for b in badges[i + 1:]), a

        # In the screenshot the agent gets, each radio button looks exactly as it does without the marks,
        # so the checked one (filled) and the others (empty) can be told apart.
        marked = Image.open(io.BytesIO(shown.images[0])).convert("RGB")
        plain = Image.open(io.BytesIO(await capture(env.session, env.session.current()))).convert("RGB")
        assert marked.size == plain.size == (1280, 720)
        for radio in radios:
            assert _region(marked, radio["box"]) == _region(plain, radio["box"]), radio
        checked = next(r for r in radios if r["checked"])
        unchecked = next(r for r in radios if not r["checked"])
        size = [0, 0, min(checked["box"][2], unchecked["box"][2]), min(checked["box"][3], unchecked["box"][3])]
        assert (_region(marked, checked["box"][:2] + size[2:])
                != _region(marked, unchecked["box"][:2] + size[2:]))
    finally:
        await env.close()


async def test_badges_sit_outside_the_boxes_of_what_they_mark(site_services):
    """On a page of links and form fields (the recipes index) no badge covers any control or link ..."""
    env = await open_env(site_services, "recipes:/", episode_id="ep-marks-index", options={"observation": "vision"})
    try:
        page = env.session.current().page
        badges, info = await _badges(env)
        assert len(badges) > 10
        boxes = await page.evaluate("""() => [...document.querySelectorAll('a, button, input, select')]
          .map((e) => e.getBoundingClientRect()).filter((r) => r.width > 0 && r.bottom > 0 && r.top < innerHeight)
          .map((r) => [r.x, r.y, r.width, r.height])""")
        assert len(boxes) >= len(badges)
        # ... nor any word of the page: the labels above the drop-downs, the links' own text.
        words = await page.evaluate("""() => {
          const rects = [], walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
          const range = document.createRange();
          for (let n = walker.nextNode(); n; n = walker.nextNode()) {
            if (!n.data.trim()) continue;
            range.selectNodeContents(n);
            for (const r of range.getClientRects()) if (r.bottom > 0 && r.top < innerHeight) rects.push([r.x, r.y, r.width, r.height]);
          }
          return rects;
        }""")
        assert any(w[1] < 250 for w in words)  # the filter labels are on screen
        for badge in badges:
            assert _on_screen(badge[1:], info[3], info[4]), badge
            assert not [box for box in boxes if _meet(badge[1:], box)], badge
            assert not [word for word in words if _meet(badge[1:], word)], badge
    finally:
        await env.close()


@pytest.mark.parametrize("mode", ["text", "vision"])
async def test_next_step_shows_the_new_step_on_the_first_screen(site_services, mode):
    env = await open_env(site_services, "recipes:/recipe/r001", episode_id=f"ep-steps-{mode}",
                         options={"observation": mode})
    try:
        [recipe] = [r for r in load_recipes() if r["id"] == "r001"]
        steps = [s["text"] for s in recipe["steps"]]
        first = await env.snapshot(viewport_only=True)
        assert steps[0] not in first.text  # the recipe opens at its top: the step box is further down
        clicked = await env.click("link 'Next step'")
        assert clicked.data["url"].endswith("/recipe/r001?step=2#step") and clicked.data["scroll"]["y"] > 0
        if mode == "vision":
            assert len(clicked.images) == 1
        visible = await env.snapshot(viewport_only=True)
        assert steps[1] in visible.text and "Step 2 of" in visible.text
    finally:
        await env.close()
