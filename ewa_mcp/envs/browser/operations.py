"""WebArena's browser actions on an episode's session, each ending with the new observation.

One job: run an action on the current tab (``perform``), wait for the page to settle (settle.py),
turn what went wrong into an error the agent can act on, and observe (observation.py).
"""

from __future__ import annotations

import asyncio
import re
import time
from typing import Any

from playwright.async_api import Error as PlaywrightError
from playwright.async_api import TimeoutError as PlaywrightTimeoutError

from ewa_mcp.core.environment import EnvError, Observation
from .aria import AriaNode
from .observation import collect, observe, present
from .tree_text import EDITABLE_ROLES, FOLD_WHEN_NAMELESS
from .safety import BlockedUrlError
from .session import BrowserSession, PageBusyError
from .settle import CHANGES_JS
from .tabs import PAGE_INFO_JS, Tab, first_line, is_closed_error, locate, navigate, timeout_reason

# The page facts and the DOM-change counter, read together when the page says it has settled.
FACTS_AND_CHANGES_JS = f"() => [({PAGE_INFO_JS})(), {CHANGES_JS}]"
SCROLL_JS = """(dir) => {
  const x = scrollX, y = scrollY;
  const dx = dir === 'left' ? -0.8 * innerWidth : dir === 'right' ? 0.8 * innerWidth : 0;
  const dy = dir === 'up' ? -0.8 * innerHeight : dir === 'down' ? 0.8 * innerHeight : 0;
  window.scrollBy({left: dx, top: dy, behavior: 'instant'});
  return [x !== scrollX || y !== scrollY, Math.round(scrollY), document.documentElement.scrollHeight, innerHeight];
}"""


# What a type lands in, found as Playwright's fill finds it: from text inside a button to the button, from a label
# (or text in one) to the control it labels. A control that is no text field is refused by name, before the fill.
TYPE_TARGET_JS = """(node) => {
  let e = node.nodeType === 1 ? node : node.parentElement;
  const via = e;
  if (!e.matches('input, textarea, select') && !e.isContentEditable)
    e = e.closest('button, [role=button], [role=checkbox], [role=radio]') || e;
  if (!e.matches('input, textarea, select, [contenteditable]') && !e.getAttribute('role')) {
    const label = e.closest('label');
    if (label && label.control) e = label.control;
  }
  return {tag: e.localName, type: (e.getAttribute('type') || '').toLowerCase(), role: e.getAttribute('role') || '',
          label: e !== via && via.closest('label') !== null && via.closest('label').control === e,
          text: ((e.labels && e.labels[0] && e.labels[0].textContent) || e.getAttribute('aria-label') || e.value
                 || e.textContent || '').trim().replace(/\\s+/g, ' ').slice(0, 60)};
}"""
# Input types whose value is text of some kind (fill types into them, or sets a date, colour or number).
TEXT_INPUT_TYPES = frozenset({"", "text", "email", "number", "password", "search", "tel", "url", "date", "time",
                              "datetime-local", "month", "week", "color", "range"})
BUTTON_INPUT_TYPES = frozenset({"submit", "button", "reset", "image"})


def _is_number(text: str) -> bool:
    try:
        float(text.strip())
    except ValueError:
        return False
    return True


def type_refusal(desc: str, target: dict[str, Any], text: str, fields: str) -> str | None:
    """Why typing ``text`` into ``desc`` cannot work, given what it lands in (TYPE_TARGET_JS); None where it
    can. ``fields``: the page's text fields, as the refusal lists them."""
    tag, kind, role = target.get("tag", ""), target.get("type", ""), target.get("role", "")
    if tag == "input" and kind == "number" and text.strip() and not _is_number(text):
        return f"{desc} takes a number only, and {text!r} is not one; type digits such as 2"
    if tag == "input" and kind in TEXT_INPUT_TYPES or tag in ("textarea", "select"):
        return None
    radio = "radio" in (kind, role)
    if tag == "input" and kind in ("checkbox", "radio") or role in ("checkbox", "radio"):
        what, todo = ("a radio button", "choose it") if radio else ("a checkbox", "tick or untick it")
        todo = f"{todo} with browser_click"
    elif tag == "input" and kind in BUTTON_INPUT_TYPES or tag == "button" or role == "button":
        what, todo = "a button", f"type into a text field instead{fields}; press a button with browser_click"
    elif tag == "input" and kind == "file":
        what, todo = "a file chooser", "files cannot be chosen in this browser"
    else:
        return None
    if target.get("label"):  # the reference is a label's text: name the control it labels
        what = f"the label of {what}" + (f" '{target['text']}'" if target.get("text") else "")
    return f"{desc} is {what} and does not accept text; {todo}"


