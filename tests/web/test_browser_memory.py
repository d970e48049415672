"""Memory upkeep of open episodes: garbage collection in quiet renderers (ewa_mcp/web/idlegc.py)."""

from __future__ import annotations

import asyncio

import pytest
from pydantic import ValidationError

from ewa_mcp.web.config import BrowserConfig
from ewa_mcp.web.idlegc import IdleCollector

from .helpers import open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]

# Builds ~16 MB of arrays and drops them: garbage that nothing on an idle page would collect.
MAKE_GARBAGE = "() => { let a = []; for (let i = 0; i < 400; i++) a.push(new Array(5000).fill(i)); return a.length; }"


async def heap_used(env, session=None) -> float:
    session = session or await env.context.new_cdp_session(env.tabs[0].page)
    return float((await session.send("Runtime.getHeapUsage"))["usedSize"])


async def test_a_quiet_page_is_collected_once_and_a_busy_one_is_left_alone(web_services):
    service = web_services.peek("chromium")
    browser = await service.browser()
    await service.collector.stop()  # the service's own sweeper would move the heap between the sweeps below
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
        service.collector.start(service.current_browser)


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


def test_memory_settings_are_checked():
    assert BrowserConfig().pool_keep_idle == 2 and BrowserConfig().pool_idle_s == 30 and BrowserConfig().idle_gc_s == 10
    with pytest.raises(ValidationError, match="pool_keep_idle"):
        BrowserConfig(pool_keep_idle=9)
    with pytest.raises(ValidationError, match="pool_idle_s"):
        BrowserConfig(pool_idle_s=0)
    with pytest.raises(ValueError, match="every_s must be a number of seconds"):
        IdleCollector(every_s=-1)
