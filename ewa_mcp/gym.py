"""Gymnasium environments over ewa-mcp episodes. ``import ewa_mcp.gym`` registers ``ewa_mcp/<domain>-v0`` for every
scored domain and ``ewa_mcp/suite-v0`` for all of them:

    import gymnasium, ewa_mcp.gym
    env = gymnasium.make("ewa_mcp/navigation-v0")                  # reward="dense" for the change in completion
    obs, info = env.reset(seed=0)                                   # or options={"task_id": "navigation-boston-000"}
    obs, reward, terminated, truncated, info = env.step({"tool": "street_observe", "arguments": {}})

The environment runs the real server in-process: one ``build_server`` per environment, its episodes started through
the server's own ``start_episode`` and played through a ``BoundServer`` (ewa_mcp/bound.py), i.e. the MCP server's
``call_tool`` with the episode bound. That is the path every transport ends in, so argument validation, refusals,
the step rule and the records are those an MCP agent gets; only the JSON-RPC framing is skipped (no session to
keep alive, no serialization per step). The server's event loop runs in a thread of its own (an anyio blocking
portal), so ``reset`` and ``step`` are plain synchronous calls. docs/training.md has the reasoning and the figures.

Spaces. An observation is the text an MCP agent reads (``ToolText``: a Text space that admits any characters, since
page text and street names are not alphanumeric); images, when the episode's observation mode asks for them, are in
``info["images"]`` as PNG bytes. An action is ``{"tool": name, "arguments": {...}}`` without the episode id
(``ToolCallSpace``, whose ``sample()`` draws a tool of the domain and arguments from its input schema).

Rewards. ``reward="sparse"`` (default): 1.0 on the step that ends an episode the grader judges successful
(``grade_episode`` on its record), else 0. ``reward="dense"``: the change in completion after each step, from the
grader's own checks on the live state (ewa_mcp/dense.py); over an episode it sums to the final completion.
``terminated`` is true when the agent ended the episode (finish_episode, submit_location), ``truncated`` when the
step limit (or a reset) did. ``info`` carries the task id, the tool's outcome, the steps, the completion and, on the
last step, the grade.
"""

from __future__ import annotations

import copy
import fnmatch
import string
import weakref
from contextlib import ExitStack
from pathlib import Path
from typing import Any, Literal

try:
    import gymnasium as gym
    from gymnasium import spaces
except ImportError as exc:  # an optional extra
    raise ImportError("ewa_mcp.gym needs Gymnasium: pip install 'ewa-mcp[gym]' (in a checkout: "
                      ".venv/bin/pip install -e '.[gym]')") from exc

import numpy as np
from anyio.from_thread import start_blocking_portal
from mcp.server.mcpserver.exceptions import ToolError
from mcp_types import CallToolResult, ImageContent, TextContent

from .core import registry
from .bound import CONTROL_TOOLS, BoundServer
from .dense import live_completion
from .forking import fork_episode
from .core.taskmodel import Task

MAX_OBSERVATION_CHARS = 2_000_000  # far above any observation (the web budget is 500,000 characters)
SUITE = "suite"
RewardMode = Literal["sparse", "dense"]


class ToolText(spaces.Text):
    """A Text space whose members are any strings up to ``max_length`` characters. Gymnasium's Text checks each
    character against a finite charset; observations hold any Unicode, so membership checks only type and length
    (``sample()`` still draws from the printable ASCII charset)."""

    def __init__(self, max_length: int = MAX_OBSERVATION_CHARS, seed: int | np.random.Generator | None = None):
        super().__init__(max_length, min_length=0, charset=string.printable, seed=seed)

    def contains(self, x: Any) -> bool:
        return isinstance(x, str) and self.min_length <= len(x) <= self.max_length

    def __repr__(self) -> str:
        return f"ToolText(max_length={self.max_length})"


