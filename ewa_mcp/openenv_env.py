"""OpenEnv environments over ewa-mcp episodes (``openenv-core``'s ``Environment``, served by its FastAPI app).

    from ewa_mcp.openenv_env import EwaAction, create_ewa_app
    app = create_ewa_app("navigation", max_concurrent_envs=16)     # uvicorn.run(app, host="127.0.0.1", port=8000)

A client opens a session on the app's ``/ws`` WebSocket (``EwaEnvClient`` below, openenv's ``EnvClient``) and sends
``{"type": "reset", "data": {"seed": 0, "task_id": "navigation-boston-000"}}``, then
``{"type": "step", "data": {"tool": "street_observe", "arguments": {}}}`` until the observation says ``done``.

One OpenEnv session is one ``EwaOpenEnv``, and each ``reset`` starts a new ewa-mcp episode in it (the previous one,
if still running, is aborted). The environment is a thin layer over the Gymnasium environment of ewa_mcp/gym.py,
so an action takes exactly the path an MCP agent's tool call takes: a ``BoundServer`` (ewa_mcp/bound.py) with the
episode already bound, the server's validation, step rule and records. Every session of an app shares one
in-process ewa-mcp server (episodes are isolated there as they are for concurrent MCP clients), so sessions are
cheap and ``SUPPORTS_CONCURRENT_SESSIONS`` is true.

The agent's action space is the bound plane's: a tool of the episode's environments and its arguments, without the
episode id. ``list_tasks`` and ``start_episode`` are not in it (the observation's ``tools`` lists what is), and a
call naming one is refused as a step, as the bound MCP plane refuses it: choosing, starting and resetting episodes
stays with the trainer, which reaches them only through OpenEnv's reset (``reset(task_id=...)``).

Reward: the grader's. ``reward="sparse"`` (default) gives 1.0 on the step that ends an episode the grader
(``grade_episode`` on the episode's record) judges successful, else 0.0; ``reward="dense"`` the change in completion
after each step (ewa_mcp/dense.py). ``done`` is true on the step that ends the episode (a finishing call, the step
limit). The grade is the trainer's to read, in the state (``state.grade``) and the observation's ``metadata``,
which openenv keeps off the wire: a client over ``/ws`` reads the state.

``openenv-core`` 0.3 requires Gradio for its optional web UI, and every Gradio release requires Pillow < 13, which
ewa-mcp cannot use; ``make install`` therefore installs ``openenv-core`` without its dependencies and the
``openenv`` extra adds the ones its server needs (docs/training.md, "OpenEnv"). The web UI
(``ENABLE_WEB_INTERFACE``) is not available; ``create_ewa_app`` builds the plain API app.
"""

from __future__ import annotations

import base64
import functools
import threading
from pathlib import Path
from typing import Any, Literal

try:
    from openenv.core.client_types import StepResult
    from openenv.core.env_client import EnvClient
    from openenv.core.env_server import Environment, create_fastapi_app
    from openenv.core.env_server.types import Action, EnvironmentMetadata, Observation, State
except ImportError as exc:  # an optional extra
    raise ImportError("ewa_mcp.openenv_env needs openenv-core: in a checkout, `make install` installs it (it "
                      "is installed without its Gradio dependency; see docs/training.md, \"OpenEnv\")") from exc

from pydantic import Field

from . import __version__
from .core.taskmodel import Task
from .gym import SUITE, EwaEnv, RewardMode, ToolCallSpace, _release, _Runtime

# EwaEnv construction and close change the shared server's user count; sessions are created and closed in
# different executor threads.
_USERS_LOCK = threading.Lock()


class EwaAction(Action):
    """A tool call on the session's episode: the tool's name and its arguments, without the episode id."""

    tool: str = Field(..., min_length=1, max_length=100, description="the tool to call, e.g. street_move")
    arguments: dict[str, Any] = Field(default_factory=dict, description="the tool's arguments")


