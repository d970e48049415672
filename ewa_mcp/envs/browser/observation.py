"""The browser observation an agent reads: tabs, URL, scroll position, notices, then either the
accessibility tree or the list of what the screenshot's marks label (``body``).

One job: from a tab's snapshot (tabs.py) and, where the mode asks for it, the Set-of-Marks
screenshot, build the Observation (``observe``, ``collect``, ``present``, ``build_observation``).
"""

from __future__ import annotations

import asyncio
import base64
import json
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

from playwright.async_api import Error as PlaywrightError

from ewa_mcp.core.environment import Observation
from .tree_text import RenderedTree, render_tree
from .som import DRAW_MARKS_JS, REMOVE_MARKS_JS, marks_payload
from .tabs import PAGE_INFO_JS, Tab, take_snapshot

if TYPE_CHECKING:
    from .session import BrowserSession

__all__ = ["PAGE_INFO_JS", "TabLine", "build_observation", "collect", "observe", "present"]


@dataclass
class TabLine:
    index: int
    title: str
    url: str
    site_url: str | None
    active: bool

    def as_dict(self) -> dict[str, Any]:
        return {"index": self.index, "title": self.title, "url": self.url, "site_url": self.site_url,
                "active": self.active}


def build_observation(
    *,
    tabs: list[TabLine],
    facts: list[Any],
    url: str,
    site_url: str | None,
    rendered: RenderedTree,
    notices: list[str],
    body: Literal["tree", "marks"],
    viewport_only: bool,
    budget: int,
    png: bytes = b"",
    changes: str | None = None,
) -> Observation:
    """``body`` "tree": the accessibility tree as text (and in ``data["tree"]``); "marks": the list
    of marked elements that label ``png`` (``data["tree"]`` is None: the tree is not shown)."""
    title, sx, sy, vw, vh, page_w, page_h = facts
    header = [f"Tab {t.index}{' (current)' if t.active else ''}: {t.title or '(untitled)'} — {t.site_url or t.url}"
              for t in tabs]
    header.append(f"URL: {url}" + (f" ({site_url})" if site_url else ""))
    if page_h > vh or page_w > vw:
        header.append(f"Scroll: viewing y {sy}–{sy + vh} of {page_h} px"
                      + (f", x {sx}–{sx + vw} of {page_w} px" if page_w > vw else ""))
    if notices:
        header.append("Notices:\n" + "\n".join(f"- {n}" for n in notices))
    if body == "marks":  # the image carries the page: list what its labels name
        shown = "Marked elements (see the screenshot):\n" + "\n".join(
            f"[{m.id}] {m.role} '{m.name}'" for m in rendered.marks)
    elif changes is not None:  # web_incremental: the page the agent read, changed (incremental.py)
        shown = (f"Accessibility tree, changes since your last observation of this page ({rendered.lines} lines; "
                 "every line not listed here is as you last read it; browser_snapshot shows it whole):"
                 f"\n{changes}")
    else:
        scope = "visible part of the page" if viewport_only else "whole page"
        shown = f"Accessibility tree ({scope}):\n{rendered.text}"
        if rendered.truncated:
            shown += (f"\n[truncated: {rendered.lines} of {rendered.total_lines} lines shown, limit {budget} "
                     "characters; scroll and use browser_snapshot(viewport_only=true), or ask for a larger max_chars]")
    data = {
        "kind": "browser",
        "tabs": [t.as_dict() for t in tabs],
        "active_tab": next((t.index for t in tabs if t.active), 0),
        "url": url,
        "site_url": site_url,
        "title": title,
        "scroll": {"x": sx, "y": sy, "viewport_width": vw, "viewport_height": vh,
                   "page_width": page_w, "page_height": page_h},
        "viewport_only": viewport_only,
        "tree": rendered.text if body == "tree" else None,
        "truncated": rendered.truncated and body == "tree",
        "lines_shown": rendered.lines,
        "lines_total": rendered.total_lines,
        "marks": len(rendered.marks),
        "notices": notices,
        "incremental": changes is not None,
    }
    return Observation(text="\n".join(header) + "\n\n" + shown, data=data, images=[png] if png else [])


async def observe(session: BrowserSession, *, viewport_only: bool | None = None, max_chars: int | None = None,
                  view: Literal["mode", "tree", "screenshot"] = "mode", incremental: bool = False) -> Observation:
    """``view`` "mode": what the observation mode shows (text: tree; vision: screenshot and its
    marks; both: tree and screenshot); "tree" and "screenshot": that alone, in any mode.
    ``incremental``: the page after an action, sent as its changes when the episode asks for that."""
    tab = session.current()
    mode = session.mode()
    if view == "mode":
        want_image = mode in ("vision", "both")
        body: Literal["tree", "marks"] = "marks" if mode == "vision" else "tree"
    else:
        want_image = view == "screenshot"
        body = "marks" if want_image else "tree"
    # No DOM-change count here: it would have to be read before the snapshot (a round trip more on
    # start_episode and every get_observation); the facts are read while the snapshot is taken. The
    # next action that names an element then takes its own snapshot, as it always did.
    if viewport_only and not want_image:
        collected = (await take_snapshot(session, tab, boxes=True, count=False), b"")
    else:
        collected = await collect(session, tab, want_image, count=False)
    return await present(session, tab, collected, viewport_only=viewport_only, max_chars=max_chars, body=body,
                         incremental=incremental)


