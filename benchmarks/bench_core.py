"""Round-trip latency of a trivial tool (episode_status) in-process, over stdio and over HTTP.

Prints JSON: p50/p95 in milliseconds per transport. Target: in-process p50 <= 1 ms.
"""

from __future__ import annotations

import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import anyio
import httpx
from mcp import Client, StdioServerParameters

from ewa_mcp.server import ServerConfig, build_server

import logging
logging.getLogger("httpx").setLevel(logging.WARNING)  # one line per request otherwise

N = int(os.environ.get("BENCH_N", "300"))


def pct(values: list[float], q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, int(round(q * (len(values) - 1))))]


async def measure(client) -> dict[str, float]:
    r = await client.call_tool("start_episode", {"task_id": "demo-hello"})
    ep = r.structured_content["episode_id"]
    for _ in range(20):  # warm-up
        await client.call_tool("episode_status", {"episode_id": ep})
    times = []
    for _ in range(N):
        t0 = time.perf_counter()
        r = await client.call_tool("episode_status", {"episode_id": ep})
        times.append((time.perf_counter() - t0) * 1000)
        assert not r.is_error
    await client.call_tool("finish_episode", {"episode_id": ep})
    return {"p50_ms": round(statistics.median(times), 3), "p95_ms": round(pct(times, 0.95), 3), "n": N}


async def main() -> None:
    tmp = tempfile.mkdtemp(prefix="ewa-bench-")
    env = {**os.environ, "EWA_RUNS_DIR": tmp}
    results = {}
    mcp, _ = build_server(ServerConfig(run_dir=Path(tmp) / "inproc"))
    async with Client(mcp) as client:
        results["in_process"] = await measure(client)
    params = StdioServerParameters(command=sys.executable, args=["-m", "ewa_mcp", "serve"], env=env)
    async with Client(params) as client:
        results["stdio"] = await measure(client)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen([sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--port", str(port)],
                            env=env, stderr=subprocess.DEVNULL)
    try:
        for _ in range(300):
            try:
                httpx.get(f"http://127.0.0.1:{port}/mcp", timeout=1)
                break
            except httpx.TransportError:
                time.sleep(0.1)
        async with Client(f"http://127.0.0.1:{port}/mcp") as client:
            results["http"] = await measure(client)
    finally:
        proc.terminate()
        proc.wait()
    results["target"] = {"in_process_p50_ms": 1.0, "met": results["in_process"]["p50_ms"] <= 1.0}
    print(json.dumps({"benchmark": "episode_status round trip", **results}, indent=2))


if __name__ == "__main__":
    anyio.run(main)
