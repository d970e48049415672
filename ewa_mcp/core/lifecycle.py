"""Episode lifecycle tools and resources: tasks, episodes, observation, switching, finishing."""

from __future__ import annotations

import json
from typing import Annotated, Any, Literal, cast

from mcp.server.mcpserver import Context, MCPServer
from mcp.server.mcpserver.exceptions import ResourceError
from mcp_types import CallToolResult
from pydantic import BaseModel, Field, create_model

from . import registry
from .environment import Observation
from .episodes import EpisodeError, EpisodeManager
from .options import EpisodeOptions, episode_options
from .response import (IMAGE_NAME, StepOutput, compact_requested, footer, image_links, observation_data, step_result,
                       tool_result)
from .tool_table import EpisodeId, define_tool

DomainName = str  # replaced by a Literal of the registry's domain names in register()


class TaskSummary(BaseModel):
    id: str
    domain: str
    difficulty: str
    intent: str
    step_limit: int


class TaskList(BaseModel):
    tasks: list[TaskSummary]
    total: int
    offset: int
    next_offset: int | None


class EpisodeStarted(BaseModel):
    episode_id: str
    task_id: str
    domain: str
    intent: str
    active_environment: str
    environments: dict[str, str]
    step_limit: int
    observation: dict[str, Any]


class _StatusHead(BaseModel):
    episode_id: str
    task_id: str
    domain: str
    status: str
    end_reason: str | None
    active_environment: str
    environments: dict[str, str]
    steps: int
    step_limit: int
    steps_left: int
    switches: int


SERVER_DESCRIPTION = ("the server's admission rules: open_episodes, max_episodes, max_episodes_per_client, "
                      "idle_timeout_s (an episode with no call for this long is ended as aborted), reaped_idle")


class EpisodeStatus(_StatusHead):
    answer: str | None
    server: dict[str, Any] | None = Field(default=None, description=SERVER_DESCRIPTION)


def status_model() -> type[EpisodeStatus]:
    """EpisodeStatus with the fields the registered environments declare (registry.StatusField), before
    ``answer`` as they have always been listed."""
    fields: dict[str, Any] = {f.name: (bool | None, Field(default=None, description=f.description))
                              for f in registry.status_fields()}
    if not fields:
        return EpisodeStatus
    model = create_model("EpisodeStatus", __base__=_StatusHead, **fields, answer=(str | None, ...),
                         server=(dict[str, Any] | None, Field(default=None, description=SERVER_DESCRIPTION)))
    return cast("type[EpisodeStatus]", model)


def public_task(task: Any) -> dict[str, Any]:
    """What an agent may see of a task: never its goals, answer or oracle (the reference leaked goals)."""
    return {
        "id": task.id,
        "domain": task.domain,
        "intent": task.intent,
        "step_limit": task.step_limit,
        "start_environment": task.start.environment,
        "environments": task.environment_names(),
    }


def page_span(offset: int, shown: int, total: int) -> str:
    """Which tasks a list_tasks page holds, by 0-based position like its ``offset`` argument."""
    if shown == 0:
        return f"none at offset {offset} (offsets run 0–{total - 1})" if total else "none"
    if shown == 1:
        return f"showing 1 task, at offset {offset} (0-based)"
    return f"showing {shown} tasks, offsets {offset}–{offset + shown - 1} (0-based)"


async def _observe(episode: Any) -> Observation:
    env = episode.environments.get(episode.active)
    if env is None:
        return Observation(text="(this episode has no environment to observe)")
    return await env.observe()


def client_key(ctx: Context | None) -> str | None:
    """The client a call came from (the per-client cap counts its episodes). The 2026 protocol has no sessions,
    so this is the transport's: an in-process or stdio connection, or over HTTP the Mcp-Session-Id of a client
    that keeps a session (2025 protocols). Sessionless HTTP requests have none: only the server's cap counts
    them."""
    if ctx is None:
        return None
    try:
        headers = ctx.headers
        if headers is not None:
            session_id = headers.get("mcp-session-id")
            return f"http:{session_id[:100]}" if session_id else None
        # The server's lifespan state, which the SDK makes once per in-process or stdio connection (server.py).
        state = ctx.request_context.lifespan_context
    except (AttributeError, LookupError, ValueError):
        return None
    return state.get("connection") if isinstance(state, dict) else None


