"""A real `ewa-mcp serve --transport http` process for tests: started on a free loopback port, waited for, stopped."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time

import httpx


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def serve(tmp_path, *args: str, env: dict[str, str] | None = None,
          address: str = "127.0.0.1") -> tuple[subprocess.Popen, int]:
    """Start the server (runs under tmp_path/runs, no token from the caller's environment) and wait until it answers
    at ``address``."""
    port = free_port()
    environ = {k: v for k, v in os.environ.items() if k != "EWA_MCP_TOKEN"}
    environ.update({"EWA_RUNS_DIR": str(tmp_path / "runs"), **(env or {})})
    proc = subprocess.Popen([sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--port", str(port),
                             *args], env=environ, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while True:
        try:
            httpx.get(f"http://{address}:{port}/mcp", timeout=1)
            return proc, port
        except httpx.TransportError:
            if proc.poll() is not None or time.monotonic() > deadline:
                proc.kill()
                raise AssertionError(f"the server did not start: {proc.stderr.read()}") from None
            time.sleep(0.1)


def stop(proc: subprocess.Popen) -> str:
    """Stop the server; returns what it wrote to stderr."""
    proc.terminate()
    try:
        _, err = proc.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        proc.kill()
        _, err = proc.communicate()
    return err
