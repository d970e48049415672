"""Helpers of the browser tests (fixtures live in conftest.py)."""

from __future__ import annotations

import asyncio
import contextlib
from types import SimpleNamespace
from typing import Any

from ewa_mcp.core.services import Services
from ewa_mcp.core.taskmodel import Task


def web_task(start_url: str = "fixture:/", task_id: str = "web-test") -> Task:
    return Task.model_validate(
        {"id": task_id, "domain": "demo", "intent": "test",
         "start": {"environment": "web", "web": {"start_url": start_url}}}
    )


async def open_env(services: Services, start_url: str = "fixture:/", episode_id: str = "ep-test",
                   options: dict[str, Any] | None = None) -> Any:
    """A BrowserEnvironment of a stand-in episode (the environment reads only its id)."""
    from ewa_mcp.envs.browser.env import BrowserEnvironment

    env = BrowserEnvironment(SimpleNamespace(id=episode_id, options=options or {}), services)
    await env.reset(web_task(start_url), options or {})
    return env


def element_id(observation: Any, role: str, name: str) -> int:
    """The id the observation text shows for ``role 'name'`` (what an agent would read off it)."""
    needle = f"] {role} '{name}'"
    for line in observation.text.splitlines():
        stripped = line.strip()
        if needle in stripped and stripped.startswith("["):
            return int(stripped[1 : stripped.index("]")])
    raise AssertionError(f"{role} '{name}' not in observation:\n{observation.text}")


async def crash_tab(env: Any, tab: Any) -> None:
    """Kill the renderer of ``tab`` and wait (bounded) until the environment has noticed."""
    session = await env.context.new_cdp_session(tab.page)
    crash = asyncio.ensure_future(session.send("Page.crash"))  # never answered: the renderer dies
    for _ in range(500):
        if tab.crashed:
            break
        await asyncio.sleep(0.01)
    crash.cancel()
    with contextlib.suppress(BaseException):
        await crash
