"""Episodes: the unit of evaluation. One task, its environments, its record.

Every tool call that touches an episode goes through ``EpisodeManager.act``, which
checks the episode is running and the right environment is active, runs the action,
counts the step and appends the trajectory line — in that order, in one place.
"""

from __future__ import annotations

import time
import uuid
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, Literal

import anyio
from mcp.server.mcpserver.exceptions import ToolError

from . import registry
from .environment import Environment, Observation
from .records import EpisodeRecorder
from .services import Services
from .taskmodel import SCHEMA_VERSION, Task, TaskStore

EnvKind = Literal["web", "embodied"]
Status = Literal["running", "finished", "step_limit", "aborted"]


class EpisodeError(ToolError):
    """A problem with the episode itself (unknown, finished, wrong environment)."""


@dataclass
class Episode:
    id: str
    task: Task
    recorder: EpisodeRecorder
    options: dict[str, Any]
    environments: dict[EnvKind, Environment] = field(default_factory=dict)
    active: EnvKind = "web"
    status: Status = "running"
    end_reason: str | None = None
    steps: int = 0  # counted actions (the step limit applies to these)
    calls: int = 0  # every recorded call, counted or not
    switches: int = 0
    answer: str | None = None
    submission: dict[str, Any] | None = None
    # Events the embedded sites emitted for this episode (page views, orders, ...), in order;
    # environments may read them (a kitchen receives groceries the agent ordered online).
    web_events: list[dict[str, Any]] = field(default_factory=list)
    started_at: float = field(default_factory=time.time)
    ended_at: float | None = None
    lock: anyio.Lock = field(default_factory=anyio.Lock)

    @property
    def steps_left(self) -> int:
        return max(0, self.task.step_limit - self.steps)

    def environment(self, kind: EnvKind) -> Environment:
        env = self.environments.get(kind)
        if env is None:
            raise EpisodeError(
                f"episode {self.id} has no {kind} environment (task {self.task.id} is {self.task.domain}); "
                f"use the tools of the {self.active} environment"
            )
        return env

    def summary(self) -> dict[str, Any]:
        return {
            "episode_id": self.id,
            "task_id": self.task.id,
            "domain": self.task.domain,
            "status": self.status,
            "end_reason": self.end_reason,
            "active_environment": self.active,
            "environments": {k: type(v).name for k, v in self.environments.items()},
            "steps": self.steps,
            "step_limit": self.task.step_limit,
            "steps_left": self.steps_left,
            "switches": self.switches,
            "answer": self.answer,
        }


def environment_names_for(task: Task) -> dict[EnvKind, str]:
    """Which environment implementations a task needs."""
    names: dict[EnvKind, str] = {}
    if task.start.web is not None or task.web_goals:
        names["web"] = "browser"
    if task.start.embodied is not None:
        names["embodied"] = task.start.embodied.kind
    return names


