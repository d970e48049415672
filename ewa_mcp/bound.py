"""The agent plane: an MCP server whose tools act on one episode the harness already started.

The full server (ewa_mcp/server.py) is the control plane: ``list_tasks`` and ``start_episode`` choose and open
episodes, and every tool takes an ``episode_id``. A harness that trains or evaluates an agent starts the episode
itself and hands the agent a ``BoundServer``: the same tools under the same names, minus ``list_tasks`` and
``start_episode``, with the ``episode_id`` parameter gone from every schema. A call is forwarded to the full
server with the bound id filled in, so validation, the step rule (a refused call is still a step) and the
record are exactly those of the full server; the agent cannot reach another episode, start one or list the
tasks. The results' text names no episode id (the footer reads ``[web · step 3/68]``): the agent needs none,
and observations that carry a fresh random id could not repeat under the same seed.

``ewa-mcp serve --bind-task TASK`` serves one bound episode over stdio or HTTP; ``ewa_mcp.gym`` plays bound
episodes in-process.
"""

from __future__ import annotations

import copy
import json
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Any, Literal

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp_types import CallToolResult, ResourceLink, TextContent
from mcp_types import Tool as MCPTool

from . import __version__
from .core import registry
from .core.response import environment_for_tool
from .core.episodes import EpisodeManager

# The control plane's tools: choosing and opening episodes is the harness's business, never the agent's.
CONTROL_TOOLS = frozenset({"list_tasks", "start_episode"})

BOUND_INSTRUCTIONS = """\
ewa-mcp, one episode already started for you. Its task and first observation follow.
Each episode has a web environment (browser_* tools) and/or an embodied one (kitchen_*, street_* or geo_* tools).
Only the active one accepts actions; switch_environment(target, message) changes it (a recorded action).
finish_episode(answer) ends the episode (geolocation: submit_location). A walk ends at your first street_stop,
or else at finish_episode. Every call is recorded and uses one step, failed calls included; steps are limited.
"""


class BindError(ValueError):
    """A bound server that cannot be made (unknown task, bad options); the message names the fix."""


def unbind_schema(schema: dict[str, Any]) -> dict[str, Any]:
    """A tool's input schema without its ``episode_id`` parameter."""
    out = copy.deepcopy(schema)
    props = out.get("properties")
    if isinstance(props, dict):
        props.pop("episode_id", None)
    if isinstance(out.get("required"), list):
        out["required"] = [name for name in out["required"] if name != "episode_id"]
    return out


# Schema keys a model does not need to call a tool right: the server validates every call against the full
# schema anyway (lengths, extra properties), and the titles repeat the names.
_VERBOSE_KEYS = frozenset({"title", "maxLength", "minLength", "maximum", "minimum", "additionalProperties", "default"})


def _cut(text: str, clause: bool) -> str:
    """``text`` up to its first sentence end (". " before a capital) or, with ``clause``, its first ", " or "; ",
    outside brackets and quotes and never after "e.g."."""
    depth, quoted = 0, False
    for i, ch in enumerate(text):
        if ch == '"':
            quoted = not quoted
        elif ch in "([":
            depth += 1
        elif ch in ")]":
            depth = max(0, depth - 1)
        elif depth or quoted or text[i + 1:i + 2] != " " or text[max(0, i - 3):i + 1] == "e.g.":
            continue
        elif ch == "." and (text[i + 2:i + 3].isupper() or clause):
            return text[:i + 1]
        elif ch in ";," and clause or ch == ";":
            return text[:i] + ("" if clause else ".")
    return text


def first_sentence(text: str) -> str:
    """The first sentence of a tool's description."""
    return _cut(" ".join(text.split()), clause=False)


