"""The one response builder: every tool answers with a short text the model reads, the same
content as structured data (matching the tool's output schema), and optional PNG images."""

from __future__ import annotations

import base64
import re
from collections.abc import Awaitable, Callable, Sequence
from typing import Any

from mcp_types import CallToolResult, ImageContent, ResourceLink, TextContent
from pydantic import BaseModel, Field

from . import registry
from .environment import Environment, Observation


class StepOutput(BaseModel):
    """What every environment action returns."""

    episode_id: str
    status: str = Field(description="running, finished, step_limit or aborted")
    active_environment: str = Field(description="web or embodied")
    steps: int
    steps_left: int
    observation: dict[str, Any] = Field(default_factory=dict, description="the environment's structured observation")


def image_uri(episode_id: str, step: int, k: int) -> str:
    """The resource address of the k-th image of an episode's call ``step`` (read from its record)."""
    return f"ewa://episodes/{episode_id}/images/{step}-{k}.png"


IMAGE_NAME = re.compile(r"^(\d{1,9})-(\d{1,4})\.png$")


def compact_requested(episode: Any) -> bool:
    """Whether the episode asked for compact structured content (episode option ``structured: compact``, the
    agent plane's default): no more in the structured content than its text says."""
    return (getattr(episode, "options", None) or {}).get("structured") == "compact"


def without_nulls(value: Any) -> Any:
    """``value`` (JSON data) without the null members of its objects, at any depth."""
    if isinstance(value, dict):
        return {k: without_nulls(v) for k, v in value.items() if v is not None}
    if isinstance(value, list):
        return [without_nulls(v) for v in value]
    return value


def tool_result(model: BaseModel, text: str, images: Sequence[bytes] = (),
                image_links: Sequence[str] = (), compact: bool = False) -> CallToolResult:
    """``image_links``, one per image, adds a resource_link after each inline image: many clients drop
    or delay images returned inline by a tool, and can still fetch them by address.

    ``compact``: the structured content leaves out the null fields the output schema does not require (a
    status field of an environment the episode does not have says nothing the text has to repeat)."""
    content: list[Any] = [TextContent(type="text", text=text)]
    for i, png in enumerate(images):
        content.append(ImageContent(type="image", data=base64.b64encode(png).decode("ascii"), mime_type="image/png"))
        if i < len(image_links):
            uri = image_links[i]
            content.append(ResourceLink(type="resource_link", uri=uri, name=uri.rsplit("/", 1)[-1],
                                        title=f"observation image {i + 1} of {len(images)}",
                                        mime_type="image/png", size=len(png)))
    structured = model.model_dump(mode="json")
    if compact:
        required = {name for name, f in type(model).model_fields.items() if f.is_required()}
        structured = {k: without_nulls(v) for k, v in structured.items() if v is not None or k in required}
    return CallToolResult(content=content, structured_content=structured)


def image_links(episode: Any, images: Sequence[bytes]) -> list[str]:
    """Addresses of the images of the episode's latest recorded call (EpisodeManager records each call's
    images under its call index, which is ``episode.calls`` once the call has returned)."""
    return [image_uri(episode.id, episode.calls, k) for k in range(len(images))]


def footer(episode: Any) -> str:
    line = f"[{episode.id} · {episode.active} · step {episode.steps}/{episode.task.step_limit}"
    if episode.status != "running":
        line += f" · ended: {episode.end_reason}"
    return line + "]"


def observation_data(episode: Any, observation: Observation) -> dict[str, Any]:
    """The observation as structured content: all its data, or with the episode option ``structured: compact``
    only its kind (the text already carries the observation; a model that reads both pays for it twice)."""
    if compact_requested(episode):
        return {"kind": observation.data["kind"]} if "kind" in observation.data else {}
    return observation.data


def step_result(episode: Any, observation: Observation, *, include_images: bool = True) -> CallToolResult:
    model = StepOutput(
        episode_id=episode.id,
        status=episode.status,
        active_environment=episode.active,
        steps=episode.steps,
        steps_left=episode.steps_left,
        observation=observation_data(episode, observation),
    )
    text = f"{observation.text}\n{footer(episode)}"
    images = observation.images if include_images else []
    return tool_result(model, text, images, image_links(episode, images))


def environment_for_tool(tool: str) -> str | None:
    """Environment tools are named <environment>_<action> after the registry name of the environment they are
    made for (ewa_mcp/core/registry.py), so a kitchen tool called on a street episode is refused before anything runs."""
    prefix = tool.partition("_")[0]
    return prefix if prefix in registry.environments() else None


async def env_action(
    episodes: Any,
    episode_id: str,
    tool: str,
    args: dict[str, Any],
    environment: str,
    action: Callable[[Environment], Awaitable[Observation]],
) -> CallToolResult:
    """Run ``action`` on the episode's ``environment`` (web/embodied) through the episode manager.
    Like every call on a running episode, it is recorded and uses one step."""

    async def run(episode: Any) -> Observation:
        return await action(episode.environment(environment))

    episode, observation = await episodes.act(episode_id, tool, args, run, environment=environment,
                                              requires=environment_for_tool(tool))
    return step_result(episode, observation)
