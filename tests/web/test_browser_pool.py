"""Warm contexts handed from one episode to the next (ewa_mcp/envs/browser/pool.py): reused, and scrubbed."""

from __future__ import annotations

import asyncio
import time
from types import SimpleNamespace

import pytest

from ewa_mcp.core.environment import EnvError
from ewa_mcp.envs.browser.pool import IDLE_S, KEEP_IDLE, ContextPool, WarmContext

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


class FakeClock:
    """The pool's clock, moved by the test: no waiting for idle periods."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


async def _open_and_close(web_services, n: int, prefix: str) -> None:
    envs = [await open_env(web_services, f"fixture:/item/{i + 1}", episode_id=f"{prefix}-{i}") for i in range(n)]
    for env in envs:
        await env.close()
    await _landed(web_services)  # hand-backs run in the background: wait until the contexts are in the pool


async def test_idle_contexts_beyond_keep_idle_are_closed_after_the_idle_period(web_services):
    pool = await _pool(web_services)
    browser = await web_services.peek("chromium").browser()
    clock = FakeClock()
    pool.clock, pool.keep_idle, pool.idle_s = clock, 2, 30.0
    await _open_and_close(web_services, 4, "ep-shrink")  # a burst: four warm contexts stay behind
    assert pool.idle() == 4
    contexts = len(browser.contexts)
    newest = list(pool._idle[-2:])
    clock.now += 29.0
    assert await pool.shrink() == 0 and pool.idle() == 4  # not idle long enough yet
    assert pool.next_shrink_in() == pytest.approx(1.0)
    clock.now += 1.0
    assert await pool.shrink() == 2 and pool.idle() == 2
    assert pool._idle == newest  # the longest idle went first
    assert len(browser.contexts) == contexts - 2  # really closed in the browser: their renderers are gone
    clock.now += 1000.0
    assert await pool.shrink() == 0 and pool.idle() == 2  # keep_idle stay however long the pool idles
    assert pool.next_shrink_in() is None
    # The kept contexts still serve episodes.
    reused = pool.reused
    env = await open_env(web_services, "fixture:/item/9", episode_id="ep-shrink-after")
    assert pool.reused == reused + 1 and "fixture:/item/9" in (await env.observe()).text
    await env.close()
    pool.clock, pool.idle_s = time.monotonic, IDLE_S


async def test_the_pool_shrinks_by_itself_when_left_idle(web_services):
    pool = await _pool(web_services)
    pool.keep_idle, pool.idle_s = 1, 0.2  # a short idle period, on the real clock
    try:
        await _open_and_close(web_services, 3, "ep-reap")
        for _ in range(500):  # bounded wait for the pool's own timer; nothing here is asserted on time
            if pool.idle() <= 1:
                break
            await asyncio.sleep(0.02)
        assert pool.idle() == 1 and pool.shrinks >= 1
    finally:
        pool.keep_idle, pool.idle_s = KEEP_IDLE, IDLE_S


async def test_concurrent_hand_overs_never_overfill_the_pool(web_services):
    pool = await _pool(web_services)
    pool.max_idle = 2
    try:
        envs = [await open_env(web_services, "fixture:/", episode_id=f"ep-fill-{i}") for i in range(4)]
        await asyncio.gather(*(env.close() for env in envs))  # all scrubbing at the same time
        await _landed(web_services)
        assert pool.idle() == 2
    finally:
        pool.max_idle = 8


def test_pool_settings_are_checked():
    with pytest.raises(ValueError, match="keep_idle must be between 0 and max_idle"):
        ContextPool(max_idle=2, keep_idle=3)
    with pytest.raises(ValueError, match="idle_s must be a positive"):
        ContextPool(idle_s=0)
