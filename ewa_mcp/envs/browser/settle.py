"""Waiting for a page to settle after an action, without fixed sleeps.

Two sources of truth, each bounded by what is left of one deadline:

* Navigations, from Playwright's events (``PageActivity``): a main-frame navigation the action
  started must commit and reach the ``load`` state.
* The page's own work, from hooks installed in every document before its scripts run
  (``PAGE_HOOKS_JS``): fetch/XHR calls (until their bodies are read) started since the last
  action. ``idle()`` resolves once they are done and the callbacks that follow them have run,
  so the snapshot shows what their results changed. Counting inside the page avoids a race:
  with request interception on, Playwright may report a request only after the click that
  started it has returned.

The hooks also count the popups a document asks for (window.open, links and forms with a
target), so that the environment can wait for exactly that many new tabs, and the changes made to
the DOM (a MutationObserver), so that an action can tell whether the latest snapshot still shows
the page and skip taking another.
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Awaitable, Callable
from typing import Any

PAGE_HOOKS_JS = """(() => {
  if (window.__ewa) return;
  let epoch = 0, pending = 0, popups = 0;
  const waiters = [];
  const start = () => { pending++; return epoch; };
  const done = (started) => {
    if (started !== epoch) return;  // begun before the last idle(): not this action's work
    pending = Math.max(0, pending - 1);
    if (!pending) waiters.splice(0).forEach((wake) => wake());
  };
  const track = (promise) => { const e = start(); promise.then(() => done(e), () => done(e)); return promise; };
  if (window.fetch) {
    const fetch = window.fetch;
    window.fetch = function (...args) { return track(fetch.apply(this, args)); };
    for (const name of ['json', 'text', 'blob', 'arrayBuffer', 'formData']) {
      const read = Response.prototype[name];
      if (read) Response.prototype[name] = function (...args) { return track(read.apply(this, args)); };
    }
  }
  const send = XMLHttpRequest.prototype.send;
  XMLHttpRequest.prototype.send = function (...args) {
    const e = start();
    this.addEventListener('loadend', () => done(e), {once: true});
    return send.apply(this, args);
  };
  const note = () => { popups++; };
  const open = window.open;
  window.open = function (...args) { note(); return open.apply(this, args); };
  const opensWindow = (t) => !!t && !['_self', '_top', '_parent'].includes(t.toLowerCase());
  document.addEventListener('click', (e) => {
    const a = e.target instanceof Element ? e.target.closest('a[href], area[href]') : null;
    if (a && (opensWindow(a.target) || e.ctrlKey || e.metaKey || e.shiftKey || e.button === 1)) note();
  }, true);
  document.addEventListener('submit', (e) => { if (opensWindow(e.target.target)) note(); }, true);
  // Every change to the DOM (shadow roots included) bumps a counter: a snapshot taken after the
  // counter was read is still the page as it is while the counter reads the same (see changes()).
  // Counting starts at the load event (observing the parser build a large page costs tens of ms);
  // until then changes() answers null: unknown, so every snapshot is taken afresh.
  const token = Math.random().toString(36).slice(2);  // counts of two documents never compare equal
  let changes = 0, watching = false;
  const early = [];  // shadow roots attached before the load event
  const options = {subtree: true, childList: true, attributes: true, characterData: true};
  const observer = new MutationObserver(() => { changes++; });
  const watch = (root) => { if (watching) observer.observe(root, options); else early.push(root); };
  const begin = () => {
    if (watching) return;
    watching = true;
    observer.observe(document, options);
    early.splice(0).forEach((root) => observer.observe(root, options));
  };
  if (document.readyState === 'complete') begin(); else window.addEventListener('load', begin, {once: true});
  const attachShadow = Element.prototype.attachShadow;
  Element.prototype.attachShadow = function (...args) { const root = attachShadow.apply(this, args); watch(root); return root; };
  Object.defineProperty(window, '__ewa', {value: {
    // Mutation records are delivered as a microtask: take them now so that none is pending.
    changes() {
      if (!watching) return null;
      if (observer.takeRecords().length) changes++;
      return token + ':' + changes;
    },
    // Resolves [settled, popups asked for, had work] once this action's requests are done and a
    // macrotask has let their callbacks run (a callback may start more work: then wait again).
    idle(ms) {
      const asked = popups; popups = 0;
      return new Promise((resolve) => {
        let finished = false, hadWork = pending > 0;
        const finish = (settled) => {
          if (!finished) { finished = true; epoch++; pending = 0; resolve([settled, asked, hadWork]); }
        };
        if (!pending) { finish(true); return; }  // callbacks of finished work have already run
        const timer = setTimeout(() => finish(false), ms);
        const check = () => setTimeout(() => {
          if (finished) return;
          if (pending) { hadWork = true; waiters.push(check); return; }
          clearTimeout(timer); finish(true);
        }, 0);
        waiters.push(check);
      });
    },
  }});
})();"""
IDLE_JS = "(ms) => Promise.resolve(window.__ewa ? window.__ewa.idle(ms) : [true, 0, false])"
# The page's DOM-change count ("<document token>:<count>"), or null where the hooks are not
# installed (about:blank, error pages) or the document has not reached its load event.
CHANGES_JS = "(window.__ewa ? window.__ewa.changes() : null)"


class PageActivity:
    """One page's main-frame navigations, from Playwright's events."""

    def __init__(self, page: Any):
        self.page = page
        self.seq = 0  # main-frame navigation requests seen so far
        self.navigations = 0  # main-frame navigations committed so far
        self._inflight: dict[Any, int] = {}  # navigation request -> seq
        self._changed = asyncio.Event()
        self._handlers = {"request": self._on_request, "requestfinished": self._on_done,
                          "requestfailed": self._on_done, "framenavigated": self._on_navigated}
        for event, handler in self._handlers.items():
            page.on(event, handler)

    def detach(self) -> None:
        for event, handler in self._handlers.items():
            self.page.remove_listener(event, handler)

    def _on_request(self, request: Any) -> None:
        try:
            is_nav = request.is_navigation_request() and request.frame == self.page.main_frame
        except Exception:  # a request of a frame that is already gone
            is_nav = False
        if is_nav:
            self.seq += 1
            self._inflight[request] = self.seq
            self._changed.set()

    def _on_done(self, request: Any) -> None:
        if self._inflight.pop(request, None) is not None:
            self._changed.set()

    def _on_navigated(self, frame: Any) -> None:
        if frame == self.page.main_frame:
            self.navigations += 1
            self._changed.set()

    def mark(self) -> tuple[int, int]:
        return self.seq, self.navigations

    def navigated_since(self, mark: tuple[int, int]) -> bool:
        return self.navigations > mark[1] or self.seq > mark[0]

    async def _navigations_done(self, mark: tuple[int, int], deadline: float) -> bool:
        while any(seq > mark[0] for seq in self._inflight.values()):
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            self._changed.clear()
            try:
                await asyncio.wait_for(self._changed.wait(), remaining)
            except TimeoutError:
                return False
        return True

    async def _loaded(self, deadline: float) -> bool:
        try:
            await self.page.wait_for_load_state("load", timeout=max(1.0, (deadline - time.monotonic()) * 1000))
        except Exception:
            return False
        return True

    async def navigation(self, mark: tuple[int, int], deadline: float) -> list[str]:
        """Wait for a navigation the action started to commit and load; notices if it did not."""
        if self.navigated_since(mark):
            if not await self._navigations_done(mark, deadline) or not await self._loaded(deadline):
                return ["the page was still loading; observe again (get_observation) to see it complete"]
        return []

    async def idle(self, mark: tuple[int, int], deadline: float, evaluate: Callable[[str], Awaitable[Any]],
                   facts_js: str) -> tuple[bool, int, bool, Any]:
        """Wait for the page's own work (see PAGE_HOOKS_JS).

        Returns (settled, popups asked for, waited, facts): ``waited`` is true when there was work
        to wait for, so a snapshot taken meanwhile is stale; ``facts`` is ``facts_js`` evaluated
        right after, saving the observation a round trip. ``evaluate`` runs an expression in the
        page's main world (where the hooks live)."""
        waited = False
        for _ in range(2):
            remaining_ms = max(1, int((deadline - time.monotonic()) * 1000))
            expression = f"({IDLE_JS})({remaining_ms}).then((r) => [...r, ({facts_js})()])"
            try:
                settled, popups, had_work, facts = await asyncio.wait_for(evaluate(expression),
                                                                          remaining_ms / 1000 + 1)
                return bool(settled), int(popups), waited or bool(had_work), facts
            except Exception:
                # The document went away under the evaluation: a navigation started late.
                waited = True
                if not self.navigated_since(mark) or time.monotonic() >= deadline:
                    break
                await self.navigation(mark, deadline)
        return True, 0, waited, None
