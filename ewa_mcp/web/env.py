"""The web environment: one Playwright BrowserContext per episode, driven with WebArena's actions.

Isolation: every episode has its own context (cookies, storage, tabs) and every request it
makes carries ``X-EWA-Episode: <episode id>``, which the embedded sites key their state on.
Safety: only the embedded sites (and an explicit allowlist) are reachable (see safety.py).
Robustness: actions wait for the page to settle (settle.py); a crashed or closed browser is
relaunched on the next call and the episode's tabs are reopened at their last URLs.
"""

from __future__ import annotations

import asyncio
import base64
import json
import time
from typing import Any, ClassVar, Literal
from urllib.parse import urldefrag

from playwright.async_api import Error as PlaywrightError
from playwright.async_api import TimeoutError as PlaywrightTimeoutError

from ..environment import EnvError, Environment, Observation
from ..websites.common import EPISODE_HEADER
from ..websites.serve import site_service
from .aria import AriaNode, parse_snapshot
from .chromium import BrowserService, ChromiumNotFoundError, chromium_service
from .config import BrowserConfig
from .elements import ElementRefError, ElementRegistry, IdRef, parse_element, resolve_role_name
from .observation import PAGE_INFO_JS, TabLine, build_observation
from .pool import WarmContext
from .render import EDITABLE_ROLES, render_tree
from .safety import BlockedUrlError, UrlPolicy, normalize_origin
from .settle import PAGE_HOOKS_JS, PageActivity
from .tabs import Tab, first_line, is_closed_error, timeout_reason
from .som import DRAW_MARKS_JS, REMOVE_MARKS_JS, marks_payload

SCROLL_JS = """(dir) => {
  const x = scrollX, y = scrollY;
  const dx = dir === 'left' ? -0.8 * innerWidth : dir === 'right' ? 0.8 * innerWidth : 0;
  const dy = dir === 'up' ? -0.8 * innerHeight : dir === 'down' ? 0.8 * innerHeight : 0;
  window.scrollBy({left: dx, top: dy, behavior: 'instant'});
  return [x !== scrollX || y !== scrollY, Math.round(scrollY), document.documentElement.scrollHeight, innerHeight];
}"""
MAX_NOTICES = 12


