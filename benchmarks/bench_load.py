"""Throughput under training load: many concurrent episodes in one server over streamable HTTP.

Starts one real ``ewa-mcp serve --transport http`` process and opens ``--kitchen`` kitchen episodes and
``--street`` street episodes at once (default 128 + 128 = 256), each from its own MCP client session (its own
HTTP connection), plus ``--web`` whole web episodes (navigation tasks with their map site; default 0, 64 where the
machine allows). Every client starts its episode, plays the task's oracle (kitchen: teleport, pick up, slice, put...;
street: moves; web: the map site's directions, then the walk) for up to ``--steps`` calls, and finishes it. All
clients run at the same time; an episode that finished is followed by the next one (``--rounds``).

The kitchen and street episodes are the walk and kitchen part of suite tasks (``embodied_only`` variants: no
browser), the shape of an RL rollout worker's traffic. Prints one JSON object:

- ``errors``: transport failures (an exception on a call: connection, timeout, protocol), target 0; then
  ``refused_at_cap``: start_episode refused by the admission cap (the server's back-pressure, named in the
  refusal), and ``tool_errors``: other calls the server answered with an error (a step, as for any agent);
- ``latency_ms``: p50/p95/max per call, over all calls, and per kind of episode;
- ``steps_per_s``: tool calls answered per second over the whole run;
- ``server_memory_mb``: the server's process tree (Python, and Playwright's driver and Chromium with --web), PSS
  at its peak (sampled each second) and at the start;
- ``load_average``: the 1-minute load average at the start, its peak and the end; the machine's core count.

    .venv/bin/python benchmarks/bench_load.py [--kitchen 128] [--street 128] [--web 0] [--steps 20] [--rounds 1]
        [--think-s S] [--max-episodes N]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import httpx
from mcp import Client
from mcp.client.streamable_http import streamable_http_client
from mcp.shared._httpx_utils import create_mcp_http_client

from ewa_mcp.core.taskmodel import Task, TaskStore
from ewa_mcp.task_variants import embodied_only
from ewa_mcp.taskgen import write_tasks
from ewa_mcp.taskgen.splits import public_test_tasks


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def tree_pss_mb(pid: int) -> float:
    """PSS of a process and all its descendants (MB)."""
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                ppid = int((entry / "stat").read_text().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(ppid, []).append(int(entry.name))
    total, todo = 0, [pid]
    while todo:
        p = todo.pop()
        todo.extend(children.get(p, []))
        try:
            for line in Path(f"/proc/{p}/smaps_rollup").read_text().splitlines():
                if line.startswith("Pss:"):
                    total += int(line.split()[1])
        except OSError:
            pass
    return round(total / 1024, 1)


def describe(exc: BaseException) -> str:
    """The innermost exception of a task group's, which is the one that says what went wrong."""
    while isinstance(exc, BaseExceptionGroup) and exc.exceptions:
        exc = exc.exceptions[0]
    return f"{type(exc).__name__}: {str(exc)[:200]}"


def percentile(values: list[float], q: float) -> float:
    if not values:
        return 0.0
    ordered = sorted(values)
    return round(ordered[min(len(ordered) - 1, int(q * len(ordered)))], 1)


def load_tasks(kinds: dict[str, int]) -> tuple[list[Task], dict[str, list[Task]]]:
    """Web-free variants of suite tasks (kitchen, street) and whole navigation tasks (web)."""
    cooking = [t for t in public_test_tasks("cooking") if not t.metadata.get("buy")]
    navigation = [t for t in public_test_tasks("navigation") if len(t.embodied_goals) == 1]
    variants = {"kitchen": [embodied_only(t, f"load-{t.id}") for t in cooking[: max(1, kinds["kitchen"])]],
                "street": [embodied_only(t, f"load-{t.id}") for t in navigation[: max(1, kinds["street"])]],
                "web": navigation[: max(1, kinds["web"])]}
    return variants["kitchen"] + variants["street"], variants


class Stats:
    def __init__(self) -> None:
        self.latency: dict[str, list[float]] = {"kitchen": [], "street": [], "web": []}
        self.errors: list[str] = []
        self.refused_at_cap = 0
        self.tool_errors = 0
        self.episodes = 0


async def call(client: Any, stats: Stats, kind: str, tool: str, args: dict[str, Any]) -> Any:
    t0 = time.perf_counter()
    try:
        result = await client.call_tool(tool, args)
    except Exception as exc:  # a transport failure: what this benchmark counts as an error
        stats.errors.append(f"{kind} {tool}: {describe(exc)}")
        return None
    stats.latency[kind].append((time.perf_counter() - t0) * 1000)
    if result.is_error:
        text = " ".join(getattr(c, "text", "") for c in result.content)
        if tool == "start_episode" and "EWA_MAX_EPISODES" in text:
            stats.refused_at_cap += 1
        else:
            stats.tool_errors += 1
    return result


