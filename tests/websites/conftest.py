"""Shared fixtures for the embedded web sites' tests.

- ``event_log``: a thread-safe sink for site events (``SiteContext(emit=event_log.emit)``).
- ``site_context``: a SiteContext wired to ``event_log``, for Starlette TestClient route tests.
- ``site_server``: every site that exists in this build, served on loopback by the real
  ``SiteServer`` (one per test session); ``site_server.events`` is its EventLog.
- ``chromium``: a headless system Chromium through Playwright's sync API (one per test module),
  skipped with the reason when /usr/bin/chromium or Playwright is missing.
- ``browser_page``: a factory ``browser_page(episode_id=None) -> (page, episode_id)`` opening a
  fresh context whose requests carry ``X-EWA-Episode`` like the MCP server's browser does.
"""

from __future__ import annotations

import itertools
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from ewa_mcp.websites.common import EPISODE_HEADER, SiteContext
from ewa_mcp.websites.serve import SiteServer

CHROMIUM_PATH = Path("/usr/bin/chromium")
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]
_episode_numbers = itertools.count(1)


class EventLog:
    """Collects (episode_id, event) pairs emitted by sites, possibly from the server thread."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._items: list[tuple[str, dict[str, Any]]] = []

    def emit(self, episode_id: str, event: dict[str, Any]) -> None:
        with self._lock:
            self._items.append((episode_id, dict(event)))

    def all(self) -> list[tuple[str, dict[str, Any]]]:
        with self._lock:
            return list(self._items)

    def for_episode(self, episode_id: str, type: str | None = None, site: str | None = None) -> list[dict[str, Any]]:
        return [e for ep, e in self.all()
                if ep == episode_id and (type is None or e.get("type") == type)
                and (site is None or e.get("site") == site)]

    def clear(self) -> None:
        with self._lock:
            self._items.clear()


def new_episode_id(prefix: str = "test") -> str:
    """A fresh episode id, so tests sharing the session-wide server never read each other's events."""
    return f"{prefix}-{next(_episode_numbers)}"


@pytest.fixture
def event_log() -> EventLog:
    return EventLog()


@pytest.fixture
def site_context(event_log: EventLog) -> SiteContext:
    urls = {name: f"http://{name}.test" for name in ("home", "recipes", "shop", "map", "wiki")}
    return SiteContext(urls=urls, emit=event_log.emit)


@pytest.fixture(scope="session")
def site_server() -> Iterator[SiteServer]:
    log = EventLog()
    server = SiteServer(emit=log.emit).start()
    server.events = log  # type: ignore[attr-defined]
    try:
        yield server
    finally:
        server.stop()


@pytest.fixture(scope="module")
def chromium() -> Iterator[Any]:
    # Module scope: the sync API owns an event loop, so it must not outlive the module that uses it
    # (anyio tests elsewhere start their own loops).
    if not CHROMIUM_PATH.exists():
        pytest.skip(f"no Chromium at {CHROMIUM_PATH} (apt-get install chromium)")
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright is not installed")
    manager = sync_api.sync_playwright()
    playwright = manager.start()
    try:
        try:
            browser = playwright.chromium.launch(executable_path=str(CHROMIUM_PATH), headless=True,
                                                 args=CHROMIUM_ARGS)
        except Exception as exc:  # a broken Chromium install is an environment problem, not a failure
            pytest.skip(f"Chromium at {CHROMIUM_PATH} did not start: {exc}")
        yield browser
        browser.close()
    finally:
        manager.__exit__(None, None, None)


@pytest.fixture
def browser_page(chromium: Any) -> Iterator[Callable[..., tuple[Any, str]]]:
    contexts: list[Any] = []

    def open_page(episode_id: str | None = None) -> tuple[Any, str]:
        episode_id = episode_id or new_episode_id("browser")
        context = chromium.new_context(extra_http_headers={EPISODE_HEADER: episode_id})
        contexts.append(context)
        page = context.new_page()
        page.set_default_timeout(10_000)
        return page, episode_id

    yield open_page
    for context in contexts:
        context.close()
