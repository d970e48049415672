"""The documented Claude Desktop configuration launches the server as written (path filled in)."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest
from mcp import Client, StdioServerParameters

from ewa_mcp.core.paths import REPO_ROOT

pytestmark = pytest.mark.anyio


async def test_claude_desktop_config_starts_the_server(tmp_path):
    config = json.loads((REPO_ROOT / "examples" / "clients" / "claude_desktop_config.json").read_text())
    entry = config["mcpServers"]["ewa-mcp"]
    command = entry["command"].replace("/ABSOLUTE/PATH/TO/ewa-mcp/.venv/bin", str(Path(sys.executable).parent))
    assert Path(command).name == "ewa-mcp" and Path(command).exists()
    env = {**os.environ, **{k: v.replace("/ABSOLUTE/PATH/TO/ewa-mcp", str(tmp_path)) for k, v in entry["env"].items()}}
    async with Client(StdioServerParameters(command=command, args=entry["args"], env=env)) as client:
        names = {t.name for t in (await client.list_tools()).tools}
        r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
        ep = r.structured_content["episode_id"]
        await client.call_tool("finish_episode", {"episode_id": ep})
    assert {"list_tasks", "start_episode", "finish_episode"} <= names
    assert list((tmp_path / "runs").glob(f"*/{ep}/final_state.json"))
