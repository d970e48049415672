"""Tool results match what happened: an action that took effect while the page (or the machine) was too busy to
confirm it or be read in time is reported as done, with the page it led to, never as a timeout."""

from __future__ import annotations

from collections.abc import AsyncIterator
from typing import Any

import pytest

from ewa_mcp.core.services import Services
from ewa_mcp.settings import load_settings
from ewa_mcp.envs.browser.operations import input_dispatched
from ewa_mcp.envs.browser.chromium import chromium_service

from .helpers import open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


@pytest.fixture(scope="module")
async def busy_services(fixture_sites: Any, anyio_backend: str) -> AsyncIterator[Services]:
    # Short bounds, so that a page busy for 4 s outlasts every wait of the action and of its settling
    # (as a page does on a loaded machine with the default bounds).
    services = Services(load_settings({"browser": {"action_timeout_s": 1.0, "settle_timeout_s": 1.0,
                                                   "navigation_timeout_s": 20.0}}))
    await services.get("websites", lambda _: fixture_sites)
    await services.get("chromium", chromium_service)
    yield services
    await services.aclose()


@pytest.mark.parametrize("when", [
    "after",  # the click is confirmed, then the page is too busy to be read
    "in",  # the click's own handler keeps the page busy: Playwright gives up waiting for it to confirm
])
async def test_a_click_that_happened_is_reported_as_done_with_the_resulting_page(busy_services, when):
    env = await open_env(busy_services, f"fixture:/busy?ms=4000&when={when}")
    try:
        obs = await env.click("button 'Start work'")  # no EnvError: the click took effect
        assert "StaticText 'Clicked once'" in obs.text, obs.text
        assert obs.data["title"] == "Busy page (clicked)"
        if when == "in":  # the handler's own work outlasts the click's wait: the action must say so
            assert "browser_click was done, but the page was too busy to be read at once" in obs.text
        # "after": the page may be read before its scheduled work starts; either way the click is done and shown
        # (the page may still be spinning: the check waits it out, past the short bounds these services set)
        assert await env.tabs[0].page.text_content("#state", timeout=30_000) == "Clicked once"  # once: no repeat
    finally:
        await env.close()


def test_only_a_sent_input_counts_as_done():
    def log(*lines: str) -> str:
        return "Locator.click: Timeout 1000ms exceeded.\nCall log:\n" + "".join(f"  - {ln}\n" for ln in lines)

    assert input_dispatched(Exception(log("waiting for locator", "attempting click action",
                                          "element is visible, enabled and stable", "performing click action")))
    assert input_dispatched(Exception(log("attempting click action", "performing click action", "click action done",
                                          "waiting for scheduled navigations to finish")))
    assert not input_dispatched(Exception(log("attempting click action", "waiting for element to be visible")))
    assert not input_dispatched(Exception(log("performing click action", "<div> intercepts pointer events",
                                              "retrying click action", "waiting for element to be visible")))
    assert not input_dispatched(Exception("Timeout 1000ms exceeded."))
