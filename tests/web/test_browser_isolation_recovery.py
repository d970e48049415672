"""Episode isolation (two concurrent episodes) and recovery from a killed browser or crashed tab."""

from __future__ import annotations

import asyncio
import os
import re
import signal

import pytest

from ewa_mcp.core.environment import EnvError

from .helpers import crash_tab, element_id, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


async def test_two_concurrent_episodes_do_not_share_state(web_services, fixture_sites):
    a, b = await asyncio.gather(open_env(web_services, "fixture:/counter", episode_id="ep-iso-a"),
                                open_env(web_services, "fixture:/counter", episode_id="ep-iso-b"))

    async def visit(env, times):
        last = None
        for _ in range(times):
            last = await env.goto("fixture:/counter")
        return last

    last_a, last_b = await asyncio.gather(visit(a, 3), visit(b, 2))
    # Each site request carried its own episode's header, so each counter counts one episode.
    assert "Episode ep-iso-a visit 4" in last_a.text
    assert "Episode ep-iso-b visit 3" in last_b.text
    # Browser state (cookies, storage) is per episode too.
    await a.tabs[0].page.evaluate("document.cookie = 'cart=tomato; path=/'; localStorage.setItem('k', 'a')")
    assert await b.tabs[0].page.evaluate("document.cookie") == ""
    assert await b.tabs[0].page.evaluate("localStorage.getItem('k')") is None
    # Element ids of one episode mean nothing in the other.
    link_a = element_id(await a.goto("fixture:/"), "link", "Tomato Bruschetta")
    await b.goto("fixture:/item/1")
    with pytest.raises(EnvError):
        await b.click(str(link_a))
    assert (await b.observe()).data["site_url"] == "fixture:/item/1"
    await asyncio.gather(a.close(), b.close())


async def test_killed_browser_is_relaunched_with_tabs_restored(web_services):
    env = await open_env(web_services, "fixture:/item/2")
    await env.new_tab("fixture:/item/4")
    before = await env.tab_focus(0)
    old_id = element_id(before, "link", "Next item")
    service = web_services.peek("chromium")
    launches = service.launches
    pid = await service.browser_pid()
    assert pid is not None
    os.kill(pid, signal.SIGKILL)
    for _ in range(500):  # wait (bounded) until Playwright has noticed the browser is gone
        if not service.is_alive():
            break
        await asyncio.sleep(0.01)
    assert not service.is_alive()

    restored = await env.observe()  # the next call relaunches and restores
    assert service.launches == launches + 1
    assert [t["site_url"] for t in restored.data["tabs"]] == ["fixture:/item/2", "fixture:/item/4"]
    assert restored.data["active_tab"] == 0 and restored.data["title"] == "Lentil Soup"
    assert any("restarted" in n for n in restored.data["notices"])
    with pytest.raises(EnvError, match="no longer open"):
        await env.click(str(old_id))  # ids of the dead browser's pages never act on the new ones
    moved = await env.click("link 'Next item'")
    assert moved.data["site_url"] == "fixture:/item/3"
    state = await env.final_state()
    assert state["restarts"] == 1 and state["site_history"][-1] == "fixture:/item/3"
    # Restoring tabs is not browsing: the history has no duplicate entries from it.
    assert state["site_history"] == ["fixture:/item/2", "fixture:/item/4", "fixture:/item/3"]
    await env.close()


async def test_closed_browser_is_relaunched_on_next_action(web_services):
    env = await open_env(web_services, "fixture:/item/1")
    service = web_services.peek("chromium")
    await (await service.browser()).close()
    obs = await env.goto("fixture:/item/5")
    assert obs.data["site_url"] == "fixture:/item/5" and obs.data["tabs"][0]["site_url"] == "fixture:/item/5"
    await env.close()


async def test_crashed_tab_is_reloaded(web_services):
    env = await open_env(web_services, "fixture:/item/3")
    tab = env.tabs[0]
    await crash_tab(env, tab)
    assert tab.crashed
    obs = await env.observe()
    assert obs.data["site_url"] == "fixture:/item/3" and obs.data["title"] == "Apple Crumble"
    assert any(re.search(r"tab \[0\] had crashed", n) for n in obs.data["notices"])
    await env.close()
