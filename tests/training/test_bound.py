"""The agent plane: a BoundServer hands an agent one episode's tools, through a real in-process MCP client session."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import anyio
import pytest
from mcp import Client

from ewa_mcp.bound import BoundServer, bind, scrub_result, scrub_text, unbind_schema
from ewa_mcp.graders import grade_episode
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio
TASK = "geo-0018-baseline"  # embodied only: no browser needed


async def test_bound_tools_have_no_episode_id_and_no_control_tools(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    bound = BoundServer(full, task_id=TASK, own_services=True)
    async with Client(bound) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        assert "list_tasks" not in tools and "start_episode" not in tools
        assert {"geo_look", "geo_move", "submit_location", "finish_episode", "get_observation"} <= set(tools)
        assert not any(name.startswith(("kitchen_", "street_")) for name in tools)  # not this episode's world
        for tool in tools.values():
            assert "episode_id" not in tool.input_schema.get("properties", {}), tool.name
            assert "episode_id" not in tool.input_schema.get("required", []), tool.name
        # The task and the first observation reach the agent without start_episode.
        assert "Where in the world are you?" in client.instructions
        result = await client.call_tool("geo_look", {"direction": "north"})
        assert not result.is_error
        assert bound.episode_id is not None and bound.episode_id not in result.content[0].text
        assert result.content[0].text.rstrip().endswith("[embodied · step 1/10]")


async def test_bound_server_refuses_control_tools_and_episode_ids_as_recorded_steps(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        other = (await full.call_tool("start_episode", {"task_id": TASK})).structured_content["episode_id"]
        started = await full.call_tool("start_episode", {"task_id": TASK})
        bound = bind(full, started.structured_content["episode_id"])
        async with Client(bound) as client:
            refused = await client.call_tool("start_episode", {"task_id": TASK})
            assert refused.is_error and "bound to one episode" in refused.content[0].text
            listed = await client.call_tool("list_tasks", {})
            assert listed.is_error
            # An agent cannot reach another episode by naming it.
            stolen = await client.call_tool("geo_look", {"episode_id": other})
            assert stolen.is_error and "episode_id is not a parameter here" in stolen.content[0].text
            done = await client.call_tool("submit_location", {"lat": 48.8656, "lng": 2.3212, "country": "France"})
            assert not done.is_error
        mine = episodes.get(bound.episode_id)
        assert mine.steps == 4  # the three refusals were steps, like any refused call
        assert episodes.get(other).steps == 0
        lines = [json.loads(x) for x in (mine.recorder.directory / "trajectory.jsonl").read_text().splitlines()]
        assert [line["tool"] for line in lines] == ["start_episode", "start_episode", "list_tasks", "geo_look",
                                                    "submit_location"]
        assert grade_episode(mine.recorder.directory).geolocation["country"] is True
    finally:
        await episodes.aclose()
        await episodes.services.aclose()


def test_unbind_schema_and_scrub_text():
    schema = {"type": "object", "properties": {"episode_id": {"type": "string"}, "x": {"type": "integer"}},
              "required": ["episode_id", "x"]}
    assert unbind_schema(schema) == {"type": "object", "properties": {"x": {"type": "integer"}}, "required": ["x"]}
    assert schema["required"] == ["episode_id", "x"]  # the full server's schema is left alone
    text = "Episode ep-1234 finished. [ep-1234 · web · step 3/9]"
    assert scrub_text(text, "ep-1234") == "The episode finished. [web · step 3/9]"


def test_scrub_result_drops_links_that_name_the_episode():
    from mcp_types import CallToolResult, ImageContent, ResourceLink, TextContent

    result = CallToolResult(content=[
        TextContent(type="text", text="[ep-1234 · embodied · step 1/9]"),
        ImageContent(type="image", data="AAAA", mime_type="image/png"),
        ResourceLink(type="resource_link", uri="ewa://episodes/ep-1234/images/1-0.png", name="1-0.png"),
        ResourceLink(type="resource_link", uri="ewa://tasks/t-1", name="t-1"),
    ])
    kept = scrub_result(result, "ep-1234").content
    assert [c.type for c in kept] == ["text", "image", "resource_link"]
    assert str(kept[2].uri) == "ewa://tasks/t-1" and "ep-1234" not in kept[0].text


def test_serve_bind_task_over_stdio(tmp_path):
    """`ewa-mcp serve --bind-task` starts the episode itself; a stdio client plays it without an episode id."""
    from mcp import StdioServerParameters

    async def main() -> tuple[list[str], str]:
        params = StdioServerParameters(command=sys.executable, args=[
            "-m", "ewa_mcp", "serve", "--bind-task", TASK, "--run-dir", str(tmp_path / "run")])
        async with Client(params) as client:
            names = [t.name for t in (await client.list_tools()).tools]
            result = await client.call_tool("submit_location", {"lat": 48.8656, "lng": 2.3212})
            return names, result.content[0].text

    names, text = anyio.run(main)
    assert "start_episode" not in names and "geo_look" in names
    assert "Location submitted" in text
    [episode_dir] = [p for p in (tmp_path / "run").iterdir() if p.is_dir()]
    assert grade_episode(episode_dir).status == "finished"


def test_serve_bind_task_refuses_an_unknown_task(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "ewa_mcp", "serve", "--bind-task", "no-such-task",
                           "--run-dir", str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2
    assert "unknown task id 'no-such-task'" in proc.stderr and "tasks list" in proc.stderr
    assert not any(Path(tmp_path).iterdir())
