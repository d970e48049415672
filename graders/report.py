"""grade_run: a whole run directory -> RunReport."""

from __future__ import annotations

import json
from pathlib import Path

from ewa_mcp.core import registry

from .aggregate import domain_aggregate, error_breakdown
from .episode import grade_episode
from .models import EpisodeResult, ErrorClassification, RunReport
from .rundir import EPISODE_FILES, episode_dirs

DIFFICULTY_ORDER = ("easy", "medium", "hard")


class RunDirError(ValueError):
    """RUN_DIR itself is unusable (missing, not a directory, no episodes); the message says how to fix it."""


def _domain_key(domain: str) -> tuple[int, str]:
    """Report order: the registry's display order (ewa_mcp/core/registry.py), unknown domains last by name."""
    order = registry.domain_names()
    return (order.index(domain) if domain in order else len(order), domain)


def _scored(domain: str) -> bool:
    """Whether a domain's episodes count in the run's aggregates (the demo does not; unknown domains do)."""
    declared = registry.domain(domain)
    return declared is None or declared.scored


def grade_run(run_dir: str | Path, radius_m: float | None = None, label: str | None = None) -> RunReport:
    """Grade every episode under RUN_DIR. Raises RunDirError only when RUN_DIR does not exist or holds
    no episode directory; damaged episodes are graded as far as their data allows."""
    if radius_m is not None and not radius_m > 0:
        raise ValueError(f"radius_m must be a positive number of metres, got {radius_m!r}")
    root = Path(run_dir)
    if not root.exists():
        raise RunDirError(f"run directory {root} does not exist; pass the directory a run wrote (runs/<run_id>)")
    if not root.is_dir():
        raise RunDirError(f"{root} is a file, not a run directory; pass the directory that holds the episode folders")
    dirs = episode_dirs(root)
    if not dirs:
        raise RunDirError(
            f"{root} holds no episodes (no sub-directory with any of {', '.join(EPISODE_FILES)}); "
            "pass a run directory (runs/<run_id>), not the runs/ folder or an episode folder"
            if not (root / "task.json").exists() and not (root / "trajectory.jsonl").exists()
            else f"{root} is an episode directory; pass its parent (the run directory), or use grade_episode"
        )
    episodes = [_grade_safely(d, radius_m) for d in dirs]
    # Episodes cut off by infrastructure (the server shut down, a worker died, no browser) are not the agent's
    # failures: they are counted apart and left out of every aggregate and error table.
    cut_off = [e for e in episodes if e.infrastructure_failure is not None]
    played = [e for e in episodes if e.infrastructure_failure is None]
    scored = [e for e in played if _scored(e.domain)]
    domains = sorted({e.domain for e in episodes if _scored(e.domain)}, key=_domain_key)
    by_domain = {d: [e for e in played if e.domain == d] for d in domains}
    demo = [e for e in played if e.domain == "demo"]
    errors = {d: error_breakdown(eps) for d, eps in by_domain.items()}
    errors["all"] = error_breakdown(scored)
    problems = [f"{e.episode_id}: {p}" for e in episodes for p in e.problems]
    return RunReport(
        run_dir=str(root),
        label=label or root.name,
        radius_m=radius_m,
        n_episodes=len(episodes),
        domains={d: domain_aggregate(d, eps) for d, eps in by_domain.items()},
        by_difficulty={d: {level: domain_aggregate(d, [e for e in eps if e.difficulty == level])
                           for level in DIFFICULTY_ORDER if any(e.difficulty == level for e in eps)}
                       for d, eps in by_domain.items() if any(e.difficulty for e in eps)},
        demo=domain_aggregate("demo", demo) if demo else None,
        errors=errors,
        episodes=episodes,
        problems=problems,
        infrastructure={d: n for d in [*domains, "demo"] if (n := sum(e.domain == d for e in cut_off))},
        infrastructure_failures=[f"{e.episode_id} ({e.task_id}): {e.infrastructure_failure}" for e in cut_off],
    )


def _grade_safely(directory: Path, radius_m: float | None) -> EpisodeResult:
    """One episode's grade; a record that trips the grader itself becomes an invalid_record failure of that
    episode, listed with the reason, and the rest of the run is still graded."""
    try:
        return grade_episode(directory, radius_m)
    except Exception as exc:  # the principle: graders never crash on a run
        reason = f"the grader could not read this record ({type(exc).__name__}: {str(exc)[:200]})"
        try:
            task = json.loads((directory / "task.json").read_text(encoding="utf-8"))
        except Exception:
            task = None
        task = task if isinstance(task, dict) else {}
        task_id = task.get("id") if isinstance(task.get("id"), str) else None
        domain = task.get("domain") if isinstance(task.get("domain"), str) else "unknown"
        return EpisodeResult(
            episode_id=directory.name, task_id=task_id, domain=domain, status="invalid", gradable=True,
            has_web_goals=False, has_embodied_goals=False, answer_checked=False, web_success=None,
            embodied_success=None, answer_correct=None, overall_success=False, completion=0.0, conditions_met=0,
            conditions_total=0, conditions=[], steps=0, calls=0, switches=0, wall_time_s=None,
            error=ErrorClassification(category="invalid_record", group="other", matched=["invalid_record"],
                                      evidence={"invalid_record": reason}),
            problems=[f"invalid record: {reason}"],
        )
