"""Playing episodes through a real MCP client session: connect to a server (in-process, stdio or HTTP), play one
task's episode with an agent, or a list of them at a bounded concurrency. Used by the runner, the workers and the
Ray actors alike."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import anyio
import httpx
from mcp import Client, StdioServerParameters

from ..core.records import RECORD_WRITE_MARKER
from ..settings import child_server_env
from ewa_mcp.core.taskmodel import Task

from .outcomes import EpisodeOutcome, EvalError, EvalSummary, Progress


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _server_args(task_dirs: list[Path], run_dir: Path) -> list[str]:
    args = ["-m", "ewa_mcp", "serve", "--run-dir", str(run_dir)]
    for d in task_dirs:
        args += ["--tasks-dir", str(d)]
    return args


async def _wait_for_http(url: str, proc: subprocess.Popen, timeout: float = 60) -> None:
    """Until the server at url answers (any status): polled without blocking the event loop."""
    deadline = time.monotonic() + timeout
    async with httpx.AsyncClient(timeout=1) as http:
        while True:
            try:
                await http.get(url)
                return
            except httpx.TransportError:
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise EvalError("the HTTP server did not start; run `ewa-mcp serve --transport http` "
                                    "by hand to see why") from None
                await anyio.sleep(0.1)


@asynccontextmanager
async def connect(transport: str, task_dirs: list[Path], run_dir: Path):
    """One MCP client session to a server that records into run_dir."""
    if transport == "inprocess":
        from ..server import ServerConfig, build_server

        mcp, _ = build_server(ServerConfig(task_dirs=task_dirs, run_dir=run_dir))
        async with Client(mcp) as client:
            yield client
    elif transport == "stdio":
        params = StdioServerParameters(command=sys.executable, args=_server_args(task_dirs, run_dir),
                                       env=child_server_env(os.environ))
        async with Client(params) as client:
            yield client
    elif transport == "http":
        port = free_port()
        proc = subprocess.Popen([sys.executable, *_server_args(task_dirs, run_dir), "--transport", "http",
                                 "--port", str(port)], stderr=subprocess.DEVNULL,
                                env=child_server_env(os.environ))  # loopback: no token, not the caller's EWA_HOST/PORT
        try:
            await _wait_for_http(f"http://127.0.0.1:{port}/mcp", proc)
            async with Client(f"http://127.0.0.1:{port}/mcp") as client:
                yield client
        finally:
            proc.terminate()
            proc.wait(timeout=20)
    else:
        raise EvalError(f"unknown transport {transport!r}; use inprocess, stdio or http")


async def play_episode(client: Any, task: Task, agent: Any,
                       on_start: Callable[[str], None] | None = None) -> EpisodeOutcome:
    """One episode of task played by agent over client; never raises (a broken episode is an outcome).

    on_start(episode_id) is called as soon as the server has opened the episode's record."""
    from .agents import Session

    t0 = time.monotonic()
    outcome = EpisodeOutcome(task_id=task.id, domain=task.domain, episode_id=None)
    try:
        start_args: dict[str, Any] = {"task_id": task.id}
        if getattr(agent, "episode_options", None):  # e.g. {"observation": "vision"} (ewa-mcp eval --observation)
            start_args["options"] = dict(agent.episode_options)
        start = await client.call_tool("start_episode", start_args)
        if start.is_error:
            outcome.failure = "start_episode: " + " ".join(getattr(c, "text", "") for c in start.content)
            if RECORD_WRITE_MARKER in outcome.failure:
                outcome.record_problem = outcome.failure[outcome.failure.index(RECORD_WRITE_MARKER):][:600]
            return outcome
        session = Session(client=client, task=task, episode_id=start.structured_content["episode_id"],
                          start=start)
        outcome.episode_id = session.episode_id
        if on_start is not None:
            on_start(session.episode_id)
        await agent.play(session)
        if not session.ended:  # make sure every episode leaves a final state
            await session.call("finish_episode", {})
        outcome.calls = len(session.log)
        outcome.errors = sum(not entry["ok"] for entry in session.log)
        if session.record_problem is not None:
            outcome.record_problem = session.record_problem
            outcome.failure = session.record_problem
    except Exception as exc:  # one broken episode must not end the run
        outcome.failure = f"{type(exc).__name__}: {exc}"
    finally:
        outcome.seconds = time.monotonic() - t0
    return outcome


async def run_eval(tasks: list[Task], agent: Any, *, transport: str = "inprocess", concurrency: int | None = None,
                   run_dir: Path, task_dirs: list[Path], progress: bool = True,
                   workers: int | None = None) -> EvalSummary:
    """Every task played in this process over one client session, `concurrency` episodes at a time.

    `workers` is the old name of `concurrency` (before --workers meant processes: evaluation/workers.py)."""
    concurrency = max(1, concurrency or workers or 1)
    run_dir.mkdir(parents=True, exist_ok=True)
    summary = EvalSummary(run_dir=run_dir, agent=agent.name, transport=transport)
    bar = Progress(len(tasks), progress)
    started = time.monotonic()
    queue = list(reversed(tasks))

    async with connect(transport, task_dirs, run_dir) as client:

        async def lane() -> None:
            while queue:
                outcome = await play_episode(client, queue.pop(), agent)
                summary.outcomes.append(outcome)
                bar.tick(outcome)
                if outcome.record_problem is not None:  # every episode after it would fail the same way
                    summary.record_problem = summary.record_problem or outcome.record_problem
                    queue.clear()

        async with anyio.create_task_group() as tg:
            for _ in range(concurrency):
                tg.start_soon(lane)
    summary.seconds = time.monotonic() - started
    return summary
