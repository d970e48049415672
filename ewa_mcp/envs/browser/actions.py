"""The browser's action table: one entry per tool (WebArena's actions and the two looks), from which tools.py
declares them. Each runs the environment's method of the same job (operations.py, through env.py)."""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated, Any, Literal

from pydantic import Field

from ewa_mcp.core.environment import EnvError, Observation
from ewa_mcp.core.tool_table import Param, ToolAction

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
# What every action returns, by the episode's observation mode (the start_episode option).
OBSERVES = (" Returns the page afterwards as the episode's observation mode shows it: text mode the accessibility "
            "tree (only the lines that changed, when you read the page before; browser_snapshot shows it whole); "
            "vision mode a Set-of-Marks screenshot plus the list of its marked elements; both mode the tree "
            "and the screenshot.")




def _method(name: str, *params: str) -> Callable[..., Awaitable[Observation]]:
    """Run the web environment's ``name`` with the tool's ``params`` in order."""

    async def call(env: Any, **args: Any) -> Observation:
        method = getattr(env, name, None)
        if method is None:
            raise EnvError(f"this episode's web environment ({type(env).__name__}) has no {name} action")
        return await method(*(args[p] for p in params))

    return call


def _web(name: str, title: str, effect: Any, description: str, method: str, params: dict[str, Param]) -> ToolAction:
    return ToolAction(name, title, effect, description, _method(method, *params), params, side="web", keep_none=True)


ACTIONS = [
    _web("browser_click", "Click an element", "destructive", "Click an element of the current page." + OBSERVES,
         "click", {"element": Param(Element)}),
    _web("browser_type", "Type text", "destructive",
         "Type text into a text field (replacing its content), optionally pressing Enter after. "
         "For a drop-down (combobox), the text chooses the option with that label." + OBSERVES,
         "type", {"element": Param(Element), "text": Param(Annotated[str, Field(max_length=10_000)]),
                  "press_enter": Param(bool, False)}),
    _web("browser_hover", "Hover over an element", "act",
         "Move the mouse over an element (opens hover menus)." + OBSERVES, "hover", {"element": Param(Element)}),
    _web("browser_press", "Press keys", "destructive",
         "Press a key or key combination on the focused element, e.g. Enter, Tab, ArrowDown, "
         "Escape, Control+a." + OBSERVES, "press", {"keys": Param(Annotated[str, Field(min_length=1, max_length=100)])}),
    _web("browser_scroll", "Scroll the page", "act", "Scroll the page by most of a screen in a direction." + OBSERVES,
         "scroll", {"direction": Param(Literal["up", "down", "left", "right"])}),
    _web("browser_new_tab", "Open a new tab", "act",
         "Open a new tab (blank, or at a URL of an embedded site) and make it current." + OBSERVES,
         "new_tab", {"url": Param(Url | None, None)}),
    _web("browser_close_tab", "Close the current tab", "act",
         "Close the current tab; the tab to its left becomes current." + OBSERVES, "close_tab", {}),
    _web("browser_tab_focus", "Switch to a tab", "act",
         "Make the tab with this index (from the observation's tab list, 0-based) current." + OBSERVES,
         "tab_focus", {"index": Param(Annotated[int, Field(ge=0, le=100)])}),
    _web("browser_goto", "Go to a URL", "act", "Open a URL of an embedded site in the current tab." + OBSERVES,
         "goto", {"url": Param(Url)}),
    _web("browser_go_back", "Go back", "act", "Go back to the previous page of the current tab." + OBSERVES,
         "go_back", {}),
    _web("browser_go_forward", "Go forward", "act",
         "Go forward to the next page of the current tab (after going back)." + OBSERVES, "go_forward", {}),
    _web("browser_snapshot", "Page snapshot (accessibility tree)", "look",
         "The current page's accessibility tree as text, without acting (it counts as a step, like every "
         "call). It is always the tree and never an image, whatever the observation mode (browser_screenshot gives "
         "the image). viewport_only limits it to what is on screen; max_chars sets the size budget.",
         "snapshot", {"viewport_only": Param(bool | None, None),
                      "max_chars": Param(Annotated[int | None, Field(ge=500, le=500_000)], None)}),
    _web("browser_screenshot", "Page screenshot", "look",
         "A screenshot of the current tab's viewport with each interactive element boxed and labelled by "
         "its id (Set-of-Marks), plus the list of marked elements as text; it counts as a step, like every call. It "
         "is always the image and never the accessibility tree, whatever the observation mode (browser_snapshot "
         "gives the tree).", "screenshot", {}),
]