class EwaObservation(Observation):
    """What the agent reads after a reset or a step; ``metadata`` has the harness's view (task, steps, grade)."""

    text: str = Field(default="", description="the text an MCP agent reads: the task (at reset) or the tool's result")
    images: list[str] = Field(default_factory=list, description="base64 PNG images, when the observation mode has them")
    ok: bool | None = Field(default=None, description="whether the tool call succeeded (None at reset)")
    tools: list[str] = Field(default_factory=list,
                             description="at reset: the tools the agent may call in this episode (no control tools)")


class EwaState(State):
    """The session's episode as the trainer sees it."""

    task_id: str | None = None
    domain: str | None = None
    status: str | None = None
    completion: float = 0.0
    record_id: str | None = Field(default=None, description="the episode's id in the server's records (runs/)")
    grade: dict[str, Any] | None = Field(default=None, description="the grader's verdict, once the episode ended")


class EwaOpenEnv(Environment[EwaAction, EwaObservation, EwaState]):
    """ewa-mcp episodes of one domain (or the suite) as an OpenEnv environment; see the module docstring."""

    SUPPORTS_CONCURRENT_SESSIONS = True

    def __init__(self, domain: str = SUITE, *, tasks: list[str] | None = None, extra_tasks: list[Task] | None = None,
                 reward: RewardMode = "sparse", observation: Literal["text", "vision", "both"] = "text",
                 episode_options: dict[str, Any] | None = None, task_dirs: list[str | Path] | None = None,
                 run_dir: str | Path | None = None, settings: Any = None, _runtime: _Runtime | None = None):
        super().__init__()
        with _USERS_LOCK:
            self._env = EwaEnv(domain, tasks=tasks, extra_tasks=extra_tasks, reward=reward, observation=observation,
                               episode_options=episode_options, task_dirs=task_dirs, run_dir=run_dir,
                               settings=settings, _runtime=_runtime)
        assert isinstance(self._env.action_space, ToolCallSpace)
        self._space: ToolCallSpace = self._env.action_space
        self._state = EwaState(domain=None if domain == SUITE else domain)
        self._closed = False

    @property
    def tools(self) -> list[str]:
        """The tools an agent of this environment may call (the bound plane's: no control tools)."""
        return sorted(self._space.tools)

    @property
    def task_ids(self) -> list[str]:
        return list(self._env.task_ids)

    def reset(self, seed: int | None = None, episode_id: str | None = None, task_id: str | None = None,
              **kwargs: Any) -> EwaObservation:
        """Start a new episode: the task ``task_id``, or one drawn with ``seed`` from the environment's tasks."""
        if kwargs:
            raise ValueError(f"unknown reset parameter(s) {sorted(kwargs)}; reset takes seed, episode_id and task_id")
        options = {"task_id": task_id} if task_id is not None else None
        text, info = self._env.reset(seed=seed, options=options)
        self._state = EwaState(episode_id=episode_id or self._env.episode_id, step_count=0, task_id=info["task_id"],
                               domain=info["domain"], status=info["status"], completion=info["completion"],
                               record_id=self._env.episode_id)
        tools = self._episode_tools()
        return EwaObservation(text=text, images=_encode(info.pop("images", [])), tools=tools, done=False,
                              reward=0.0, metadata=info)

    def step(self, action: EwaAction, timeout_s: float | None = None, **kwargs: Any) -> EwaObservation:
        """Call one tool on the episode; the reward is the grader's (see the module docstring)."""
        if self._env.episode_id is None:
            raise RuntimeError("no episode yet: send a reset first (it starts the session's episode)")
        if self._state.status not in (None, "running"):
            raise RuntimeError(f"the episode has ended ({self._state.status}); send a reset to start another")
        text, reward, terminated, truncated, info = self._env.step({"tool": action.tool,
                                                                   "arguments": dict(action.arguments)})
        self._state.step_count = info["steps"]
        self._state.status = info["status"]
        self._state.completion = info["completion"]
        self._state.grade = info.get("grade")
        return EwaObservation(text=text, images=_encode(info.pop("images", [])), ok=info.get("ok"),
                              done=terminated or truncated, reward=reward, metadata=info)

    @property
    def state(self) -> EwaState:
        return self._state

    def get_metadata(self) -> EnvironmentMetadata:
        return EnvironmentMetadata(name="ewa-mcp", version=__version__,
                                   description="Embodied web agent episodes (kitchen, street, geolocation, web) with "
                                               "the grader's reward; actions are tool calls on a bound episode")

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        with _USERS_LOCK:
            self._env.close()

    def _episode_tools(self) -> list[str]:
        """The tools of the environments the running episode has (a geolocation episode lists no kitchen tools)."""
        bound = self._env.bound
        assert bound is not None
        return sorted(name for name in self._space.tools if not bound._foreign(name))


