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

Shrinking: every idle context keeps a renderer process resident (~30 MB PSS). After a burst of
episodes the pool would hold ``max_idle`` of them for good, so a context idle for ``idle_s``
seconds is closed, the longest-idle first, until ``keep_idle`` remain. A timer task of the pool
does it (started when a context goes idle, ended by ``aclose``); ``shrink()`` is the same step,
callable with an injected clock (tests, benchmarks).
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

SCRUB_TIMEOUT_S = 5.0
# After a burst, the pool falls back to this many warm contexts once they have been idle this long.
KEEP_IDLE = 2
IDLE_S = 30.0


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
    idle_since: float = 0.0  # the pool's clock when it was last handed back

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
    def __init__(self, max_idle: int = 8, max_uses: int = 50, gc_every: int = 10, keep_idle: int = KEEP_IDLE,
                 idle_s: float = IDLE_S, clock: Callable[[], float] = time.monotonic):
        if not 0 <= keep_idle <= max_idle:
            raise ValueError(f"keep_idle must be between 0 and max_idle ({max_idle}), got {keep_idle!r}")
        if not idle_s > 0:
            raise ValueError(f"idle_s must be a positive number of seconds, got {idle_s!r}")
        self.max_idle = max_idle
        self.max_uses = max_uses
        self.gc_every = gc_every
        self.keep_idle = keep_idle
        self.idle_s = idle_s
        self.clock = clock
        self._idle: list[WarmContext] = []  # the longest idle first: take() hands on the most recent
        self._scrubbing = 0  # hand-overs under way: they count against max_idle already
        self._reaper: asyncio.Task[None] | None = None
        self._wake = asyncio.Event()  # tells the reaper that the pool changed (made lazily, see _ensure_reaper)
        self.shrinks = 0  # times shrink() closed something (read by benchmarks and tests)
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

        The caller has already removed its own listeners."""
        if (warm.broken or warm.page is None or warm.page.is_closed() or warm.uses + 1 >= self.max_uses
                or len(self._idle) + self._scrubbing >= self.max_idle):
            await self._close(warm)
            return False
        self._scrubbing += 1  # concurrent hand-overs must not overfill the pool while they scrub
        try:
            await asyncio.wait_for(self._scrub(warm, sorted(set(origins))), SCRUB_TIMEOUT_S)
        except Exception:
            await self._close(warm)
            return False
        finally:
            self._scrubbing -= 1
        if warm.broken:
            await self._close(warm)
            return False
        warm.idle_since = self.clock()
        self._idle.append(warm)
        self._ensure_reaper()
        return True

    async def shrink(self) -> int:
        """Close the contexts idle for ``idle_s`` or longer, the longest idle first, leaving at least
        ``keep_idle``; returns how many were closed."""
        now = self.clock()
        stale: list[WarmContext] = []
        while len(self._idle) > self.keep_idle and self._idle[0].idle_since + self.idle_s <= now:
            stale.append(self._idle.pop(0))
        for warm in stale:
            await self._close(warm)
        if stale:
            self.shrinks += 1
        return len(stale)

    def next_shrink_in(self) -> float | None:
        """Seconds until shrink() would close something, or None while nothing is to be closed."""
        if len(self._idle) <= self.keep_idle:
            return None
        return max(0.0, self._idle[0].idle_since + self.idle_s - self.clock())

    def _ensure_reaper(self) -> None:
        """Start the timer task that calls shrink(), or wake it to look at the pool again."""
        if self._reaper is None or self._reaper.done():
            self._wake = asyncio.Event()  # bound to the running loop (a pool may be made outside one)
            self._reaper = asyncio.get_running_loop().create_task(self._reap(), name="context-pool-shrink")
        else:
            self._wake.set()

    async def _reap(self) -> None:
        while True:
            wait = self.next_shrink_in()
            if wait is None:
                return  # started again by the next context that goes idle beyond keep_idle
            self._wake.clear()
            try:
                await asyncio.wait_for(self._wake.wait(), wait)
            except asyncio.TimeoutError:
                pass
            try:
                await self.shrink()
            except Exception:
                pass  # closing is best effort (_close already ignores a browser that is gone)

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
        reaper, self._reaper = self._reaper, None
        if reaper is not None and not reaper.done():
            reaper.cancel()
            try:
                await reaper
            except (asyncio.CancelledError, Exception):
                pass
        idle, self._idle = self._idle, []
        for warm in idle:
            await self._close(warm)
