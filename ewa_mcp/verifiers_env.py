"""A verifiers environment over ewa-mcp episodes (``verifiers`` 0.4, its ``verifiers.v1`` API).

    import ewa_mcp.verifiers_env as ewa_vf
    env = ewa_vf.load_environment(domain="navigation", split="train", split_seed=7)   # a vf.SingleAgentEnv
    # or one rollout: vf.Agent(ewa_vf.agent_config(model, base_url)).run(task) for a task of ewa_vf.taskset(...)

The module is a verifiers plugin: once imported, its id ``ewa_mcp_verifiers`` names it as a taskset and as a
harness; it exports one ``Taskset``, one ``Task`` and one ``Harness`` (verifiers finds each through ``__all__``).

- **Tasks.** ``EwaTaskset`` yields one ``EwaTask`` per ewa-mcp task of a domain (or the suite), of a split
  (``split="train"`` with ``split_seed``: fresh tasks, ewa_mcp/taskgen/splits.py) or of a list of ids and globs.
- **Per-episode rollouts.** ``EwaTask.setup`` starts the rollout's own episode, bound (ewa_mcp/bound.py): the agent
  gets the episode's tools without ``list_tasks``, ``start_episode`` or an ``episode_id``. All rollouts of a process
  share one in-process ewa-mcp server, as the Gymnasium and OpenEnv adapters do.
- **The harness.** verifiers' own tool-calling harnesses run the agent as a PEP 723 script through ``uv``, which
  installs its packages from the network when a rollout starts. ``EwaHarness`` is an in-process harness instead:
  it asks the model through the rollout's interception endpoint (so verifiers records every turn and routes it to
  the run's client) with the episode's tools as OpenAI function tools, plays each tool call on the bound episode
  and returns the result as the tool message, until the episode ends or the model answers without a tool call.
- **Reward: the grader's.** ``EwaTask``'s ``@vf.reward`` ``success`` is 1.0 when ``grade_episode`` judges the
  episode's record successful, else 0.0; the ``@vf.metric`` ``completion`` is the grade's completion. An episode the
  model left running is aborted first (graded as the step limit would leave it).

Install: verifiers 0.4 pins ``mcp==2.0.0`` and ``openai<3``, which ewa-mcp cannot share (it needs mcp >= 2.3 and
its ``agents`` extra openai >= 3.54), so ``make install`` installs ``verifiers`` with ``--no-deps`` and the
``verifiers`` extra brings its other dependencies; docs/training.md, "verifiers".
"""

from __future__ import annotations

import asyncio
import json
import sys
import threading
from pathlib import Path
from typing import Any

try:
    import verifiers.v1 as vf
    from verifiers.v1.clients import EvalClientConfig
    from verifiers.v1.configs.agent import AgentConfig
    from verifiers.v1.configs.harness import HarnessConfig
    from verifiers.v1.envs.single_agent import SingleAgentEnvConfig
    from verifiers.v1.runtimes import ProgramResult, SubprocessConfig
except ImportError as exc:  # an optional extra
    raise ImportError("ewa_mcp.verifiers_env needs verifiers 0.4: in a checkout, `make install` installs it "
                      "(without its pinned mcp and openai; see docs/training.md, \"verifiers\")") from exc

from .bound import BOUND_INSTRUCTIONS
from .gym import SUITE, EwaEnv, _release, _Runtime

# verifiers imports a plugin by a top-level module name (it looks for `verifiers.v1.harnesses.<id>` first, which
# fails for a dotted id), and the wheel installs one import name, ewa_mcp: importing this module registers it under
# the plugin id as well.
PLUGIN_ID = "ewa_mcp_verifiers"
sys.modules.setdefault(PLUGIN_ID, sys.modules[__name__])

# One in-process ewa-mcp server per (task dirs, run dir), shared by every rollout of the process, and the live
# episode of each rollout by its trace id (the harness and the reward find it there).
_LOCK = threading.Lock()
_RUNTIMES: dict[tuple[tuple[str, ...], str | None], _Runtime] = {}
_LIVE: dict[str, EwaEnv] = {}
_GRADES: dict[str, dict[str, Any]] = {}


def _runtime(task_dirs: tuple[str, ...], run_dir: str | None) -> _Runtime:
    key = (task_dirs, run_dir)
    with _LOCK:
        runtime = _RUNTIMES.get(key)
        if runtime is None or runtime.closed:
            runtime = _Runtime([Path(d) for d in task_dirs] or None, Path(run_dir) if run_dir else None, None)
            runtime.users += 1  # held until shutdown(): rollouts come and go
            _RUNTIMES[key] = runtime
        return runtime


