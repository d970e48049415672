"""A tab of an episode's browser, and how Playwright's errors read."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .aria import AriaNode
from .settle import PageActivity


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