class BrowserEnvironment(Environment):
    kind: ClassVar[str] = "web"
    name: ClassVar[str] = "browser"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.config = BrowserConfig()
        self.options: dict[str, Any] = {}
        self.service: BrowserService | None = None
        self.policy: UrlPolicy | None = None
        self.context: Any = None
        self._warm: WarmContext | None = None  # the pool's record of self.context
        self._route: Any = None  # the URL pattern our request guard is routed on
        self.tabs: list[Tab] = []
        self.active = 0
        self.history: list[str] = []
        self.blocked: list[str] = []
        self.restarts = 0
        self.elements = ElementRegistry()
        self._notices: list[str] = []
        self._next_tab_uid = 1
        self._context_closed = False
        self._launch_seen = 0
        self._opening = 0  # our own new_page() calls in flight (their "page" events are not popups)
        self._restoring = False
        self._blocked_nav: str | None = None
        self._closed = False
        self._popups_seen = 0
        self._popup_event = asyncio.Event()

    # ------------------------------------------------------------ lifecycle
    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        self.options = dict(options or {})
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
        await self._new_context(warm=True)
        tab = await self._open_tab()
        await self._goto(tab, url)

    async def close(self) -> None:
        self._closed = True
        context, self.context = self.context, None
        warm, self._warm = self._warm, None
        tabs, self.tabs = self.tabs, []  # a kept page serves the next episode: this one lets go of it
        self.elements = ElementRegistry()
        if context is None:
            return
        keep = self._page_to_keep(tabs)
        if (warm is not None and keep is not None and self.service is not None and not self._context_closed
                and self.service.is_alive() and self._launch_seen == self.service.launches):
            try:
                await self._detach(context, tabs)
            except Exception:
                pass  # a context we cannot detach from is closed below
            else:
                warm.watch(keep.page)
                if warm.cdp is None:
                    warm.cdp = keep.cdp
                # Every origin the pages could have stored something for (the route refuses all others).
                await self.service.pool.give_back(warm, self.policy.allowed_origins if self.policy else ())
                return  # kept, or closed by the pool
        try:
            await context.close()
        except Exception:
            pass  # the browser is already gone

    def _page_to_keep(self, tabs: list[Tab]) -> Tab | None:
        """The tab whose page (and warm renderer) the next episode can use: the current one if it is fine."""
        ordered = ([tabs[self.active]] if 0 <= self.active < len(tabs) else []) + tabs
        return next((t for t in ordered if not (t.crashed or t.closed or t.page.is_closed())), None)

    async def _detach(self, context: Any, tabs: list[Tab]) -> None:
        """Remove everything this episode attached to the context, so that the next one starts bare."""
        for tab in tabs:
            tab.detach()
        context.remove_listener("page", self._on_page)
        context.remove_listener("close", self._on_context_close)
        if self._route is not None:
            await context.unroute(self._route, self._block_request)

    async def observe(self) -> Observation:
        await self._ensure_alive()
        return await self._observe()

    async def final_state(self) -> dict[str, Any]:
        tabs = []
        for tab in self.tabs:
            title = tab.last_title
            if not tab.page.is_closed():
                try:
                    title = await asyncio.wait_for(tab.page.title(), 2)
                except Exception:
                    pass
            url = tab.page.url if not tab.page.is_closed() else tab.last_url
            tabs.append({"url": url, "title": title, "site_url": self._site_url(url)})
        return {
            "tabs": tabs,
            "active_tab": self.active,
            "history": list(self.history),
            "site_history": [self._site_url(u) for u in self.history],
            "blocked": list(self.blocked),
            "restarts": self.restarts,
        }

    # ------------------------------------------------------------ browser plumbing
    async def _new_context(self, warm: bool = False) -> None:
        """A context for this episode: a warm one from the pool when ``warm`` and one is idle (see
        pool.py), else a new one."""
        assert self.service is not None and self.policy is not None
        browser = await self.service.browser()
        self._launch_seen = self.service.launches
        key = (self.config.viewport_width, self.config.viewport_height)
        self._warm = await self.service.pool.take(key, self._launch_seen) if warm else None
        if self._warm is not None:
            context = self._warm.context
        else:
            context = await browser.new_context(
                viewport={"width": self.config.viewport_width, "height": self.config.viewport_height},
                accept_downloads=False,
                service_workers="block",  # a service worker could answer requests the route never sees
            )
            await context.add_init_script(PAGE_HOOKS_JS)
            self._warm = WarmContext(context, launch=self._launch_seen, key=key)
        await context.set_extra_http_headers({EPISODE_HEADER: self.episode.id})
        context.set_default_timeout(self.config.action_timeout_s * 1000)
        context.set_default_navigation_timeout(self.config.navigation_timeout_s * 1000)
        self._route = self.policy.route_pattern()
        await context.route(self._route, self._block_request)
        context.on("page", self._on_page)
        context.on("close", self._on_context_close)
        self.context = context
        self._context_closed = False

    def _on_context_close(self, context: Any) -> None:
        if context is self.context:
            self._context_closed = True

    async def _block_request(self, route: Any) -> None:
        request = route.request
        url = request.url
        is_nav = False
        try:
            is_nav = request.is_navigation_request()
            main = request.frame.parent_frame is None
        except Exception:
            main = False
        if len(self.blocked) < 500:
            self.blocked.append(url)
        if is_nav and main:
            self._blocked_nav = url
            self._notice(f"navigation to {url[:120]} was refused (not an embedded site)")
            # ERR_ABORTED leaves the current document in place instead of showing an error page.
            await route.abort("aborted")
        else:
            self._notice(f"a request to {url[:120]} was blocked (not an embedded site)")
            await route.abort("blockedbyclient")

    def _notice(self, text: str) -> None:
        if text not in self._notices and len(self._notices) < MAX_NOTICES:
            self._notices.append(text)

    def _track(self, page: Any) -> Tab:
        for tab in self.tabs:
            if tab.page is page:
                return tab
        tab = Tab(uid=self._next_tab_uid, page=page, activity=PageActivity(page), last_url=page.url)
        self._next_tab_uid += 1
        tab.listen("framenavigated", lambda frame: self._on_navigated(tab, frame))
        tab.listen("crash", lambda _page: setattr(tab, "crashed", True))
        tab.listen("close", lambda _page: setattr(tab, "closed", True))
        tab.listen("dialog", self._on_dialog)
        tab.listen("download", self._on_download)
        tab.listen("request", lambda request: self._on_request(tab, request))
        return tab

    def _on_page(self, page: Any) -> None:
        if self._opening or self._restoring or any(t.page is page for t in self.tabs):
            return
        tab = self._track(page)
        self.tabs.append(tab)
        self.active = len(self.tabs) - 1
        self._popups_seen += 1
        self._popup_event.set()
        self._notice(f"the page opened a new tab [{self.active}]; it is now the current tab")

    def _on_navigated(self, tab: Tab, frame: Any) -> None:
        if frame != tab.page.main_frame:
            return
        url = frame.url
        old = tab.last_url
        # Only a fragment change keeps the document (and so its elements); anything else is a new page.
        if not (urldefrag(url)[0] == urldefrag(old)[0] and url != old):
            tab.generation += 1
        tab.last_url = url
        if not self._restoring and url != "about:blank" and not url.startswith("chrome-error:"):
            self.history.append(url)

    def _on_request(self, tab: Tab, request: Any) -> None:
        # Routing never sees redirect hops; the browser's proxy guard fails them, and this
        # notices the ones that would have moved the page so that the action reports it.
        if request.redirected_from is None or self.policy is None or self.policy.is_allowed(request.url):
            return
        try:
            is_main_nav = request.is_navigation_request() and request.frame == tab.page.main_frame
        except Exception:
            is_main_nav = False
        if len(self.blocked) < 500:
            self.blocked.append(request.url)
        if is_main_nav:
            self._blocked_nav = request.url
        else:
            self._notice(f"a redirect to {request.url[:120]} was blocked (not an embedded site)")

    async def _on_dialog(self, dialog: Any) -> None:
        self._notice(f"the page showed a dialog ({dialog.type}): {dialog.message[:200]!r}; it was accepted")
        try:
            await dialog.accept()
        except PlaywrightError:
            pass

    def _on_download(self, download: Any) -> None:
        self._notice(f"the page started a download ({download.suggested_filename} from {download.url[:120]}); "
                     "downloads are disabled and nothing was saved")

    async def _open_tab(self) -> Tab:
        warm = self._warm
        if not self.tabs and warm is not None and warm.page is not None and not warm.page.is_closed():
            page = warm.page  # a warm context's kept page: blank, with its history cleared
        else:
            self._opening += 1
            try:
                page = await self.context.new_page()
            finally:
                self._opening -= 1
        tab = self._track(page)
        if warm is not None and page is warm.page:
            tab.cdp = warm.cdp
        tab.blank_start = True
        if tab not in self.tabs:
            self.tabs.append(tab)
        self.active = self.tabs.index(tab)
        return tab

    async def _goto(self, tab: Tab, url: str) -> None:
        if url == "about:blank" and tab.page.url == "about:blank":
            return
        try:
            await tab.page.goto(url, wait_until="load")
            if tab.blank_start and url != "about:blank":
                tab.blank_start = False
                await self._bounded((await self._cdp(tab)).send("Page.resetNavigationHistory"))
        except PlaywrightTimeoutError:
            self._notice(f"{url} did not finish loading within {self.config.navigation_timeout_s:g} s")
        except PlaywrightError as exc:
            if is_closed_error(exc):
                raise
            reason = first_line(exc)
            if self._blocked_nav is not None:
                return  # a redirect to a refused URL: _perform reports it
            if "ERR_ABORTED" in reason:
                raise EnvError(f"{url} did not open a page (it is a download or an empty response)") from exc
            raise EnvError(f"could not load {url}: {reason}") from exc

    def _site_url(self, url: str) -> str | None:
        return self.policy.site_relative(url) if self.policy else None

    def _tab(self) -> Tab:
        if not self.tabs:
            raise EnvError("the browser has no open tab; open one with browser_new_tab(url)")
        self.active = min(self.active, len(self.tabs) - 1)
        return self.tabs[self.active]

    # ------------------------------------------------------------ crash recovery
    async def _ensure_alive(self) -> None:
        if self._closed or self.service is None:
            raise EnvError("this episode's browser has been closed; start a new episode")
        if (not self.service.is_alive() or self._context_closed or self.context is None
                or self._launch_seen != self.service.launches):
            await self._rebuild()
            return
        for tab in list(self.tabs):
            if tab.crashed:
                index = self.tabs.index(tab)
                await self._replace_page(tab)
                self._notice(f"tab [{index}] had crashed; it was reopened at {tab.last_url}")
            elif tab.closed and not tab.closing:
                index = self.tabs.index(tab)
                self.tabs.remove(tab)
                if self.active >= index and self.active > 0:
                    self.active -= 1
                self._notice(f"tab [{index}] was closed by the page")
        if not self.tabs:
            await self._open_tab()
            self._notice("every tab was closed; a blank tab was opened (use browser_goto)")

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
        await self._new_context()
        old_tabs, active = self.tabs, self.active
        self.tabs = []
        self._restoring = True
        try:
            for previous in old_tabs or [None]:
                tab = await self._open_tab()
                if previous is not None:
                    tab.generation = previous.generation + 1
                    url = previous.last_url
                    tab.last_url = url
                    if url != "about:blank" and self.policy and self.policy.is_allowed(url):
                        try:
                            await self._goto(tab, url)
                        except EnvError as exc:
                            self._notice(f"could not reopen {url}: {exc}")
        finally:
            self._restoring = False
        self.active = min(active, len(self.tabs) - 1)
        await self.tabs[self.active].page.bring_to_front()
        self._notice("the browser had crashed or was closed; it was restarted and your tabs were reopened at their "
                     "last URLs (form input and scroll positions are lost; element ids changed)")

    async def _replace_page(self, tab: Tab) -> None:
        try:
            await tab.page.close()
        except Exception:
            pass
        self._opening += 1
        try:
            page = await self.context.new_page()
        finally:
            self._opening -= 1
        fresh = self._track(page)
        fresh.blank_start = True
        fresh.generation = tab.generation + 1
        fresh.last_url = tab.last_url
        self.tabs[self.tabs.index(tab)] = fresh
        self._restoring = True
        try:
            if tab.last_url != "about:blank" and self.policy and self.policy.is_allowed(tab.last_url):
                await self._goto(fresh, tab.last_url)
        finally:
            self._restoring = False

    # ------------------------------------------------------------ acting
    async def _perform(self, action_name: str, fn: Any, *, settle: bool = True, popups: bool = False) -> Observation:
        await self._ensure_alive()
        tab = self._tab()
        mark = tab.activity.mark()
        popups_before = self._popups_seen
        self._blocked_nav = None
        try:
            # A last-resort bound: every step below has its own timeout, but keyboard input and
            # some CDP calls do not, and a page stuck in a script must not hang the episode.
            limit = self.config.action_timeout_s + self.config.navigation_timeout_s + 5
            try:
                await asyncio.wait_for(fn(tab), limit)
            except TimeoutError as exc:
                raise EnvError(f"{action_name} did not finish within {limit:g} s; the page may be stuck in a "
                               "script. Try browser_goto to reload it") from exc
            if not settle or tab.page.is_closed():
                return await self._observe()
            return await self._settle_and_observe(action_name, tab, mark, popups_before if popups else None)
        except EnvError:
            raise
        except PlaywrightTimeoutError as exc:
            raise EnvError(f"{action_name} did not complete within {self.config.action_timeout_s:g} s: "
                           f"{timeout_reason(exc)}. The element may be hidden, covered or disabled; scroll it into "
                           "view, close what covers it, or choose another element") from exc
        except PlaywrightError as exc:
            if is_closed_error(exc):
                await self._ensure_alive()
                raise EnvError(f"the browser tab closed or crashed during {action_name}; it is restored with "
                               "the tabs reopened at their last URLs. Look at the page again (get_observation) "
                               "and repeat the action if it is still needed") from exc
            raise EnvError(f"{action_name} failed: {first_line(exc)}") from exc

    async def _settle_and_observe(self, action_name: str, tab: Tab, mark: tuple[int, int],
                                  popups_before: int | None) -> Observation:
        deadline = time.monotonic() + self.config.settle_timeout_s
        for note in await tab.activity.navigation(mark, deadline):
            self._notice(note)
        if self._blocked_nav is not None:
            await self._refuse_navigation(action_name, tab)
        # Most actions leave nothing running, so the snapshot is taken while the page is asked
        # whether it has work in flight; it is taken again only when the page had some.
        want_image = self._mode() in ("vision", "both")
        idle, collected = await asyncio.gather(
            tab.activity.idle(mark, deadline, lambda expression: self._main_world(tab, expression), PAGE_INFO_JS),
            self._collect(tab, want_image, facts=False),  # the idle answer brings the facts
            return_exceptions=True)
        if isinstance(idle, BaseException):
            raise idle
        settled, asked, waited, facts = idle
        if not settled:
            self._notice(f"requests of the page were still running after {self.config.settle_timeout_s:g} s")
        if popups_before is not None and asked > self._popups_seen - popups_before:
            # Popups arrive as "page" events some time after the click that opened them.
            await self._await_popups(popups_before, asked)
        current = self._tab()
        if current is not tab:  # a popup became the current tab
            await self._wait_loaded(current)
        if (waited or current is not tab or isinstance(collected, BaseException)
                or tab.snapshot_generation != tab.generation):
            if isinstance(collected, BaseException) and is_closed_error(collected):
                raise collected
            collected = await self._collect(current, want_image)
        elif not want_image:
            if facts is None:  # the page could not be asked: ask for the facts now
                facts = await self._main_world(tab, f"({PAGE_INFO_JS})()")
            collected = (facts, b"")
        return await self._present(current, collected)

    async def _refuse_navigation(self, action_name: str, tab: Tab) -> None:
        url, self._blocked_nav = self._blocked_nav or "", None
        self._notices = [n for n in self._notices if url[:120] not in n]
        current = self._tab()
        if current is not tab and (current.page.url in ("about:blank", "")
                                   or current.page.url.startswith("chrome-error:")):
            # A popup whose only destination was refused: close it, the agent stays where it was.
            current.closing = True
            await current.page.close()
            self.tabs.remove(current)
            self.active = self.tabs.index(tab)
            current = tab
        if current.page.url.startswith("chrome-error:"):
            # A redirect got as far as an error page: step back to where the agent was.
            try:
                await current.page.go_back(wait_until="load")
            except PlaywrightError:
                pass
        raise EnvError(f"{action_name} led to {url[:200]}, which is refused: only the embedded sites are "
                       f"reachable ({self.policy.describe_allowed() if self.policy else ''}); the page is "
                       "unchanged")

    async def _bounded(self, awaitable: Any) -> Any:
        """Playwright's evaluate and CDP calls have no timeout of their own; a page stuck in a
        script must not hang the episode."""
        limit = self.config.action_timeout_s * 2
        try:
            return await asyncio.wait_for(awaitable, limit)
        except TimeoutError as exc:
            raise EnvError(f"the page did not respond within {limit:g} s (a script may be stuck); try "
                           "browser_goto to reload it, or another tab") from exc

    async def _await_popups(self, popups_before: int, asked: int) -> None:
        """Wait (bounded) until the popups the page asked for have arrived as tabs."""
        deadline = asyncio.get_running_loop().time() + self.config.settle_timeout_s
        while self._popups_seen - popups_before < asked:
            remaining = deadline - asyncio.get_running_loop().time()
            if remaining <= 0:
                self._notice("the page asked for a new tab that did not open")
                return
            self._popup_event.clear()
            try:
                await asyncio.wait_for(self._popup_event.wait(), remaining)
            except TimeoutError:
                pass

    async def _locate(self, tab: Tab, element: str) -> tuple[Any, AriaNode, int]:
        """The Playwright locator of an element reference, checked against the latest snapshot."""
        try:
            ref = parse_element(element)
        except ElementRefError as exc:
            raise EnvError(str(exc)) from exc
        if isinstance(ref, IdRef):
            entry = self.elements.get(ref.id)
            if entry is None:
                ids = sorted(tab.ref_ids.values())
                span = f"this page's ids run from {ids[0]} to {ids[-1]}" if ids else "this page has no ids yet"
                raise EnvError(f"there is no element [{ref.id}]; use an id from the latest observation ({span})")
            if entry.tab_uid != tab.uid:
                index = next((i for i, t in enumerate(self.tabs) if t.uid == entry.tab_uid), None)
                if index is not None and self.tabs[index].generation == entry.generation:
                    raise EnvError(f"element {entry.describe()} is on tab [{index}], not the current tab "
                                   f"[{self.active}]; call browser_tab_focus({index}) first")
                raise EnvError(f"element {entry.describe()} belonged to a page that is no longer open; use ids from "
                               "the latest observation")
            if entry.generation != tab.generation:
                raise EnvError(f"element {entry.describe()} belongs to an earlier page of this tab, which has since "
                               f"navigated to {self._site_url(tab.page.url) or tab.page.url}; its ids are stale, use "
                               "ids from the latest observation")
            if tab.snapshot_generation != tab.generation:
                await self._snapshot(tab)
            node = next((n for n in tab.nodes if n.ref == entry.ref), None)
            if node is None:
                raise EnvError(f"element {entry.describe()} is no longer on the page; use ids from the latest "
                               "observation")
            element_id = entry.id
        else:
            await self._snapshot(tab)  # role+name references resolve against the page as it is now
            try:
                node = resolve_role_name(ref, tab.nodes, tab.ref_ids)
            except ElementRefError as exc:
                raise EnvError(str(exc)) from exc
            element_id = tab.ref_ids[node.ref or ""]
        locator = tab.page.locator(f"aria-ref={node.ref}")
        if await self._bounded(locator.count()) == 0:
            # The DOM changed since the snapshot; refusing beats acting on whatever the ref means now.
            raise EnvError(f"element [{element_id}] {node.role} '{node.name}' is no longer on the page; use ids "
                           "from the latest observation")
        return locator, node, element_id

    @staticmethod
    def _describe(node: AriaNode, element_id: int) -> str:
        return f"[{element_id}] {node.role}" + (f" '{node.name}'" if node.name else "")

    async def click(self, element: str) -> Observation:
        async def act(tab: Tab) -> None:
            locator, node, element_id = await self._locate(tab, element)
            if "disabled" in node.attrs:
                raise EnvError(f"{self._describe(node, element_id)} is disabled; it cannot be clicked now")
            await locator.click()

        return await self._perform("browser_click", act, popups=True)

    async def hover(self, element: str) -> Observation:
        async def act(tab: Tab) -> None:
            locator, _, _ = await self._locate(tab, element)
            await locator.hover()

        return await self._perform("browser_hover", act)

    async def type(self, element: str, text: str, press_enter: bool = False) -> Observation:
        async def act(tab: Tab) -> None:
            locator, node, element_id = await self._locate(tab, element)
            desc = self._describe(node, element_id)
            if "disabled" in node.attrs:
                raise EnvError(f"{desc} is disabled; it does not accept text now")
            tag = ""
            if node.role in ("combobox", "listbox"):
                tag = await self._bounded(locator.evaluate("e => e.localName"))
            if tag == "select":
                await self._select(locator, node, desc, text)
            else:
                try:
                    editable = await locator.is_editable()
                except PlaywrightError:
                    editable = False  # not an input, textarea or contenteditable element at all
                if not editable:
                    fields = [f"[{tab.ref_ids[n.ref]}] {n.role} '{n.name}'" for n in tab.nodes
                              if n.ref in tab.ref_ids and n.role in EDITABLE_ROLES][:10]
                    why = "is read-only" if node.role in EDITABLE_ROLES else "does not accept text"
                    raise EnvError(f"{desc} {why}; type into a text field instead"
                                   + (f" — editable elements here: {', '.join(fields)}" if fields else
                                      " (this page has no editable elements)"))
                await locator.fill(text)
            if press_enter:
                await locator.press("Enter")

        return await self._perform("browser_type", act, popups=press_enter)

    async def _select(self, locator: Any, node: AriaNode, desc: str, text: str) -> None:
        options = [c.name for c in node.walk() if isinstance(c, AriaNode) and c.role == "option"]
        match = next((o for o in options if o == text), None) or next(
            (o for o in options if o.casefold().strip() == text.casefold().strip()), None)
        if match is None:
            raise EnvError(f"{desc} is a drop-down without an option {text!r}; its options are "
                           + ", ".join(repr(o) for o in options))
        await locator.select_option(label=match)

    async def press(self, keys: str) -> Observation:
        keys = keys.strip()
        if not keys or len(keys) > 100:
            raise EnvError("keys must be one key combination such as Enter, Tab, ArrowDown, Escape or Control+a")

        async def act(tab: Tab) -> None:
            # Pressing through the focused element's locator makes Playwright wait for a navigation
            # the key starts (Enter submitting a form); the bare keyboard does not.
            focused = tab.page.locator("*:focus")
            try:
                if await self._bounded(focused.count()) == 1:
                    await focused.press(keys)
                else:
                    await tab.page.keyboard.press(keys)
            except PlaywrightError as exc:
                if "Unknown key" in str(exc):
                    raise EnvError(f"unknown key in {keys!r}: {first_line(exc)}; use key names such as Enter, Tab, "
                                   "ArrowDown, PageDown, Escape, Backspace, or combinations like Control+a") from exc
                raise

        return await self._perform("browser_press", act, popups=True)

    async def scroll(self, direction: str) -> Observation:
        if direction not in ("up", "down", "left", "right"):
            raise EnvError(f"direction must be up, down, left or right, not {direction!r}")

        async def act(tab: Tab) -> None:
            moved, *_ = await self._bounded(tab.page.evaluate(SCROLL_JS, direction))
            if not moved:
                edge = {"up": "top", "down": "bottom", "left": "left edge", "right": "right edge"}[direction]
                self._notice(f"already at the {edge} of the page; nothing scrolled")

        return await self._perform("browser_scroll", act)

    async def goto(self, url: str) -> Observation:
        async def act(tab: Tab) -> None:
            try:
                target = self.policy.resolve(url, tab.page.url)  # type: ignore[union-attr]
            except BlockedUrlError as exc:
                raise EnvError(f"browser_goto refused {url!r}: {exc}") from exc
            await self._goto(tab, target)

        return await self._perform("browser_goto", act)

    async def go_back(self) -> Observation:
        return await self._history_step("back")

    async def go_forward(self) -> Observation:
        return await self._history_step("forward")

    async def _history_step(self, direction: str) -> Observation:
        async def act(tab: Tab) -> None:
            mark = tab.activity.mark()
            step = tab.page.go_back if direction == "back" else tab.page.go_forward
            await step(wait_until="load")  # does nothing (returns None) at the end of the history
            if not tab.activity.navigated_since(mark):
                where = "earlier" if direction == "back" else "later"
                raise EnvError(f"cannot go {direction}: this tab has no {where} page in its history")

        return await self._perform(f"browser_go_{direction}", act)

    async def new_tab(self, url: str | None = None) -> Observation:
        async def act(_: Tab) -> None:
            target = "about:blank"
            if url:
                try:
                    target = self.policy.resolve(url)  # type: ignore[union-attr]
                except BlockedUrlError as exc:
                    raise EnvError(f"browser_new_tab refused {url!r}: {exc}") from exc
            previous = self.active
            tab = await self._open_tab()
            try:
                await tab.page.bring_to_front()
                await self._goto(tab, target)
                refused = self._blocked_nav
                if refused is None and target != "about:blank" and tab.page.url.startswith("chrome-error:"):
                    refused = target
                if refused is not None:  # e.g. a redirect off-site: no tab shows a page it did not open
                    self._blocked_nav = None
                    self._notices = [n for n in self._notices if refused[:120] not in n]
                    raise EnvError(f"browser_new_tab: {target[:200]} led to {refused[:200]}, which is refused: only "
                                   "the embedded sites are reachable ("
                                   f"{self.policy.describe_allowed() if self.policy else ''}); no tab was opened")
            except BaseException:
                await self._discard_tab(tab, previous)
                raise

        return await self._perform("browser_new_tab", act, settle=False)

    async def _discard_tab(self, tab: Tab, previous: int) -> None:
        """Close a tab this action opened and make ``previous`` current again."""
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

    async def close_tab(self) -> Observation:
        async def act(tab: Tab) -> None:
            if len(self.tabs) == 1:
                raise EnvError("cannot close the only tab; open another with browser_new_tab first, or navigate "
                               "with browser_goto")
            index = self.tabs.index(tab)
            tab.closing = True
            await tab.page.close()
            self.tabs.remove(tab)
            self.active = max(0, index - 1)
            await self.tabs[self.active].page.bring_to_front()

        return await self._perform("browser_close_tab", act, settle=False)

    async def tab_focus(self, index: int) -> Observation:
        async def act(_: Tab) -> None:
            if not 0 <= index < len(self.tabs):
                raise EnvError(f"there is no tab [{index}]; the open tabs are 0 to {len(self.tabs) - 1}")
            self.active = index
            await self.tabs[index].page.bring_to_front()

        return await self._perform("browser_tab_focus", act, settle=False)

    async def snapshot(self, viewport_only: bool | None = None, max_chars: int | None = None) -> Observation:
        """The accessibility tree as text, never an image, whatever the observation mode."""
        await self._ensure_alive()
        return await self._observe(viewport_only=viewport_only, max_chars=max_chars, view="tree")

    async def screenshot(self) -> Observation:
        """The Set-of-Marks screenshot and the list of marked elements, whatever the observation mode."""
        await self._ensure_alive()
        return await self._observe(view="screenshot")

    # ------------------------------------------------------------ observing
    async def _snapshot(self, tab: Tab, boxes: bool = False, facts: bool = True) -> Any:
        """Take the ARIA snapshot (and the page facts, when asked); assign ids. Retries when a
        navigation lands meanwhile."""
        for attempt in range(3):
            generation = tab.generation
            try:
                text, info = await self._bounded(asyncio.gather(
                    # Boxes (for viewport filtering and marks) cost a layout query per element: only on demand.
                    tab.page.aria_snapshot(mode="ai", boxes=boxes, timeout=self.config.action_timeout_s * 1000),
                    self._main_world(tab, f"({PAGE_INFO_JS})()") if facts else asyncio.sleep(0),
                ))
            except PlaywrightError as exc:
                if is_closed_error(exc) or attempt == 2:
                    raise
                # "Execution context was destroyed": a navigation is under way; let it land.
                await self._wait_loaded(tab)
                continue
            if tab.generation != generation:
                await self._wait_loaded(tab)
                continue
            break
        roots = parse_snapshot(text)
        tab.nodes = [n for root in roots for n in root.walk()]
        tab.ref_ids = {n.ref: self.elements.id_for(tab.uid, tab.generation, n) for n in tab.nodes if n.ref}
        tab.snapshot_generation = tab.generation
        if info is not None:
            tab.last_title = info[0]
        tab.last_url = tab.page.url
        tab.roots = roots
        return info

    async def _capture(self, tab: Tab) -> bytes:
        """A viewport PNG straight from CDP with Chromium's fast PNG encoder (Playwright's screenshot
        adds caret and animation handling, which cost round trips)."""
        session = await self._cdp(tab)
        shot = await self._bounded(session.send("Page.captureScreenshot", {"format": "png", "optimizeForSpeed": True}))
        return base64.b64decode(shot["data"])

    async def _main_world(self, tab: Tab, expression: str) -> Any:
        """Evaluate in the page's main world over CDP: cheaper than Playwright's evaluate, which
        installs its own serialisation helpers in every new document first."""
        session = await self._cdp(tab)
        reply = await self._bounded(session.send("Runtime.evaluate", {
            "expression": expression, "awaitPromise": True, "returnByValue": True}))
        if "exceptionDetails" in reply:
            details = reply["exceptionDetails"]
            raise PlaywrightError(details.get("exception", {}).get("description") or details.get("text", "error"))
        return reply["result"].get("value")

    async def _cdp(self, tab: Tab) -> Any:
        if tab.cdp is None:
            tab.cdp = await self.context.new_cdp_session(tab.page)
        return tab.cdp

    async def _wait_loaded(self, tab: Tab) -> None:
        try:
            await tab.page.wait_for_load_state("load", timeout=self.config.settle_timeout_s * 1000)
        except PlaywrightError:
            pass

    def _mode(self) -> str:
        """The episode's observation mode: text, vision or both."""
        return str(self.options.get("observation") or "text")

    async def _observe(self, *, viewport_only: bool | None = None, max_chars: int | None = None,
                       view: Literal["mode", "tree", "screenshot"] = "mode") -> Observation:
        """``view`` "mode": what the observation mode shows (text: tree; vision: screenshot and its
        marks; both: tree and screenshot); "tree" and "screenshot": that alone, in any mode."""
        tab = self._tab()
        if view == "mode":
            want_image = self._mode() in ("vision", "both")
            body: Literal["tree", "marks"] = "marks" if self._mode() == "vision" else "tree"
        else:
            want_image = view == "screenshot"
            body = "marks" if want_image else "tree"
        if viewport_only and not want_image:
            collected = (await self._snapshot(tab, boxes=True), b"")
        else:
            collected = await self._collect(tab, want_image)
        return await self._present(tab, collected, viewport_only=viewport_only, max_chars=max_chars, body=body)

    async def _collect(self, tab: Tab, want_image: bool, facts: bool = True) -> tuple[Any, bytes]:
        """The snapshot (with the page facts unless ``facts`` is false) and, when wanted, the
        Set-of-Marks screenshot."""
        info = await self._snapshot(tab, boxes=want_image or self._viewport_only(), facts=facts or want_image)
        if not want_image:
            return info, b""
        marks = render_tree(tab.roots, lambda n: tab.ref_ids[n.ref], title="", viewport=(info[3], info[4])).marks
        await self._main_world(tab, f"({DRAW_MARKS_JS})({json.dumps(marks_payload(marks))})")
        try:
            png = await self._capture(tab)
        finally:
            # Not awaited: later commands to this page run after it, so nothing ever sees the overlay.
            removal = asyncio.ensure_future(self._main_world(tab, f"({REMOVE_MARKS_JS})()"))
            removal.add_done_callback(lambda f: f.cancelled() or f.exception())
        return info, png

    def _viewport_only(self, requested: bool | None = None) -> bool:
        if requested is not None:
            return requested
        return bool(self.options.get("web_viewport_only", self.config.viewport_only))

    async def _present(self, tab: Tab, collected: tuple[list[Any], bytes], *, viewport_only: bool | None = None,
                       max_chars: int | None = None, body: Literal["tree", "marks"] | None = None) -> Observation:
        facts, png = collected
        # The page now shown names the tab: after a navigation the title the snapshot kept may be
        # the previous page's (an observation after an action reads the facts separately).
        tab.last_title = facts[0]
        viewport_only = self._viewport_only(viewport_only)
        budget = int(max_chars or self.options.get("web_max_chars") or self.config.max_chars)
        rendered = render_tree(tab.roots, lambda n: tab.ref_ids[n.ref], title=facts[0], viewport=(facts[3], facts[4]),
                               viewport_only=viewport_only, max_chars=budget)
        titles = await asyncio.gather(*[self._title_of(t) for t in self.tabs])
        lines = []
        for i, t in enumerate(self.tabs):
            url = t.last_url if t.page.is_closed() else t.page.url
            lines.append(TabLine(i, titles[i], url, self._site_url(url), i == self.active))
        notices, self._notices = self._notices, []
        return build_observation(tabs=lines, facts=facts, url=tab.page.url, site_url=self._site_url(tab.page.url),
                                 rendered=rendered, notices=notices,
                                 body=body or ("marks" if self._mode() == "vision" else "tree"),
                                 viewport_only=viewport_only, budget=budget, png=png)

    async def _title_of(self, tab: Tab) -> str:
        if tab is self._tab() or tab.page.is_closed():
            return tab.last_title
        try:
            tab.last_title = await asyncio.wait_for(tab.page.title(), 2)
        except (PlaywrightError, TimeoutError):
            pass
        return tab.last_title
