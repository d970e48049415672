"""``check_environment``: what Gymnasium's ``check_env`` is for Gymnasium, for an environment of the registry.

It checks the contract an environment makes with the kernel (docs/extending.md, "The environment contract"):

- its ``EnvironmentSpec`` loads: the class is an ``Environment`` whose ``name`` and ``side`` are the spec's, and
  its tools module has ``register(mcp, episodes)``;
- every tool that module registers is named ``<name>_<action>`` (or is named in the spec's ``tool_hint``), has a
  title and annotations (``define_tool``), and takes ``episode_id`` first;
- played on a task of its domain through a real ``EpisodeManager``: ``reset`` then ``observe`` give an
  ``Observation`` whose text is a non-empty string, whose data is JSON and whose images are PNG bytes; the
  same task reset twice gives the same first observation (determinism); ``status()`` gives only the fields
  the spec declares; ``final_state()`` is JSON; ending the episode writes a ``final_state.json`` that the
  record model accepts.

Each problem is a sentence naming what is wrong and how to fix it; ``check_environment`` returns them all
(an empty list: the environment conforms). It imports no world: environments come from the registry.
"""

from __future__ import annotations

import inspect
import json
import tempfile
from pathlib import Path
from typing import Any

from . import registry
from .environment import Environment, Observation
from .records import FinalState, record_problem
from .taskmodel import Task, TaskStore

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _json_problem(value: Any, what: str) -> str | None:
    try:
        json.dumps(value)
    except (TypeError, ValueError) as exc:
        return f"{what} is not JSON-serializable ({exc}); return plain dicts, lists, strings and numbers"
    return None


def check_spec(spec: registry.EnvironmentSpec) -> list[str]:
    """The static half: the class, its name and side, and the tools its module registers."""
    problems: list[str] = []
    if not spec.name.isidentifier() or "_" in spec.name:
        problems.append(f"environment name {spec.name!r} must be one word (it prefixes its tools: {spec.name}_*)")
    try:
        cls = registry.load_object(spec.cls)
    except Exception as exc:  # an import error names the module to fix
        return [f"{spec.name}: cannot load its class {spec.cls!r} ({type(exc).__name__}: {exc})"]
    if not (inspect.isclass(cls) and issubclass(cls, Environment)):
        return [f"{spec.name}: {spec.cls} is not a subclass of ewa_mcp.core.environment.Environment"]
    if getattr(cls, "name", None) != spec.name:
        problems.append(f"{spec.name}: {cls.__name__}.name is {getattr(cls, 'name', None)!r}; set it to "
                        f"{spec.name!r}, the registry name")
    if getattr(cls, "side", None) != spec.side:
        problems.append(f"{spec.name}: {cls.__name__}.side is {getattr(cls, 'side', None)!r}, the spec says "
                        f"{spec.side!r}")
    for hook in ("reset", "observe", "final_state"):
        if getattr(cls, hook) is getattr(Environment, hook):
            problems.append(f"{spec.name}: {cls.__name__} does not implement {hook}()")
    if spec.tools:
        problems += _check_tools(spec)
    return problems


def _check_tools(spec: registry.EnvironmentSpec) -> list[str]:
    from mcp.server.mcpserver import MCPServer

    try:
        module = registry.load_object(f"{spec.tools}:register")
    except Exception as exc:
        return [f"{spec.name}: its tools module {spec.tools!r} has no usable register(mcp, episodes) "
                f"({type(exc).__name__}: {exc})"]
    mcp = MCPServer("conformance")
    module(mcp, None)
    problems = []
    for tool in mcp._tool_manager.list_tools():
        if not tool.name.startswith(f"{spec.name}_") and tool.name not in spec.hint():
            problems.append(f"{spec.name}: tool {tool.name!r} must be named {spec.name}_<action> (or be named in "
                            "the spec's tool_hint), so that it refuses other domains' episodes")
        if not tool.title or tool.annotations is None:
            problems.append(f"{spec.name}: tool {tool.name!r} has no title or annotations; declare it with "
                            "ewa_mcp.core.tool_table.define_tool")
        if list(tool.parameters.get("properties", {}))[:1] != ["episode_id"]:
            problems.append(f"{spec.name}: tool {tool.name!r} must take episode_id as its first argument")
    return problems


async def check_environment(spec: registry.EnvironmentSpec, task: Task, services: Any = None) -> list[str]:
    """Every problem with ``spec``'s environment, played on ``task`` (one that uses it)."""
    from .episodes import EpisodeManager
    from .services import Services

    problems = check_spec(spec)
    if problems:
        return problems
    side = spec.side
    if task.environment_names().get(side) != spec.name:
        return [f"task {task.id} does not use the {spec.name} environment; pick a task of a domain that does"]
    owned = services is None
    services = services or Services()
    declared = {f.name for f in spec.status_fields}
    try:
        with tempfile.TemporaryDirectory(prefix="ewa-conformance-") as tmp:
            store = TaskStore([])
            store.add(task)
            manager = EpisodeManager(store, Path(tmp), services, {spec.name: registry.load_object(spec.cls)})
            firsts: list[str] = []
            for attempt in range(2):
                episode = await manager.start(task.id)
                env = episode.environments[side]
                observation = await env.observe()
                problems += _observation_problems(spec.name, observation)
                firsts.append(observation.text)
                status = env.status()
                if not isinstance(status, dict) or set(status) - declared:
                    problems.append(f"{spec.name}: status() returned {status!r}; it may hold only the declared "
                                    f"status fields {sorted(declared)}")
                state = await env.final_state()
                problem = _json_problem(state, f"{spec.name}: final_state()")
                if problem:
                    problems.append(problem)
                await manager.finish(episode.id, "conformance check")
                if attempt == 0:
                    path = Path(tmp) / episode.id / "final_state.json"
                    if not path.exists():
                        problems.append(f"{spec.name}: ending the episode wrote no final_state.json")
                    else:
                        problem = record_problem(FinalState, json.loads(path.read_text(encoding="utf-8")),
                                                 "final_state.json")
                        if problem:
                            problems.append(f"{spec.name}: {problem}")
            if firsts[0] != firsts[1]:
                problems.append(f"{spec.name}: the same task reset twice gave different first observations; make "
                                "reset depend only on the task and its options (seed your randomness)")
    finally:
        if owned:
            await services.aclose()
    return problems


def _observation_problems(name: str, observation: Any) -> list[str]:
    if not isinstance(observation, Observation):
        return [f"{name}: observe() returned {type(observation).__name__}, not an Observation"]
    problems = []
    if not isinstance(observation.text, str) or not observation.text.strip():
        problems.append(f"{name}: the observation's text is empty; the model reads it")
    problem = _json_problem(observation.data, f"{name}: the observation's data")
    if problem:
        problems.append(problem)
    for i, image in enumerate(observation.images):
        if not isinstance(image, bytes | bytearray) or not bytes(image).startswith(PNG_MAGIC):
            problems.append(f"{name}: image {i} of the observation is not PNG bytes")
    return problems
