"""Fork a running episode: a new episode, with its own id and record, in exactly the state of the original.

From the fork on, the two are independent and behave identically: the same actions give the same observations
(tests/training/test_fork.py). Tree search expands a node by forking it; GRPO groups share a prefix by playing it
once and forking the group from its end.

What is copied:
- the episode's counters (steps, calls, switches), its active environment, options, answer and web events;
- its record so far (task.json, trajectory.jsonl, web_events.jsonl, images/), so the fork's record grades like a
  record of the whole episode; one uncounted trajectory line ``fork_episode`` notes where it came from;
- each embodied environment, by a deep copy of the environment object in which the read-only world data
  (the street world and its city graph, the geolocation location and its standpoint graph) is shared, not copied.

Not (yet) forkable: an episode with a web environment (a browser context: its tabs, history, page state and the
sites' per-episode SQLite rows would all have to be copied), and a kitchen on the AI2-THOR backend (a Unity
process). Both are refused with a ``ForkError`` that says so; nothing is created.
"""

from __future__ import annotations

import copy
import shutil
import time
import uuid
from typing import Any

from .core.environment import Environment
from .core.episodes import Episode, EpisodeError, EpisodeManager
from .core.records import EpisodeRecorder

# Attributes holding read-only world data, shared between an environment and its fork (by registry name).
SHARED_ATTRIBUTES: dict[str, tuple[str, ...]] = {
    "street": ("world", "graph"),
    "geo": ("loc", "graph"),
    "kitchen": (),
}


class ForkError(EpisodeError):
    """An episode that cannot be forked; the message says why and what can be forked."""


def _check_forkable(episode: Episode) -> None:
    for side, name in episode.environment_names.items():
        if name not in SHARED_ATTRIBUTES:
            raise ForkError(
                f"episode {episode.id} (task {episode.task.id}) has a {name} environment ({side}), and episodes with "
                f"a {name} environment cannot be forked yet: only kitchen (simulator), street and geolocation "
                "episodes without a web environment can. Replay the episode's actions on a new episode instead."
            )
        env = episode.environments.get(side)
        session = getattr(env, "session", None)
        backend = getattr(session, "backend", "sim")
        if name == "kitchen" and backend != "sim":
            raise ForkError(f"episode {episode.id} runs its kitchen on the {backend} backend, whose state "
                            "lives in another process and cannot be forked; use the built-in simulator "
                            "(kitchen_backend='sim') for episodes you fork")


def clone_environment(env: Environment, name: str, episode: Episode) -> Environment:
    """A deep copy of ``env`` owned by ``episode``: shared world data and services, everything else copied."""
    memo: dict[int, Any] = {id(getattr(env, "episode", None)): episode}
    services = getattr(env, "services", None)
    if services is not None:
        memo[id(services)] = services
    for attr in SHARED_ATTRIBUTES.get(name, ()):
        value = getattr(env, attr, None)
        if value is not None:
            memo[id(value)] = value
    return copy.deepcopy(env, memo)


def _copy_record(source: EpisodeRecorder, target_dir: Any) -> None:
    target_dir.mkdir(parents=True, exist_ok=False)
    for name in ("task.json", "trajectory.jsonl", "web_events.jsonl"):
        path = source.directory / name
        if path.exists():
            shutil.copyfile(path, target_dir / name)
    images = source.directory / "images"
    if images.is_dir():
        shutil.copytree(images, target_dir / "images")


async def fork_episode(manager: EpisodeManager, episode_id: str) -> Episode:
    """Copy the running episode ``episode_id`` into a new running episode and return it."""
    source = manager.running(episode_id)
    async with source.lock:
        source = manager.running(episode_id)  # a call racing the fork may have ended it
        _check_forkable(source)
        fork_id = "ep-" + uuid.uuid4().hex[:12]
        directory = manager.run_dir / fork_id
        _copy_record(source.recorder, directory)
        recorder = EpisodeRecorder(directory)
        fork = Episode(
            id=fork_id, task=source.task, recorder=recorder, options=copy.deepcopy(source.options),
            environment_names=dict(source.environment_names), active=source.active, steps=source.steps,
            calls=source.calls, switches=source.switches, answer=source.answer,
            submission=copy.deepcopy(source.submission), web_events=copy.deepcopy(source.web_events),
        )
        try:
            for side, env in source.environments.items():
                fork.environments[side] = clone_environment(env, source.environment_names[side], fork)
        except BaseException:
            recorder.close()
            shutil.rmtree(directory, ignore_errors=True)
            raise
        fork.calls += 1
        recorder.step(index=fork.calls, tool="fork_episode", args={"from_episode": source.id, "at_step": source.steps},
                      ok=True, error=None, duration_ms=0.0, environment=fork.active,
                      observation=f"forked from {source.id} at step {source.steps}", counted=False)
        fork.started_at = time.time()
        manager.adopt(fork)
        return fork
