"""Warm contexts handed from one episode to the next (ewa_mcp/web/pool.py): reused, and scrubbed."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from ewa_mcp.environment import EnvError
from ewa_mcp.web.pool import ContextPool, WarmContext

from .helpers import crash_tab, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


async def _pool(web_services):
    await _landed(web_services)
    pool = web_services.peek("chromium").pool
    await pool.aclose()  # start from an empty pool whatever earlier tests left idle
    return pool


async def _landed(web_services):
    """Wait until every context handed back (in the background, see session.py) is in the pool."""
    handovers = web_services.peek("web-handovers")
    if handovers is not None:
        await handovers.drain()


async def test_next_episode_gets_the_warm_page_with_nothing_of_the_last(web_services):
    pool = await _pool(web_services)
    a = await open_env(web_services, "fixture:/counter", episode_id="ep-pool-a")
    await a.goto("fixture:/item/1")
    await a.new_tab("fixture:/item/2")
    kept = a.tabs[a.active].page
    await kept.evaluate("document.cookie = 'k=v; path=/'; localStorage.setItem('k', 'l'); "
                        "sessionStorage.setItem('k', 's')")
    await a.close()
    await _landed(web_services)
    assert pool.idle() == 1

    reused = pool.reused
    b = await open_env(web_services, "fixture:/counter", episode_id="ep-pool-b")
    assert pool.reused == reused + 1 and pool.idle() == 0
    assert b.tabs[0].page is kept and b.context.pages == [kept]  # same renderer; a's other tab is gone
    first = await b.observe()
    assert "Episode ep-pool-b visit 1" in first.text  # the header is b's, and b's count starts afresh
    assert [t["site_url"] for t in first.data["tabs"]] == ["fixture:/counter"]
    assert await kept.evaluate("[document.cookie, localStorage.getItem('k'), sessionStorage.getItem('k')]") == [
        "", None, None]
    with pytest.raises(EnvError, match="cannot go back"):
        await b.go_back()  # a's pages are not in the tab's history
    a_history = list(a.history)
    await b.goto("fixture:/item/3")
    assert a.history == a_history  # a no longer hears the page it handed on
    state = await b.final_state()
    assert state["site_history"] == ["fixture:/counter", "fixture:/item/3"]
    await b.new_tab("fixture:/item/4")
    await b.tab_focus(0)
    await b.close_tab()  # closes the warm page itself: the page to hand on is now the other tab's
    await b.close()
    await _landed(web_services)
    assert pool.idle() == 1 and b.context is None and not b.tabs
    c = await open_env(web_services, "fixture:/item/5", episode_id="ep-pool-b2")
    assert pool.reused == reused + 2 and [t["site_url"] for t in (await c.observe()).data["tabs"]] == ["fixture:/item/5"]
    await c.close()


async def test_blocked_requests_are_refused_by_the_new_episode_only(web_services):
    await _pool(web_services)
    a = await open_env(web_services, "fixture:/", episode_id="ep-pool-c")
    await a.close()
    b = await open_env(web_services, "fixture:/", episode_id="ep-pool-d")
    offsite = await b.goto("fixture:/offsite")
    assert "a request to http://example.com/tracker.png was blocked" in offsite.text
    # One route, b's: a's request guard was removed with its listeners.
    assert "http://example.com/tracker.png" in b.blocked and not a.blocked
    await b.close()


async def test_a_context_whose_page_crashed_is_not_handed_on(web_services):
    pool = await _pool(web_services)
    env = await open_env(web_services, "fixture:/item/3", episode_id="ep-pool-e")
    tab = env.tabs[0]
    await crash_tab(env, tab)
    await env.close()
    assert pool.idle() == 0
    reused = pool.reused
    fresh = await open_env(web_services, "fixture:/item/1", episode_id="ep-pool-f")
    assert pool.reused == reused and not fresh.tabs[0].page.is_closed()
    await fresh.close()


def _warm(launch: int = 1, key: tuple[int, int] = (1280, 720), closed: bool = False) -> WarmContext:
    page = SimpleNamespace(is_closed=lambda: closed, on=lambda *_: None)
    warm = WarmContext(context=SimpleNamespace(), launch=launch, key=key)
    warm.page = page
    return warm


async def test_pool_hands_on_only_contexts_of_this_launch_and_settings():
    pool = ContextPool()
    closed: list[WarmContext] = []

    async def close(warm: WarmContext) -> None:
        closed.append(warm)

    pool._close = close  # nothing real to close here
    stale = [_warm(launch=0), _warm(key=(800, 600)), _warm(closed=True)]
    pool._idle += stale
    assert await pool.take((1280, 720), launch=1) is None and pool.idle() == 0
    assert sorted(map(id, closed)) == sorted(map(id, stale))  # let go of, not leaked
    good, broken = _warm(), _warm()
    broken.broken = True
    pool._idle += [good, broken]
    assert await pool.take((1280, 720), launch=1) is good and good.uses == 1
