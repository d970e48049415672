"""Episodes: the unit of evaluation. One task, its environments, its record.

Every tool call that touches an episode goes through ``EpisodeManager.act``, which
checks the episode is running and the right environment is active, runs the action,
counts the step and appends the trajectory line — in that order, in one place.
"""

from __future__ import annotations

import shutil
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
from .environment import EnvError, Environment, Observation
from .records import EpisodeRecorder, FinalState, RecordWriteError
from .services import Services
from .taskmodel import SCHEMA_VERSION, EnvSide, Task, TaskStore

Status = Literal["running", "finished", "step_limit", "aborted"]
END_REASONS: dict[str, str] = {"finished": "the agent finished the episode"}
ARG_LIMIT = 2000  # characters of one argument kept in the trajectory line of a refused call


# What to do when the run directory cannot be written (it went away, became read-only or filled up).
WRITABLE_RUN_DIR = ("restart the server with a writable run directory: --run-dir DIR, EWA_RUN_DIR=DIR or "
                    "EWA_RUNS_DIR=DIR")


class EpisodeError(ToolError):
    """A problem with the episode itself (unknown, finished, wrong environment)."""


QUOTE_LIMIT = 200  # an error quotes at most this many characters of a value the caller sent


def quote(value: Any, limit: int = QUOTE_LIMIT) -> str:
    """repr() of a caller's value, cut to ``limit`` characters so a huge argument is never echoed whole."""
    text = repr(value)
    if len(text) <= limit:
        return text
    return f"{text[:limit]}… ({len(text)} characters)"


@dataclass
class Episode:
    id: str
    task: Task
    recorder: EpisodeRecorder
    options: dict[str, Any]
    environments: dict[EnvSide, Environment] = field(default_factory=dict)
    # side -> the registry name it was created from ("browser", "kitchen", "street", "geo"):
    # what a tool checks before it acts (a kitchen tool refuses a street episode).
    environment_names: dict[EnvSide, str] = field(default_factory=dict)
    active: EnvSide = "web"
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
    # Who started it (an MCP session: per-client cap) and when a call last touched it (idle reaping).
    client: str | None = None
    last_call: float = field(default_factory=time.monotonic)
    record_error: str | None = None  # why its record could not be written (then it is ended: an incomplete record)

    @property
    def steps_left(self) -> int:
        return max(0, self.task.step_limit - self.steps)

    def environment(self, side: EnvSide) -> Environment:
        env = self.environments.get(side)
        if env is None:
            raise EpisodeError(
                f"episode {self.id} has no {side} environment (task {self.task.id} is {self.task.domain}); "
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
            **self.status_values(),
            "answer": self.answer,
        }

    def status_values(self) -> dict[str, Any]:
        """Each declared status field (registry.StatusField) with its environment's value; None where the
        episode has no environment that reports it."""
        values: dict[str, Any] = {f.name: None for f in registry.status_fields()}
        for env in self.environments.values():
            values.update({k: v for k, v in env.status().items() if k in values})
        return values


def bounded_args(args: dict[str, Any]) -> dict[str, Any]:
    """The arguments of a refused call as the trajectory keeps them: strings cut to ARG_LIMIT characters,
    anything that is not plain JSON shown by a bounded repr."""
    out: dict[str, Any] = {}
    for key, value in list(args.items())[:50]:
        key = str(key)[:100]
        if isinstance(value, str):
            out[key] = value if len(value) <= ARG_LIMIT else value[:ARG_LIMIT] + f"… ({len(value)} characters)"
        elif value is None or isinstance(value, bool | int | float):
            out[key] = value
        else:
            out[key] = quote(value, ARG_LIMIT)
    return out


class CapacityError(EpisodeError):
    """The server (or this client) holds as many open episodes as it admits; the message names the setting."""