def shutdown() -> None:
    """Stop the in-process servers this module started (each stops its browser too)."""
    with _LOCK:
        for env in _LIVE.values():
            env.close()
        _LIVE.clear()
        _GRADES.clear()
        for runtime in _RUNTIMES.values():
            _release(runtime)
        _RUNTIMES.clear()


class EwaTasksetConfig(vf.TasksetConfig):
    id: str = PLUGIN_ID
    domain: str = SUITE
    """A domain (navigation, cooking, shopping, traveling, geolocation) or "suite"."""
    tasks: list[str] | None = None
    """Task ids or globs to draw from (default: the domain's tasks)."""
    split: str = "test"
    """"test" (the public suite), or "train"/"hidden" with split_seed: fresh tasks of one domain."""
    split_seed: int = 0
    task_dirs: list[str] = []
    """Task suites to serve (default: the installed or checkout suite)."""
    run_dir: str | None = None
    """Where episode records go (default: the server's runs directory)."""


class EwaTaskData(vf.TaskData):
    task_id: str
    """The ewa-mcp task this rollout plays."""


class EwaTask(vf.Task[EwaTaskData]):
    """One ewa-mcp task: setup starts the rollout's bound episode, the reward is the grader's."""

    host: tuple[tuple[str, ...], str | None] = ((), None)  # set by the taskset: which shared server to use

    async def setup(self, trace: Any, runtime: Any) -> None:
        server = _runtime(*self.host)
        env = EwaEnv(SUITE, tasks=[self.data.task_id], _runtime=server)
        try:
            await asyncio.to_thread(env.reset, options={"task_id": self.data.task_id})
        except BaseException:
            env.close()
            raise
        with _LOCK:
            _LIVE[trace.id] = env

    @vf.metric
    async def completion(self, trace: Any) -> float:
        """The fraction of the task's conditions met (docs/grading.md)."""
        return float(_grade(trace.id).get("completion") or 0.0)

    @vf.reward
    async def success(self, trace: Any) -> float:
        """1.0 when the grader judges the episode successful, else 0.0."""
        with _LOCK:
            grade = _GRADES.pop(trace.id, None)
        grade = grade or _grade(trace.id, keep=False)
        return 1.0 if grade.get("overall_success") is True else 0.0


def _grade(trace_id: str, keep: bool = True) -> dict[str, Any]:
    """The grade of the rollout's episode (ended first if the model left it running); the episode is released."""
    from .graders import grade_episode

    with _LOCK:
        cached = _GRADES.get(trace_id)
        env = _LIVE.pop(trace_id, None)
    if cached is not None:
        return cached
    if env is None:
        raise RuntimeError(f"no episode for rollout {trace_id}: its task setup did not run or failed")
    episode = env.episode
    env.close()  # aborts an episode still running, so its record is complete
    result = grade_episode(episode.recorder.directory)
    grade = {"overall_success": result.overall_success, "completion": result.completion,
             "status": result.status, "end_reason": result.end_reason, "steps": result.steps}
    if keep:
        with _LOCK:
            _GRADES[trace_id] = grade
    return grade


class EwaTaskset(vf.Taskset[EwaTask, EwaTasksetConfig]):
    """The ewa-mcp tasks of a domain, a split or a list, one ``EwaTask`` each."""

    def load(self) -> Any:
        config = self.config
        host = (tuple(config.task_dirs), config.run_dir)
        server = _runtime(*host)
        extra = []
        if config.split != "test" or config.split_seed:
            from .taskgen.splits import generate_split

            if config.domain == SUITE:
                raise ValueError(f"split={config.split!r} needs one domain (navigation or cooking), not the suite")
            extra = generate_split(config.domain, config.split, config.split_seed)
            for task in extra:
                server.episodes.tasks.add(task)
        # The gym environment selects the tasks exactly as `gymnasium.make` does (domain, ids, globs).
        chooser = EwaEnv(config.domain, tasks=config.tasks or ([t.id for t in extra] or None), _runtime=server)
        try:
            ids = list(chooser.task_ids)
        finally:
            chooser.close()
        for task_id in ids:
            spec = server.episodes.tasks.get(task_id)
            assert spec is not None  # chosen from the same store
            task = EwaTask(EwaTaskData(id=task_id, name=task_id, task_id=task_id, prompt=spec.intent,
                                       system_prompt=BOUND_INSTRUCTIONS), config.task)
            task.host = host
            yield task


class EwaHarnessConfig(HarnessConfig):
    id: str = PLUGIN_ID
    max_tool_calls: int = 500
    """A bound on the model's calls beyond the episode's own step limit (which ends the episode first)."""


