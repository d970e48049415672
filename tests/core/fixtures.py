"""A tiny pair of environments for exercising the episode protocol without any real domain."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Any

from mcp.server.mcpserver import MCPServer
from pydantic import Field


from ewa_mcp.core.environment import EnvError, Environment, Observation
from ewa_mcp.core.response import env_action


class CounterEnv(Environment):
    """Counts up; refuses negative increments (an action that must change nothing)."""

    side = "embodied"
    name = "counter"

    def __init__(self, episode: Any, services: Any):
        self.value = 0
        self.closed = False

    async def reset(self, task, options):
        self.value = int(task.metadata.get("counter_start", 0))

    async def observe(self) -> Observation:
        return Observation(text=f"counter is {self.value}", data={"value": self.value})

    async def add(self, amount: int) -> Observation:
        if amount < 0:
            raise EnvError(f"cannot add {amount}: amounts must be >= 0")
        self.value += amount
        return await self.observe()

    async def final_state(self) -> dict[str, Any]:
        return {"value": self.value}

    async def close(self) -> None:
        self.closed = True


class NoteEnv(CounterEnv):
    side = "web"
    name = "browser"

    async def observe(self) -> Observation:
        import io

        from PIL import Image

        buf = io.BytesIO()
        Image.new("RGB", (4, 4), (self.value * 40 % 256, 0, 0)).save(buf, format="PNG")
        return Observation(text=f"page {self.value}", data={"page": self.value}, images=[buf.getvalue()])


def register(mcp: MCPServer, episodes) -> None:
    @mcp.tool(description="test tool: add to the counter")
    async def counter_add(episode_id: str, amount: Annotated[int, Field(ge=-100, le=100)] = 1):
        return await env_action(episodes, episode_id, "counter_add", {"amount": amount}, "embodied",
                                lambda env: env.add(amount))

    @mcp.tool(description="test tool: turn the page")
    async def page_next(episode_id: str):
        return await env_action(episodes, episode_id, "page_next", {}, "web", lambda env: env.add(1))


def write_tasks(directory: Path, tasks: list[dict[str, Any]]) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "tasks.json"
    path.write_text(json.dumps(tasks), encoding="utf-8")
    return directory


def counter_task(task_id: str = "t-counter", step_limit: int = 5, start: str = "embodied") -> dict[str, Any]:
    return {
        "id": task_id,
        "domain": "demo",
        "intent": "count to three",
        "start": {"environment": start, "web": {"start_url": "home:/"},
                  "embodied": {"kind": "kitchen", "scene": "FloorPlan1"}},
        "step_limit": step_limit,
        "metadata": {"counter_start": 1},
        "answer": {"kind": "text", "must_include": ["three"]},
        "oracle": [{"tool": "counter_add", "args": {"amount": 2}}],
    }


def listed_tools(tmp_path: Path) -> list[Any]:
    """Every tool the full server lists (an in-process client's tools/list)."""
    import anyio
    from mcp import Client

    from ewa_mcp.server import ServerConfig, build_server

    async def main() -> list[Any]:
        mcp, _ = build_server(ServerConfig(run_dir=tmp_path))
        async with Client(mcp) as client:
            return (await client.list_tools()).tools

    return anyio.run(main)
