"""The web step's cost, pinned by counting rather than timing: snapshots per action (counted on the
real browser) and the hand-over of a finished episode's context in the background."""

from __future__ import annotations

import pytest
from playwright.async_api import Page

from ewa_mcp.core.environment import EnvError

from .helpers import element_id, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


@pytest.fixture
def snapshots(monkeypatch):
    """Counts Playwright's ARIA snapshots (each still taken by the real browser)."""
    calls: list[str] = []
    original = Page.aria_snapshot

    async def counted(self, *args, **kwargs):
        calls.append(self.url)
        return await original(self, *args, **kwargs)

    monkeypatch.setattr(Page, "aria_snapshot", counted)
    return calls


async def test_a_click_takes_one_snapshot_whatever_the_reference(web_services, snapshots):
    env = await open_env(web_services, "fixture:/", episode_id="ep-snap-a")
    try:
        await env.goto("fixture:/")  # an action: its observation's snapshot records the page's DOM-change count
        snapshots.clear()
        done = await env.click("button 'Mark done'")  # role+name: resolved on the observation's snapshot
        assert "button 'Done'" in done.text and len(snapshots) == 1
        snapshots.clear()
        soup = await env.click("link 'Lentil Soup'")  # a click that loads a page
        assert soup.data["site_url"] == "fixture:/item/2" and len(snapshots) == 1
        await env.go_back()
        again = await env.snapshot()
        snapshots.clear()
        await env.click(str(element_id(again, "link", "Apple Crumble")))  # an id: the same
        assert len(snapshots) == 1
        await env.go_back()
        seen = await env.observe()  # a plain observation records no count: the next action snapshots
        snapshots.clear()
        await env.click("button 'Mark done'")
        assert len(snapshots) == 2 and "button 'Mark done'" in seen.text
    finally:
        await env.close()


async def test_a_click_whose_page_has_work_in_flight_takes_one_snapshot_after_it(web_services, snapshots):
    env = await open_env(web_services, "fixture:/", episode_id="ep-snap-c")
    try:
        await env.goto("fixture:/")
        snapshots.clear()
        # The button's fetch answers after 50 ms: the one snapshot is taken once the page says it is done.
        counted = await env.click("button 'Count click'")
        assert "Clicked 1 times" in counted.text and len(snapshots) == 1
    finally:
        await env.close()


async def test_what_the_page_changed_since_the_observation_is_seen_by_the_next_action(web_services, snapshots):
    env = await open_env(web_services, "fixture:/", episode_id="ep-snap-b")
    try:
        seen = await env.observe()
        mark_done = element_id(seen, "button", "Mark done")
        # The page adds an element after the observation: a role+name reference finds it.
        await env.tabs[0].page.evaluate("""() => { const b = document.createElement('button');
            b.textContent = 'Added later'; b.onclick = () => { b.textContent = 'Added and clicked'; };
            document.body.append(b); }""")
        snapshots.clear()
        clicked = await env.click("button 'Added later'")
        assert "button 'Added and clicked'" in clicked.text
        assert len(snapshots) == 2  # one to resolve the reference on the changed page, one to observe
        # The page disables a button after the observation: the action sees it (an attribute change).
        await env.tabs[0].page.evaluate("document.querySelector('#ping').disabled = true")
        with pytest.raises(EnvError, match="is disabled"):
            await env.click("button 'Count click'")
        # The page removes an element after the observation: its id is refused, not acted on.
        await env.tabs[0].page.evaluate(
            "[...document.querySelectorAll('button')].find((b) => b.textContent === 'Mark done').remove()")
        with pytest.raises(EnvError, match="no longer on the page"):
            await env.click(str(mark_done))
    finally:
        await env.close()


async def test_finish_returns_before_the_scrub_and_the_next_episode_gets_a_clean_context(web_services):
    handovers = web_services.peek("web-handovers")
    if handovers is not None:
        await handovers.drain()
    pool = web_services.peek("chromium").pool
    await pool.aclose()  # start from an empty pool whatever earlier tests left idle
    a = await open_env(web_services, "fixture:/counter", episode_id="ep-bg-a")
    kept = a.tabs[0].page
    await kept.evaluate("document.cookie = 'k=v; path=/'; localStorage.setItem('k', 'l')")
    await a.close()
    handover = a.session.handover
    # close() has let go of the context without waiting for its scrub.
    assert handover is not None and not handover.done() and pool.idle() == 0
    reused = pool.reused
    b = await open_env(web_services, "fixture:/counter", episode_id="ep-bg-b")
    try:
        # b found the pool empty and waited for a's context instead of making a cold one.
        assert handover.done() and pool.reused == reused + 1 and b.tabs[0].page is kept
        assert await kept.evaluate("[document.cookie, localStorage.getItem('k')]") == ["", None]
        seen = await b.observe()
        assert "Episode ep-bg-b visit 1" in seen.text
        assert [b.session.site_url(u) for u in b.history] == ["fixture:/counter"]
        with pytest.raises(EnvError, match="cannot go back"):
            await b.go_back()
    finally:
        await b.close()
