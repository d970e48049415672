"""The one place that names the environments and tool groups the server is built from.

Entries are import paths so that a server that never touches, say, the browser never
imports Playwright. A domain plugs in by adding a line here.
"""

from __future__ import annotations

import importlib
from typing import Any

# environment name -> "module:Class"; the class takes (episode, services).
ENVIRONMENTS: dict[str, str] = {
    "browser": "ewa_mcp.web.env:BrowserEnvironment",
    "kitchen": "ewa_mcp.indoor.env:KitchenEnvironment",
    "street": "ewa_mcp.outdoor.env:StreetEnvironment",
    "geo": "ewa_mcp.geo.env:GeoEnvironment",
}

# modules exposing register(mcp, episodes); core first so its tools list first.
TOOL_GROUPS: list[str] = [
    "ewa_mcp.tools.core",
    "ewa_mcp.tools.street",
    "ewa_mcp.tools.browser",
    "ewa_mcp.tools.kitchen",
    "ewa_mcp.tools.geo",
]


def load_object(path: str) -> Any:
    module_name, _, attr = path.partition(":")
    return getattr(importlib.import_module(module_name), attr)

