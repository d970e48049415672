"""Process-wide resources shared by all episodes (a browser, the embedded web sites, city graphs).

Each is created on first use by a named factory and closed when the server stops, so a
server that never runs a web task never starts Chromium. ``Services`` also carries what those
factories and the environments need to know: the process's ``Settings`` (browser options, site
ports, kitchen backend, ...) and the episode manager's event sink.
"""

from __future__ import annotations

import inspect
from collections.abc import Awaitable, Callable
from typing import Any

import anyio

from ewa_mcp.settings import Settings, load_settings

# (episode_id, event) -> None: how the embedded web sites report orders and page views to the episodes.
EventSink = Callable[[str, dict[str, Any]], None]


class Services:
    def __init__(self, settings: Settings | None = None, *, emit_event: EventSink | None = None):
        # Built once by the CLI or build_server and handed down; environments read it, never os.environ.
        self.settings: Settings = settings if settings is not None else load_settings()
        self.emit_event: EventSink | None = emit_event
        self._items: dict[str, Any] = {}
        self._closers: list[Callable[[], Any]] = []
        self._locks: dict[str, anyio.Lock] = {}

    async def get(self, name: str, factory: Callable[["Services"], Awaitable[Any] | Any]) -> Any:
        """The service ``name``, made by ``factory`` on first use (one maker at a time per name). A
        factory may get other services; each is closed after the ones made with it (last made,
        first closed), so the browser closes before the sites it was launched for."""
        if name in self._items:
            return self._items[name]
        async with self._locks.setdefault(name, anyio.Lock()):
            if name not in self._items:
                value = factory(self)
                if inspect.isawaitable(value):
                    value = await value
                self._items[name] = value
                closer = getattr(value, "aclose", None) or getattr(value, "close", None)
                if closer is not None:
                    self._closers.append(closer)
        return self._items[name]

    def peek(self, name: str) -> Any | None:
        return self._items.get(name)

    async def aclose(self) -> None:
        while self._closers:
            closer = self._closers.pop()
            result = closer()
            if inspect.isawaitable(result):
                await result
        self._items.clear()