class EwaHarness(vf.Harness[EwaHarnessConfig]):
    """Plays the model's tool calls on the rollout's bound episode, in-process (see the module docstring)."""

    APPENDS_SYSTEM_PROMPT = True
    EXECUTES_CODE = False
    NEEDS_CONTAINER = False

    async def launch(self, ctx: Any, trace: Any, runtime: Any, endpoint: str, secret: str,
                     mcp_urls: dict[str, str], data: Any, tool_interception_url: str | None = None) -> Any:
        from openai import AsyncOpenAI

        with _LOCK:
            env = _LIVE.get(trace.id)
        if env is None or env.bound is None:
            return ProgramResult(exit_code=1, stdout="", stderr="no episode: the task's setup did not start one")
        bound = env.bound
        tools = [{"type": "function", "function": {"name": t.name, "description": t.description or t.name,
                                                   "parameters": t.input_schema}}
                 for t in await asyncio.to_thread(env._runtime.portal.call, bound.list_tools)]
        # What the agent reads first is what a bound MCP agent reads: the task and the first observation.
        messages: list[dict[str, Any]] = [{"role": "system", "content": data.system_prompt or BOUND_INSTRUCTIONS},
                                          {"role": "user", "content": bound.start_text or data.prompt}]
        client = AsyncOpenAI(base_url=endpoint, api_key=secret or "unused", max_retries=0)
        calls = 0
        try:
            while calls < self.config.max_tool_calls:
                reply = await client.chat.completions.create(model=ctx.model, messages=messages,  # type: ignore
                                                             tools=tools)  # type: ignore[arg-type]
                message = reply.choices[0].message
                messages.append(message.model_dump(exclude_none=True))
                if not message.tool_calls:
                    break
                ended = False
                for call in message.tool_calls:
                    calls += 1
                    function = getattr(call, "function", None)
                    text, ended = await self._play(env, getattr(function, "name", ""),
                                                   getattr(function, "arguments", "") or "{}")
                    messages.append({"role": "tool", "tool_call_id": call.id, "content": text})
                    if ended:
                        break
                if ended:
                    break
        finally:
            await client.close()
        return ProgramResult(exit_code=0, stdout="", stderr="")

    @staticmethod
    async def _play(env: EwaEnv, tool: str, raw_arguments: str) -> tuple[str, bool]:
        """One tool call on the episode: (the text the model reads, whether the episode ended)."""
        try:
            arguments = json.loads(raw_arguments)
        except json.JSONDecodeError as exc:
            return f"the arguments of {tool} are not JSON ({exc.msg}); call it again with a JSON object", False
        if not isinstance(arguments, dict):
            return f"the arguments of {tool} must be a JSON object, not {type(arguments).__name__}", False
        text, _, terminated, truncated, _ = await asyncio.to_thread(env.step, {"tool": tool, "arguments": arguments})
        return text, terminated or truncated


def taskset(domain: str = SUITE, **options: Any) -> EwaTaskset:
    """The taskset for a domain (options: tasks, split, split_seed, task_dirs, run_dir)."""
    return EwaTaskset(EwaTasksetConfig(domain=domain, **options))


def agent_config(model: str, base_url: str, *, api_key_var: str = "OPENAI_API_KEY", **options: Any) -> AgentConfig:
    """An agent seat that plays ewa-mcp episodes with ``EwaHarness`` on the host (no container: the harness runs
    no code the model writes) against an OpenAI-compatible endpoint at ``base_url``."""
    return AgentConfig(model=model, harness=EwaHarnessConfig(), runtime=SubprocessConfig(),
                       client=EvalClientConfig(base_url=base_url, api_key_var=api_key_var), **options)


def load_environment(domain: str = SUITE, *, model: str | None = None, base_url: str | None = None,
                     api_key_var: str = "OPENAI_API_KEY", **taskset_options: Any) -> Any:
    """A ``vf.SingleAgentEnv`` over ewa-mcp tasks with the grader's reward, its agent seat on ``EwaHarness``."""
    agent = (agent_config(model, base_url, api_key_var=api_key_var) if model and base_url
             else AgentConfig(harness=EwaHarnessConfig(), runtime=SubprocessConfig()))
    config = SingleAgentEnvConfig(taskset=EwaTasksetConfig(domain=domain, **taskset_options), agent=agent)
    return vf.load_environment(config)


__all__ = ["EwaTaskset", "EwaTask", "EwaHarness", "EwaTaskData", "EwaTasksetConfig", "EwaHarnessConfig",
           "load_environment", "taskset", "agent_config", "shutdown"]