class EpisodeManager:
    def __init__(
        self,
        tasks: TaskStore,
        run_dir: Path,
        services: Services | None = None,
        environments: dict[str, Any] | None = None,
    ):
        self.tasks = tasks
        self.run_dir = run_dir
        self.services = services or Services()
        # name -> class; defaults to the registry, tests may inject their own.
        self._env_classes = environments
        self._episodes: dict[str, Episode] = {}
        self.event_listeners: list[Callable[[str, dict[str, Any]], None]] = []

    # ------------------------------------------------------------ lifecycle
    def env_class(self, name: str) -> Any:
        if self._env_classes is not None and name in self._env_classes:
            return self._env_classes[name]
        path = registry.ENVIRONMENTS.get(name)
        if path is None:
            raise EpisodeError(
                f"environment {name!r} is not available in this build of ewa-mcp "
                f"(available: {sorted(set(registry.ENVIRONMENTS) | set(self._env_classes or {}))})"
            )
        return registry.load_object(path)

    async def start(self, task_id: str, options: dict[str, Any] | None = None) -> Episode:
        task = self.tasks.get(task_id)
        if task is None:
            close = sorted(t.id for t in self.tasks.all() if task_id.split("-")[0] in t.id)[:5]
            hint = f" Similar ids: {', '.join(close)}." if close else ""
            raise EpisodeError(f"unknown task id {task_id!r}; call list_tasks to see the ids.{hint}")
        options = dict(options or {})
        needed = environment_names_for(task)
        classes = {kind: self.env_class(name) for kind, name in needed.items()}  # fail before creating anything
        episode_id = "ep-" + uuid.uuid4().hex[:12]
        recorder = EpisodeRecorder(self.run_dir / episode_id)
        recorder.write_task(task.model_dump(mode="json"))
        episode = Episode(id=episode_id, task=task, recorder=recorder, options=options, active=task.start.environment)
        try:
            for kind, cls in classes.items():
                env = cls(episode, self.services)
                episode.environments[kind] = env
                await env.reset(task, options)
        except BaseException:
            for env in episode.environments.values():
                with anyio.CancelScope(shield=True):
                    await env.close()
            recorder.close()
            raise
        if episode.active not in episode.environments and episode.environments:
            episode.active = next(iter(episode.environments))
        self._episodes[episode_id] = episode
        return episode

    def get(self, episode_id: str) -> Episode:
        episode = self._episodes.get(episode_id)
        if episode is None:
            raise EpisodeError(f"unknown episode id {episode_id!r}; start one with start_episode(task_id)")
        return episode

    def running(self, episode_id: str) -> Episode:
        episode = self.get(episode_id)
        if episode.status != "running":
            raise EpisodeError(
                f"episode {episode_id} has ended ({episode.end_reason}); it accepts no more actions. "
                "Start a new episode with start_episode(task_id)."
            )
        return episode

    # ------------------------------------------------------------ acting
    async def act(
        self,
        episode_id: str,
        tool: str,
        args: dict[str, Any],
        fn: Callable[[Episode], Awaitable[Observation]],
        *,
        environment: EnvKind | None,
        counted: bool = True,
    ) -> tuple[Episode, Observation]:
        """Run one tool call against an episode, enforcing the protocol and recording it."""
        episode = self.running(episode_id)
        async with episode.lock:
            # Re-check under the lock: a concurrent call may have ended the episode.
            episode = self.running(episode_id)
            started = time.perf_counter()
            error: str | None = None
            observation: Observation | None = None
            try:
                if environment is not None and environment != episode.active:
                    raise EpisodeError(
                        f"{tool} acts on the {environment} environment, but the active environment is "
                        f"{episode.active}. Call switch_environment(episode_id, target='{environment}', "
                        "message=...) first."
                    )
                observation = await fn(episode)
                return episode, observation
            except ToolError as exc:
                error = str(exc)
                raise
            except Exception as exc:  # an environment bug: report it, keep the server alive
                error = f"internal error in {tool}: {type(exc).__name__}: {exc}"
                raise ToolError(error) from exc
            finally:
                episode.calls += 1
                if counted:
                    episode.steps += 1
                episode.recorder.step(
                    index=episode.calls,
                    tool=tool,
                    args=args,
                    ok=error is None,
                    error=error,
                    duration_ms=(time.perf_counter() - started) * 1000,
                    environment=episode.active,
                    observation=observation.text if observation else (error or ""),
                    counted=counted,
                    images=episode.recorder.save_images(episode.calls, observation.images) if observation else None,
                )
                if counted and episode.status == "running" and episode.steps >= episode.task.step_limit:
                    await self._end(episode, "step_limit", f"step limit of {episode.task.step_limit} reached")

    async def switch(self, episode_id: str, target: EnvKind, message: str) -> tuple[Episode, Observation]:
        async def do(episode: Episode) -> Observation:
            if target not in episode.environments:
                raise EpisodeError(
                    f"this task has no {target} environment; its environments are {sorted(episode.environments)}"
                )
            if target == episode.active:
                raise EpisodeError(f"the {target} environment is already active; act in it or switch to the other")
            episode.active = target
            episode.switches += 1
            return await episode.environments[target].observe()

        return await self.act(episode_id, "switch_environment", {"target": target, "message": message}, do,
                              environment=None)

    async def finish(
        self, episode_id: str, answer: str | None = None, submission: dict[str, Any] | None = None,
        tool: str = "finish_episode", args: dict[str, Any] | None = None,
    ) -> Episode:
        async def do(episode: Episode) -> Observation:
            episode.answer = answer
            episode.submission = submission
            return Observation(text=f"episode finished; answer: {answer!r}")

        episode, _ = await self.act(episode_id, tool, args if args is not None else {"answer": answer}, do,
                                    environment=None, counted=False)
        async with episode.lock:
            await self._end(episode, "finished", "the agent finished the episode")
        return episode

    async def _end(self, episode: Episode, status: Status, reason: str) -> None:
        if episode.status != "running":
            return
        episode.status = status
        episode.end_reason = reason
        episode.ended_at = time.time()
        env_states: dict[str, Any] = {}
        for kind, env in episode.environments.items():
            try:
                env_states[kind] = {"name": type(env).name, **(await env.final_state())}
            except Exception as exc:  # a broken environment still leaves a gradable record
                env_states[kind] = {"name": type(env).name, "error": f"{type(exc).__name__}: {exc}"}
        episode.recorder.write_final_state(
            {
                "schema_version": SCHEMA_VERSION,
                "episode_id": episode.id,
                "task_id": episode.task.id,
                "domain": episode.task.domain,
                "status": status,
                "end_reason": reason,
                "answer": episode.answer,
                "submission": episode.submission,
                "steps": episode.steps,
                "calls": episode.calls,
                "switches": episode.switches,
                "active_environment": episode.active,
                "options": episode.options,
                "started_at": datetime.fromtimestamp(episode.started_at, UTC).isoformat(),
                "ended_at": datetime.fromtimestamp(episode.ended_at, UTC).isoformat(),
                "wall_time_s": round(episode.ended_at - episode.started_at, 3),
                "environments": env_states,
            }
        )
        for env in episode.environments.values():
            with anyio.CancelScope(shield=True):
                try:
                    await env.close()
                except Exception:
                    pass
        episode.recorder.close()

    def emit_event(self, episode_id: str, event: dict[str, Any]) -> None:
        """Called by the embedded sites (any thread) to record a per-episode web event."""
        episode = self._episodes.get(episode_id)
        if episode is not None:
            episode.web_events.append(event)
            episode.recorder.event(event)
        for listener in self.event_listeners:
            listener(episode_id, event)

    async def aclose(self) -> None:
        for episode in list(self._episodes.values()):
            if episode.status == "running":
                async with episode.lock:
                    await self._end(episode, "aborted", "the server shut down before the episode finished")