async def client_loop(url: str, kind: str, tasks: list[Task], index: int, rounds: int, steps: int,
                      stats: Stats, gate: asyncio.Event, think_s: float = 0.0) -> None:
    http = create_mcp_http_client()  # 30 s to connect and write, 300 s to read: the SDK's defaults
    try:
        async with http, Client(streamable_http_client(url, http_client=http)) as client:
            await gate.wait()  # every client connected: the load starts at once
            for r in range(rounds):
                task = tasks[(index + r) % len(tasks)]
                started = await call(client, stats, kind, "start_episode", {"task_id": task.id})
                if started is None or started.is_error:
                    continue
                episode = started.structured_content["episode_id"]
                body = [s for s in task.oracle if s.tool != "finish_episode"][:steps]
                for step in body:
                    await asyncio.sleep(think_s)
                    await call(client, stats, kind, step.tool, {"episode_id": episode, **dict(step.args)})
                await call(client, stats, kind, "finish_episode", {"episode_id": episode})
                stats.episodes += 1
    except Exception as exc:  # the session itself failed (connect, initialize)
        stats.errors.append(f"{kind} session: {describe(exc)}")


def _set(event: asyncio.Event) -> asyncio.Event:
    event.set()
    return event


async def run(args: argparse.Namespace) -> dict[str, Any]:
    counts = {"kitchen": args.kitchen, "street": args.street, "web": args.web}
    variants, by_kind = load_tasks(counts)
    work = Path(tempfile.mkdtemp(prefix="ewa-load-"))
    for domain in ("cooking", "navigation"):
        write_tasks(work / "tasks", domain, [t for t in variants if t.domain == domain])
    assert len(TaskStore([work / "tasks"]).all()) == len(variants)
    port = free_port()
    env = {k: v for k, v in os.environ.items() if k != "EWA_MCP_TOKEN"}
    env.update({"EWA_RUNS_DIR": str(work / "runs"), "EWA_MAX_EPISODES": str(args.max_episodes)})
    suite = Path(__file__).resolve().parents[1] / "tasks"
    server = subprocess.Popen([sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--port", str(port),
                               "--tasks-dir", str(work / "tasks"), "--tasks-dir", str(suite)],
                              env=env, stderr=subprocess.DEVNULL, stdout=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}/mcp"
    try:
        deadline = time.monotonic() + 120
        while True:
            try:
                httpx.get(url, timeout=1)
                break
            except httpx.TransportError:
                if server.poll() is not None or time.monotonic() > deadline:
                    raise SystemExit("the server did not start") from None
                await asyncio.sleep(0.2)
        # One episode of each kind first, uncounted: the first loads the street graphs and kitchen data.
        await asyncio.gather(*(client_loop(url, kind, by_kind[kind], 0, 1, 1, Stats(), _set(asyncio.Event()))
                               for kind, n in counts.items() if n))
        stats = Stats()
        memory = {"start": tree_pss_mb(server.pid), "peak": 0.0}
        load = {"start": round(os.getloadavg()[0], 2), "peak": 0.0}
        gate = asyncio.Event()
        clients = [client_loop(url, kind, by_kind[kind], i, args.rounds, args.steps, stats, gate, args.think_s)
                   for kind, n in counts.items() for i in range(n)]

        async def sample() -> None:
            while True:
                memory["peak"] = max(memory["peak"], await asyncio.to_thread(tree_pss_mb, server.pid))
                load["peak"] = max(load["peak"], round(os.getloadavg()[0], 2))
                await asyncio.sleep(1.0)

        sampler = asyncio.create_task(sample())
        runners = [asyncio.create_task(c) for c in clients]
        await asyncio.sleep(2.0 + len(clients) * 0.02)  # let every session initialize
        t0 = time.perf_counter()
        gate.set()
        await asyncio.gather(*runners)
        elapsed = time.perf_counter() - t0
        sampler.cancel()
        load["end"] = round(os.getloadavg()[0], 2)
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
    every = [x for v in stats.latency.values() for x in v]
    return {
        "clients": counts, "rounds": args.rounds, "steps_per_episode": args.steps,
        "max_episodes": args.max_episodes,
        "errors": len(stats.errors), "error_samples": stats.errors[:5],
        "refused_at_cap": stats.refused_at_cap, "tool_errors": stats.tool_errors,
        "episodes_finished": stats.episodes, "calls": len(every),
        "latency_ms": {"p50": percentile(every, 0.5), "p95": percentile(every, 0.95), "max": percentile(every, 1.0),
                       **{kind: {"p50": percentile(v, 0.5), "p95": percentile(v, 0.95)}
                          for kind, v in stats.latency.items() if v}},
        "steps_per_s": round(len(every) / elapsed, 1), "seconds": round(elapsed, 1),
        "server_memory_mb": memory, "load_average": load, "cores": os.cpu_count(),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kitchen", type=int, default=128, help="concurrent kitchen episodes")
    ap.add_argument("--street", type=int, default=128, help="concurrent street episodes")
    ap.add_argument("--web", type=int, default=0, help="concurrent whole web (navigation) episodes")
    ap.add_argument("--steps", type=int, default=20, help="calls per episode besides start and finish (at most "
                    "the oracle's)")
    ap.add_argument("--rounds", type=int, default=1, help="episodes each client plays one after the other")
    ap.add_argument("--think-s", type=float, default=0.0, help="seconds each client waits before each call, as "
                    "an agent thinks")
    ap.add_argument("--max-episodes", type=int, default=512, help="the server's admission cap (EWA_MAX_EPISODES)")
    args = ap.parse_args()
    print(json.dumps(asyncio.run(run(args)), indent=1))


if __name__ == "__main__":
    main()
