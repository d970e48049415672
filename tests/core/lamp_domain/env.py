"""The lamp: off or on; the task's start says which (start.embodied = {"kind": "lamp", "lit": false})."""

from __future__ import annotations

from typing import Any

from ewa_mcp.core.environment import EnvError, Environment, Observation


class LampEnvironment(Environment):
    side = "embodied"
    name = "lamp"

    def __init__(self, episode: Any, services: Any):
        self.lit = False
        self.presses = 0

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        self.lit = bool(getattr(task.start.embodied, "lit", False))

    async def observe(self) -> Observation:
        return Observation(text=f"the lamp is {'on' if self.lit else 'off'}", data={"lit": self.lit})

    async def switch(self, on: bool) -> Observation:
        if on == self.lit:
            raise EnvError(f"the lamp is already {'on' if on else 'off'}; switch it the other way")
        self.lit = on
        self.presses += 1
        return await self.observe()

    async def final_state(self) -> dict[str, Any]:
        return {"lit": self.lit, "presses": self.presses}