async def collect(session: BrowserSession, tab: Tab, want_image: bool,
                  known: tuple[list[Any], str | None, int] | None = None, count: bool = True) -> tuple[Any, bytes]:
    """The snapshot with the page facts and, when wanted, the Set-of-Marks screenshot.

    ``known``: (facts, DOM-change counter, tab generation) just read in the page by the caller.
    ``count`` false: the snapshot records no DOM-change count (see tabs.take_snapshot)."""
    if known is not None:
        info, changes, generation = known
        await take_snapshot(session, tab, boxes=want_image or session.viewport_only(), facts=False,
                            counted=(changes, generation))
        if tab.generation != generation:  # a navigation landed meanwhile: these facts are the old page's
            info = await session.main_world(tab, f"({PAGE_INFO_JS})()")
    else:
        info = await take_snapshot(session, tab, boxes=want_image or session.viewport_only(),
                                   count=count and not want_image)
    if not want_image:
        return info, b""
    await draw_marks(session, tab, info)
    try:
        png = await capture(session, tab)
    finally:
        # Not awaited: it is sent before the observation is returned (present() passes the event loop
        # at least once), and later commands to the page run after it, so nothing ever sees the overlay.
        removal = asyncio.ensure_future(session.main_world(tab, f"({REMOVE_MARKS_JS})()"))
        removal.add_done_callback(lambda f: f.cancelled() or f.exception())
    return info, png


async def draw_marks(session: BrowserSession, tab: Tab, info: list[Any]) -> list[list[int]]:
    """Draw the Set-of-Marks overlay of the tab's latest snapshot (``info``: its page facts) and return where
    the badges went, as [id, x, y, width, height] in viewport pixels (som.py). REMOVE_MARKS_JS takes it off."""
    marks = render_tree(tab.roots, lambda n: tab.ref_ids[n.ref or ""], title="", viewport=(info[3], info[4])).marks
    return list(await session.main_world(tab, f"({DRAW_MARKS_JS})({json.dumps(marks_payload(marks))})") or [])


async def capture(session: BrowserSession, tab: Tab) -> bytes:
    """A viewport PNG straight from CDP with Chromium's fast PNG encoder (Playwright's screenshot
    adds caret and animation handling, which cost round trips)."""
    cdp = await session.cdp(tab)
    shot = await session.bounded(cdp.send("Page.captureScreenshot", {"format": "png", "optimizeForSpeed": True}))
    return base64.b64decode(shot["data"])


async def present(session: BrowserSession, tab: Tab, collected: tuple[list[Any], bytes], *,
                  viewport_only: bool | None = None, max_chars: int | None = None,
                  body: Literal["tree", "marks"] | None = None, incremental: bool = False) -> Observation:
    facts, png = collected
    # The page now shown names the tab: after a navigation the title the snapshot kept may be
    # the previous page's (an observation after an action reads the facts separately).
    tab.last_title = facts[0]
    viewport_only = session.viewport_only(viewport_only)
    budget = session.budget(max_chars)
    rendered = render_tree(tab.roots, lambda n: tab.ref_ids[n.ref or ""], title=facts[0], viewport=(facts[3], facts[4]),
                           viewport_only=viewport_only, max_chars=budget)
    # Every tab's title (the current tab's is in the facts). Gathered as tasks even with one tab:
    # that passes the event loop, so a marks removal scheduled by collect() has been sent.
    await asyncio.gather(*[_refresh_title(t) for t in session.tabs if t is not tab], asyncio.sleep(0))
    lines = []
    for i, t in enumerate(session.tabs):
        url = t.last_url if t.page.is_closed() else t.page.url
        lines.append(TabLine(i, t.last_title, url, session.site_url(url), i == session.active))
    body = body or ("marks" if session.mode() == "vision" else "tree")
    tree_lines = rendered.text.splitlines() if body == "tree" else None
    changes = session.see_tree(tree_lines, incremental, tab.page.url)
    return build_observation(tabs=lines, facts=facts, url=tab.page.url, site_url=session.site_url(tab.page.url),
                             rendered=rendered, notices=session.take_notices(), body=body,
                             viewport_only=viewport_only, budget=budget, png=png, changes=changes)


async def _refresh_title(tab: Tab) -> None:
    if tab.page.is_closed():
        return
    try:
        tab.last_title = await asyncio.wait_for(tab.page.title(), 2)
    except (PlaywrightError, TimeoutError):
        pass
