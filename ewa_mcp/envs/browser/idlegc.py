"""Garbage collection in the renderers of pages that have gone quiet.

Why: an episode's renderer is most of what an open web episode costs in memory, and after a few
page loads and accessibility snapshots about a quarter of it is garbage that V8 frees late or not
at all: an idle page allocates nothing more, so nothing triggers a collection (V8's memory reducer
frees part of it after a while, not always), and headless Chromium sends its renderers no
memory-pressure signal (``Memory.simulatePressureNotification`` changes nothing here). A full
collection of V8's and Blink's heaps (``HeapProfiler.collectGarbage``) took renderers that had
loaded three recipe pages from ~40 to ~31 MB PSS (docs/performance.md, benchmarks/bench_memory.py).

How: every ``every_s`` seconds the sweeper reads each page's JavaScript heap
(``Runtime.getHeapUsage``, which allocates nothing on the page). A page whose heap has not
changed by more than ``quiet_bytes`` since the last sweep has been idle for a whole period;
it gets one full collection, and none again until its heap moves. A page in use is never
collected in the middle of its work, and an idle page costs one cheap call per period.
"""

from __future__ import annotations

import asyncio
import contextlib
import weakref
from collections.abc import Callable
from typing import Any

EVERY_S = 10.0
QUIET_BYTES = 64 * 1024  # a heap that moved less than this between two sweeps is idle
PAGE_TIMEOUT_S = 2.0  # a page whose main thread is busy this long is skipped, not waited for


class _PageRecord:
    __slots__ = ("session", "last_used", "collected_at")

    def __init__(self, session: Any) -> None:
        self.session = session
        self.last_used: float | None = None  # heap bytes in use at the last sweep
        self.collected_at: float | None = None  # heap bytes in use right after our last collection


class IdleCollector:
    """The sweeper of one browser (started and stopped by BrowserService)."""

    def __init__(self, every_s: float = EVERY_S, quiet_bytes: int = QUIET_BYTES):
        if not every_s >= 0:
            raise ValueError(f"every_s must be a number of seconds (0: never collect), got {every_s!r}")
        self.every_s = every_s
        self.quiet_bytes = quiet_bytes
        self._pages: weakref.WeakKeyDictionary[Any, _PageRecord] = weakref.WeakKeyDictionary()
        self._task: asyncio.Task[None] | None = None
        self.collections = 0  # full collections run (read by benchmarks and tests)
        self.sweeps = 0

    def start(self, browser_source: Callable[[], Any | None]) -> None:
        """Sweep every ``every_s`` the pages of ``browser_source()`` (None: no browser up) until stop()."""
        if self.every_s and (self._task is None or self._task.done()):
            self._task = asyncio.get_running_loop().create_task(self._run(browser_source), name="idle-gc")

    async def _run(self, browser_source: Callable[[], Any | None]) -> None:
        while True:
            await asyncio.sleep(self.every_s)
            browser = browser_source()
            if browser is None:
                continue  # crashed or closed: the next episode call relaunches it, not this sweeper
            try:
                await self.sweep(browser)
            except Exception:
                pass  # the browser went away during the sweep

    async def sweep(self, browser: Any) -> int:
        """One pass over every page of ``browser``; returns how many pages were collected."""
        self.sweeps += 1
        collected = 0
        for context in list(browser.contexts):
            for page in list(context.pages):
                if page.is_closed():
                    continue
                try:
                    collected += await asyncio.wait_for(self._visit(context, page), PAGE_TIMEOUT_S)
                except Exception:  # closed, crashed or busy: a new session next time
                    record = self._pages.pop(page, None)
                    if record is not None:
                        with contextlib.suppress(Exception):
                            await asyncio.wait_for(record.session.detach(), PAGE_TIMEOUT_S)
        return collected

    async def _visit(self, context: Any, page: Any) -> int:
        record = self._pages.get(page)
        if record is None:
            record = self._pages[page] = _PageRecord(await context.new_cdp_session(page))
        used = float((await record.session.send("Runtime.getHeapUsage"))["usedSize"])
        quiet = record.last_used is not None and abs(used - record.last_used) <= self.quiet_bytes
        record.last_used = used
        if not quiet or (record.collected_at is not None and abs(used - record.collected_at) <= self.quiet_bytes):
            return 0  # in use, or already collected in this state
        await record.session.send("HeapProfiler.collectGarbage")
        after = float((await record.session.send("Runtime.getHeapUsage"))["usedSize"])
        record.last_used = record.collected_at = after
        self.collections += 1
        return 1

    async def stop(self) -> None:
        task, self._task = self._task, None
        if task is not None and not task.done():
            task.cancel()
            try:
                await task
            except (asyncio.CancelledError, Exception):
                pass
        self._pages = weakref.WeakKeyDictionary()
