"""Completion of a running episode, by the grader's own checks on its live state (the dense reward).

The grader (ewa_mcp.graders) reads a finished episode's files. To grade a running one the same way, this
builds the record the grader would read if the episode ended now: its task, its web events so far, and a
final state whose embodied part is the environment's ``final_state()`` at this moment (where the walk would
end, the kitchen's objects), with the answer given so far (none before finish_episode). ``grade_record`` then
runs every condition check unchanged. The dense reward of a step is the change in this completion; once
the episode has ended, the completion is the real grade of its record, so the rewards of an episode sum to
its final completion exactly (up to float rounding) and nothing is rewarded that the final grade takes back
without the reward being taken back too.
"""

from __future__ import annotations

from typing import Any

from .core.episodes import Episode
from .graders.episode import grade_record
from .graders.models import EpisodeResult
from .graders.rundir import EpisodeRecord, task_view


async def live_record(episode: Episode) -> EpisodeRecord:
    """The record the grader would read if ``episode`` ended now (nothing is written)."""
    environments: dict[str, Any] = {}
    env = episode.environments.get("embodied")
    if env is not None:  # the web side is graded from its events; its state is not read by any check
        try:
            environments["embodied"] = {"name": type(env).name, **(await env.final_state())}
        except Exception as exc:
            environments["embodied"] = {"name": type(env).name, "error": f"{type(exc).__name__}: {exc}"}
    final = {
        "episode_id": episode.id, "task_id": episode.task.id, "domain": episode.task.domain,
        "status": episode.status, "answer": episode.answer, "submission": episode.submission,
        "steps": episode.steps, "calls": episode.calls, "switches": episode.switches,
        "options": dict(episode.options), "environments": environments,
    }
    problems: list[str] = []
    task = task_view(episode.task.model_dump(mode="json"), problems)
    return EpisodeRecord(episode.recorder.directory, task, [], list(episode.web_events), final, problems)


async def live_grade(episode: Episode) -> EpisodeResult:
    return grade_record(await live_record(episode))


async def live_completion(episode: Episode) -> float:
    """The fraction of the task's conditions met now (0 when none can be decided yet)."""
    return (await live_grade(episode)).completion or 0.0
