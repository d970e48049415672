"""The web environment: one Playwright BrowserContext per episode, driven with WebArena's actions.

Isolation: every episode has its own context (cookies, storage, tabs) and every request it
makes carries ``X-EWA-Episode: <episode id>``, which the embedded sites key their state on.
Safety: only the embedded sites (and an explicit allowlist) are reachable (see safety.py).
Robustness: actions wait for the page to settle (settle.py); a crashed or closed browser is
relaunched on the next call and the episode's tabs are reopened at their last URLs.

``BrowserEnvironment`` is the class the registry names; it holds one episode's parts, split the
way microsoft/playwright-mcp splits Context, Tab and Response:

* session.py: the context's life (warm pool, refused requests, tab list, crash recovery, hand-back);
* tabs.py: a tab's events, navigation, snapshot and element locating;
* operations.py: the actions and the settling after them (actions.py is the tools' table);
* observation.py: the observation built from a snapshot (and a screenshot).
"""

from __future__ import annotations

import asyncio
from typing import Any, ClassVar, Literal

from ewa_mcp.core.environment import Environment, Observation
from .operations import BrowserActions
from .observation import observe
from .session import BrowserSession
from .tabs import Tab


class BrowserEnvironment(Environment):
    side: ClassVar[Literal["web", "embodied"]] = "web"
    name: ClassVar[str] = "browser"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.session = BrowserSession(episode.id, services)
        self.actions = BrowserActions(self.session)

    # What tests and tools read of the session.
    @property
    def tabs(self) -> list[Tab]:
        return self.session.tabs

    @property
    def active(self) -> int:
        return self.session.active

    @property
    def context(self) -> Any:
        return self.session.context

    @property
    def history(self) -> list[str]:
        return self.session.history

    @property
    def blocked(self) -> list[str]:
        return self.session.blocked

    @property
    def restarts(self) -> int:
        return self.session.restarts

    # ------------------------------------------------------------ lifecycle
    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        await self.session.start(task, options)

    async def close(self) -> None:
        """Returns once the context is let go of; its scrub for the next episode runs in the background."""
        await self.session.close()

    async def observe(self) -> Observation:
        await self.session.ensure_alive()
        return await observe(self.session)

    async def final_state(self) -> dict[str, Any]:
        s = self.session

        async def title_of(tab: Tab) -> str:
            if not tab.page.is_closed():
                try:
                    return await asyncio.wait_for(tab.page.title(), 2)
                except Exception:
                    pass
            return tab.last_title

        titles = await asyncio.gather(*[title_of(tab) for tab in s.tabs])  # one round trip for every tab
        tabs = []
        for tab, title in zip(s.tabs, titles, strict=True):
            url = tab.page.url if not tab.page.is_closed() else tab.last_url
            tabs.append({"url": url, "title": title, "site_url": s.site_url(url)})
        return {
            "tabs": tabs,
            "active_tab": s.active,
            "history": list(s.history),
            "site_history": [s.site_url(u) for u in s.history],
            "blocked": list(s.blocked),
            "restarts": s.restarts,
        }

    # ------------------------------------------------------------ actions (tools/browser.py)
    async def click(self, element: str) -> Observation:
        return await self.actions.click(element)

    async def hover(self, element: str) -> Observation:
        return await self.actions.hover(element)

    async def type(self, element: str, text: str, press_enter: bool = False) -> Observation:
        return await self.actions.type(element, text, press_enter)

    async def press(self, keys: str) -> Observation:
        return await self.actions.press(keys)

    async def scroll(self, direction: str) -> Observation:
        return await self.actions.scroll(direction)

    async def goto(self, url: str) -> Observation:
        return await self.actions.goto(url)

    async def go_back(self) -> Observation:
        return await self.actions.history_step("back")

    async def go_forward(self) -> Observation:
        return await self.actions.history_step("forward")

    async def new_tab(self, url: str | None = None) -> Observation:
        return await self.actions.new_tab(url)

    async def close_tab(self) -> Observation:
        return await self.actions.close_tab()

    async def tab_focus(self, index: int) -> Observation:
        return await self.actions.tab_focus(index)

    async def snapshot(self, viewport_only: bool | None = None, max_chars: int | None = None) -> Observation:
        """The accessibility tree as text, never an image, whatever the observation mode."""
        await self.session.ensure_alive()
        return await observe(self.session, viewport_only=viewport_only, max_chars=max_chars, view="tree")

    async def screenshot(self) -> Observation:
        """The Set-of-Marks screenshot and the list of marked elements, whatever the observation mode."""
        await self.session.ensure_alive()
        return await observe(self.session, view="screenshot")
