"""The documented client configurations (examples/clients/) launch the server as written: each runs
`uvx ewa-mcp serve`, which is the package's `ewa-mcp` console script with `serve`; here that script is the
installed one (uvx would fetch the same from PyPI), started over stdio with the configuration's arguments."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest
from mcp import Client, StdioServerParameters

from ewa_mcp.core.paths import REPO_ROOT

pytestmark = pytest.mark.anyio
CLIENTS = REPO_ROOT / "examples" / "clients"


def _entries() -> dict[str, dict]:
    out = {}
    for name, key in (("claude_desktop_config.json", "mcpServers"), ("cursor_mcp.json", "mcpServers"),
                      ("vscode_mcp.json", "servers")):
        out[name] = json.loads((CLIENTS / name).read_text())[key]["ewa-mcp"]
    return out


def test_every_client_snippet_runs_uvx_ewa_mcp_serve():
    for name, entry in _entries().items():
        assert (entry["command"], entry["args"]) == ("uvx", ["ewa-mcp", "serve"]), name
    assert "-- uvx ewa-mcp serve" in (CLIENTS / "claude_code.sh").read_text()
    assert '"command": "uvx", "args": ["ewa-mcp", "serve"]' in (CLIENTS / "openai_agents_sdk.py").read_text()


async def test_claude_desktop_config_starts_the_server(tmp_path):
    entry = _entries()["claude_desktop_config.json"]
    package, *args = entry["args"]  # uvx PACKAGE ARGS runs the package's console script of that name
    command = Path(sys.executable).parent / package
    assert command.exists()
    env = {**os.environ, **{k: v.replace("/ABSOLUTE/PATH/TO/ewa-runs", str(tmp_path / "runs"))
                            for k, v in entry["env"].items()}}
    async with Client(StdioServerParameters(command=str(command), args=args, env=env)) as client:
        names = {t.name for t in (await client.list_tools()).tools}
        prompts = {p.name for p in (await client.list_prompts()).prompts}
        r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
        ep = r.structured_content["episode_id"]
        await client.call_tool("finish_episode", {"episode_id": ep})
    assert {"list_tasks", "start_episode", "finish_episode"} <= names
    assert {"cooking", "navigation", "geolocation"} <= prompts
    assert list((tmp_path / "runs").glob(f"*/{ep}/final_state.json"))
