"""Run an agent over tasks through the real MCP server (in-process, stdio or HTTP), then grade."""

from __future__ import annotations

import fnmatch
import os
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from contextlib import asynccontextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import anyio
import httpx
from mcp import Client, StdioServerParameters

from ..core.records import RECORD_WRITE_MARKER
from ..settings import child_server_env
from ewa_mcp.core.taskmodel import Task, TaskStore

if TYPE_CHECKING:
    from .scale import RayOptions, ScaleOptions


class EvalError(ValueError):
    """Bad eval input (no matching tasks, bad replay): the message names the fix."""


def select_tasks(store: TaskStore, patterns: list[str] | None, sample: int | None,
                 domains: list[str] | None = None, difficulties: list[str] | None = None) -> list[Task]:
    tasks = sorted(store.all(), key=lambda t: t.id)
    if domains:
        tasks = [t for t in tasks if t.domain in domains]
    if difficulties:
        tasks = [t for t in tasks if t.difficulty in difficulties]
    if patterns:
        tasks = [t for t in tasks if any(fnmatch.fnmatchcase(t.id, p) for p in patterns)]
        if not tasks:
            raise EvalError(f"no task id matches {patterns}; see `ewa-mcp tasks list` for the ids")
    if not tasks:
        raise EvalError("no tasks to run; check --tasks-dir / --domain / --difficulty")
    if sample:
        # N per domain, evenly spaced over the sorted ids: deterministic and spread across templates.
        by_domain: dict[str, list[Task]] = {}
        for t in tasks:
            by_domain.setdefault(t.domain, []).append(t)
        tasks = []
        for domain in sorted(by_domain):
            group = by_domain[domain]
            n = min(sample, len(group))
            tasks += [group[(i * len(group)) // n] for i in range(n)]
    return tasks


def _free_port() -> int:
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
        port = _free_port()
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


@dataclass
class EpisodeOutcome:
    task_id: str
    domain: str
    episode_id: str | None
    calls: int = 0
    errors: int = 0
    failure: str | None = None  # the episode could not be played at all
    seconds: float = 0.0
    record_problem: str | None = None  # its record could not be written (a full disk): the run stops


@dataclass
class EvalSummary:
    run_dir: Path
    agent: str
    transport: str
    outcomes: list[EpisodeOutcome] = field(default_factory=list)
    seconds: float = 0.0
    record_problem: str | None = None


def clock(seconds: float) -> str:
    """A duration as m:ss, or h:mm:ss past an hour."""
    seconds = max(0, int(round(seconds)))
    hours, rest = divmod(seconds, 3600)
    return f"{hours}:{rest // 60:02d}:{rest % 60:02d}" if hours else f"{rest // 60}:{rest % 60:02d}"


class Progress:
    """Episodes done, infrastructure failures, time so far and the estimated time left, on stderr.

    On a terminal: one line redrawn in place (a carriage-return frame per episode). Anywhere else (a log file, a
    CI console, a pipe): a plain line per update, at most one every `interval` seconds plus the last, so logs
    hold readable lines and no frames."""

    def __init__(self, total: int, enabled: bool, stream: Any = None, interactive: bool | None = None,
                 interval: float = 10.0):
        self.total, self.done, self.failed, self.enabled = total, 0, 0, enabled
        self.stream = stream if stream is not None else sys.stderr
        if interactive is None:
            isatty = getattr(self.stream, "isatty", None)
            interactive = bool(isatty and isatty())
        self.interactive, self.interval = interactive, interval
        self.started = time.monotonic()
        self.last_line = -float("inf")

    def eta(self, elapsed: float) -> str:
        if not self.done:
            return "?"
        return clock(elapsed / self.done * (self.total - self.done))

    def status(self, elapsed: float) -> str:
        return (f"{self.done}/{self.total} episodes · {self.failed} not played (infrastructure) · "
                f"{clock(elapsed)} elapsed · ETA {self.eta(elapsed)}")

    def tick(self, outcome: EpisodeOutcome) -> None:
        self.done += 1
        self.failed += outcome.failure is not None
        if not self.enabled:
            return
        now = time.monotonic()
        elapsed = now - self.started
        last = self.done == self.total
        if self.interactive:
            width = 30
            filled = int(width * self.done / max(1, self.total))
            self.stream.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {self.status(elapsed)} ")
            if last:
                self.stream.write("\n")
        elif last or now - self.last_line >= self.interval:
            self.last_line = now
            self.stream.write(f"progress: {self.status(elapsed)}\n")
        self.stream.flush()


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


def task_dirs_from(given: list[str] | None) -> list[Path]:
    from ..core.paths import task_dirs

    return [Path(p) for p in given] if given else task_dirs()  # every directory of EWA_TASKS_DIR=a:b


def run_dir_from(given: str | None, prefix: str = "") -> Path:
    from ewa_mcp.core.paths import runs_dir
    from ewa_mcp.core.records import new_run_id

    return Path(given) if given else runs_dir() / (prefix + new_run_id())


def play(tasks: list[Task], agent: Any, *, run_dir: Path, task_dirs: list[Path], transport: str = "inprocess",
         workers: int = 1, concurrency: int = 1, ray: "RayOptions | None" = None,
         progress: bool = True) -> EvalSummary:
    """Run the episodes (blocking) and report on stderr the ones that could not be played.

    workers > 1: that many processes, each with its own server, browser and sites (evaluation/workers.py);
    ray: actors on a Ray cluster (evaluation/ray_eval.py); otherwise this process. Each runs `concurrency`
    episodes at a time. A missing Chromium stops the run before the first episode (EvalError; on Ray the actors'
    machines decide). Episodes that could not be played are written into run_dir as infrastructure failures
    (evaluation/resume.py): the grader reports them apart and a resumed run plays them again."""
    from .resume import record_infrastructure_failures

    if not tasks:
        return EvalSummary(run_dir=run_dir, agent=agent.name, transport=transport)
    if ray is None:
        from .preflight import check_browser

        check_browser(tasks)
    if ray is not None:
        from .ray_eval import play_on_ray

        summary = play_on_ray(tasks, agent, ray, run_dir=run_dir, task_dirs=task_dirs, transport=transport,
                              concurrency=concurrency, progress=progress)
    elif workers > 1:
        from .workers import play_in_processes

        summary = play_in_processes(tasks, agent, workers=workers, concurrency=concurrency, run_dir=run_dir,
                                    task_dirs=task_dirs, transport=transport, progress=progress)
    else:
        summary = anyio.run(lambda: run_eval(tasks, agent, transport=transport, concurrency=concurrency,
                                             run_dir=run_dir, task_dirs=task_dirs, progress=progress))
    if summary.record_problem is not None:
        raise record_stop(run_dir, summary.record_problem)
    failed = [o for o in summary.outcomes if o.failure]
    record_infrastructure_failures(run_dir, failed, tasks)
    for o in failed[:10]:
        sys.stderr.write(f"  could not play {o.task_id}: {o.failure}\n")
    sys.stderr.write(f"played {len(summary.outcomes) - len(failed)}/{len(summary.outcomes)} episodes in "
                     f"{summary.seconds:.1f}s\n")
    if failed:
        sys.stderr.write(f"{len(failed)} episode(s) not played to their end for reasons other than the agent "
                         "(infrastructure failures): they are not scored; run the same command with "
                         f"--run-dir {run_dir} to play just those again\n")
    return summary


def record_stop(run_dir: Path, problem: str) -> EvalError:
    """The one-line error that stops a run whose records can no longer be written (a full disk), after removing
    every episode folder that is not whole (no final state, or one ended because its record failed)."""
    import json
    import shutil

    kept = 0
    for folder in sorted(run_dir.glob("ep-*")) if run_dir.is_dir() else []:
        try:
            final = json.loads((folder / "final_state.json").read_text(encoding="utf-8"))
            whole = RECORD_WRITE_MARKER not in str(final.get("end_reason") or "")
        except (OSError, ValueError):
            whole = False
        if whole:
            kept += 1
        else:
            shutil.rmtree(folder, ignore_errors=True)
    return EvalError(f"eval stopped: {problem.rstrip('. ')}. {run_dir} keeps the {kept} whole episodes recorded "
                     "before; run the remaining tasks again once there is space")


def play_from_args(tasks: list[Task], agent: Any, args: Any, *, run_dir: Path, task_dirs: list[Path],
                   announce: Callable[[ScaleOptions], None] | None = None) -> EvalSummary:
    """``play`` with the command line's --transport, --workers, --concurrency, --ray* and --quiet (``ewa-mcp eval``
    and the LLM agents' shared options); the scale options are checked first (EvalError names the fix). A run
    directory that already holds episodes is resumed: only the tasks missing or cut off there are played."""
    from .resume import plan_resume, start_run
    from .scale import scale_options

    scale = scale_options(args)
    plan = plan_resume(run_dir, tasks, agent.name)  # a run directory that exists is resumed
    if announce is not None:
        announce(scale)
    if message := plan.describe(run_dir, len(tasks)):
        sys.stderr.write(message + "\n")
    if scale.ray is None:
        from .preflight import check_browser

        check_browser(plan.to_play)  # before the run directory is touched
    try:
        start_run(run_dir, plan, agent.name)
    except OSError as exc:  # a full or read-only disk before the first episode: one line, nothing half-made
        from ..core.records import write_problem

        raise record_stop(run_dir, write_problem(run_dir, exc)) from None
    return play(plan.to_play, agent, run_dir=run_dir, task_dirs=task_dirs, transport=args.transport,
                workers=scale.workers, concurrency=scale.concurrency, ray=scale.ray, progress=not args.quiet)
