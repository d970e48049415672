"""A tab of an episode's browser: what it hears, how it navigates, and how its elements are read and located.

* Events (``watch_page``): navigations (a new document starts a new generation of element ids),
  crashes and closes, dialogs (accepted), downloads (refused), redirects the browser refuses.
* Navigation (``navigate``): a checked URL loaded in the tab.
* Elements (``take_snapshot``, ``locate``): Playwright's AI-mode ARIA snapshot parsed into nodes
  with episode-wide ids, and an agent's reference (an id, or role and name) turned into a locator.
  A snapshot taken after an action (or to locate an element) remembers the page's DOM-change counter
  (settle.py) read just before it was taken; while the counter reads the same, the snapshot still
  shows the page, so locating an element needs no new snapshot (and no check that its ref still
  resolves). Plain observations do not count (observation.py): the next locate snapshots.

The tab list and the context are session.py's; what the agent is shown is observation.py's.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass, field
from functools import partial
from typing import Any, Protocol
from urllib.parse import urldefrag

from playwright.async_api import Error as PlaywrightError
from playwright.async_api import TimeoutError as PlaywrightTimeoutError

from ewa_mcp.core.environment import EnvError
from .aria import AriaNode, parse_snapshot
from ewa_mcp.settings import BrowserConfig
from .elements import ElementRefError, ElementRegistry, IdRef, parse_element, resolve_role_name
from .settle import CHANGES_JS, PageActivity



class BrowserSession(Protocol):
    """What a tab needs of its browser session (session.py's ``BrowserSession`` provides it): declared here so
    that the session imports the tabs and never the other way round."""

    config: BrowserConfig
    tabs: list[Tab]
    active: int
    history: list[str]
    elements: ElementRegistry
    restoring: bool
    blocked_nav: str | None

    def notice(self, text: str) -> None: ...
    def site_url(self, url: str) -> str | None: ...
    async def bounded(self, awaitable: Any) -> Any: ...
    async def cdp(self, tab: Tab) -> Any: ...
    async def main_world(self, tab: Tab, expression: str) -> Any: ...
    async def wait_loaded(self, tab: Tab) -> None: ...

# Page facts, evaluated in the page: [title, scrollX, scrollY, viewport w, h, page w, h].
PAGE_INFO_JS = (
    "() => [document.title, Math.round(scrollX), Math.round(scrollY), innerWidth, innerHeight,"
    " document.documentElement.scrollWidth, document.documentElement.scrollHeight]"
)


@dataclass
class Tab:
    uid: int
    page: Any
    activity: PageActivity
    generation: int = 0  # bumped when the tab shows a new document: ids of older documents are stale
    last_url: str = "about:blank"
    last_title: str = ""
    nodes: list[AriaNode] = field(default_factory=list)  # the latest snapshot, in document order
    ref_ids: dict[str, int] = field(default_factory=dict)  # aria ref -> element id, latest snapshot
    snapshot_generation: int = -1
    # The page's DOM-change count read just before the latest snapshot; None: unknown (no hooks,
    # or frames inside, whose changes the count does not see).
    snapshot_changes: str | None = None
    roots: list[AriaNode] = field(default_factory=list)
    crashed: bool = False
    closed: bool = False
    closing: bool = False  # closed by us (browser_close_tab), not by the page
    # A tab we open starts at about:blank; its history is reset after the first page so that
    # going back never lands on that blank entry.
    blank_start: bool = False
    cdp: Any = None  # a CDP session (history reset, screenshots), made on first use
    listeners: list[tuple[str, Any]] = field(default_factory=list)  # our page listeners, removed by detach()

    def listen(self, event: str, handler: Any) -> None:
        self.page.on(event, handler)
        self.listeners.append((event, handler))

    def detach(self) -> None:
        """Stop hearing this page's events: the page outlives the episode when it is kept warm."""
        for event, handler in self.listeners:
            self.page.remove_listener(event, handler)
        self.listeners.clear()
        self.activity.detach()


def first_line(exc: BaseException) -> str:
    text = str(exc).strip()
    return text.splitlines()[0] if text else type(exc).__name__


def timeout_reason(exc: BaseException) -> str:
    """The most telling line of Playwright's call log ("element is not visible", ...)."""
    lines = [ln.strip(" -") for ln in str(exc).splitlines() if ln.strip().startswith("-")]
    reasons = [ln for ln in lines if not ln.startswith(("waiting for", "locator resolved", "attempting", "retrying",
                                                        "waiting ", "scrolling", "done scrolling"))]
    return (reasons or lines or [first_line(exc)])[-1]


def is_closed_error(exc: BaseException) -> bool:
    text = str(exc)
    return type(exc).__name__ == "TargetClosedError" or any(
        marker in text for marker in ("has been closed", "Target crashed", "Browser closed", "Connection closed"))


# ---------------------------------------------------------------- events
def watch_page(session: BrowserSession, page: Any, uid: int) -> Tab:
    """A Tab for ``page``, listening to what the session needs to know about it."""
    tab = Tab(uid=uid, page=page, activity=PageActivity(page), last_url=page.url)
    tab.listen("framenavigated", partial(_on_navigated, session, tab))
    tab.listen("crash", lambda _page: setattr(tab, "crashed", True))
    tab.listen("close", lambda _page: setattr(tab, "closed", True))
    tab.listen("dialog", partial(_on_dialog, session))
    tab.listen("download", partial(_on_download, session))
    return tab


def _on_navigated(session: BrowserSession, tab: Tab, frame: Any) -> None:
    if frame != tab.page.main_frame:
        return
    url = frame.url
    old = tab.last_url
    # Only a fragment change keeps the document (and so its elements); anything else is a new page.
    if not (urldefrag(url)[0] == urldefrag(old)[0] and url != old):
        tab.generation += 1
    tab.last_url = url
    if not session.restoring and url != "about:blank" and not url.startswith("chrome-error:"):
        session.history.append(url)


async def _on_dialog(session: BrowserSession, dialog: Any) -> None:
    session.notice(f"the page showed a dialog ({dialog.type}): {dialog.message[:200]!r}; it was accepted")
    try:
        await dialog.accept()
    except PlaywrightError:
        pass


def _on_download(session: BrowserSession, download: Any) -> None:
    session.notice(f"the page started a download ({download.suggested_filename} from {download.url[:120]}); "
                   "downloads are disabled and nothing was saved")


# ---------------------------------------------------------------- navigation
async def navigate(session: BrowserSession, tab: Tab, url: str) -> None:
    """Load ``url`` (already checked by the URL policy) in ``tab``."""
    if url == "about:blank" and tab.page.url == "about:blank":
        return
    try:
        await tab.page.goto(url, wait_until="load")
        if tab.blank_start and url != "about:blank":
            tab.blank_start = False
            await session.bounded((await session.cdp(tab)).send("Page.resetNavigationHistory"))
    except PlaywrightTimeoutError:
        session.notice(f"{url} did not finish loading within {session.config.navigation_timeout_s:g} s")
    except PlaywrightError as exc:
        if is_closed_error(exc):
            raise
        reason = first_line(exc)
        if session.blocked_nav is not None:
            return  # a redirect to a refused URL: the action reports it
        if "ERR_ABORTED" in reason:
            raise EnvError(f"{url} did not open a page (it is a download or an empty response)") from exc
        raise EnvError(f"could not load {url}: {reason}") from exc


# ---------------------------------------------------------------- elements
async def take_snapshot(session: BrowserSession, tab: Tab, boxes: bool = False, facts: bool = True,
                        counted: tuple[str | None, int] | None = None, count: bool = True) -> Any:
    """Take the ARIA snapshot (after the page facts, when asked, and the DOM-change counter); assign
    ids. Retries when a navigation lands meanwhile. Returns the facts (None unless asked).

    ``counted``: (counter, tab generation) the caller has just read in the page (the settling after
    an action does, with the page facts), which saves reading it again when no facts are asked.
    ``count`` false: no counter (a screenshot's marks change the page anyway), and the facts are read
    while the snapshot is taken."""
    expression = f"[{CHANGES_JS}, ({PAGE_INFO_JS})()]" if facts else f"[{CHANGES_JS}, null]"
    for attempt in range(3):
        generation = tab.generation
        try:
            # The counter is read before the snapshot starts, so that an unchanged counter later
            # means nothing changed since (the facts come with it, one round trip for both).
            # Boxes (for viewport filtering and marks) cost a layout query per element: only on demand.
            def snapshot() -> Any:
                return tab.page.aria_snapshot(mode="ai", boxes=boxes, timeout=session.config.action_timeout_s * 1000)

            if not count:
                changes = None
                text, info = await session.bounded(asyncio.gather(
                    snapshot(), session.main_world(tab, f"({PAGE_INFO_JS})()") if facts else asyncio.sleep(0)))
            else:
                if counted is not None and attempt == 0 and not facts and counted[1] == generation:
                    changes, info = counted[0], None
                else:
                    changes, info = await session.main_world(tab, expression)
                text = await session.bounded(snapshot())
        except PlaywrightError as exc:
            if is_closed_error(exc) or attempt == 2:
                raise
            # "Execution context was destroyed": a navigation is under way; let it land.
            await session.wait_loaded(tab)
            continue
        if tab.generation != generation:
            await session.wait_loaded(tab)
            continue
        break
    roots = parse_snapshot(text)
    tab.nodes = [n for root in roots for n in root.walk()]
    tab.ref_ids = {n.ref: session.elements.id_for(tab.uid, tab.generation, n) for n in tab.nodes if n.ref}
    tab.snapshot_generation = tab.generation
    framed = any(n.role == "iframe" for n in tab.nodes)  # a frame's changes are not counted by the page
    tab.snapshot_changes = None if framed or not isinstance(changes, str) else changes
    if info is not None:
        tab.last_title = info[0]
    tab.last_url = tab.page.url
    tab.roots = roots
    return info


async def snapshot_is_current(session: BrowserSession, tab: Tab) -> bool:
    """Whether the latest snapshot still shows the page: same document, no DOM change since."""
    if tab.snapshot_generation != tab.generation or tab.snapshot_changes is None:
        return False
    try:
        changes = await session.main_world(tab, CHANGES_JS)
    except PlaywrightError as exc:
        if is_closed_error(exc):
            raise
        return False  # the document is going away: a navigation is under way
    return changes == tab.snapshot_changes and tab.snapshot_generation == tab.generation


async def locate(session: BrowserSession, tab: Tab, element: str) -> tuple[Any, AriaNode, int]:
    """The Playwright locator of an element reference, checked against the latest snapshot (retaken
    when the page has changed since)."""
    try:
        ref = parse_element(element)
    except ElementRefError as exc:
        raise EnvError(str(exc)) from exc
    if isinstance(ref, IdRef):
        entry = session.elements.get(ref.id)
        if entry is None:
            ids = sorted(tab.ref_ids.values())
            span = f"this page's ids run from {ids[0]} to {ids[-1]}" if ids else "this page has no ids yet"
            raise EnvError(f"there is no element [{ref.id}]; use an id from the latest observation ({span})")
        if entry.tab_uid != tab.uid:
            index = next((i for i, t in enumerate(session.tabs) if t.uid == entry.tab_uid), None)
            if index is not None and session.tabs[index].generation == entry.generation:
                raise EnvError(f"element {entry.describe()} is on tab [{index}], not the current tab "
                               f"[{session.active}]; call browser_tab_focus({index}) first")
            raise EnvError(f"element {entry.describe()} belonged to a page that is no longer open; use ids from "
                           "the latest observation")
        if entry.generation != tab.generation:
            raise EnvError(f"element {entry.describe()} belongs to an earlier page of this tab, which has since "
                           f"navigated to {session.site_url(tab.page.url) or tab.page.url}; its ids are stale, use "
                           "ids from the latest observation")
        current = await snapshot_is_current(session, tab)
        if tab.snapshot_generation != tab.generation:
            await take_snapshot(session, tab)
        node = next((n for n in tab.nodes if n.ref == entry.ref), None)
        if node is None:
            raise EnvError(f"element {entry.describe()} is no longer on the page; use ids from the latest "
                           "observation")
        element_id = entry.id
    else:
        # Role+name references resolve against the page as it is now: the latest snapshot when
        # nothing has changed since, else a new one.
        current = await snapshot_is_current(session, tab)
        if not current:
            await take_snapshot(session, tab)
        try:
            node = resolve_role_name(ref, tab.nodes, tab.ref_ids)
        except ElementRefError as exc:
            raise EnvError(str(exc)) from exc
        element_id = tab.ref_ids[node.ref or ""]
    locator = tab.page.locator(f"aria-ref={node.ref}")
    if not current and await session.bounded(locator.count()) == 0:
        # The DOM changed since the snapshot; refusing beats acting on whatever the ref means now.
        raise EnvError(f"element [{element_id}] {node.role} '{node.name}' is no longer on the page; use ids "
                       "from the latest observation")
    return locator, node, element_id