# How long a refused navigation's error page may take to commit past the action's own deadline on a loaded machine
# (it normally commits within milliseconds, and the wait ends as soon as it does).
ERROR_PAGE_WAIT_MS = 3000.0


class NavigationRefused(EnvError):
    """The action led the tab to a URL the guard refused (the tab was stepped back)."""


def input_dispatched(exc: BaseException) -> bool:
    """Whether Playwright's call log of a timed-out action shows the input was sent to the page ("performing
    click action", "click action done") with no retry after it: the page then takes it in (a busy page
    later), so the action happened even though Playwright gave up waiting for the page to confirm it."""
    lines = [ln.strip(" -") for ln in str(exc).splitlines() if ln.strip().startswith("-")]
    sent = [i for i, ln in enumerate(lines) if re.fullmatch(r"(performing \w+ action|\w+ action done)", ln)]
    after = lines[sent[-1] + 1:] if sent else []
    return bool(sent) and not any(ln.startswith(("retrying", "attempting")) or "intercepts pointer events" in ln
                                  for ln in after)


def describe(node: AriaNode, element_id: int) -> str:
    """The element as the observation shows it: a nameless container of one text as its StaticText."""
    if not node.name and node.role in FOLD_WHEN_NAMELESS and node.text and node.attrs.get("cursor") != "pointer":
        return f"[{element_id}] StaticText '{' '.join(node.text.split())}'"
    return f"[{element_id}] {node.role}" + (f" '{node.name}'" if node.name else "")


