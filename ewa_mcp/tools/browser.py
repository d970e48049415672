"""Browser tools: WebArena's action grammar on an episode's web environment.

click, type, hover, press, scroll, new_tab, close_tab, tab_focus, goto, go_back, go_forward,
plus snapshot and screenshot on demand (steps like every call). Every tool returns the new
observation. This module must not import Playwright: the server imports every tool group at
start, and a server that never runs a web task never needs a browser.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated, Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp_types import CallToolResult
from pydantic import Field

from ..environment import EnvError, Observation
from ..episodes import EpisodeManager
from ..response import StepOutput, env_action
from .adapter import define_tool
from .core import EpisodeId

Element = Annotated[
    str,
    Field(
        min_length=1,
        max_length=500,
        description="an element id from the latest observation (\"12\" or \"[12]\"), or a role and name such as "
        "\"link 'Tomato Bruschetta'\" or \"button 'Next'\" (append #2 for the second of several matches)",
    ),
]
Url = Annotated[
    str,
    Field(
        min_length=1,
        max_length=2000,
        description="a site-relative URL such as \"recipes:/\" or \"shop:/product/7\", an absolute URL of an embedded "
        "site, or a path (\"/search?q=egg\") on the current site",
    ),
]
Result = Annotated[CallToolResult, StepOutput]
# What every action returns, by the episode's observation mode (the start_episode option).
OBSERVES = (" Returns the page afterwards as the episode's observation mode shows it: text mode the accessibility "
            "tree; vision mode a Set-of-Marks screenshot plus the list of its marked elements; both mode the tree "
            "and the screenshot.")


def _method(name: str, *args: Any, **kwargs: Any) -> Callable[[Any], Awaitable[Observation]]:
    async def call(env: Any) -> Observation:
        method = getattr(env, name, None)
        if method is None:
            raise EnvError(f"this episode's web environment ({type(env).__name__}) has no {name} action")
        return await method(*args, **kwargs)

    return call


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    async def act(episode_id: str, tool: str, args: dict[str, Any], method: str, *call_args: Any,
                  **call_kwargs: Any) -> CallToolResult:
        return await env_action(episodes, episode_id, tool, args, "web", _method(method, *call_args, **call_kwargs))

    @define_tool(
        mcp, title="Click an element", effect="destructive",
        description="Click an element of the current page." + OBSERVES,
    )
    async def browser_click(episode_id: EpisodeId, element: Element) -> Result:
        return await act(episode_id, "browser_click", {"element": element}, "click", element)

    @define_tool(
        mcp, title="Type text", effect="destructive",
        description="Type text into a text field (replacing its content), optionally pressing Enter after. "
        "For a drop-down (combobox), the text chooses the option with that label." + OBSERVES
    )
    async def browser_type(
        episode_id: EpisodeId,
        element: Element,
        text: Annotated[str, Field(max_length=10_000)],
        press_enter: bool = False,
    ) -> Result:
        args = {"element": element, "text": text, "press_enter": press_enter}
        return await act(episode_id, "browser_type", args, "type", element, text, press_enter)

    @define_tool(
        mcp, title="Hover over an element", effect="act",
        description="Move the mouse over an element (opens hover menus)." + OBSERVES,
    )
    async def browser_hover(episode_id: EpisodeId, element: Element) -> Result:
        return await act(episode_id, "browser_hover", {"element": element}, "hover", element)

    @define_tool(
        mcp, title="Press keys", effect="destructive",
        description="Press a key or key combination on the focused element, e.g. Enter, Tab, ArrowDown, "
        "Escape, Control+a." + OBSERVES,
    )
    async def browser_press(
        episode_id: EpisodeId, keys: Annotated[str, Field(min_length=1, max_length=100)]
    ) -> Result:
        return await act(episode_id, "browser_press", {"keys": keys}, "press", keys)

    @define_tool(
        mcp, title="Scroll the page", effect="act",
        description="Scroll the page by most of a screen in a direction." + OBSERVES,
    )
    async def browser_scroll(episode_id: EpisodeId, direction: Literal["up", "down", "left", "right"]) -> Result:
        return await act(episode_id, "browser_scroll", {"direction": direction}, "scroll", direction)

    @define_tool(
        mcp, title="Open a new tab", effect="act",
        description="Open a new tab (blank, or at a URL of an embedded site) and make it current." + OBSERVES,
    )
    async def browser_new_tab(episode_id: EpisodeId, url: Url | None = None) -> Result:
        return await act(episode_id, "browser_new_tab", {"url": url}, "new_tab", url)

    @define_tool(
        mcp, title="Close the current tab", effect="act",
        description="Close the current tab; the tab to its left becomes current." + OBSERVES,
    )
    async def browser_close_tab(episode_id: EpisodeId) -> Result:
        return await act(episode_id, "browser_close_tab", {}, "close_tab")

    @define_tool(
        mcp, title="Switch to a tab", effect="act",
        description="Make the tab with this index (from the observation's tab list, 0-based) current." + OBSERVES,
    )
    async def browser_tab_focus(episode_id: EpisodeId, index: Annotated[int, Field(ge=0, le=100)]) -> Result:
        return await act(episode_id, "browser_tab_focus", {"index": index}, "tab_focus", index)

    @define_tool(
        mcp, title="Go to a URL", effect="act",
        description="Open a URL of an embedded site in the current tab." + OBSERVES,
    )
    async def browser_goto(episode_id: EpisodeId, url: Url) -> Result:
        return await act(episode_id, "browser_goto", {"url": url}, "goto", url)

    @define_tool(
        mcp, title="Go back", effect="act",
        description="Go back to the previous page of the current tab." + OBSERVES,
    )
    async def browser_go_back(episode_id: EpisodeId) -> Result:
        return await act(episode_id, "browser_go_back", {}, "go_back")

    @define_tool(
        mcp, title="Go forward", effect="act",
        description="Go forward to the next page of the current tab (after going back)." + OBSERVES,
    )
    async def browser_go_forward(episode_id: EpisodeId) -> Result:
        return await act(episode_id, "browser_go_forward", {}, "go_forward")

    @define_tool(
        mcp, title="Page snapshot (accessibility tree)", effect="look",
        description="The current page's accessibility tree as text, without acting (it counts as a step, like every "
        "call). It is always the tree and never an image, whatever the observation mode (browser_screenshot gives "
        "the image). viewport_only limits it to what is on screen; max_chars sets the size budget."
    )
    async def browser_snapshot(
        episode_id: EpisodeId,
        viewport_only: bool | None = None,
        max_chars: Annotated[int | None, Field(ge=500, le=500_000)] = None,
    ) -> Result:
        args = {"viewport_only": viewport_only, "max_chars": max_chars}
        return await act(episode_id, "browser_snapshot", args, "snapshot", viewport_only, max_chars)

    @define_tool(
        mcp, title="Page screenshot", effect="look",
        description="A screenshot of the current tab's viewport with each interactive element boxed and labelled by "
        "its id (Set-of-Marks), plus the list of marked elements as text; it counts as a step, like every call. It "
        "is always the image and never the accessibility tree, whatever the observation mode (browser_snapshot "
        "gives the tree)."
    )
    async def browser_screenshot(episode_id: EpisodeId) -> Result:
        return await act(episode_id, "browser_screenshot", {}, "screenshot")
