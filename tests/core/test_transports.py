"""Smoke tests that spawn the real server process over stdio and streamable HTTP."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from mcp import Client, StdioServerParameters

from .servers import serve, stop

pytestmark = pytest.mark.anyio


def _env(tmp_path):
    return {**os.environ, "EWA_RUNS_DIR": str(tmp_path / "runs")}


async def _play(client) -> str:
    r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
    assert not r.is_error, r.content
    ep = r.structured_content["episode_id"]
    r = await client.call_tool("finish_episode", {"episode_id": ep, "answer": "hello"})
    assert r.structured_content["status"] == "finished"
    return ep


async def test_stdio_server(tmp_path):
    params = StdioServerParameters(command=sys.executable, args=["-m", "ewa_mcp", "serve", "--transport", "stdio"],
                                   env=_env(tmp_path))
    async with Client(params) as client:
        names = {t.name for t in (await client.list_tools()).tools}
        assert {"start_episode", "finish_episode"} <= names
        ep = await _play(client)
    assert list((tmp_path / "runs").glob(f"*/{ep}/final_state.json"))


async def test_http_server(tmp_path):
    proc, port = serve(tmp_path)
    try:
        async with Client(f"http://127.0.0.1:{port}/mcp") as client:
            ep = await _play(client)
        assert list((tmp_path / "runs").glob(f"*/{ep}/final_state.json"))
    finally:
        stop(proc)


def test_http_refuses_public_host_without_flag(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--host", "0.0.0.0"],
                       env=_env(tmp_path), capture_output=True, text=True, timeout=30)
    assert r.returncode == 2 and "--allow-remote" in r.stderr
