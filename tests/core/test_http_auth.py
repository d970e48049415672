"""The HTTP server's bearer token: required past loopback (and wherever one is given), checked on
every request over real HTTP; loopback without a token stays open (test_transports.py)."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import httpx
import pytest
from mcp import Client
from mcp.client.streamable_http import streamable_http_client
from mcp.shared._httpx_utils import create_mcp_http_client
from mcp.shared.exceptions import MCPError

from .servers import serve, stop

pytestmark = pytest.mark.anyio

TOKEN = "test-token-0123456789abcdef"
INITIALIZE = {"jsonrpc": "2.0", "id": 1, "method": "initialize",
              "params": {"protocolVersion": "2025-06-18", "capabilities": {},
                         "clientInfo": {"name": "probe", "version": "0"}}}
HEADERS = {"Accept": "application/json, text/event-stream", "Content-Type": "application/json"}


def _initialize(port: int, authorization: str | None = None) -> httpx.Response:
    headers = dict(HEADERS, **({"Authorization": authorization} if authorization is not None else {}))
    return httpx.post(f"http://127.0.0.1:{port}/mcp", json=INITIALIZE, headers=headers, timeout=10)


def _assert_refused(response: httpx.Response, problem: str) -> None:
    assert response.status_code == 401, response.text
    assert response.headers["www-authenticate"].startswith('Bearer realm="ewa-mcp"')
    description = response.json()["error_description"]
    assert "requires a bearer token" in description and problem in description
    assert "Authorization: Bearer <token>" in description and TOKEN not in response.text


async def _play(port: int, token: str) -> None:
    http = create_mcp_http_client(headers={"Authorization": f"Bearer {token}"})
    async with http, Client(streamable_http_client(f"http://127.0.0.1:{port}/mcp", http_client=http)) as client:
        r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
        assert not r.is_error, r.content
        r = await client.call_tool("finish_episode", {"episode_id": r.structured_content["episode_id"],
                                                      "answer": "hello"})
        assert r.structured_content["status"] == "finished"


@pytest.mark.parametrize("how", ["flag", "env"])
async def test_a_given_token_is_required_on_every_request(tmp_path, how):
    args, env = (["--token", TOKEN], None) if how == "flag" else ([], {"EWA_MCP_TOKEN": TOKEN})
    proc, port = serve(tmp_path, *args, env=env)
    try:
        _assert_refused(_initialize(port), "no Authorization header")
        _assert_refused(_initialize(port, "Bearer not-the-token-at-all-000"), "the bearer token is wrong")
        _assert_refused(_initialize(port, f"Basic {TOKEN}"), "is not 'Bearer <token>'")
        _assert_refused(_initialize(port, f"Bearer {TOKEN}x"), "wrong")
        _assert_refused(httpx.get(f"http://127.0.0.1:{port}/anything", timeout=10), "no Authorization header")
        accepted = _initialize(port, f"Bearer {TOKEN}")
        assert accepted.status_code == 200, accepted.text
        assert "serverInfo" in accepted.text
        await _play(port, TOKEN)  # every request of a real session carries it
        with pytest.RaisesGroup(MCPError, flatten_subgroups=True):  # the 401, as the client reports it
            async with Client(f"http://127.0.0.1:{port}/mcp") as client:
                await client.list_tools()
    finally:
        err = stop(proc)
    assert TOKEN not in err  # a given token is never echoed


async def test_serving_past_loopback_generates_and_prints_a_token(tmp_path):
    proc, port = serve(tmp_path, "--host", "0.0.0.0", "--allow-remote")
    try:
        printed: list[str] = []  # all printed before the port opened, the endpoint last
        while not printed or not (printed[-1].startswith("MCP endpoint") or printed[-1] == ""):
            printed.append(proc.stderr.readline())
        match = re.search(r"bearer token \(shown once[^)]*\): (\S+)", "".join(printed))
        assert match, printed
        token = match.group(1)
        assert len(token) >= 32
        _assert_refused(_initialize(port), "no Authorization header")
        _assert_refused(_initialize(port, f"Bearer {TOKEN}"), "the bearer token is wrong")
        assert _initialize(port, f"Bearer {token}").status_code == 200
        await _play(port, token)
    finally:
        err = stop(proc)
    assert token not in err  # shown once


def test_a_short_token_is_refused_before_serving(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--token", "abc"],
                       env={**os.environ, "EWA_RUNS_DIR": str(tmp_path / "runs")}, capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 2 and "at least 16 characters" in r.stderr


def test_loopback_detection():
    from ewa_mcp.http_serve import is_loopback_host

    assert all(map(is_loopback_host, ["127.0.0.1", "localhost", "::1", "[::1]", "127.0.0.2"]))
    assert not any(map(is_loopback_host, ["0.0.0.0", "::", "10.0.0.5", "example.org"]))
