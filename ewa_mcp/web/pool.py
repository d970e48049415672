"""Warm browser contexts, scrubbed and handed from one episode to the next.

Why: a new BrowserContext gets a new renderer process whose JavaScript engine starts cold. On
the 2-core reference machine an episode's first page load plus snapshot costs ~650 ms in a
fresh context and ~200 ms in a renderer that has served pages before (docs/performance.md,
benchmarks/bench_browser.py). So when an episode ends cleanly its context is scrubbed and kept
for the next episode instead of being closed.

What the scrub resets: extra tabs (closed), the episode header (removed before anything else,
so a late request of the old page is anonymous, never the next episode's), the document
(about:blank), the tab's history, cookies, and storage of every origin the browser may reach.
What does cross the boundary: Chromium's HTTP cache (the sites' pages carry no validators, so
they are fetched again; their images are the same for every episode). Visited-link colours do
not: Playwright's contexts keep no browsing history, so a followed link still draws unvisited
(checked by screenshot, with both the headless shell and the full chromium, when this was built).
A context that cannot be scrubbed, or has served ``max_uses`` episodes, is closed instead.

Garbage: a renderer that only navigates lets its heap grow (to ~1 GB after a hundred episodes
here) and slows down with it, ~1.7x over 150 episodes; a full collection every ``gc_every``
hand-overs keeps it flat. ``max_uses`` also bounds what Playwright keeps per page (one object
per request, released only when the page closes).
"""

from __future__ import annotations

import asyncio
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

SCRUB_TIMEOUT_S = 5.0


@dataclass(eq=False)
class WarmContext:
    """A context made for episodes (init script installed) and the page kept with it."""

    context: Any
    launch: int  # BrowserService.launches when it was made: a relaunch makes it useless
    key: tuple[Any, ...]  # the settings it was made with (viewport); reused only for the same
    page: Any = None
    cdp: Any = None
    uses: int = 0
    broken: bool = False  # its page crashed or closed (with the context, or the browser)

    def watch(self, page: Any) -> None:
        """Keep ``page`` as the tab to hand on, and hear if it dies while idle."""
        if page is self.page:
            return
        if self.page is not None:  # the scrub closes the page kept before: that is no breakage
            self.page.remove_listener("crash", self._broke)
            self.page.remove_listener("close", self._broke)
        self.page, self.cdp, self.broken = page, None, False  # what happened to the old page no longer matters
        page.on("crash", self._broke)
        page.on("close", self._broke)

    def _broke(self, *_: Any) -> None:
        self.broken = True


class ContextPool:
    def __init__(self, max_idle: int = 8, max_uses: int = 50, gc_every: int = 10):
        self.max_idle = max_idle
        self.max_uses = max_uses
        self.gc_every = gc_every
        self._idle: list[WarmContext] = []
        self.reused = 0  # contexts handed on (read by benchmarks and tests)
        self.closed = 0  # contexts closed instead of kept

    def idle(self) -> int:
        return len(self._idle)

    async def take(self, key: tuple[Any, ...], launch: int) -> WarmContext | None:
        """An idle context made for this browser launch and these settings, or None."""
        while self._idle:
            warm = self._idle.pop()
            if warm.launch == launch and warm.key == key and not warm.broken and not warm.page.is_closed():
                warm.uses += 1
                self.reused += 1
                return warm
            await self._close(warm)  # made for another browser launch or other settings
        return None

    async def give_back(self, warm: WarmContext, origins: Iterable[str]) -> bool:
        """Scrub ``warm`` and keep it for the next episode; close it when that is not possible.

        The caller has already removed its own listeners and routes."""
        if (warm.broken or warm.page is None or warm.page.is_closed() or warm.uses + 1 >= self.max_uses
                or len(self._idle) >= self.max_idle):
            await self._close(warm)
            return False
        try:
            await asyncio.wait_for(self._scrub(warm, sorted(set(origins))), SCRUB_TIMEOUT_S)
        except Exception:
            await self._close(warm)
            return False
        if warm.broken:
            await self._close(warm)
            return False
        self._idle.append(warm)
        return True

    async def _scrub(self, warm: WarmContext, origins: list[str]) -> None:
        context, page = warm.context, warm.page
        await context.set_extra_http_headers({})
        for other in list(context.pages):
            if other is not page:
                await other.close()
        await page.goto("about:blank")
        if warm.cdp is None:
            warm.cdp = await context.new_cdp_session(page)
        await warm.cdp.send("Page.resetNavigationHistory")
        await context.clear_cookies()
        for origin in origins:
            # "all" covers local and session storage, IndexedDB, cache storage and service workers.
            await warm.cdp.send("Storage.clearDataForOrigin", {"origin": origin, "storageTypes": "all"})
        if self.gc_every and (warm.uses + 1) % self.gc_every == 0:
            await warm.cdp.send("HeapProfiler.collectGarbage")

    async def _close(self, warm: WarmContext) -> None:
        self.closed += 1
        try:
            await warm.context.close()
        except Exception:
            pass  # the browser is already gone

    async def aclose(self) -> None:
        idle, self._idle = self._idle, []
        for warm in idle:
            await self._close(warm)
