"""Inspect AI tasks: evaluate any model on ewa-mcp with ``inspect eval ewa_mcp/<domain> --model ...``.

Registered through the ``inspect_ai`` entry point in pyproject.toml, so after ``pip install ewa-mcp[inspect]``
the tasks ``ewa_mcp/cooking``, ``ewa_mcp/navigation``, ``ewa_mcp/shopping``, ``ewa_mcp/traveling``,
``ewa_mcp/geolocation`` and ``ewa_mcp/suite`` (every domain) run from any directory.

- Dataset: the task store (sample id = task id); task parameters (``-T``) filter it: ``difficulty``
  (easy/medium/hard, where tasks carry it), ``sample`` (N per domain, the same deterministic choice as
  ``ewa-mcp eval --sample``), ``tasks`` (an id glob), ``tasks_dir``.
- Solver: one ``ewa-mcp serve --transport http`` per eval process (one browser, one run directory); each
  sample starts its episode through the MCP client and the model plays through Inspect's MCP tools, with
  ``episode_id`` bound by the harness (removed from the schemas the model sees, as in evaluation/llm.py).
  ``observation=vision|both`` sends the observation images to the model.
- Scorer: the project's grader (``ewa_mcp.graders.grade_episode``) on the episode's record; the metrics are
  Overall success with its standard error, Completion, Overall per domain and per difficulty (with standard
  errors), and, where some sample has them, Web-only and Embodied-only success and the geolocation levels.
- The dataset takes tasks in turns across domains (``--limit 5`` on the suite plays every domain); each task's
  ``version`` is the package's.
"""

from __future__ import annotations

import atexit
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import anyio
import httpx
from inspect_ai import Task, task
from inspect_ai.dataset import MemoryDataset, Sample
from inspect_ai.model import ChatMessageSystem, ChatMessageUser, ContentImage, ContentText, execute_tools, get_model
from inspect_ai.scorer import Score, Target, metric, scorer
from inspect_ai.solver import Generate, TaskState, solver
from inspect_ai.tool import ToolDef, mcp_server_http, mcp_tools
from mcp import Client

from . import __version__
from .core import registry
from .evaluation.llm import HIDDEN_TOOLS, NUDGE, SYSTEM_PROMPT
from .evaluation.playing import free_port
from .evaluation.runner import EvalError, select_tasks
from .core.paths import TaskStoreMissing, check_task_dirs, runs_dir  # noqa: F401 (re-exported)
from .core.paths import task_dirs as default_task_dirs
from .core.records import new_run_id
from .settings import child_server_env
from .core.taskmodel import TaskStore

DOMAINS = tuple(registry.domain_names(scored_only=True))  # the suite task runs every scored domain
GEO_LEVELS = ("continent", "country", "city", "street")


# ---------------------------------------------------------------- dataset
def ewa_dataset(domains: list[str] | None = None, difficulty: str | None = None, sample: int | None = None,
                tasks: str | None = None, tasks_dir_: str | None = None) -> MemoryDataset:
    """The task store as an Inspect dataset: one sample per task, id = task id, metadata = domain etc."""
    # tasks_dir_ may list several directories, like EWA_TASKS_DIR (dir1:dir2)
    dirs = [Path(p) for p in tasks_dir_.split(os.pathsep) if p] if tasks_dir_ else default_task_dirs()
    check_task_dirs(dirs)
    store = TaskStore(dirs)
    chosen = select_tasks(store, [tasks] if tasks else None, None, domains)
    if difficulty:
        wanted = {d.strip() for d in difficulty.split(",")}
        chosen = [t for t in chosen if (getattr(t, "difficulty", None) or t.metadata.get("difficulty")) in wanted]
        if not chosen:
            raise EvalError(f"no task has difficulty {difficulty!r}; use easy, medium or hard (tasks without a "
                            "difficulty field are never selected by it)")
    if sample:
        chosen = select_tasks(TaskStore(dirs), [t.id for t in chosen], sample, domains)
    return MemoryDataset(
        [Sample(id=t.id, input=t.intent,
                metadata={"domain": t.domain, "step_limit": t.step_limit,
                          "difficulty": getattr(t, "difficulty", None) or t.metadata.get("difficulty") or "none",
                          "has_web": bool(t.web_goals), "has_embodied": bool(t.embodied_goals)})
         for t in interleave(chosen)],
        name="ewa-mcp" + (f"-{domains[0]}" if domains and len(domains) == 1 else ""),
    )


