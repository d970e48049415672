"""Shared fixtures of the browser tests: one Chromium and one fixture-site server per test module.

Tests that need a browser take ``chromium_path`` (directly or through ``web_services``) and are
skipped, with the reason, when this machine has no Chromium.
"""

from __future__ import annotations

from collections.abc import AsyncIterator, Iterator
from typing import Any

import pytest

from ewa_mcp.core.services import Services
from ewa_mcp.settings import load_settings
from ewa_mcp.envs.browser.chromium import ChromiumNotFoundError, chromium_service, find_chromium


@pytest.fixture(scope="module")
def anyio_backend() -> str:
    # Module scope: the browser fixture below lives across a module's tests, on one event loop.
    return "asyncio"


@pytest.fixture(scope="session")
def chromium_path() -> str:
    try:
        return find_chromium().path
    except ChromiumNotFoundError as exc:
        pytest.skip(f"no Chromium on this machine: {exc}")


@pytest.fixture(scope="module")
def fixture_sites(chromium_path: str) -> Iterator[Any]:
    from .testsite import start_fixture_sites

    events: list[tuple[str, dict[str, Any]]] = []
    server = start_fixture_sites(emit=lambda episode_id, event: events.append((episode_id, event)))
    server.events = events  # type: ignore[attr-defined]
    yield server
    server.stop()


@pytest.fixture(scope="module")
async def web_services(fixture_sites: Any, anyio_backend: str) -> AsyncIterator[Services]:
    services = Services(load_settings({"browser": {"action_timeout_s": 3.0}}))
    await services.get("websites", lambda _: fixture_sites)
    await services.get("chromium", chromium_service)
    yield services
    await services.aclose()
