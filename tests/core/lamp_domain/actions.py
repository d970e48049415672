"""The lamp's action table: one tool, lamp_switch."""

from __future__ import annotations

from typing import Any, Literal

from ewa_mcp.core.environment import Observation
from ewa_mcp.core.tool_table import Param, ToolAction


async def _switch(env: Any, state: str) -> Observation:
    result: Observation = await env.switch(state == "on")
    return result


ACTIONS = [
    ToolAction("lamp_switch", "Switch the lamp", "act", "Switch the lamp on or off.", _switch,
               {"state": Param(Literal["on", "off"])}),
]
