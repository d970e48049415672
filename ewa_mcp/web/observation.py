"""The browser observation an agent reads: tabs, URL, scroll position, notices, then either the
accessibility tree or the list of what the screenshot's marks label (``body``)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

from ..environment import Observation
from .render import RenderedTree

# Page facts, evaluated in the page: [title, scrollX, scrollY, viewport w, h, page w, h].
PAGE_INFO_JS = (
    "() => [document.title, Math.round(scrollX), Math.round(scrollY), innerWidth, innerHeight,"
    " document.documentElement.scrollWidth, document.documentElement.scrollHeight]"
)


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
    }
    return Observation(text="\n".join(header) + "\n\n" + shown, data=data, images=[png] if png else [])