class ToolCallSpace(spaces.Space[dict[str, Any]]):
    """Actions ``{"tool": name, "arguments": {...}}``: a member names one of ``tools`` and gives an argument object
    (the server validates the arguments, and refuses bad ones as a step, as it does for any MCP client)."""

    def __init__(self, tools: dict[str, dict[str, Any]], seed: int | np.random.Generator | None = None):
        if not tools:
            raise ValueError("a ToolCallSpace needs at least one tool")
        self.tools = {name: tools[name] for name in sorted(tools)}  # name -> input schema
        super().__init__(None, None, seed)

    @property
    def is_np_flattenable(self) -> bool:
        return False

    def contains(self, x: Any) -> bool:
        return (isinstance(x, dict) and set(x) <= {"tool", "arguments"} and x.get("tool") in self.tools
                and isinstance(x.get("arguments", {}), dict))

    def sample(self, mask: Any = None, probability: Any = None) -> dict[str, Any]:
        if mask is not None or probability is not None:
            raise ValueError("ToolCallSpace.sample takes no mask or probability")
        names = list(self.tools)
        name = names[int(self.np_random.integers(len(names)))]
        return {"tool": name, "arguments": sample_arguments(self.tools[name], self.np_random)}

    def __repr__(self) -> str:
        return f"ToolCallSpace({', '.join(self.tools)})"

    def __eq__(self, other: Any) -> bool:
        return isinstance(other, ToolCallSpace) and other.tools == self.tools


def _sample_value(schema: dict[str, Any], rng: np.random.Generator) -> Any:
    if "enum" in schema:
        return schema["enum"][int(rng.integers(len(schema["enum"])))]
    if "const" in schema:
        return schema["const"]
    if "anyOf" in schema:
        options = [s for s in schema["anyOf"] if s.get("type") != "null"] or schema["anyOf"]
        return _sample_value(options[int(rng.integers(len(options)))], rng)
    kind = schema.get("type")
    if kind == "boolean":
        return bool(rng.integers(2))
    if kind == "integer":
        low = int(schema.get("minimum", 0))
        high = int(schema.get("maximum", low + 10))
        return int(rng.integers(low, min(high, low + 10) + 1))
    if kind == "number":
        lo = float(schema.get("minimum", -10.0))
        hi = float(schema.get("maximum", 10.0))
        return round(float(rng.uniform(lo, hi)), 4)
    if kind == "string":
        low = int(schema.get("minLength", 1))
        high = max(low, min(int(schema.get("maxLength", 12)), 12))
        length = int(rng.integers(low, high + 1))
        return "".join(string.ascii_lowercase[int(i)] for i in rng.integers(26, size=length))
    if kind == "object":
        return sample_arguments(schema, rng)
    return None


def sample_arguments(schema: dict[str, Any], rng: np.random.Generator) -> dict[str, Any]:
    """Random arguments for an input schema: every required property, each optional one half the time."""
    props = schema.get("properties") or {}
    required = set(schema.get("required") or ())
    out: dict[str, Any] = {}
    for name in sorted(props):
        if name in required or rng.integers(2):
            out[name] = _sample_value(props[name], rng)
    return out


def _texts(result: CallToolResult) -> str:
    return "\n".join(c.text for c in result.content if isinstance(c, TextContent))


def _images(result: CallToolResult) -> list[bytes]:
    import base64

    return [base64.b64decode(c.data) for c in result.content if isinstance(c, ImageContent)]


class _Runtime:
    """One in-process server and the thread its event loop runs in; shared by an environment and its forks."""

    def __init__(self, task_dirs: list[Path] | None, run_dir: Path | None, settings: Any):
        from .server import ServerConfig, build_server

        self._stack = ExitStack()
        self.portal = self._stack.enter_context(start_blocking_portal())
        self.full, self.episodes = build_server(ServerConfig(settings=settings, task_dirs=task_dirs, run_dir=run_dir))
        self.users = 0
        self.closed = False

    def close(self) -> None:
        if self.closed:
            return
        self.closed = True
        try:
            self.portal.call(self.episodes.aclose)
            self.portal.call(self.episodes.services.aclose)
        finally:
            self._stack.close()


