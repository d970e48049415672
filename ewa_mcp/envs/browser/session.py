"""An episode's browser session: its BrowserContext and the tabs in it.

One job: the context's life. It takes a warm context from the pool (pool.py) or makes one, notes
every request of it that the browser's guard refuses (chromium.py, safety.py), keeps the list of
tabs (popups included) and the notices the agent has not seen, recovers after a crash (relaunch,
reopen every tab at its last URL), and at the end hands the context back to the pool. The
hand-over (the pool's scrub) runs in the background so that ``finish_episode`` does not wait for it;
the next episode that finds no idle context waits for a hand-over in flight instead of making a
cold context (``Handovers``).

What a tab hears and how it navigates and locates elements is tabs.py; what the agent is shown,
observation.py; the actions, operations.py.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Iterator
from typing import Any
from urllib.parse import urlsplit

from playwright.async_api import Error as PlaywrightError

from ewa_mcp.core.environment import EnvError
from ewa_mcp.websites.common import EPISODE_HEADER
from ewa_mcp.websites.serve import site_service
from .chromium import BrowserService, ChromiumNotFoundError, chromium_service
from ewa_mcp.settings import BrowserConfig
from .elements import ElementRegistry
from .incremental import tree_changes
from .pool import WarmContext
from .safety import BlockedUrlError, UrlPolicy, normalize_origin
from .settle import PAGE_HOOKS_JS
from .tabs import Tab, navigate, watch_page

MAX_NOTICES = 12
GUARDED_SCHEMES = ("http:", "https:", "ws:", "wss:")  # what goes through the network (and the guard)


class Handovers:
    """Contexts on their way back to the pool (a service: one per server, closed before the browser).

    ``start`` runs a hand-over in the background; ``wait_one`` lets an episode that found the pool
    empty wait for one to land instead of making a cold context; ``drain`` (and ``aclose``) lets
    every one finish."""

    def __init__(self, _services: Any = None):
        self._tasks: set[asyncio.Task[Any]] = set()

    def pending(self) -> int:
        return len(self._tasks)

    def start(self, work: Any) -> asyncio.Task[Any]:
        task = asyncio.ensure_future(work)
        self._tasks.add(task)
        task.add_done_callback(self._done)
        return task

    def _done(self, task: asyncio.Task[Any]) -> None:
        self._tasks.discard(task)
        if not task.cancelled():
            task.exception()  # retrieved: a failed hand-over has already closed its context

    async def wait_one(self) -> bool:
        """Wait until one hand-over in flight has finished; False when none was in flight."""
        if not self._tasks:
            return False
        await asyncio.wait(set(self._tasks), return_when=asyncio.FIRST_COMPLETED)
        return True

    async def drain(self) -> None:
        """Wait until no hand-over is in flight."""
        while self._tasks:
            await asyncio.wait(set(self._tasks))

    async def aclose(self) -> None:
        await self.drain()


class PageBusyError(EnvError):
    """The page did not answer in time (a script running, or a loaded machine); it may answer later."""


class BrowserSession:
    """The state of one episode's browser and the context's lifecycle."""

    def __init__(self, episode_id: str, services: Any):
        self.episode_id = episode_id
        self.services = services
        self.config = BrowserConfig()
        self.options: dict[str, Any] = {}
        self.seen_tree: list[str] | None = None  # the tree lines of the last observation (incremental.py)
        self.seen_path: str | None = None  # the URL path of that observation's page
        self.service: BrowserService | None = None
        self.policy: UrlPolicy | None = None
        self.context: Any = None
        self.warm: WarmContext | None = None  # the pool's record of self.context
        self.tabs: list[Tab] = []
        self.active = 0
        self.history: list[str] = []
        self.blocked: list[str] = []
        self.restarts = 0
        self.elements = ElementRegistry()
        self.notices: list[str] = []
        self.next_tab_uid = 1
        self.context_closed = False
        self.launch_seen = 0
        self.opening = 0  # our own new_page() calls in flight (their "page" events are not popups)
        self.restoring = False
        self.blocked_nav: str | None = None
        self.closed = False
        self.popups_seen = 0
        self.popup_event = asyncio.Event()
        self.handover: asyncio.Task[Any] | None = None  # this session's context on its way to the pool

    # ------------------------------------------------------------ lifecycle
    async def start(self, task: Any, options: dict[str, Any]) -> None:
        """Settings, browser, sites and URL policy; a context; one tab at the task's start page."""
        self.options = dict(options or {})
        self.seen_tree = None
        self.seen_path = None
        self.config = self.services.settings.browser  # validated when the settings were loaded
        try:
            for origin in self.config.allow_origins:
                normalize_origin(origin)
        except ValueError as exc:
            raise EnvError(f"invalid browser allowlist: {exc}") from exc
        try:
            self.service = await self.services.get("chromium", chromium_service)
        except ChromiumNotFoundError as exc:
            raise EnvError(str(exc)) from exc
        # Made after the browser service, so closed before it: hand-overs finish while it still runs.
        await self.services.get("web-handovers", Handovers)
        sites = await self.services.get("websites", site_service)
        try:
            self.policy = UrlPolicy(sites.urls, self.config.allow_origins)
        except ValueError as exc:
            raise EnvError(f"invalid browser allowlist: {exc}") from exc
        start = task.start.web.start_url if task.start.web is not None else "home:/"
        try:
            url = self.policy.resolve(start)
        except BlockedUrlError as exc:
            raise EnvError(f"task {task.id}: start_url {start!r} is refused: {exc}") from exc
        await self.new_context(warm=True)
        tab = await self.open_tab()
        await navigate(self, tab, url)

    async def close(self) -> None:
        """Let go of the context: hand it to the pool in the background when it is healthy, else close it."""
        self.closed = True
        context, self.context = self.context, None
        warm, self.warm = self.warm, None
        tabs, self.tabs = self.tabs, []  # a kept page serves the next episode: this one lets go of it
        self.elements = ElementRegistry()
        if context is None:
            return
        keep = self._page_to_keep(tabs)
        if (warm is not None and keep is not None and self.service is not None and not self.context_closed
                and self.service.is_alive() and self.launch_seen == self.service.launches):
            # Listeners go now (no await): from here on this episode hears nothing of the pages.
            for tab in tabs:
                tab.detach()
            context.remove_listener("page", self._on_page)
            context.remove_listener("request", self._on_request)
            context.remove_listener("close", self._on_context_close)
            warm.watch(keep.page)
            if warm.cdp is None:
                warm.cdp = keep.cdp
            # Every origin the pages could have stored something for (the guard refuses all others).
            origins = tuple(self.policy.allowed_origins) if self.policy else ()
            handovers = await self.services.get("web-handovers", Handovers)
            self.handover = handovers.start(self.service.pool.give_back(warm, origins))
            return
        try:
            await context.close()
        except Exception:
            pass  # the browser is already gone

    def _page_to_keep(self, tabs: list[Tab]) -> Tab | None:
        """The tab whose page (and warm renderer) the next episode can use: the current one if it is fine."""
        ordered = ([tabs[self.active]] if 0 <= self.active < len(tabs) else []) + tabs
        return next((t for t in ordered if not (t.crashed or t.closed or t.page.is_closed())), None)

    async def new_context(self, warm: bool = False) -> None:
        """A context for this episode: a warm one from the pool when ``warm`` and one is idle or on
        its way back (see pool.py), else a new one."""
        assert self.service is not None and self.policy is not None
        browser = await self.service.browser()
        self.launch_seen = self.service.launches
        key = (self.config.viewport_width, self.config.viewport_height)
        self.warm = None
        if warm:
            handovers = await self.services.get("web-handovers", Handovers)
            self.warm = await self.service.pool.take(key, self.launch_seen)
            while self.warm is None and await handovers.wait_one():
                self.warm = await self.service.pool.take(key, self.launch_seen)
        if self.warm is not None:
            context = self.warm.context
        else:
            context = await browser.new_context(
                viewport={"width": self.config.viewport_width, "height": self.config.viewport_height},
                accept_downloads=False,
                service_workers="block",  # a service worker could answer requests from its cache
            )
            await context.add_init_script(PAGE_HOOKS_JS)
            self.warm = WarmContext(context, launch=self.launch_seen, key=key)
        context.set_default_timeout(self.config.action_timeout_s * 1000)
        context.set_default_navigation_timeout(self.config.navigation_timeout_s * 1000)
        await context.set_extra_http_headers({EPISODE_HEADER: self.episode_id})
        context.on("page", self._on_page)
        context.on("request", self._on_request)
        context.on("close", self._on_context_close)
        self.context = context
        self.context_closed = False

    def _on_context_close(self, context: Any) -> None:
        if context is self.context:
            self.context_closed = True

    # ------------------------------------------------------------ refused requests and notices
    def _on_request(self, request: Any) -> None:
        """Note a request the browser's guard refuses (chromium.py): every one outside the allowed
        origins. The guard itself fails it; this records it, and a refused navigation of a tab's
        main frame makes the action report it and step the tab back (operations.py)."""
        url = request.url
        if not url.startswith(GUARDED_SCHEMES) or self.policy is None:
            return  # data:, blob:, about: never reach the network
        if url.startswith(self.policy.allowed_prefixes) or self.policy.is_allowed(url):
            return  # Chromium's URLs are canonical: an allowed origin and a path is allowed
        try:
            main_nav = request.is_navigation_request() and request.frame.parent_frame is None
        except Exception:
            main_nav = False
        if len(self.blocked) < 500:
            self.blocked.append(url)
        if main_nav:
            self.blocked_nav = url
        else:
            what = "a redirect" if request.redirected_from is not None else "a request"
            self.notice(f"{what} to {url[:120]} was blocked (not an embedded site)")

    def notice(self, text: str) -> None:
        if text not in self.notices and len(self.notices) < MAX_NOTICES:
            self.notices.append(text)

    def take_notices(self) -> list[str]:
        notices, self.notices = self.notices, []
        return notices

    def drop_notices_about(self, url: str) -> None:
        """Forget the notices that name ``url`` (a refusal the agent is told about otherwise)."""
        self.notices = [n for n in self.notices if url[:120] not in n]

    def take_refused_navigation(self) -> str | None:
        """The URL of the last main-frame navigation the guard refused since the last call, if any."""
        url, self.blocked_nav = self.blocked_nav, None
        return url

    @contextlib.contextmanager
    def restoring_tabs(self) -> Iterator[None]:
        """While the session itself moves a tab (steps back, reopens a page), a page it opens is no popup."""
        self.restoring = True
        try:
            yield
        finally:
            self.restoring = False

    # ------------------------------------------------------------ tabs
    def track(self, page: Any) -> Tab:
        for tab in self.tabs:
            if tab.page is page:
                return tab
        tab = watch_page(self, page, self.next_tab_uid)
        self.next_tab_uid += 1
        return tab

    def _on_page(self, page: Any) -> None:
        if self.opening or self.restoring or any(t.page is page for t in self.tabs):
            return
        tab = self.track(page)
        self.tabs.append(tab)
        self.active = len(self.tabs) - 1
        self.popups_seen += 1
        self.popup_event.set()
        self.notice(f"the page opened a new tab [{self.active}]; it is now the current tab")

    async def open_tab(self) -> Tab:
        warm = self.warm
        if not self.tabs and warm is not None and warm.page is not None and not warm.page.is_closed():
            page = warm.page  # a warm context's kept page: blank, with its history cleared
        else:
            self.opening += 1
            try:
                page = await self.context.new_page()
            finally:
                self.opening -= 1
        tab = self.track(page)
        if warm is not None and page is warm.page:
            tab.cdp = warm.cdp
        tab.blank_start = True
        if tab not in self.tabs:
            self.tabs.append(tab)
        self.active = self.tabs.index(tab)
        return tab

    def remove_tab(self, tab: Tab, focus: Tab | None = None) -> Tab:
        """Take a closed tab off the list; ``focus`` (else the tab before it) becomes current, and is returned."""
        index = self.tabs.index(tab)
        self.tabs.remove(tab)
        self.active = self.tabs.index(focus) if focus is not None else max(0, index - 1)
        return self.tabs[self.active]

    def focus(self, index: int) -> Tab:
        """Make the tab at ``index`` current (an index the agent gave: refused naming the open tabs)."""
        if not 0 <= index < len(self.tabs):
            raise EnvError(f"there is no tab [{index}]; the open tabs are 0 to {len(self.tabs) - 1}")
        self.active = index
        return self.tabs[index]

    async def discard_tab(self, tab: Tab, previous: int) -> None:
        """Close a tab an action opened and make ``previous`` current again."""
        tab.closing = True
        if tab in self.tabs:
            self.tabs.remove(tab)
        self.active = min(previous, len(self.tabs) - 1)
        try:
            await tab.page.close()
            if self.tabs:
                await self.tabs[self.active].page.bring_to_front()
        except PlaywrightError:
            pass  # the browser is gone; the next call restores it

    def current(self) -> Tab:
        if not self.tabs:
            raise EnvError("the browser has no open tab; open one with browser_new_tab(url)")
        self.active = min(self.active, len(self.tabs) - 1)
        return self.tabs[self.active]

    def site_url(self, url: str) -> str | None:
        return self.policy.site_relative(url) if self.policy else None

    async def await_popups(self, popups_before: int, asked: int) -> None:
        """Wait (bounded) until the popups the page asked for have arrived as tabs."""
        deadline = asyncio.get_running_loop().time() + self.config.settle_timeout_s
        while self.popups_seen - popups_before < asked:
            remaining = deadline - asyncio.get_running_loop().time()
            if remaining <= 0:
                self.notice("the page asked for a new tab that did not open")
                return
            self.popup_event.clear()
            try:
                await asyncio.wait_for(self.popup_event.wait(), remaining)
            except TimeoutError:
                pass

    # ------------------------------------------------------------ talking to a page
    async def bounded(self, awaitable: Any) -> Any:
        """Playwright's evaluate and CDP calls have no timeout of their own; a page stuck in a
        script must not hang the episode."""
        limit = self.config.action_timeout_s * 2
        try:
            return await asyncio.wait_for(awaitable, limit)
        except TimeoutError as exc:
            raise PageBusyError(f"the page did not respond within {limit:g} s (a script may be stuck); try "
                                "browser_goto to reload it, or another tab") from exc

    async def cdp(self, tab: Tab) -> Any:
        if tab.cdp is None:
            tab.cdp = await self.context.new_cdp_session(tab.page)
        return tab.cdp

    async def main_world(self, tab: Tab, expression: str) -> Any:
        """Evaluate in the page's main world over CDP: cheaper than Playwright's evaluate, which
        installs its own serialisation helpers in every new document first."""
        session = await self.cdp(tab)
        reply = await self.bounded(session.send("Runtime.evaluate", {
            "expression": expression, "awaitPromise": True, "returnByValue": True}))
        if "exceptionDetails" in reply:
            details = reply["exceptionDetails"]
            raise PlaywrightError(details.get("exception", {}).get("description") or details.get("text", "error"))
        return reply["result"].get("value")

    async def wait_loaded(self, tab: Tab) -> None:
        try:
            await tab.page.wait_for_load_state("load", timeout=self.config.settle_timeout_s * 1000)
        except PlaywrightError:
            pass

    def mode(self) -> str:
        """The episode's observation mode: text, vision or both."""
        return str(self.options.get("observation") or "text")

    def budget(self, requested: int | None = None) -> int:
        """The size budget of a web observation: the one asked for, else the episode's option, else the config's."""
        return int(requested or self.options.get("web_max_chars") or self.config.max_chars)

    def see_tree(self, lines: list[str] | None, incremental: bool, url: str = "") -> str | None:
        """Remember the tree lines an observation shows (None: it shows no tree); return the changes since the
        last tree it showed when the observation may be incremental and the episode asked for that."""
        changes = None
        # On by default: a page after an action does not resend what the agent has already read of it; the option
        # web_incremental false asks for the whole page every time (browser_snapshot and get_observation always are).
        # Another page (another path: another recipe, article or product) is shown whole: sent as its
        # differences from the last one, the lines two recipes share went unread and players took them as
        # missing. The same page after an action or with other parameters (the next step, a new search) is not.
        path = urlsplit(url).path if url else None
        same_page = path is not None and path == self.seen_path
        if incremental and same_page and lines is not None and self.options.get("web_incremental") is not False:
            changes = tree_changes(self.seen_tree, lines)
        self.seen_tree = lines  # what the agent now knows of the page (a marks list shows no tree)
        self.seen_path = path
        return changes

    def viewport_only(self, requested: bool | None = None) -> bool:
        if requested is not None:
            return requested
        return bool(self.options.get("web_viewport_only", self.config.viewport_only))

    # ------------------------------------------------------------ crash recovery
    async def ensure_alive(self) -> None:
        if self.closed or self.service is None:
            raise EnvError("this episode's browser has been closed; start a new episode")
        if (not self.service.is_alive() or self.context_closed or self.context is None
                or self.launch_seen != self.service.launches):
            await self._rebuild()
            return
        for tab in list(self.tabs):
            if tab.crashed:
                index = self.tabs.index(tab)
                await self._replace_page(tab)
                self.notice(f"tab [{index}] had crashed; it was reopened at {tab.last_url}")
            elif tab.closed and not tab.closing:
                index = self.tabs.index(tab)
                self.tabs.remove(tab)
                if self.active >= index and self.active > 0:
                    self.active -= 1
                self.notice(f"tab [{index}] was closed by the page")
        if not self.tabs:
            await self.open_tab()
            self.notice("every tab was closed; a blank tab was opened (use browser_goto)")

    async def _rebuild(self) -> None:
        """Relaunch (if needed), make a fresh context and reopen every tab at its last URL."""
        self.restarts += 1
        old = self.context
        self.context = None
        if old is not None:
            try:
                await old.close()
            except Exception:
                pass
        await self.new_context()
        old_tabs, active = self.tabs, self.active
        self.tabs = []
        self.restoring = True
        try:
            reopen: list[Tab | None] = list(old_tabs) or [None]
            for previous in reopen:
                tab = await self.open_tab()
                if previous is not None:
                    tab.generation = previous.generation + 1
                    url = previous.last_url
                    tab.last_url = url
                    if url != "about:blank" and self.policy and self.policy.is_allowed(url):
                        try:
                            await navigate(self, tab, url)
                        except EnvError as exc:
                            self.notice(f"could not reopen {url}: {exc}")
        finally:
            self.restoring = False
        self.active = min(active, len(self.tabs) - 1)
        await self.tabs[self.active].page.bring_to_front()
        self.notice("the browser had crashed or was closed; it was restarted and your tabs were reopened at their "
                    "last URLs (form input and scroll positions are lost; element ids changed)")

    async def _replace_page(self, tab: Tab) -> None:
        try:
            await tab.page.close()
        except Exception:
            pass
        self.opening += 1
        try:
            page = await self.context.new_page()
        finally:
            self.opening -= 1
        fresh = self.track(page)
        fresh.blank_start = True
        fresh.generation = tab.generation + 1
        fresh.last_url = tab.last_url
        self.tabs[self.tabs.index(tab)] = fresh
        self.restoring = True
        try:
            if tab.last_url != "about:blank" and self.policy and self.policy.is_allowed(tab.last_url):
                await navigate(self, fresh, tab.last_url)
        finally:
            self.restoring = False