def concise_schema(schema: Any) -> Any:
    """An input schema in fewer tokens and the same meaning to a model: no titles or length limits, an optional
    ``X | None`` shown as ``X`` (leaving it out is how a model passes None), property descriptions cut to their
    first clause."""
    if isinstance(schema, list):
        return [concise_schema(s) for s in schema]
    if not isinstance(schema, dict):
        return schema
    options = schema.get("anyOf")
    if isinstance(options, list) and schema.get("default", "") is None:
        kept = [o for o in options if o != {"type": "null"}]
        if len(kept) == 1:
            merged = {**{k: v for k, v in schema.items() if k not in ("anyOf", "default")}, **kept[0]}
            return concise_schema(merged)
    out: dict[str, Any] = {}
    for key, value in schema.items():
        if key in _VERBOSE_KEYS:
            continue
        if key == "description" and isinstance(value, str):
            out[key] = _cut(" ".join(value.split()), clause=True)
        elif key == "required" and value == []:
            continue
        elif key == "properties" and isinstance(value, dict):
            out[key] = {name: concise_schema(prop) for name, prop in value.items()}
        else:
            out[key] = concise_schema(value)
    return out


def describe_once(schema: dict[str, Any], described: set[str]) -> dict[str, Any]:
    """A parameter described in the same words in several tools (kitchen ``object``, browser ``element``) keeps its
    description in the first tool listed only: a model reads the definitions together."""
    for prop in (schema.get("properties") or {}).values():
        text = prop.get("description") if isinstance(prop, dict) else None
        if isinstance(text, str):
            if text in described:
                del prop["description"]
            described.add(text)
    return schema


def scrub_text(text: str, episode_id: str) -> str:
    """The text of a result as a bound agent reads it: no episode id (response.footer, finish_episode)."""
    text = text.replace(f"[{episode_id} · ", "[")
    text = text.replace(f"Episode {episode_id} ", "The episode ")
    text = text.replace(f"{episode_id}: ", "")
    return text.replace(episode_id, "this episode")


def scrub_result(result: CallToolResult, episode_id: str) -> CallToolResult:
    # Links to the episode's image resources name the episode, and the bound plane serves no resources:
    # they are dropped (the same images are inline).
    content = [TextContent(type="text", text=scrub_text(c.text, episode_id)) if isinstance(c, TextContent) else c
               for c in result.content if not (isinstance(c, ResourceLink) and episode_id in str(c.uri))]
    return result.model_copy(update={"content": content})


