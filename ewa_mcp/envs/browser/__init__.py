"""The web environment: a Playwright-driven Chromium with WebArena's action grammar.

Importing this package does not import Playwright; ``ewa_mcp.envs.browser.env`` does.
``find_chromium`` (in ``ewa_mcp.envs.browser.chromium``) is the browser discovery other parts may reuse.
"""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, EnvironmentSpec

BROWSER = EnvironmentSpec("browser", "web", f"{__name__}.env:BrowserEnvironment", f"{__name__}.tools",
                          "browser_* tools", tool_order=20, start=f"{__name__}.goals:WebStart",
                          goals=tuple(f"{__name__}.goals:{model}"
                                      for model in ("RecipeCompleted", "OrderPlaced", "OrdersSplit", "DirectionsShown",
                                                    "PageVisited", "RecipesCompleted")),
                          options=f"{__name__}.options:BrowserOptions")

# Web goals every domain with a browser may carry (graded by this world's checks.py).
WEB_GOALS = ("recipe_completed", "order_placed", "orders_split", "directions_shown", "page_visited",
             "recipes_completed")
WEB_CHECKS = {kind: f"{__name__}.checks:web_goal" for kind in WEB_GOALS}

DOMAINS = [Domain("demo", (BROWSER,), difficulties=(), scored=False)]
