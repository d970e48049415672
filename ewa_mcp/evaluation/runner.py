"""Run an agent over tasks through the real MCP server (in-process, stdio or HTTP), then grade."""

from __future__ import annotations

import fnmatch
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import anyio

from ..core.records import RECORD_WRITE_MARKER
from ewa_mcp.core.taskmodel import Task, TaskStore

from .playing import connect, play_episode, run_eval  # noqa: F401 (the runner's API)
from .outcomes import EpisodeOutcome, EvalError, EvalSummary, Progress, clock  # noqa: F401 (the runner's API)

from .scale import RayOptions, ScaleOptions


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