def _release(runtime: _Runtime) -> None:
    runtime.users -= 1
    if runtime.users <= 0:
        runtime.close()


class EwaEnv(gym.Env[str, dict[str, Any]]):
    """Episodes of one domain's tasks (or the whole suite) as a Gymnasium environment; see the module docstring."""

    metadata: dict[str, Any] = {"render_modes": []}

    def __init__(self, domain: str = SUITE, *, tasks: list[str] | None = None, extra_tasks: list[Task] | None = None,
                 reward: RewardMode = "sparse", observation: Literal["text", "vision", "both"] = "text",
                 episode_options: dict[str, Any] | None = None, task_dirs: list[str | Path] | None = None,
                 run_dir: str | Path | None = None, settings: Any = None, split: str = "test", split_seed: int = 0,
                 _runtime: _Runtime | None = None):
        known = registry.domain_names()
        if domain != SUITE and domain not in known:
            raise ValueError(f"unknown domain {domain!r}; use one of {', '.join([*known, SUITE])}")
        if reward not in ("sparse", "dense"):
            raise ValueError(f"unknown reward {reward!r}; use 'sparse' (1.0 for a successful episode) or 'dense' "
                             "(the change in completion after each step)")
        if observation not in ("text", "vision", "both"):
            raise ValueError(f"unknown observation {observation!r}; use 'text', 'vision' or 'both'")
        self.domain = domain
        self.reward_mode: RewardMode = reward
        self.episode_options = {**(episode_options or {}), "observation": observation}
        self._init_args = dict(domain=domain, tasks=tasks, reward=reward, observation=observation,
                               episode_options=episode_options)
        if split != "test" or split_seed:
            # A fresh split (ewa_mcp/taskgen/splits.py): its tasks join the store and are the only ones drawn.
            # Drawn before the server starts, so a refused split leaves nothing running.
            from .taskgen.splits import generate_split

            if domain == SUITE:
                raise ValueError(f"split={split!r} needs one domain (navigation or cooking), not the suite")
            drawn = generate_split(domain, split, split_seed)
            extra_tasks = [*(extra_tasks or ()), *drawn]
            tasks = tasks or [t.id for t in drawn]
            self._init_args["tasks"] = tasks  # a fork draws from the same tasks
        if _runtime is None:
            _runtime = _Runtime([Path(d) for d in task_dirs] if task_dirs else None,
                                Path(run_dir) if run_dir else None, settings)
        self._runtime = _runtime
        _runtime.users += 1
        self._finalizer = weakref.finalize(self, _release, _runtime)
        for task in extra_tasks or ():
            _runtime.episodes.tasks.add(task)
        self.task_ids = self._select_tasks(tasks)
        self.action_space = ToolCallSpace(self._domain_tools())
        self.observation_space = ToolText()
        self.bound: BoundServer | None = None
        self.episode_id: str | None = None
        self._completion = 0.0
        self._ended = False

    # ------------------------------------------------------------ setup
    def _select_tasks(self, patterns: list[str] | None) -> list[str]:
        store = self._runtime.episodes.tasks
        scored = set(registry.domain_names(scored_only=True))
        pool = sorted(t.id for t in store.all() if (t.domain == self.domain if self.domain != SUITE
                                                     else t.domain in scored))
        if patterns:
            every = sorted(t.id for t in store.all())
            pool = [tid for tid in every if any(fnmatch.fnmatchcase(tid, p) for p in patterns)]
        if not pool:
            raise ValueError(f"no tasks match {patterns or self.domain!r} in {', '.join(map(str, store.roots))}; "
                             "give task ids or globs that exist (ewa-mcp tasks list)")
        return pool

    def _domain_tools(self) -> dict[str, dict[str, Any]]:
        """The tools an agent of this domain may call: the episode tools and its environments' tools."""
        from .bound import unbind_schema

        specs = registry.environments()
        domains = ([registry.domain(self.domain)] if self.domain != SUITE
                   else [registry.domain(d) for d in registry.domain_names(scored_only=True)])
        mine = {env.name for d in domains if d is not None for env in d.environments}
        hidden = {spec.tools for name, spec in specs.items() if spec.tools and name not in mine}
        manager = self._runtime.full._tool_manager
        return {tool.name: unbind_schema(tool.parameters) for tool in manager.list_tools()
                if tool.name not in CONTROL_TOOLS and getattr(tool.fn, "__module__", None) not in hidden}

    # ------------------------------------------------------------ the Gymnasium API
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[str, dict[str, Any]]:
        super().reset(seed=seed)
        options = dict(options or {})
        unknown = set(options) - {"task_id", "episode_options"}
        if unknown:
            raise ValueError(f"unknown reset option(s) {sorted(unknown)}; reset takes options={{'task_id': ..., "
                             "'episode_options': {...}}}")
        task_id = options.get("task_id")
        if task_id is None:
            task_id = self.task_ids[int(self.np_random.integers(len(self.task_ids)))]
        elif self._runtime.episodes.tasks.get(task_id) is None:
            raise ValueError(f"unknown task id {task_id!r}; pass one of env.unwrapped.task_ids "
                             "(ewa-mcp tasks list shows them all)")
        self._end_current("the environment was reset before the episode ended")
        bound = BoundServer(self._runtime.full, task_id=task_id,
                            options={**self.episode_options, **(options.get("episode_options") or {})})
        result = self._runtime.portal.call(bound.start)
        self.bound, self.episode_id = bound, bound.episode_id
        self._completion = 0.0
        self._ended = False
        return _texts(result), self._info(images=_images(result))

    def step(self, action: dict[str, Any]) -> tuple[str, float, bool, bool, dict[str, Any]]:
        if self.bound is None or self.episode_id is None:
            raise gym.error.ResetNeeded("call reset() before step()")
        if self._ended:
            raise gym.error.ResetNeeded("the episode has ended; call reset() to start another")
        tool, arguments = parse_action(action)
        ok = True
        images: list[bytes] = []
        try:
            result = self._runtime.portal.call(self.bound.call_tool, tool, arguments)
            text, images, ok = _texts(result), _images(result), not result.is_error
        except ToolError as exc:  # refused (and recorded as a step): the agent reads the message, as over MCP
            text, ok = str(exc), False
        episode = self._runtime.episodes.get(self.episode_id)
        ended = episode.status != "running"
        grade: dict[str, Any] | None = None
        if ended:
            from .graders import grade_episode

            result_grade = grade_episode(episode.recorder.directory)
            completion = result_grade.completion or 0.0
            success = result_grade.overall_success is True
            grade = _grade_summary(result_grade)
            reward = completion - self._completion if self.reward_mode == "dense" else float(success)
            self._ended = True
        elif self.reward_mode == "dense":
            completion = self._runtime.portal.call(live_completion, episode)
            reward = completion - self._completion
        else:
            completion, reward = self._completion, 0.0
        self._completion = completion
        terminated = episode.status == "finished"
        truncated = ended and not terminated
        info = self._info(tool=tool, ok=ok, images=images, grade=grade)
        return text, float(reward), terminated, truncated, info

    def close(self) -> None:
        self._end_current("the environment was closed before the episode ended")
        self.bound = None
        self._finalizer()  # the server closes with its last environment (an environment and its forks share it)

    # ------------------------------------------------------------ beyond Gymnasium
    def fork(self) -> EwaEnv:
        """A new environment on a copy of the running episode (ewa_mcp/forking.py), sharing this one's server:
        the same actions give both the same observations from here on."""
        if self.bound is None or self.episode_id is None or self._ended:
            raise gym.error.ResetNeeded("fork() needs a running episode; call reset() first")
        forked = self._runtime.portal.call(fork_episode, self._runtime.episodes, self.episode_id)
        other = EwaEnv(**self._init_args, _runtime=self._runtime)  # type: ignore[arg-type]
        other.task_ids = list(self.task_ids)
        other.bound = BoundServer(self._runtime.full, episode_id=forked.id)
        other.episode_id = forked.id
        other._completion = self._completion
        other._np_random = copy.deepcopy(self._np_random)
        return other

    @property
    def episode(self) -> Any:
        """The running episode (ewa_mcp.core.episodes.Episode), for harnesses that look at its state."""
        return None if self.episode_id is None else self._runtime.episodes.get(self.episode_id)

    @property
    def run_dir(self) -> Path:
        return self._runtime.episodes.run_dir

    # ------------------------------------------------------------ helpers
    def _end_current(self, reason: str) -> None:
        if self.episode_id is None or self._runtime.closed:
            return
        episode = self._runtime.episodes.get(self.episode_id)
        if episode.status == "running":
            self._runtime.portal.call(self._runtime.episodes.abort, self.episode_id, reason)

    def _info(self, *, tool: str | None = None, ok: bool | None = None, images: list[bytes] | None = None,
              grade: dict[str, Any] | None = None) -> dict[str, Any]:
        """What a step reports besides the text. Nothing here varies between two runs of the same actions (no
        episode id, no timings), so seeded runs compare equal."""
        episode = self.episode
        assert episode is not None
        info: dict[str, Any] = {
            "task_id": episode.task.id, "domain": episode.task.domain, "status": episode.status,
            "active_environment": episode.active, "steps": episode.steps, "steps_left": episode.steps_left,
            "completion": self._completion,
        }
        if tool is not None:
            info["tool"] = tool
            info["ok"] = ok
        if images:
            info["images"] = list(images)
        if grade is not None:
            info["grade"] = grade
        return info