def status_text(summary: dict[str, Any], status_words: dict[str, tuple[str, str]]) -> str:
    """Every fact of an episode's summary in words (what was asked, how it stands or ended, the answer, the
    steps, the environments' status fields), so a model that reads only the text misses nothing the structured
    content holds."""
    environments = ", ".join(f"{side} {name}" for side, name in summary["environments"].items())
    words = "".join(f"; {status_words[k][0] if v else status_words[k][1]}" for k, v in summary.items()
                    if k in status_words and v is not None)
    # Quoted as JSON quotes it, so an answer costs the text what it costs the structured content.
    answer = "none given" if summary["answer"] is None else json.dumps(summary["answer"], ensure_ascii=False)
    return (f"Task: {summary['task_id']} (domain {summary['domain']}). Outcome: status {summary['status']}, end "
            f"reason: {summary['end_reason'] or 'none'}. Answer: {answer}. Steps used: {summary['steps']} of the "
            f"{summary['step_limit']} allowed ({summary['steps_left']} left); environment switches: "
            f"{summary['switches']}. Environments: {environments} (active: {summary['active_environment']}){words}.")


def server_text(limits: dict[str, Any]) -> str:
    """The server's admission rules (EpisodeManager.limits) in words."""
    return (f"Server: {limits['open_episodes']} open episodes"
            + (f" of at most {limits['max_episodes']}" if limits["max_episodes"] else " (no cap)")
            + (f", at most {limits['max_episodes_per_client']} per client" if limits["max_episodes_per_client"]
               else ", no cap per client")
            + (f"; an episode with no call for {limits['idle_timeout_s']:g} s is ended (aborted); "
               f"{limits['reaped_idle']} ended so far for idling" if limits["idle_timeout_s"]
               else "; idle episodes are not ended"))


