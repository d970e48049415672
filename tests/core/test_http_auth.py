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


def _post(address: str, port: int, **headers: str) -> httpx.Response:
    return httpx.post(f"http://{address}:{port}/mcp", json=INITIALIZE, headers=dict(HEADERS, **headers), timeout=10)


async def test_another_loopback_address_needs_the_token_and_checks_host_and_origin(tmp_path):
    """127.0.0.2 is loopback but not a default bind: it gets a token like a remote bind, and a forged Host
    (DNS rebinding) is refused even with the token."""
    proc, port = serve(tmp_path, "--host", "127.0.0.2", address="127.0.0.2")
    try:
        printed: list[str] = []
        while not printed or not (printed[-1].startswith("MCP endpoint") or printed[-1] == ""):
            printed.append(proc.stderr.readline())
        match = re.search(r"bearer token \(shown once[^)]*\): (\S+)", "".join(printed))
        assert match, printed
        token = match.group(1)
        _assert_refused(_post("127.0.0.2", port), "no Authorization header")
        bearer = f"Bearer {token}"
        assert _post("127.0.0.2", port, Authorization=bearer).status_code == 200
        forged = _post("127.0.0.2", port, Authorization=bearer, Host="attacker.example")
        assert forged.status_code == 421 and "EWA_ALLOWED_HOSTS" in forged.json()["error_description"]
        page = _post("127.0.0.2", port, Authorization=bearer, Origin="http://attacker.example")
        assert page.status_code == 403 and "attacker.example" in page.json()["error_description"]
        assert _post("127.0.0.2", port, Authorization=bearer, Origin=f"http://127.0.0.2:{port}").status_code == 200
    finally:
        stop(proc)


async def test_host_and_origin_are_checked_past_loopback(tmp_path):
    proc, port = serve(tmp_path, "--host", "0.0.0.0", "--allow-remote", "--token", TOKEN,
                       env={"EWA_ALLOWED_HOSTS": "ewa.example.org"})
    try:
        bearer = f"Bearer {TOKEN}"
        assert _post("127.0.0.1", port, Authorization=bearer).status_code == 200
        assert _post("127.0.0.1", port, Authorization=bearer, Host=f"ewa.example.org:{port}").status_code == 200
        assert _post("127.0.0.1", port, Authorization=bearer, Host="rebound.example").status_code == 421
        assert _post("127.0.0.1", port, Authorization=bearer, Origin="https://evil.example").status_code == 403
    finally:
        stop(proc)


async def test_a_forged_host_is_refused_on_the_default_bind(tmp_path):
    proc, port = serve(tmp_path)
    try:
        assert _post("127.0.0.1", port).status_code == 200  # no token on the default bind
        assert _post("127.0.0.1", port, Host="rebound.example").status_code == 421
        assert _post("127.0.0.1", port, Origin="http://rebound.example").status_code == 403
    finally:
        stop(proc)


def test_only_the_default_binds_go_without_a_token():
    from ewa_mcp.http_serve import allowed_hosts, choose_token

    for host in ("127.0.0.1", "localhost", "::1", "[::1]"):
        assert choose_token(host, None) == (None, False)
    for host in ("127.0.0.2", "127.1.2.3", "0.0.0.0", "::", "10.0.0.5"):
        token, generated = choose_token(host, None)
        assert generated and token and len(token) >= 32
    assert "127.0.0.2" in allowed_hosts("127.0.0.2") and "rebound.example" not in allowed_hosts("127.0.0.2")
    assert "[fd00::5]" in allowed_hosts("fd00::5")