class BoundServer(MCPServer):
    """The agent plane of one episode. ``episode_id`` is set when the episode starts: at once when given, or in
    the server's lifespan when ``task_id`` is given (``ewa-mcp serve --bind-task``)."""

    def __init__(self, full: Any, *, episode_id: str | None = None, task_id: str | None = None,
                 options: dict[str, Any] | None = None, own_services: bool = False,
                 descriptions: Literal["concise", "full"] = "concise"):
        if (episode_id is None) == (task_id is None):
            raise BindError("bind either a running episode (episode_id) or a task to start (task_id), not both")
        self.full = full
        self.episodes: EpisodeManager = full.episodes
        self.episode_id = episode_id
        self.task_id = task_id
        # The agent plane answers an agent: structured content carries the step's status, not a second copy of
        # the observation the text already shows (``{"structured": "full"}`` asks for it, as the control plane
        # gives it by default).
        self.options = {"structured": "compact", **(options or {})}
        if descriptions not in ("concise", "full"):
            raise BindError(f"descriptions must be 'concise' or 'full', not {descriptions!r}")
        self.descriptions = descriptions
        self.start_text: str | None = None
        self._own_services = own_services
        super().__init__("ewa-mcp (bound episode)", instructions=BOUND_INSTRUCTIONS, version=__version__,
                         lifespan=self._lifespan)

    @asynccontextmanager
    async def _lifespan(self, _: MCPServer) -> AsyncIterator[None]:
        try:
            if self.episode_id is None:
                await self.start()
            yield
        finally:
            if self._own_services:  # `serve --bind-task`: this server is the process's only one
                await self.episodes.aclose()
                await self.episodes.services.aclose()

    async def start(self) -> CallToolResult:
        """Start the bound task's episode through the control plane's start_episode; returns its result."""
        assert self.task_id is not None
        args: dict[str, Any] = {"task_id": self.task_id}
        if self.options:
            args["options"] = self.options
        result = await self.full.call_tool("start_episode", args)
        if result.is_error or not isinstance(result.structured_content, dict):
            raise BindError(_text_of(result))
        self.episode_id = str(result.structured_content["episode_id"])
        result = scrub_result(result, self.episode_id)
        self.start_text = _text_of(result)
        # The agent's instructions carry the task and its first observation: it never calls start_episode.
        self._lowlevel_server.instructions = f"{BOUND_INSTRUCTIONS}\n{self.start_text}"
        return result

    def _bound_id(self) -> str:
        if self.episode_id is None:
            raise ToolError("the bound episode has not started yet")
        return self.episode_id

    def _foreign(self, tool: str) -> bool:
        """Whether ``tool`` belongs to an environment this episode does not have (a geolocation episode lists no
        kitchen tools: a smaller action space; a call to one is still forwarded, and refused as a step like
        anywhere). A tool's environment is its name's prefix, or the one whose tool hint names it."""
        specs = registry.environments()
        owner = environment_for_tool(tool) or next((n for n, spec in specs.items() if tool in spec.hint()), None)
        return owner is not None and owner not in self.episodes.get(self._bound_id()).environment_names.values()

    async def list_tools(self) -> list[MCPTool]:
        tools = await self.full.list_tools()
        out = []
        described: set[str] = set()
        for tool in tools:
            if tool.name in CONTROL_TOOLS or self._foreign(tool.name):
                continue
            schema = unbind_schema(tool.input_schema)
            if self.descriptions == "concise":
                # A model reads every definition on every request: the first sentence of each description and a
                # lean schema (the full catalogue, with full descriptions, stays on the control-plane server).
                out.append(tool.model_copy(update={"input_schema": describe_once(concise_schema(schema), described),
                                                   "description": first_sentence(tool.description or "")}))
            else:
                out.append(tool.model_copy(update={"input_schema": schema}))
        return out

    def _tool_input_schema(self, name: str) -> dict[str, Any] | None:
        if name in CONTROL_TOOLS:
            return None
        tool = self.full._tool_manager.get_tool(name)
        return None if tool is None else unbind_schema(tool.parameters)

    async def call_tool(self, name: str, arguments: dict[str, Any], context: Any = None) -> Any:
        episode_id = self._bound_id()
        if name in CONTROL_TOOLS:
            error = (f"{name} is not available here: this server is bound to one episode, which the harness "
                     "started; act with the episode's tools and end it with finish_episode")
            await self.episodes.record_rejected(episode_id, name, dict(arguments or {}), error)
            raise ToolError(error)
        arguments = dict(arguments or {})
        if "episode_id" in arguments:
            error = ("episode_id is not a parameter here: this server is bound to one episode; call the tool "
                     "without it")
            await self.episodes.record_rejected(episode_id, name[:100], {k: v for k, v in arguments.items()
                                                                         if k != "episode_id"}, error)
            raise ToolError(error)
        try:
            result = await self.full.call_tool(name, {**arguments, "episode_id": episode_id}, context)
        except ToolError as exc:
            raise type(exc)(scrub_text(str(exc), episode_id)) from exc.__cause__
        return scrub_result(result, episode_id) if isinstance(result, CallToolResult) else result


def _text_of(result: CallToolResult) -> str:
    return "\n".join(c.text for c in result.content if isinstance(c, TextContent))


def bind(full: Any, episode_id: str) -> BoundServer:
    """The agent plane of an episode already started on ``full`` (an EpisodeServer from build_server)."""
    full.episodes.get(episode_id)  # unknown ids fail here, naming the fix
    return BoundServer(full, episode_id=episode_id)


def parse_options(text: str | None) -> dict[str, Any]:
    """``--episode-options '{"observation": "both"}'``: the start_episode options as JSON."""
    if not text:
        return {}
    try:
        value = json.loads(text)
    except json.JSONDecodeError as exc:
        raise BindError(f"--episode-options is not JSON ({exc.msg}); give an object such as "
                        "'{\"observation\": \"both\"}'") from None
    if not isinstance(value, dict):
        raise BindError("--episode-options must be a JSON object such as '{\"observation\": \"both\"}'")
    return value