def register(mcp: MCPServer, episodes: EpisodeManager) -> None:
    Status = status_model()
    finish_hints = "".join(f" {e.finish_hint}" for e in registry.ordered_environments() if e.finish_hint)
    def list_tasks(
        domain: DomainName | None = None,
        difficulty: Literal["easy", "medium", "hard"] | None = None,
        limit: Annotated[int, Field(ge=1, le=500)] = 20,
        offset: Annotated[int, Field(ge=0, description="how many tasks to skip: 0-based position of the first "
                                     "task listed (offset=0 starts at the first task)")] = 0,
    ) -> Annotated[CallToolResult, TaskList]:
        tasks = sorted(episodes.tasks.all(domain), key=lambda t: t.id)
        if difficulty is not None:
            tasks = [t for t in tasks if t.difficulty == difficulty]
        page = tasks[offset : offset + limit]
        nxt = offset + limit if offset + limit < len(tasks) else None
        out = TaskList(
            tasks=[TaskSummary(id=t.id, domain=t.domain, difficulty=t.difficulty, intent=t.intent,
                               step_limit=t.step_limit) for t in page],
            total=len(tasks),
            offset=offset,
            next_offset=nxt,
        )
        lines = [f"{len(tasks)} tasks" + (f" in {domain}" if domain else "") + "; " + page_span(offset, len(page),
                                                                                             len(tasks)) + ":"]
        lines += [f"- {t.id} [{t.domain}, {t.difficulty}] {t.intent}" for t in page]
        if nxt is not None:
            lines.append(f"(more: offset={nxt})")
        return tool_result(out, "\n".join(lines))

    # The domain choices are the registry's (ewa_mcp/core/registry.py), read when the server is built.
    list_tasks.__annotations__["domain"] = Literal[tuple(registry.domain_names())] | None
    define_tool(mcp, title="List tasks", effect="query",
                description="List benchmark tasks, optionally of one domain and difficulty (easy, medium, hard), a "
                "page at a time.")(list_tasks)

    # The options are the kernel's and every registered environment's (ewa_mcp/core/options.py), read when the
    # server is built.
    options_model = episode_options()

    async def start_episode(task_id: str, options: EpisodeOptions | None = None,
                            ctx: Context | None = None) -> Annotated[CallToolResult, EpisodeStarted]:
        opts = (options or options_model()).model_dump(exclude_none=True)
        episode = await episodes.start(task_id, opts, client=client_key(ctx))
        _, observation = await episodes.act(episode.id, "start_episode", {"task_id": task_id, "options": opts},
                                            _observe, environment=None, counted=False)
        out = EpisodeStarted(
            episode_id=episode.id,
            task_id=episode.task.id,
            domain=episode.task.domain,
            intent=episode.task.intent,
            active_environment=episode.active,
            environments={k: type(v).name for k, v in episode.environments.items()},
            step_limit=episode.task.step_limit,
            observation=observation_data(episode, observation),
        )
        envs = ", ".join(f"{k}={type(v).name}" for k, v in episode.environments.items()) or "none"
        text = (
            f"Episode {episode.id} started.\nTask: {episode.task.intent}\n"
            f"Environments: {envs}; active: {episode.active}. Step limit: {episode.task.step_limit}.\n\n"
            f"{observation.text}\n{footer(episode)}"
        )
        return tool_result(out, text, observation.images, image_links(episode, observation.images))

    start_episode.__annotations__["options"] = options_model | None
    define_tool(mcp, title="Start an episode", effect="act",
                description="Start an episode of a task. Returns the episode_id to pass to every other tool.")(start_episode)

    @define_tool(mcp, title="Observe the active environment", effect="look",
                 description="Show the active environment's observation again (counts as a step, like every call).")
    async def get_observation(episode_id: EpisodeId) -> Annotated[CallToolResult, StepOutput]:
        episode, observation = await episodes.act(episode_id, "get_observation", {}, _observe, environment=None)
        return step_result(episode, observation)

    @define_tool(mcp, title="Switch environment", effect="act",
                 description=("Switch the active environment (web <-> embodied); returns that environment's "
                              "observation, so no look is needed after it. Say in message what you will do there."))
    async def switch_environment(
        episode_id: EpisodeId,
        target: Literal["web", "embodied"],
        message: Annotated[str, Field(max_length=2000)] = "",
    ) -> Annotated[CallToolResult, StepOutput]:
        episode, observation = await episodes.switch(episode_id, target, message)
        return step_result(episode, observation)

    async def finish_episode(
        episode_id: EpisodeId, answer: Annotated[str | None, Field(max_length=4000)] = None
    ) -> CallToolResult:
        episode = await episodes.finish(episode_id, answer)
        summary = episode.summary()
        return tool_result(Status(**summary),
                           f"Episode {episode.id} finished. {status_text(summary, status_words)} {footer(episode)}",
                           compact=compact_requested(episode))

    # The output schema carries the status fields the environments declare (status_model), so the return
    # annotation is set here, where that model exists.
    finish_episode.__annotations__["return"] = Annotated[CallToolResult, Status]
    define_tool(mcp, title="Finish the episode", effect="destructive", description=(
        "End the episode, with your answer when the task asks a question. Nothing can be done after it."
        + finish_hints))(finish_episode)

    status_words = {f.name: (f.when_true, f.when_false) for f in registry.status_fields()}

    async def episode_status(episode_id: EpisodeId) -> CallToolResult:
        episode = episodes.get(episode_id)
        if episode.status == "running":
            async def note(_: Any) -> Observation:
                return Observation(text="episode status")

            episode, _ = await episodes.act(episode_id, "episode_status", {}, note, environment=None)
        s = episode.summary()
        limits = episodes.limits()
        text = f"{episode.id}: {status_text(s, status_words)}\n{server_text(limits)}"
        return tool_result(Status(**s, server=limits), text, compact=compact_requested(episode))

    episode_status.__annotations__["return"] = Annotated[CallToolResult, Status]
    define_tool(mcp, title="Episode status", effect="look", description=(
        "The episode's status: active environment, steps used and left, "
        + "".join(f"{f.phrase}, " for f in registry.status_fields())
        + "whether the episode ended. On a running episode it counts as a step, like every call."))(episode_status)

    @mcp.resource("ewa://tasks/{task_id}", mime_type="application/json", description="A task as the agent may see it")
    def task_resource(task_id: str) -> str:
        task = episodes.tasks.get(task_id)
        if task is None:
            raise ResourceError(f"unknown task id {task_id!r}; call list_tasks to see the ids")
        return json.dumps(public_task(task), indent=2)

    @mcp.resource("ewa://episodes/{episode_id}/state", mime_type="application/json",
                  description="An episode's status")
    def episode_state_resource(episode_id: str) -> str:
        try:
            return json.dumps(episodes.get(episode_id).summary(), indent=2)
        except EpisodeError as exc:
            raise ResourceError(str(exc)) from exc

    @mcp.resource("ewa://episodes/{episode_id}/trajectory", mime_type="application/jsonl",
                  description="An episode's recorded tool calls, one JSON object per line")
    def episode_trajectory_resource(episode_id: str) -> str:
        try:
            episode = episodes.get(episode_id)
        except EpisodeError as exc:
            raise ResourceError(str(exc)) from exc
        path = episode.recorder.directory / "trajectory.jsonl"
        return path.read_text(encoding="utf-8") if path.exists() else ""

    @mcp.resource("ewa://episodes/{episode_id}/images/{image}", mime_type="image/png",
                  description="An observation image of an episode, as recorded: {image} is <call>-<k>.png, the "
                  "k-th image (from 0) of the episode's call number <call>, as linked from that call's result")
    def episode_image_resource(episode_id: str, image: str) -> bytes:
        try:
            episode = episodes.get(episode_id)
        except EpisodeError as exc:
            raise ResourceError(str(exc)) from exc
        match = IMAGE_NAME.match(image)
        if match is None:
            raise ResourceError(f"bad image name {image[:80]!r}: use <call>-<k>.png as linked from a tool result, "
                                "e.g. 3-0.png")
        path = episode.recorder.directory / f"images/step-{int(match[1]):04d}-{int(match[2])}.png"
        if not path.is_file():
            raise ResourceError(f"episode {episode_id} has no image {image}: call {int(match[1])} returned no image "
                                f"number {int(match[2])}; use an address from a tool result's resource_link")
        return path.read_bytes()