class BrowserActions:
    def __init__(self, session: BrowserSession):
        self.session = session

    # ------------------------------------------------------------ the frame of every action
    async def perform(self, action_name: str, fn: Any, *, settle: bool = True, popups: bool = False) -> Observation:
        s = self.session
        await s.ensure_alive()
        tab = s.current()
        mark = tab.activity.mark()
        popups_before = s.popups_seen
        s.take_refused_navigation()  # a refusal before this action is not this action's
        try:
            # A last-resort bound: every step below has its own timeout, but keyboard input and
            # some CDP calls do not, and a page stuck in a script must not hang the episode.
            limit = s.config.action_timeout_s + s.config.navigation_timeout_s + 5
            try:
                await asyncio.wait_for(fn(tab), limit)
            except TimeoutError as exc:
                raise EnvError(f"{action_name} did not finish within {limit:g} s; the page may be stuck in a "
                               "script. Try browser_goto to reload it") from exc
            except PlaywrightTimeoutError as exc:
                if not input_dispatched(exc):
                    raise
                # The input reached the page, which was too busy to confirm it in time: the action happened, and
                # its result is what the agent must see (reporting a timeout would make it repeat the action).
                return await self._observe_when_free(action_name)
            if not settle or tab.page.is_closed():
                return await observe(s, incremental=True)
            try:
                return await self._settle_and_observe(action_name, tab, mark, popups_before if popups else None)
            except (PageBusyError, PlaywrightTimeoutError):
                # The action is done; only reading the page afterwards ran out of time.
                return await self._observe_when_free(action_name)
        except EnvError:
            raise
        except PlaywrightTimeoutError as exc:
            raise EnvError(f"{action_name} did not complete within {s.config.action_timeout_s:g} s: "
                           f"{timeout_reason(exc)}. The element may be hidden, covered or disabled; scroll it into "
                           "view, close what covers it, or choose another element") from exc
        except PlaywrightError as exc:
            if is_closed_error(exc):
                await s.ensure_alive()
                raise EnvError(f"the browser tab closed or crashed during {action_name}; it is restored with "
                               "the tabs reopened at their last URLs. Look at the page again (get_observation) "
                               "and repeat the action if it is still needed") from exc
            raise EnvError(f"{action_name} failed: {first_line(exc)}") from exc

    async def _settle_and_observe(self, action_name: str, tab: Tab, mark: tuple[int, int],
                                  popups_before: int | None) -> Observation:
        s = self.session
        deadline = time.monotonic() + s.config.settle_timeout_s
        for note in await tab.activity.navigation(mark, deadline):
            s.notice(note)
        if s.blocked_nav is not None:
            await self._refuse_navigation(action_name, tab, deadline)
        # The page is asked whether this action's work is done; its answer brings the page facts
        # and the DOM-change counter (settle.py), read when it answers, so that the snapshot taken
        # next is known to be at least that new. Most actions leave nothing running: one round trip.
        want_image = s.mode() in ("vision", "both")
        settled, asked, _waited, answer = await tab.activity.idle(
            mark, deadline, lambda expression: s.main_world(tab, expression), FACTS_AND_CHANGES_JS)
        answered_generation = tab.generation
        if not settled:
            s.notice(f"requests of the page were still running after {s.config.settle_timeout_s:g} s")
        if popups_before is not None and asked > s.popups_seen - popups_before:
            # Popups arrive as "page" events some time after the click that opened them.
            await s.await_popups(popups_before, asked)
        current = s.current()
        if current is not tab:  # a popup became the current tab
            await s.wait_loaded(current)
            collected = await collect(s, current, want_image)
        elif answer is None:  # the page could not be asked: read the facts with the snapshot
            collected = await collect(s, tab, want_image)
        else:
            collected = await collect(s, tab, want_image, known=(answer[0], answer[1], answered_generation))
        return await present(s, current, collected, incremental=True)

    async def _observe_when_free(self, action_name: str) -> Observation:
        """The observation after an action that took effect while the page was too busy to be read in time:
        the page once it answers (waiting up to the navigation timeout), with a notice saying so. Only when
        it never answers is the result text alone, still saying the action was done."""
        s = self.session
        s.notice(f"{action_name} was done, but the page was too busy to be read at once (a script running, or a "
                 "loaded machine); this is the page once it answered")
        end = time.monotonic() + s.config.navigation_timeout_s
        while True:
            try:
                return await observe(s, incremental=True)
            except (PageBusyError, PlaywrightTimeoutError):
                if time.monotonic() >= end:
                    break
        s.take_notices()
        tab = s.current()
        return Observation(
            text=(f"{action_name} was done, but the page is still busy after {s.config.navigation_timeout_s:g} s "
                  "and could not be read (a script may be stuck). Look again with get_observation, or reload it "
                  "with browser_goto"),
            data={"url": tab.page.url, "site_url": s.site_url(tab.page.url), "busy": True})

    async def _refuse_navigation(self, action_name: str, tab: Tab, deadline: float) -> None:
        s = self.session
        url = s.take_refused_navigation() or ""
        # The refused request fails at once, but Chromium commits its error page for it a little later (a
        # form's POST, or any navigation on a busy machine, after the action has settled): wait for that
        # commit, so the tab is stepped back from the error page rather than left on it.
        await self._error_page_committed(s.current(), deadline)
        s.drop_notices_about(url)
        current = s.current()
        if current is not tab and (current.page.url in ("about:blank", "")
                                   or current.page.url.startswith("chrome-error:")):
            # A popup whose only destination was refused: close it, the agent stays where it was.
            current.closing = True
            await current.page.close()
            current = s.remove_tab(current, focus=tab)
        if current.page.url.startswith("chrome-error:"):
            # The browser's guard failed the navigation (a link, a form or a redirect off-site) and
            # the tab shows its error page: step back to where the agent was, which is no new visit.
            back_to = s.history[-1] if s.history else ""  # the last page the agent saw (no error pages there)
            with s.restoring_tabs():
                try:
                    await current.page.go_back(wait_until="load")
                except PlaywrightError:
                    pass  # the step back can be interrupted by the error page committing late: checked below
                for _ in range(4):
                    # A refused form POST can leave no entry to go back to, and its error page can commit after
                    # the step back: watch a moment longer and open the page the agent was on if it does (a
                    # refused navigation is rare; the second this costs is not).
                    await asyncio.sleep(0.25)
                    if current.page.url.startswith("chrome-error:") and back_to.startswith("http"):
                        try:
                            await current.page.goto(back_to, wait_until="load")
                        except PlaywrightError:
                            pass
        raise NavigationRefused(f"{action_name} led to {url[:200]}, which is refused: only the embedded sites are "
                       f"reachable ({s.policy.describe_allowed() if s.policy else ''}); the page is "
                       "unchanged")

    @staticmethod
    async def _error_page_committed(tab: Tab, deadline: float) -> None:
        page = tab.page
        if page.is_closed() or page.url.startswith("chrome-error:"):
            return
        try:
            await page.wait_for_event(
                "framenavigated", predicate=lambda frame: frame == page.main_frame and frame.url.startswith(
                    "chrome-error:"), timeout=max(ERROR_PAGE_WAIT_MS, (deadline - time.monotonic()) * 1000))
        except PlaywrightError:
            pass  # no error page came (the navigation was cancelled, or replaced by another): nothing to undo

    # ------------------------------------------------------------ element actions
    async def click(self, element: str) -> Observation:
        async def act(tab: Tab) -> None:
            locator, node, element_id = await locate(self.session, tab, element)
            if "disabled" in node.attrs:
                raise EnvError(f"{describe(node, element_id)} is disabled; it cannot be clicked now")
            await locator.click()

        return await self.perform("browser_click", act, popups=True)

    async def hover(self, element: str) -> Observation:
        async def act(tab: Tab) -> None:
            locator, _, _ = await locate(self.session, tab, element)
            await locator.hover()

        return await self.perform("browser_hover", act)

    async def type(self, element: str, text: str, press_enter: bool = False) -> Observation:
        s = self.session

        async def act(tab: Tab) -> None:
            locator, node, element_id = await locate(s, tab, element)
            desc = describe(node, element_id)
            if "disabled" in node.attrs:
                raise EnvError(f"{desc} is disabled; it does not accept text now")
            tag = ""
            if node.role in ("combobox", "listbox"):
                tag = await s.bounded(locator.evaluate("e => e.localName"))
            if tag == "select":
                await self._select(locator, node, desc, text)
            else:
                fields = [f"[{tab.ref_ids[n.ref]}] {n.role} '{n.name}'" for n in tab.nodes
                          if n.ref in tab.ref_ids and n.role in EDITABLE_ROLES][:10]
                listed = (f" — editable elements here: {', '.join(fields)}" if fields else
                          " (this page has no editable elements)")
                try:
                    target = await s.bounded(locator.evaluate(TYPE_TARGET_JS))
                except PlaywrightError:
                    target = {}  # no element behind the reference: is_editable below refuses it
                refusal = type_refusal(desc, target, text, listed)
                if refusal:
                    raise EnvError(refusal)
                try:
                    editable = await locator.is_editable()
                except PlaywrightError:
                    editable = False  # not an input, textarea or contenteditable element at all
                if not editable:
                    why = "is read-only" if node.role in EDITABLE_ROLES else "does not accept text"
                    raise EnvError(f"{desc} {why}; type into a text field instead{listed}")
                await locator.fill(text)
            if press_enter:
                await locator.press("Enter")

        return await self.perform("browser_type", act, popups=press_enter)

    @staticmethod
    async def _select(locator: Any, node: AriaNode, desc: str, text: str) -> None:
        options = [c.name for c in node.walk() if isinstance(c, AriaNode) and c.role == "option"]
        match = next((o for o in options if o == text), None) or next(
            (o for o in options if o.casefold().strip() == text.casefold().strip()), None)
        if match is None:
            raise EnvError(f"{desc} is a drop-down without an option {text!r}; its options are "
                           + ", ".join(repr(o) for o in options))
        await locator.select_option(label=match)

    # ------------------------------------------------------------ page actions
    async def press(self, keys: str) -> Observation:
        keys = keys.strip()
        if not keys or len(keys) > 100:
            raise EnvError("keys must be one key combination such as Enter, Tab, ArrowDown, Escape or Control+a")

        async def act(tab: Tab) -> None:
            # Pressing through the focused element's locator makes Playwright wait for a navigation
            # the key starts (Enter submitting a form); the bare keyboard does not.
            focused = tab.page.locator("*:focus")
            try:
                if await self.session.bounded(focused.count()) == 1:
                    await focused.press(keys)
                else:
                    await tab.page.keyboard.press(keys)
            except PlaywrightError as exc:
                if "Unknown key" in str(exc):
                    raise EnvError(f"unknown key in {keys!r}: {first_line(exc)}; use key names such as Enter, Tab, "
                                   "ArrowDown, PageDown, Escape, Backspace, or combinations like Control+a") from exc
                raise

        return await self.perform("browser_press", act, popups=True)

    async def scroll(self, direction: str) -> Observation:
        if direction not in ("up", "down", "left", "right"):
            raise EnvError(f"direction must be up, down, left or right, not {direction!r}")

        async def act(tab: Tab) -> None:
            moved, *_ = await self.session.bounded(tab.page.evaluate(SCROLL_JS, direction))
            if not moved:
                edge = {"up": "top", "down": "bottom", "left": "left edge", "right": "right edge"}[direction]
                self.session.notice(f"already at the {edge} of the page; nothing scrolled")

        return await self.perform("browser_scroll", act)

    async def goto(self, url: str) -> Observation:
        s = self.session

        async def act(tab: Tab) -> None:
            try:
                target = s.policy.resolve(url, tab.page.url)  # type: ignore[union-attr]
            except BlockedUrlError as exc:
                raise EnvError(f"browser_goto refused {url!r}: {exc}") from exc
            await navigate(s, tab, target)

        return await self.perform("browser_goto", act)

    async def history_step(self, direction: str) -> Observation:
        async def act(tab: Tab) -> None:
            mark = tab.activity.mark()
            step = tab.page.go_back if direction == "back" else tab.page.go_forward
            await step(wait_until="load")  # does nothing (returns None) at the end of the history
            if not tab.activity.navigated_since(mark):
                where = "earlier" if direction == "back" else "later"
                raise EnvError(f"cannot go {direction}: this tab has no {where} page in its history")

        return await self.perform(f"browser_go_{direction}", act)

    # ------------------------------------------------------------ tab actions
    async def new_tab(self, url: str | None = None) -> Observation:
        s = self.session

        async def act(_: Tab) -> None:
            target = "about:blank"
            if url:
                try:
                    target = s.policy.resolve(url)  # type: ignore[union-attr]
                except BlockedUrlError as exc:
                    raise EnvError(f"browser_new_tab refused {url!r}: {exc}") from exc
            previous = s.active
            tab = await s.open_tab()
            try:
                await tab.page.bring_to_front()
                await navigate(s, tab, target)
                refused = s.take_refused_navigation()
                if refused is None and target != "about:blank" and tab.page.url.startswith("chrome-error:"):
                    refused = target
                if refused is not None:  # e.g. a redirect off-site: no tab shows a page it did not open
                    s.drop_notices_about(refused)
                    raise EnvError(f"browser_new_tab: {target[:200]} led to {refused[:200]}, which is refused: only "
                                   "the embedded sites are reachable ("
                                   f"{s.policy.describe_allowed() if s.policy else ''}); no tab was opened")
            except BaseException:
                await s.discard_tab(tab, previous)
                raise

        return await self.perform("browser_new_tab", act, settle=False)

    async def close_tab(self) -> Observation:
        s = self.session

        async def act(tab: Tab) -> None:
            if len(s.tabs) == 1:
                raise EnvError("cannot close the only tab; open another with browser_new_tab first, or navigate "
                               "with browser_goto")
            tab.closing = True
            await tab.page.close()
            await s.remove_tab(tab).page.bring_to_front()

        return await self.perform("browser_close_tab", act, settle=False)

    async def tab_focus(self, index: int) -> Observation:
        s = self.session

        async def act(_: Tab) -> None:
            await s.focus(index).page.bring_to_front()

        return await self.perform("browser_tab_focus", act, settle=False)