def _grade_summary(result: Any) -> dict[str, Any]:
    """The grade without what differs between identical runs (episode id, wall time)."""
    return {
        "overall_success": result.overall_success, "completion": result.completion,
        "web_success": result.web_success, "embodied_success": result.embodied_success,
        "answer_correct": result.answer_correct, "status": result.status, "end_reason": result.end_reason,
        "steps": result.steps,
        "conditions": [{"side": c.side, "kind": c.kind, "description": c.description, "met": c.met}
                       for c in result.conditions],
    }


def parse_action(action: Any) -> tuple[str, dict[str, Any]]:
    """``{"tool": name, "arguments": {...}}`` -> (name, arguments); anything else is refused with the form."""
    form = "an action is {'tool': <tool name>, 'arguments': {<argument>: <value>, ...}} without the episode id"
    if not isinstance(action, dict) or not isinstance(action.get("tool"), str) or not action["tool"]:
        raise ValueError(f"{form}; got {repr(action)[:200]}")
    extra = set(action) - {"tool", "arguments"}
    if extra:
        raise ValueError(f"{form}; unknown key(s) {sorted(extra)}")
    arguments = action.get("arguments") or {}
    if not isinstance(arguments, dict):
        raise ValueError(f"{form}; 'arguments' is a {type(arguments).__name__}")
    return action["tool"], dict(arguments)


def register_environments() -> list[str]:
    """Register ``ewa_mcp/<domain>-v0`` for every scored domain and ``ewa_mcp/suite-v0``; returns the ids."""
    ids = []
    for name in [*registry.domain_names(scored_only=True), SUITE]:
        env_id = f"ewa_mcp/{name}-v0"
        if env_id not in gym.registry:
            gym.register(id=env_id, entry_point="ewa_mcp.gym:EwaEnv", kwargs={"domain": name})
        ids.append(env_id)
    return ids


ENV_IDS = register_environments()
