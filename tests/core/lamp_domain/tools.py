"""The lamp's one tool. Its name starts with the environment's registry name, so a lamp tool called on
another domain's episode is refused before it runs."""

from __future__ import annotations

from typing import Literal

from ewa_mcp.response import env_action
from ewa_mcp.tools.adapter import define_tool


def register(mcp, episodes) -> None:
    @define_tool(mcp, title="Switch the lamp", effect="act", description="Switch the lamp on or off.")
    async def lamp_switch(episode_id: str, state: Literal["on", "off"]):
        return await env_action(episodes, episode_id, "lamp_switch", {"state": state}, "embodied",
                                lambda env: env.switch(state == "on"))
