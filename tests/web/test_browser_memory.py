"""Memory upkeep of open episodes: garbage collection in quiet renderers (ewa_mcp/envs/browser/idlegc.py)."""

from __future__ import annotations

import asyncio

import pytest
from pydantic import ValidationError

from ewa_mcp.settings import BrowserConfig
from ewa_mcp.envs.browser.idlegc import IdleCollector

from .helpers import crash_tab, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]

# Builds ~16 MB of arrays and drops them: garbage that nothing on an idle page would collect.
MAKE_GARBAGE = "() => { let a = []; for (let i = 0; i < 400; i++) a.push(new Array(5000).fill(i)); return a.length; }"


@pytest.fixture
async def quiet_service(web_services):
    """The browser service with its own sweeper stopped: it would move the heaps between a test's sweeps."""
    service = web_services.peek("chromium")
    await service.browser()
    await service.collector.stop()
    yield service
    service.collector.start(service.current_browser)


async def heap_used(env, session=None) -> float:
    session = session or await env.context.new_cdp_session(env.tabs[0].page)
    return float((await session.send("Runtime.getHeapUsage"))["usedSize"])


async def test_a_quiet_page_is_collected_once_and_a_busy_one_is_left_alone(web_services, quiet_service):
    browser = await quiet_service.browser()
    collector = IdleCollector(every_s=0)  # swept by hand here: no timer
    env = await open_env(web_services, "fixture:/", episode_id="ep-gc-a")
    try:
        page = env.tabs[0].page
        session = await env.context.new_cdp_session(page)
        await page.evaluate(MAKE_GARBAGE)
        with_garbage = await heap_used(env, session)
        await collector.sweep(browser)  # first sight of the page: nothing known to compare with
        assert collector._pages[page].collected_at is None
        await collector.sweep(browser)  # unchanged since the last sweep: quiet, so collected
        collected = collector._pages[page].collected_at
        assert collected is not None and collected < with_garbage - 4 * 2**20
        assert await heap_used(env, session) < with_garbage - 4 * 2**20  # the renderer really let go of it
        runs = collector.collections
        await collector.sweep(browser)
        assert collector.collections == runs  # still quiet, already collected: not collected again
        await page.evaluate(MAKE_GARBAGE)  # the page works again...
        await page.evaluate("() => { window.kept = new Array(200000).fill(1); }")
        await collector.sweep(browser)
        assert collector._pages[page].collected_at == collected  # ...busy since the last sweep: left alone
        await collector.sweep(browser)
        assert collector._pages[page].collected_at != collected  # quiet again: collected again
        assert await page.evaluate("() => window.kept.length") == 200000  # live objects are kept, of course
    finally:
        await env.close()
        await collector.stop()


async def test_the_service_collects_quiet_pages_by_itself(web_services):
    service = web_services.peek("chromium")
    collector = IdleCollector(every_s=0.05)  # a short period on the real clock
    env = await open_env(web_services, "fixture:/", episode_id="ep-gc-b")
    try:
        collector.start(service.current_browser)
        for _ in range(400):  # bounded wait for the sweeper's timer; nothing is asserted on time
            if env.tabs[0].page in collector._pages and collector._pages[env.tabs[0].page].collected_at is not None:
                break
            await asyncio.sleep(0.025)
        assert collector._pages[env.tabs[0].page].collected_at is not None
        assert "Catalogue" in (await env.observe()).text  # the page still works after being collected
    finally:
        await collector.stop()
        await env.close()
    assert collector._task is None and not collector._pages


async def test_a_crashed_page_does_not_stop_the_sweep(web_services, quiet_service):
    browser = await quiet_service.browser()
    collector = IdleCollector(every_s=0)
    crashed = await open_env(web_services, "fixture:/item/1", episode_id="ep-gc-crash")
    fine = await open_env(web_services, "fixture:/item/2", episode_id="ep-gc-fine")
    try:
        await collector.sweep(browser)
        await crash_tab(crashed, crashed.tabs[0])
        await collector.sweep(browser)  # the crashed page's calls fail; the other page is still swept
        assert collector._pages[fine.tabs[0].page].collected_at is not None
        assert crashed.tabs[0].page not in collector._pages
    finally:
        await crashed.close()
        await fine.close()
        await collector.stop()


def test_memory_settings_are_checked():
    assert BrowserConfig().pool_keep_idle == 2 and BrowserConfig().pool_idle_s == 30 and BrowserConfig().idle_gc_s == 10
    with pytest.raises(ValidationError, match="pool_keep_idle"):
        BrowserConfig(pool_keep_idle=9)
    with pytest.raises(ValidationError, match="pool_idle_s"):
        BrowserConfig(pool_idle_s=0)
    with pytest.raises(ValueError, match="every_s must be a number of seconds"):
        IdleCollector(every_s=-1)
