"""``ewa-mcp demo``: start the server in-process, play one episode through real MCP calls, print it."""

from __future__ import annotations

import tempfile
from pathlib import Path

import anyio
from mcp import Client

from .server import ServerConfig, build_server


def _first_text(result) -> str:
    return next((c.text for c in result.content if getattr(c, "type", "") == "text"), "")


async def _demo(run_dir: Path, task_id: str) -> int:
    mcp, episodes = build_server(ServerConfig(run_dir=run_dir))
    async with Client(mcp) as client:
        tools = await client.list_tools()
        print(f"server exposes {len(tools.tools)} tools: {', '.join(t.name for t in tools.tools)}\n")
        r = await client.call_tool("list_tasks", {"domain": "demo", "limit": 5})
        print(f"> list_tasks\n{_first_text(r)}\n")
        r = await client.call_tool("start_episode", {"task_id": task_id})
        if r.is_error:
            print(f"start_episode failed: {_first_text(r)}")
            return 1
        episode_id = r.structured_content["episode_id"]
        print(f"> start_episode {task_id}\n{_first_text(r)}\n")
        task = episodes.tasks.get(task_id)
        assert task is not None  # listed by list_tasks above
        for call in task.oracle:
            args = {"episode_id": episode_id, **call.args}
            r = await client.call_tool(call.tool, args)
            status = "error" if r.is_error else "ok"
            print(f"> {call.tool} {call.args} [{status}]\n{_first_text(r)[:600]}\n")
        r = await client.call_tool("episode_status", {"episode_id": episode_id})
        print(f"> episode_status\n{_first_text(r)}\n")
    print(f"recorded under {run_dir / episode_id}:")
    for path in sorted((run_dir / episode_id).iterdir()):
        print(f"  {path.name:20s} {path.stat().st_size:6d} bytes")
    return 0


def run_demo(task_id: str = "demo-hello", run_dir: Path | None = None) -> int:
    run_dir = run_dir or Path(tempfile.mkdtemp(prefix="ewa-demo-"))
    return anyio.run(_demo, run_dir, task_id)