class EpisodeManager:
    """The server's episodes. They belong to the server, not to the connection that started them: any client may
    act on an episode by its id, and a client leaving ends none (docs/architecture.md, "Episodes and clients").
    An episode ends by finish_episode (or submit_location), at its step limit, when it has had no call for
    ``episode_idle_s`` (aborted, its environments released), or when the server stops (aborted)."""

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
        # Episodes whose environments are being reset: the sites' events of their start pages land too.
        self._starting: dict[str, Episode] = {}
        self.event_listeners: list[Callable[[str, dict[str, Any]], None]] = []
        settings = self.services.settings
        self.max_episodes = settings.max_episodes  # 0: no cap
        self.max_per_client = settings.max_episodes_per_client
        self.idle_s = settings.episode_idle_s  # 0: never reaped
        self._reaper: Any = None
        self.reaped = 0

    # ------------------------------------------------------------ admission and reaping
    def open_episodes(self, client: str | None = None) -> int:
        """Running and starting episodes (of one client, when given)."""
        live = [e for e in self._episodes.values() if e.status == "running"] + list(self._starting.values())
        return sum(1 for e in live if client is None or e.client == client)

    def limits(self) -> dict[str, Any]:
        """What episode_status shows of the server's admission rules."""
        return {"open_episodes": self.open_episodes(), "max_episodes": self.max_episodes or None,
                "max_episodes_per_client": self.max_per_client or None,
                "idle_timeout_s": self.idle_s or None, "reaped_idle": self.reaped}

    def _admit(self, client: str | None) -> None:
        if self.max_episodes and self.open_episodes() >= self.max_episodes:
            wait = f", wait (episodes with no call for {self.idle_s:g} s are ended)" if self.idle_s else ""
            raise CapacityError(
                f"the server already holds {self.max_episodes} open episodes, its cap (the max_episodes setting, "
                f"EWA_MAX_EPISODES); finish one with finish_episode{wait}, or raise EWA_MAX_EPISODES where the "
                "machine can serve more")
        if self.max_per_client and client is not None and self.open_episodes(client) >= self.max_per_client:
            raise CapacityError(
                f"this client already holds {self.max_per_client} open episodes, the cap per client (the "
                "max_episodes_per_client setting, EWA_MAX_EPISODES_PER_CLIENT); finish one with finish_episode "
                "before starting another")

    async def reap_idle(self) -> int:
        """End every running episode that has had no call for ``idle_s`` (and none running now) as aborted,
        releasing its environments (a browser context holds a renderer). Returns how many were ended."""
        if not self.idle_s:
            return 0
        now = time.monotonic()
        ended = 0
        for episode in list(self._episodes.values()):
            if episode.status != "running" or episode.lock.locked() or now - episode.last_call < self.idle_s:
                continue
            async with episode.lock:
                if episode.status != "running" or time.monotonic() - episode.last_call < self.idle_s:
                    continue
                idle = time.monotonic() - episode.last_call
                await self._end(episode, "aborted",
                                f"idle: no call for {idle:.0f} s, longer than the server allows "
                                f"({self.idle_s:g} s, the episode_idle_s setting, EWA_EPISODE_IDLE_S); its "
                                "environments were released")
                self.reaped += 1
                ended += 1
        return ended

    def start_reaper(self) -> None:
        """Check for idle episodes in the background while the server runs (stopped by aclose)."""
        import asyncio

        if not self.idle_s or self._reaper is not None:
            return
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            return  # not under asyncio: idle episodes are still reaped whenever an episode starts

        async def sweep() -> None:
            every = min(30.0, max(0.2, self.idle_s / 4))
            while True:
                await asyncio.sleep(every)
                try:
                    await self.reap_idle()
                except Exception:  # an environment that fails to close must not stop the sweeping
                    pass

        self._reaper = loop.create_task(sweep())

    # ------------------------------------------------------------ lifecycle
    def env_class(self, name: str) -> Any:
        if self._env_classes is not None and name in self._env_classes:
            return self._env_classes[name]
        spec = registry.environments().get(name)
        if spec is None:
            raise EpisodeError(
                f"environment {name!r} is not available in this build of ewa-mcp "
                f"(available: {sorted(set(registry.environments()) | set(self._env_classes or {}))})"
            )
        return registry.load_object(spec.cls)

    async def start(self, task_id: str, options: dict[str, Any] | None = None, client: str | None = None) -> Episode:
        """Start an episode of ``task_id`` for ``client`` (an MCP session; per-client cap), if the server admits
        one more (``CapacityError`` names the setting when it does not)."""
        await self.reap_idle()  # an idle episode's place is free before the cap is checked
        task = self.tasks.get(task_id)
        if task is None:
            prefix = task_id[:40].split("-")[0]
            close = sorted(t.id for t in self.tasks.all() if prefix and prefix in t.id)[:5]
            hint = f" Similar ids: {', '.join(close)}." if close else ""
            raise EpisodeError(f"unknown task id {quote(task_id)}; call list_tasks to see the ids.{hint}")
        options = dict(options or {})
        needed = task.environment_names()
        classes = {kind: self.env_class(name) for kind, name in needed.items()}  # fail before creating anything
        self._admit(client)  # checked and taken (below, in _starting) with no await between
        episode_id = "ep-" + uuid.uuid4().hex[:12]
        try:
            recorder = EpisodeRecorder(self.run_dir / episode_id)
        except RecordWriteError as exc:
            raise EpisodeError(f"start_episode: nothing was started: {exc}; {WRITABLE_RUN_DIR}") from exc
        try:
            recorder.write_task(task.model_dump(mode="json"))
        except RecordWriteError as exc:
            recorder.close()
            shutil.rmtree(self.run_dir / episode_id, ignore_errors=True)  # no folder without its task.json
            raise EpisodeError(f"start_episode: nothing was started: {exc}; {WRITABLE_RUN_DIR}") from exc
        episode = Episode(id=episode_id, task=task, recorder=recorder, options=options, active=task.start.environment,
                          environment_names=dict(needed), client=client)
        self._starting[episode_id] = episode
        kind: EnvSide = task.start.environment
        try:
            for kind, cls in classes.items():
                env = cls(episode, self.services)
                episode.environments[kind] = env
                await env.reset(task, options)
        except BaseException as exc:
            self._starting.pop(episode_id, None)
            for env in episode.environments.values():
                with anyio.CancelScope(shield=True):
                    await env.close()
            recorder.close()
            # An episode that never started leaves no record: the caller was told why, and a grader must not
            # count it as the agent's failure (the eval records it as an infrastructure failure).
            shutil.rmtree(recorder.directory, ignore_errors=True)
            if isinstance(exc, EnvError):
                raise ToolError(str(exc)) from exc
            if isinstance(exc, Exception):  # e.g. a browser that fails to launch: say so, not "Error executing"
                first_line = (str(exc).strip().splitlines() or [""])[0][:300]
                raise ToolError(f"the {needed.get(kind, kind)} environment could not start for task {task.id} "
                                f"({type(exc).__name__}: {first_line}); nothing was recorded. This is a problem "
                                "of the server's machine, not of the call: see the server's log") from exc
            raise
        if episode.active not in episode.environments and episode.environments:
            episode.active = next(iter(episode.environments))
        self._episodes[episode_id] = episode
        self._starting.pop(episode_id, None)
        return episode

    def get(self, episode_id: str) -> Episode:
        episode = self._episodes.get(episode_id)
        if episode is None:
            raise EpisodeError(f"unknown episode id {quote(episode_id)}; start one with start_episode(task_id)")
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
    def _refuse_wrong_domain(self, episode: Episode, tool: str, requires: str) -> None:
        """A tool made for one kind of environment refuses an episode that has none of that kind."""
        if requires in episode.environment_names.values():
            return
        have = sorted(set(episode.environment_names.values()))
        specs = registry.environments()
        use = "; ".join(f"{name}: {specs[name].hint() if name in specs else name}" for name in have) or "none"
        raise EpisodeError(
            f"{tool} works only in episodes with a {requires} environment; episode {episode.id} "
            f"(task {episode.task.id}, {episode.task.domain}) has {', '.join(have) or 'no environment'}. "
            f"Use the tools of this episode's environments ({use}), and finish_episode to end it."
        )

    async def act(
        self,
        episode_id: str,
        tool: str,
        args: dict[str, Any],
        fn: Callable[[Episode], Awaitable[Observation]],
        *,
        environment: EnvSide | None,
        requires: str | None = None,
        counted: bool = True,
        ends: Status | None = None,
    ) -> tuple[Episode, Observation]:
        """Run one tool call against an episode, enforcing the protocol and recording it.

        The step rule (docs/architecture.md): every call on a running episode is written to the
        trajectory and, when ``counted`` (every agent call but start_episode), uses a step, whether
        it succeeds or fails. ``requires`` names the environment the tool is made for; ``ends``
        makes a successful call end the episode with that status before the lock is released,
        so no call racing it is applied or recorded after it (an atomic finish).
        """
        episode = self.running(episode_id)
        async with episode.lock:
            # Re-check under the lock: a concurrent call may have ended the episode.
            episode = self.running(episode_id)
            episode.last_call = time.monotonic()
            started = time.perf_counter()
            error: str | None = None
            observation: Observation | None = None
            try:
                if requires is not None:
                    self._refuse_wrong_domain(episode, tool, requires)
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
            except EnvError as exc:  # the environment refused: the client sees the message as a tool error
                error = str(exc)
                raise ToolError(error) from exc
            except Exception as exc:  # an environment bug: report it, keep the server alive
                error = f"internal error in {tool}: {type(exc).__name__}: {exc}"
                raise ToolError(error) from exc
            finally:
                episode.last_call = time.monotonic()  # idle time counts from the end of the last call
                try:
                    self._record(episode, tool, args, started, error, observation, counted)
                except RecordWriteError as exc:
                    episode.record_error = str(exc)
                if episode.record_error is not None and episode.status == "running":
                    # A record missing a call cannot be graded: the episode ends here, and says why.
                    await self._end(episode, "aborted", f"its record could not be written: {episode.record_error}")
                elif ends is not None and error is None:
                    await self._end(episode, ends, END_REASONS.get(ends, ends))
                elif counted and episode.status == "running" and episode.steps >= episode.task.step_limit:
                    await self._end(episode, "step_limit", f"step limit of {episode.task.step_limit} reached")
                if episode.record_error is not None:
                    done = "was done" if error is None else "failed"
                    raise ToolError(f"{tool} {done}, but the episode's record could not be written, so the episode "
                                    f"has ended ({episode.status}): {episode.record_error}")

    def _record(self, episode: Episode, tool: str, args: dict[str, Any], started: float, error: str | None,
                observation: Observation | None, counted: bool) -> None:
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

    async def record_rejected(self, episode_id: Any, tool: str, args: dict[str, Any], error: str) -> None:
        """A call the MCP layer refused before it reached ``act`` (its arguments failed validation, or the
        tool does not exist) still uses a step of the episode it names, and is written to its trajectory."""
        if not isinstance(episode_id, str):
            return
        episode = self._episodes.get(episode_id)
        if episode is None or episode.status != "running":
            return
        async with episode.lock:
            if episode.status != "running":
                return
            episode.last_call = time.monotonic()
            try:
                self._record(episode, tool, bounded_args(args), time.perf_counter(), error, None, True)
            except RecordWriteError as exc:
                episode.record_error = str(exc)
                await self._end(episode, "aborted", f"its record could not be written: {episode.record_error}")
                return
            if episode.steps >= episode.task.step_limit:
                await self._end(episode, "step_limit", f"step limit of {episode.task.step_limit} reached")

    async def switch(self, episode_id: str, target: EnvSide, message: str) -> tuple[Episode, Observation]:
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
        tool: str = "finish_episode", args: dict[str, Any] | None = None, requires: str | None = None,
        check: Callable[[Episode], None] | None = None,
    ) -> Episode:
        """End the episode with the agent's answer (or geolocation submission), atomically: the call is
        recorded and the episode ended under one hold of its lock. ``check`` may refuse the call (it is
        then recorded as a failed step and the episode stays open)."""

        async def do(episode: Episode) -> Observation:
            if check is not None:
                check(episode)
            episode.answer = answer
            episode.submission = submission
            return Observation(text=f"episode finished; answer: {quote(answer, 400)}")

        episode, _ = await self.act(episode_id, tool, args if args is not None else {"answer": answer}, do,
                                    environment=None, requires=requires, ends="finished")
        return episode

    async def _end(self, episode: Episode, status: Status, reason: str, *, infrastructure: bool = False) -> None:
        """End the episode and write its final state; ``infrastructure``: it was cut off by something other
        than the agent (records.FinalState.infrastructure_failure)."""
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
        final = FinalState(
            schema_version=SCHEMA_VERSION,
            episode_id=episode.id,
            task_id=episode.task.id,
            domain=episode.task.domain,
            status=status,
            end_reason=reason,
            answer=episode.answer,
            submission=episode.submission,
            steps=episode.steps,
            calls=episode.calls,
            switches=episode.switches,
            active_environment=episode.active,
            options=episode.options,
            started_at=datetime.fromtimestamp(episode.started_at, UTC).isoformat(),
            ended_at=datetime.fromtimestamp(episode.ended_at, UTC).isoformat(),
            wall_time_s=round(episode.ended_at - episode.started_at, 3),
            environments=env_states,
            **({"infrastructure_failure": reason} if infrastructure else {}),
        )
        try:
            episode.recorder.write_final_state(final)
        except RecordWriteError as exc:
            # The episode still ends (its environments are released below); the call that ended it says so.
            episode.record_error = episode.record_error or str(exc)
        for env in episode.environments.values():
            with anyio.CancelScope(shield=True):
                try:
                    await env.close()
                except Exception:
                    pass
        episode.recorder.close()

    async def abort(self, episode_id: str, reason: str) -> Episode:
        """End a running episode from outside (a harness resetting or closing it); its record stays gradable."""
        episode = self.get(episode_id)
        async with episode.lock:
            await self._end(episode, "aborted", reason)
        return episode

    def adopt(self, episode: Episode) -> None:
        """Register an episode built outside ``start`` (a fork, ewa_mcp/forking.py) under its id."""
        if episode.id in self._episodes:
            raise EpisodeError(f"episode id {episode.id} is taken")
        self._episodes[episode.id] = episode

    def emit_event(self, episode_id: str, event: dict[str, Any]) -> None:
        """Called by the embedded sites (any thread) to record a per-episode web event."""
        episode = self._episodes.get(episode_id) or self._starting.get(episode_id)
        if episode is not None:
            episode.web_events.append(event)
            try:
                episode.recorder.event(event)
            except RecordWriteError as exc:  # the episode's next call ends it and says why
                episode.record_error = episode.record_error or str(exc)
        for listener in self.event_listeners:
            listener(episode_id, event)

    async def aclose(self) -> None:
        reaper, self._reaper = self._reaper, None
        if reaper is not None:
            reaper.cancel()
        for episode in list(self._episodes.values()):
            if episode.status == "running":
                async with episode.lock:
                    await self._end(episode, "aborted", "the server shut down before the episode finished",
                                    infrastructure=True)

