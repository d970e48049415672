"""Process-wide resources shared by all episodes (a browser, the embedded web sites, city graphs).

Each is created on first use by a named factory and closed when the server stops, so a
server that never runs a web task never starts Chromium.
"""

from __future__ import annotations

import inspect
from collections.abc import Awaitable, Callable
from typing import Any

import anyio


class Services:
    def __init__(self, config: dict[str, Any] | None = None):
        self.config: dict[str, Any] = dict(config or {})
        self._items: dict[str, Any] = {}
        self._closers: list[Callable[[], Any]] = []
        self._lock = anyio.Lock()

    async def get(self, name: str, factory: Callable[["Services"], Awaitable[Any] | Any]) -> Any:
        if name in self._items:
            return self._items[name]
        async with self._lock:
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