def interleave(tasks: list[Any]) -> list[Any]:
    """The tasks in turns across domains (the first of each domain, then the second, ...), each domain's order
    kept, so ``--limit N`` on the suite plays every domain rather than the first one's tasks."""
    by_domain: dict[str, list[Any]] = {}
    for t in tasks:
        by_domain.setdefault(t.domain, []).append(t)
    queues = list(by_domain.values())
    return [q[i] for i in range(max((len(q) for q in queues), default=0)) for q in queues if i < len(q)]


# ---------------------------------------------------------------- the MCP server of this eval
class _Server:
    """One ``ewa-mcp serve --transport http`` per (run directory, task directories), stopped at exit."""

    running: dict[tuple[str, str], "_Server"] = {}
    lock = anyio.Lock()

    def __init__(self, run_dir: Path, task_dirs: list[Path]):
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}/mcp"
        args = [sys.executable, "-m", "ewa_mcp", "serve", "--transport", "http", "--port", str(self.port),
                "--run-dir", str(run_dir)]
        for d in task_dirs:
            args += ["--tasks-dir", str(d)]
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, env=child_server_env())
        atexit.register(self.stop)

    def wait_ready(self, timeout: float = 120) -> None:
        deadline = time.monotonic() + timeout
        while True:
            try:
                httpx.get(self.url, timeout=1)
                return
            except httpx.TransportError:
                if self.proc.poll() is not None or time.monotonic() > deadline:
                    raise EvalError("the ewa-mcp HTTP server did not start; run `ewa-mcp serve --transport http` "
                                    "by hand to see why") from None
                time.sleep(0.1)

    def stop(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.proc.kill()

    @classmethod
    async def get(cls, run_dir: Path, task_dirs: list[Path]) -> "_Server":
        key = (str(run_dir), "|".join(map(str, task_dirs)))
        async with cls.lock:
            server = cls.running.get(key)
            if server is None or server.proc.poll() is not None:
                server = cls(run_dir, task_dirs)
                await anyio.to_thread.run_sync(server.wait_ready)
                cls.running[key] = server
        return server


def _bind_episode(tool: Any, episode_id: str) -> Any:
    """The MCP tool with ``episode_id`` filled in by the harness and removed from what the model sees."""
    td = ToolDef(tool)
    params = td.parameters.model_copy(deep=True)
    params.properties.pop("episode_id", None)
    params.required = [r for r in params.required if r != "episode_id"]

    async def execute(**kwargs: Any) -> Any:
        return await td.tool(episode_id=episode_id, **kwargs)

    return ToolDef(execute, name=td.name, description=td.description, parameters=params).as_tool()


async def _estimate_tokens(text: str) -> int:
    """About four characters a token: an offline estimate (no tokenizer file, no download)."""
    return max(1, -(-len(text) // 4))


def offline_token_counts(model: Any) -> Any:
    """Inspect's ``mockllm`` provider fills in the usage of an output that has none by counting tokens with
    tiktoken's ``o200k_base`` encoding, which tiktoken downloads on first use: an unscripted
    ``--model mockllm/model`` then fails offline. For that provider only, count text tokens with a
    characters-per-token estimate instead (a mock's usage is made up either way); real providers report
    their own usage and are left alone."""
    try:
        from inspect_ai.model._providers.mockllm import MockLLM
    except ImportError:  # a future Inspect that moved it: nothing to adjust
        return model
    api = getattr(model, "api", None)
    if isinstance(api, MockLLM):
        api.count_text_tokens = _estimate_tokens  # type: ignore[method-assign]  # this model object only
    return model


def _first_message(task_id: str, start: Any, send_images: bool) -> ChatMessageUser:
    texts = [getattr(c, "text", "") for c in start.content if getattr(c, "type", "") == "text"]
    content: list[Any] = [ContentText(text=f"Task id: {task_id}\n" + "\n".join(texts))]
    if send_images:
        content += [ContentImage(image=f"data:{c.mime_type};base64,{c.data}")
                    for c in start.content if getattr(c, "type", "") == "image"]
    return ChatMessageUser(content=content)


async def _status(client: Client, episode_id: str) -> str:
    """The episode's status, read from its state resource: a harness's look is not the agent's step (calling
    the episode_status tool would use one and write a line into the agent's trajectory)."""
    result = await client.read_resource(f"ewa://episodes/{episode_id}/state")
    texts = [getattr(c, "text", "") for c in result.contents]
    try:
        return json.loads(texts[0]).get("status", "unknown") if texts else "unknown"
    except ValueError:
        return "unknown"


# ---------------------------------------------------------------- setup and solver
@solver
def ewa_episode(run_dir: str, task_dirs: list[str], observation: str = "text"):
    """The task's setup (Inspect's ``Task.setup``, kept when ``--solver`` replaces the agent): starts the sample's
    episode on the real MCP server and hands the agent that episode's tools with ``episode_id`` bound (the
    control plane stays with the harness), the system prompt, and the task with its first observation. Any
    Inspect solver or agent then plays with ``state.tools`` and ``state.messages``."""

    async def solve(state: TaskState, generate: Generate) -> TaskState:
        server = await _Server.get(Path(run_dir), [Path(d) for d in task_dirs])
        async with Client(server.url) as client:
            start = await client.call_tool("start_episode", {"task_id": str(state.sample_id),
                                                             "options": {"observation": observation}})
        if start.is_error:
            raise EvalError("start_episode failed: " + " ".join(getattr(c, "text", "") for c in start.content))
        episode_id = start.structured_content["episode_id"]
        state.metadata.update({"episode_id": episode_id, "run_dir": run_dir, "server_url": server.url})
        mcp = mcp_server_http(name="ewa-mcp", url=server.url, timeout=60)
        state.tools = [_bind_episode(t, episode_id) for t in await mcp_tools(mcp).tools()
                       if ToolDef(t).name not in HIDDEN_TOOLS]
        state.messages = [ChatMessageSystem(content=SYSTEM_PROMPT),
                          _first_message(str(state.sample_id), start, observation != "text")]
        offline_token_counts(get_model())  # whichever solver plays next, the mock model counts offline
        return state

    return solve


@solver
def ewa_agent(max_turns: int | None = None):
    """The default agent: generate, run the tool calls, stop when the episode has ended (read from its state
    resource: not a step of the agent) or the turns run out; a model that answers in prose is nudged once."""

    async def solve(state: TaskState, generate: Generate) -> TaskState:
        episode_id, url = state.metadata.get("episode_id"), state.metadata.get("server_url")
        if not episode_id or not url:
            raise EvalError("ewa_agent plays after the task's setup (ewa_episode), which starts the episode")
        model = offline_token_counts(get_model())
        nudged = False
        async with Client(url) as client:
            for _ in range(max_turns or int(state.metadata.get("step_limit") or 60)):
                output = await model.generate(state.messages, state.tools)
                state.output = output
                state.messages.append(output.message)
                if output.message.tool_calls:
                    result = await execute_tools(state.messages, state.tools)
                    state.messages.extend(result.messages)
                    if await _status(client, episode_id) != "running":
                        break
                elif nudged:
                    break  # answers in prose twice: the scorer finishes the episode
                else:
                    nudged = True
                    state.messages.append(ChatMessageUser(content=NUDGE))
        return state

    return solve


# ---------------------------------------------------------------- scorer and metrics
def _rate(key: str, applies: str | None = None):
    """Mean of one key of the score dicts over the samples where it applies (``applies`` key is 1).

    Inspect's epoch reducer turns a missing or None value into 0, so applicability is a key of its own."""

    def compute(scores: list[Any]) -> float:
        values = [float(s.score.value.get(key) or 0.0) for s in scores
                  if isinstance(s.score.value, dict) and (applies is None or s.score.value.get(applies))]
        return sum(values) / len(values) if values else float("nan")

    return compute


@metric(name="overall")
def overall_success():
    return _rate("overall")


@metric(name="completion")
def completion_rate():
    return _rate("completion")


@metric(name="web_only")
def web_only_success():
    return _rate("web", "has_web")


@metric(name="embodied_only")
def embodied_only_success():
    return _rate("embodied", "has_embodied")


def _level_metric(level: str):
    @metric(name=f"geo_{level}")
    def level_metric():
        return _rate(f"geo_{level}", "is_geolocation")

    return level_metric


GEO_METRICS = [_level_metric(level) for level in GEO_LEVELS]


def _overall(score: Any) -> float:
    value = score.score.value
    return float(value.get("overall") or 0.0) if isinstance(value, dict) else 0.0


def _stderr(values: list[float]) -> float:
    """The standard error of the mean (sample standard deviation / sqrt(n)); 0 for fewer than two values."""
    n = len(values)
    if n < 2:
        return 0.0
    mean = sum(values) / n
    return (sum((v - mean) ** 2 for v in values) / (n - 1) / n) ** 0.5


@metric(name="overall_stderr")
def overall_stderr():
    """The standard error of the overall success rate: report it beside ``overall`` (overall ± 1.96 stderr)."""
    def compute(scores: list[Any]) -> float:
        return _stderr([_overall(s) for s in scores])

    return compute


def _grouped_overall(key: str):
    """Overall success and its standard error per value of a sample metadata key (domain, difficulty)."""
    def compute(scores: list[Any]) -> dict[str, float]:
        groups: dict[str, list[float]] = {}
        for s in scores:
            groups.setdefault(str((s.sample_metadata or {}).get(key, "none")), []).append(_overall(s))
        out: dict[str, float] = {}
        for name, values in sorted(groups.items()):
            out[name] = sum(values) / len(values)
            out[f"{name}_stderr"] = _stderr(values)
        return out

    return compute


@metric(name="by_domain")
def overall_by_domain():
    return _grouped_overall("domain")


@metric(name="by_difficulty")
def overall_by_difficulty():
    return _grouped_overall("difficulty")


def task_metrics(dataset: Any) -> list[Any]:
    """The metrics that apply to a dataset: overall with its standard error and per-domain and per-difficulty
    breakdowns always; web_only, embodied_only and the geolocation levels only where some sample has web goals,
    embodied goals or is a geolocation task (elsewhere they would have no samples and read NaN)."""
    out = [overall_success(), overall_stderr(), completion_rate(), overall_by_domain(), overall_by_difficulty()]
    meta = [s.metadata or {} for s in dataset]
    if any(m.get("has_web") for m in meta):
        out.append(web_only_success())
    if any(m.get("has_embodied") for m in meta):
        out.append(embodied_only_success())
    if any(m.get("domain") == "geolocation" for m in meta):
        out += [m() for m in GEO_METRICS]
    return out


def score_value(result: Any) -> dict[str, float]:
    """The grader's EpisodeResult as one Inspect score: 1/0 successes, completion in [0, 1], and 1/0 flags
    saying which side-metrics apply to the episode (web goals, embodied goals, a geolocation answer)."""
    geo = result.geolocation or {}
    value = {
        "overall": 1.0 if result.overall_success else 0.0,
        "completion": float(result.completion or 0.0),
        "web": 1.0 if result.web_success else 0.0,
        "has_web": 1.0 if result.has_web_goals else 0.0,
        "embodied": 1.0 if result.embodied_success else 0.0,
        "has_embodied": 1.0 if result.has_embodied_goals else 0.0,
        "is_geolocation": 1.0 if result.domain == "geolocation" else 0.0,
    }
    for level in GEO_LEVELS:
        value[f"geo_{level}"] = 1.0 if geo.get(level) else 0.0
    return value


@scorer(metrics=[overall_success(), completion_rate(), web_only_success(), embodied_only_success(),
                 *(m() for m in GEO_METRICS)])
def ewa_grader():
    """Finishes the episode if the model left it open, then grades its record with the project's grader."""
    from .graders import grade_episode

    async def score(state: TaskState, target: Target) -> Score:
        episode_id, run_dir = state.metadata.get("episode_id"), state.metadata.get("run_dir")
        if not episode_id or not run_dir:
            return Score(value={"overall": 0.0, "completion": 0.0}, explanation="the episode never started")
        async with Client(state.metadata["server_url"]) as client:
            if await _status(client, episode_id) == "running":
                await client.call_tool("finish_episode", {"episode_id": episode_id})
        result = await anyio.to_thread.run_sync(grade_episode, Path(run_dir) / episode_id)
        why = result.error.category if result.error else ("success" if result.overall_success else "")
        return Score(value=score_value(result), answer=result.answer,
                     explanation=f"{result.conditions_met}/{result.conditions_total} conditions met; {why}",
                     metadata={"episode_dir": str(Path(run_dir) / episode_id), "status": result.status})

    return score


# ---------------------------------------------------------------- tasks
def ewa_task(domains: list[str] | None, *, difficulty: str | None = None, sample: int | None = None,
             tasks: str | None = None, tasks_dir: str | None = None, observation: str = "text",
             run_dir: str | None = None, max_turns: int | None = None) -> Task:
    if observation not in ("text", "vision", "both"):
        raise EvalError(f"observation={observation[:50]!r}: use text, vision or both")
    dirs = ([str(Path(p).resolve()) for p in tasks_dir.split(os.pathsep) if p] if tasks_dir
            else [str(d) for d in default_task_dirs()])
    out = str(Path(run_dir).resolve()) if run_dir else str((runs_dir() / ("inspect-" + new_run_id())).resolve())
    dataset = ewa_dataset(domains, difficulty, sample, tasks, os.pathsep.join(dirs))
    return Task(
        dataset=dataset,
        setup=ewa_episode(run_dir=out, task_dirs=dirs, observation=observation),
        solver=ewa_agent(max_turns=max_turns),
        scorer=ewa_grader(),
        metrics=task_metrics(dataset),
        # The task suites ship with the package: a new release may change tasks, tools or grading.
        version=__version__,
        metadata={"run_dir": out, "ewa_mcp_domains": domains or list(DOMAINS)},
    )


@task
def suite(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
          tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
          max_turns: int | None = None) -> Task:
    """Every domain of the benchmark."""
    return ewa_task(list(DOMAINS), difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


@task
def cooking(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
            tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
            max_turns: int | None = None) -> Task:
    """Follow a recipe web site, then cook it in the kitchen."""
    return ewa_task(["cooking"], difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


@task
def navigation(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
               tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
               max_turns: int | None = None) -> Task:
    """Get walking directions on the map site, then walk them in the street."""
    return ewa_task(["navigation"], difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


@task
def shopping(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
             tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
             max_turns: int | None = None) -> Task:
    """Order in the shop, then walk to the pickup store."""
    return ewa_task(["shopping"], difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


@task
def traveling(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
              tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
              max_turns: int | None = None) -> Task:
    """Walk to a landmark and answer a question from its wiki article."""
    return ewa_task(["traveling"], difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


@task
def geolocation(difficulty: str | None = None, sample: int | None = None, tasks: str | None = None,
                tasks_dir: str | None = None, observation: str = "text", run_dir: str | None = None,
                max_turns: int | None = None) -> Task:
    """Say where in the world a standpoint is (continent, country, city, street)."""
    return ewa_task(["geolocation"], difficulty=difficulty, sample=sample, tasks=tasks, tasks_dir=tasks_dir,
                    observation=observation, run_dir=run_dir, max_turns=max_turns)