def _encode(images: list[bytes]) -> list[str]:
    return [base64.b64encode(png).decode("ascii") for png in images]


def create_ewa_app(domain: str = SUITE, *, max_concurrent_envs: int = 8, tasks: list[str] | None = None,
                   extra_tasks: list[Task] | None = None, reward: RewardMode = "sparse",
                   observation: Literal["text", "vision", "both"] = "text",
                   episode_options: dict[str, Any] | None = None, task_dirs: list[str | Path] | None = None,
                   run_dir: str | Path | None = None, settings: Any = None) -> Any:
    """The OpenEnv FastAPI app: each WebSocket session (``/ws``) gets its own ``EwaOpenEnv``, all of them on one
    in-process ewa-mcp server, which stops when the app shuts down. ``max_concurrent_envs`` caps the sessions."""
    if max_concurrent_envs < 1:
        raise ValueError(f"max_concurrent_envs must be at least 1, not {max_concurrent_envs}")
    runtime = _Runtime([Path(d) for d in task_dirs] if task_dirs else None, Path(run_dir) if run_dir else None,
                       settings)
    with _USERS_LOCK:
        runtime.users += 1  # the app's own hold: the server outlives the sessions until shutdown
    try:
        for task in extra_tasks or ():
            runtime.episodes.tasks.add(task)
        kwargs: dict[str, Any] = dict(tasks=tasks, reward=reward, observation=observation,
                                      episode_options=episode_options)
        EwaOpenEnv(domain, **kwargs, _runtime=runtime).close()  # bad arguments fail here, not in each session
    except BaseException:
        with _USERS_LOCK:
            _release(runtime)
        raise

    # A partial of the class: openenv reads SUPPORTS_CONCURRENT_SESSIONS from it without building a session.
    make_env = functools.partial(EwaOpenEnv, domain, **kwargs, _runtime=runtime)
    app = create_fastapi_app(make_env, EwaAction, EwaObservation, max_concurrent_envs=max_concurrent_envs)

    def shutdown() -> None:
        with _USERS_LOCK:
            _release(runtime)

    app.router.on_shutdown.append(shutdown)
    app.state.ewa_runtime = runtime
    return app


class EwaEnvClient(EnvClient[EwaAction, EwaObservation, EwaState]):
    """openenv's WebSocket client for an app of ``create_ewa_app``, with ewa-mcp's types:

        async with EwaEnvClient("http://127.0.0.1:8000") as client:
            result = await client.reset(task_id="geo-0001-baseline")
            result = await client.step(EwaAction(tool="geo_look"))    # result.observation.text, .reward, .done
            state = await client.state()                              # state.grade once the episode ended
    """

    def _step_payload(self, action: EwaAction) -> dict[str, Any]:
        return action.model_dump(exclude={"metadata"})

    def _parse_result(self, payload: dict[str, Any]) -> StepResult[EwaObservation]:
        reward, done = payload.get("reward"), bool(payload.get("done", False))
        observation = EwaObservation(**payload.get("observation", {}), reward=reward, done=done)
        return StepResult(observation=observation, reward=reward, done=done)

    def _parse_state(self, payload: dict[str, Any]) -> EwaState:
        return EwaState(**payload)
