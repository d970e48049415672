"""The tool loop shared by the LLM agent examples (examples/claude_agent.py, examples/openai_agent.py).

A model adapter turns the conversation into one API's wire format; this module owns what is
the same for every model: which MCP tools the model sees (episode_id is injected, so the model
never has to copy it), the system prompt, the step budget, and feeding results back.
"""

from __future__ import annotations

import copy
import json
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

from .agents import Session

SYSTEM_PROMPT = """\
You are an agent acting in an embodied web environment through tools.
The task has a web environment (a browser on a few web sites: tools browser_*) and/or an embodied one
(a kitchen: kitchen_*; city streets: street_*; a world location: geo_*). Only the ACTIVE environment
accepts actions. To act in the other one, call switch_environment(target, message) and say in message
what you will do there. Read observations carefully; element ids in the web page are shown as [id].
When the task is done, call finish_episode (with your answer if the task asks a question; geolocation
tasks end with submit_location). You have a limited number of steps; do not repeat failing actions.
"""

HIDDEN_TOOLS = {"list_tasks", "start_episode"}
# What an adapter says when the model answers in prose instead of calling a tool.
NUDGE = "Act with a tool call. When the task is complete, call finish_episode."


@dataclass
class ToolSpec:
    name: str
    description: str
    parameters: dict[str, Any]  # JSON Schema without episode_id


@dataclass
class ToolRequest:
    id: str
    name: str
    arguments: dict[str, Any]


@dataclass
class ToolOutcome:
    request: ToolRequest
    text: str
    is_error: bool
    images: list[str] = field(default_factory=list)  # base64 PNG


class ModelAdapter(Protocol):
    def begin(self, system: str, tools: list[ToolSpec], user: str) -> None: ...

    async def next_actions(self) -> list[ToolRequest]:
        """The model's next tool calls; an empty list means it answered without a tool call."""
        ...

    def add_results(self, outcomes: list[ToolOutcome]) -> None: ...

    async def aclose(self) -> None:
        """Close the API client inside the event loop that used it."""
        ...


def tool_specs(tools: list[Any]) -> list[ToolSpec]:
    specs = []
    for tool in tools:
        if tool.name in HIDDEN_TOOLS:
            continue
        schema = copy.deepcopy(tool.input_schema)
        schema.get("properties", {}).pop("episode_id", None)
        if "required" in schema:
            schema["required"] = [r for r in schema["required"] if r != "episode_id"]
        specs.append(ToolSpec(name=tool.name, description=tool.description or "", parameters=schema))
    return specs


def _render(result: Any) -> tuple[str, list[str]]:
    texts, images = [], []
    for block in result.content:
        kind = getattr(block, "type", "")
        if kind == "text":
            texts.append(block.text)
        elif kind == "image":
            images.append(block.data)
    return "\n".join(texts), images


class LLMAgent:
    """Plays an episode by letting a model pick tool calls until it finishes or runs out of steps."""

    def __init__(self, adapter_factory: Callable[[], ModelAdapter], name: str = "llm", max_turns: int | None = None,
                 send_images: bool = True):
        # adapter_factory() makes one adapter per episode. For --workers and --ray it travels to other
        # processes, so make it picklable: a module-level class with __call__ (examples/*_agent.py) or a
        # functools.partial, not a lambda.
        self.adapter_factory = adapter_factory
        self.name = name
        self.max_turns = max_turns
        self.send_images = send_images

    async def play(self, s: Session) -> None:
        tools = tool_specs((await s.client.list_tools()).tools)
        adapter = self.adapter_factory()
        try:
            await self._loop(s, adapter, tools)
        finally:
            # An SDK client left open is closed later by the garbage collector, in whatever event loop
            # is running then (or none): close it here, in the loop that used it.
            await adapter.aclose()

    async def _loop(self, s: Session, adapter: ModelAdapter, tools: list[ToolSpec]) -> None:
        allowed = {t.name for t in tools}
        start_text, _ = _render(s.start)
        adapter.begin(SYSTEM_PROMPT, tools, f"{start_text}\n\nThe task: {s.task.intent}")
        turns = self.max_turns or s.task.step_limit
        nudged = False
        for _ in range(turns):
            if s.ended:
                return
            requests = await adapter.next_actions()
            if not requests:
                if nudged:
                    return  # the model keeps answering in prose: the runner finishes the episode
                nudged = True
                adapter.add_results([])
                continue
            outcomes = []
            for req in requests:
                if s.ended:
                    outcomes.append(ToolOutcome(req, "the episode has ended", True))
                    continue
                if req.name not in allowed:
                    outcomes.append(ToolOutcome(req, f"unknown tool {req.name!r}; available: {sorted(allowed)}",
                                                True))
                    continue
                result = await s.call(req.name, req.arguments)
                text, images = _render(result)
                outcomes.append(ToolOutcome(req, text, bool(result.is_error),
                                            images if self.send_images else []))
            adapter.add_results(outcomes)


def parse_arguments(raw: Any) -> dict[str, Any]:
    """Models send arguments as a dict or a JSON string; anything else becomes an empty call (the server
    then answers with a validation error the model can read)."""
    if isinstance(raw, dict):
        return raw
    if isinstance(raw, str) and raw.strip():
        try:
            value = json.loads(raw)
            return value if isinstance(value, dict) else {}
        except json.JSONDecodeError:
            return {}
    return {}


def example_parser(description: str, default_model: str):
    import argparse

    p = argparse.ArgumentParser(description=description)
    p.add_argument("--model", default=default_model)
    p.add_argument("--base-url", default=None, help="API base URL (a proxy, a compatible server, a test fixture)")
    p.add_argument("--tasks", action="append", metavar="GLOB", help="task id glob (repeatable)")
    p.add_argument("--domain", action="append")
    p.add_argument("--difficulty", action="append", choices=["easy", "medium", "hard"],
                   help="restrict to a difficulty (repeatable)")
    p.add_argument("--sample", type=int, metavar="N", help="N tasks per domain")
    p.add_argument("--transport", choices=["inprocess", "stdio", "http"], default="stdio")
    from .scale import add_scale_arguments

    add_scale_arguments(p)  # --workers, --concurrency, --ray: the agent's adapter factory must be picklable
    p.add_argument("--run-dir", metavar="DIR")
    p.add_argument("--tasks-dir", action="append", metavar="DIR")
    p.add_argument("--max-tokens", type=int, default=2048)
    p.add_argument("--no-images", action="store_true", help="text observations only")
    p.add_argument("-q", "--quiet", action="store_true")
    return p


def run_example(args: Any, agent: LLMAgent) -> int:
    """Select tasks, play them through the MCP server and leave a run directory for ewa-grade."""
    import sys

    from ewa_mcp.core.taskmodel import TaskStore
    from .runner import EvalError, play_from_args, run_dir_from, select_tasks, task_dirs_from

    task_dirs = task_dirs_from(args.tasks_dir)
    run_dir = run_dir_from(args.run_dir)
    try:
        tasks = select_tasks(TaskStore(task_dirs), args.tasks, args.sample, args.domain, args.difficulty)
        summary = play_from_args(tasks, agent, args, run_dir=run_dir, task_dirs=task_dirs)
    except EvalError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"run directory: {run_dir}  (grade it: ewa-grade {run_dir})")
    return 1 if any(o.failure for o in summary.outcomes) else 0
