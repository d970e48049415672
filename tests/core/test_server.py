"""The MCP server core through a real in-process MCP client: every tool and resource, the
episode protocol, the run directory, and bad input."""

from __future__ import annotations

import base64
import json

import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server

from .fixtures import CounterEnv, NoteEnv, counter_task, register, write_tasks

pytestmark = pytest.mark.anyio


def text_of(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


@pytest.fixture
def server(tmp_path):
    tasks = write_tasks(tmp_path / "tasks", [counter_task(), counter_task("t-short", step_limit=2),
                                             counter_task("t-web", start="web")])
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "run",
                                              environments={"kitchen": CounterEnv, "browser": NoteEnv}))
    register(mcp, episodes)
    return mcp, episodes, tmp_path / "run"


async def start(client, task_id="t-counter"):
    r = await client.call_tool("start_episode", {"task_id": task_id})
    assert not r.is_error, text_of(r)
    return r.structured_content["episode_id"]


async def test_tools_have_schemas_and_instructions(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        for name in ["list_tasks", "start_episode", "get_observation", "switch_environment", "finish_episode",
                     "episode_status"]:
            assert tools[name].output_schema, name
            assert tools[name].input_schema["type"] == "object"
        assert "episode_id" in tools["finish_episode"].input_schema["properties"]
    assert "switch_environment" in mcp.instructions


async def test_list_tasks_pages_and_filters(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        r = await client.call_tool("list_tasks", {"limit": 2})
        assert r.structured_content["total"] == 3
        assert [t["id"] for t in r.structured_content["tasks"]] == ["t-counter", "t-short"]
        assert r.structured_content["next_offset"] == 2
        r = await client.call_tool("list_tasks", {"limit": 2, "offset": 2})
        assert [t["id"] for t in r.structured_content["tasks"]] == ["t-web"]
        assert r.structured_content["next_offset"] is None
        r = await client.call_tool("list_tasks", {"domain": "cooking"})
        assert r.structured_content["total"] == 0
        r = await client.call_tool("list_tasks", {"domain": "gardening"})
        assert r.is_error


async def test_list_tasks_names_the_page_by_the_offsets_it_takes(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        assert "0-based" in tools["list_tasks"].input_schema["properties"]["offset"]["description"]
        r = await client.call_tool("list_tasks", {"limit": 5, "offset": 1})
        lines = text_of(r).splitlines()
        assert lines[0] == "3 tasks; showing 2 tasks, offsets 1–2 (0-based):"
        assert [line.split()[1] for line in lines[1:]] == ["t-short", "t-web"]
        r = await client.call_tool("list_tasks", {"limit": 5, "offset": 2})
        assert text_of(r).splitlines()[0] == "3 tasks; showing 1 task, at offset 2 (0-based):"
        r = await client.call_tool("list_tasks", {"offset": 7})
        assert text_of(r) == "3 tasks; none at offset 7 (offsets run 0–2):"


async def test_episode_lifecycle_and_records(server):
    mcp, _, run = server
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "t-counter"})
        sc = r.structured_content
        assert sc["active_environment"] == "embodied" and sc["observation"] == {"value": 1}
        assert sc["environments"] == {"web": "browser", "embodied": "counter"}
        ep = sc["episode_id"]
        r = await client.call_tool("counter_add", {"episode_id": ep, "amount": 2})
        assert not r.is_error and r.structured_content["observation"] == {"value": 3}
        assert r.structured_content["steps"] == 1
        r = await client.call_tool("get_observation", {"episode_id": ep})
        assert "counter is 3" in text_of(r) and r.structured_content["steps"] == 2  # every call is a step
        r = await client.call_tool("finish_episode", {"episode_id": ep, "answer": "three"})
        assert r.structured_content["status"] == "finished"
        r = await client.call_tool("counter_add", {"episode_id": ep, "amount": 1})
        assert r.is_error and "has ended" in text_of(r)
        r = await client.call_tool("episode_status", {"episode_id": ep})
        assert r.structured_content["status"] == "finished" and r.structured_content["answer"] == "three"

    ep_dir = run / ep
    lines = [json.loads(line) for line in (ep_dir / "trajectory.jsonl").read_text().splitlines()]
    assert [line["tool"] for line in lines] == ["start_episode", "counter_add", "get_observation", "finish_episode"]
    assert [line["counted"] for line in lines] == [False, True, True, True]
    assert lines[1]["args"] == {"amount": 2} and lines[1]["ok"] and lines[1]["environment"] == "embodied"
    final = json.loads((ep_dir / "final_state.json").read_text())
    assert final["status"] == "finished" and final["answer"] == "three" and final["steps"] == 3
    assert final["environments"]["embodied"] == {"name": "counter", "value": 3}
    task = json.loads((ep_dir / "task.json").read_text())
    assert task["id"] == "t-counter" and task["oracle"]  # the record keeps the full task for grading


async def test_inactive_environment_is_refused_and_switch_is_recorded(server):
    mcp, episodes, run = server
    async with Client(mcp) as client:
        ep = await start(client, "t-web")
        r = await client.call_tool("counter_add", {"episode_id": ep, "amount": 5})
        assert r.is_error and "switch_environment" in text_of(r)
        assert episodes.get(ep).environments["embodied"].value == 1  # unchanged
        r = await client.call_tool("switch_environment", {"episode_id": ep, "target": "embodied",
                                                          "message": "go count"})
        assert not r.is_error and r.structured_content["active_environment"] == "embodied"
        r = await client.call_tool("switch_environment", {"episode_id": ep, "target": "embodied", "message": ""})
        assert r.is_error and "already active" in text_of(r)
        r = await client.call_tool("page_next", {"episode_id": ep})
        assert r.is_error
        assert episodes.get(ep).switches == 1
    lines = [json.loads(x) for x in (run / ep / "trajectory.jsonl").read_text().splitlines()]
    assert [(x["tool"], x["ok"]) for x in lines] == [
        ("start_episode", True), ("counter_add", False), ("switch_environment", True),
        ("switch_environment", False), ("page_next", False)]


async def test_step_limit_ends_episode(server):
    mcp, _, run = server
    async with Client(mcp) as client:
        ep = await start(client, "t-short")
        await client.call_tool("counter_add", {"episode_id": ep})
        r = await client.call_tool("counter_add", {"episode_id": ep})
        assert not r.is_error and r.structured_content["status"] == "step_limit"
        r = await client.call_tool("counter_add", {"episode_id": ep})
        assert r.is_error and "step limit" in text_of(r)
    final = json.loads((run / ep / "final_state.json").read_text())
    assert final["status"] == "step_limit" and final["environments"]["embodied"]["value"] == 3


async def test_failed_action_changes_nothing_and_is_recorded(server):
    mcp, episodes, run = server
    async with Client(mcp) as client:
        ep = await start(client)
        r = await client.call_tool("counter_add", {"episode_id": ep, "amount": -3})
        assert r.is_error and "amounts must be >= 0" in text_of(r)
        assert episodes.get(ep).environments["embodied"].value == 1
    last = json.loads((run / ep / "trajectory.jsonl").read_text().splitlines()[-1])
    assert last["ok"] is False and "amounts must be" in last["error"]


async def test_bad_input_errors_name_the_fix(server):
    mcp, episodes, run = server
    async with Client(mcp) as client:
        ep = await start(client)
        r = await client.call_tool("start_episode", {"task_id": "nope"})
        assert r.is_error and "list_tasks" in text_of(r)
        r = await client.call_tool("get_observation", {"episode_id": "ep-unknown"})
        assert r.is_error and "start_episode" in text_of(r)
        r = await client.call_tool("counter_add", {"episode_id": ep, "amount": "lots"})
        assert r.is_error
        r = await client.call_tool("start_episode", {"task_id": "t-counter", "options": {"observaton": "text"}})
        assert r.is_error  # a misspelt option is rejected, not ignored
        r = await client.call_tool("episode_status", {"episode_id": ep})
        assert r.structured_content["status"] == "running"
    # Calls addressed elsewhere left no trace on the valid episode; the two addressed to it are steps,
    # the refused one (its argument failed the schema) included, with its error.
    lines = [json.loads(x) for x in (run / ep / "trajectory.jsonl").read_text().splitlines()]
    assert [(x["tool"], x["ok"], x["counted"]) for x in lines] == [
        ("start_episode", True, False), ("counter_add", False, True), ("episode_status", True, True)]
    assert "amount" in lines[1]["error"] and lines[1]["args"] == {"amount": "lots"}


async def test_concurrent_episodes_are_independent(server):
    mcp, episodes, _ = server
    async with Client(mcp) as client:
        a, b = await start(client), await start(client)
        assert a != b
        await client.call_tool("counter_add", {"episode_id": a, "amount": 10})
        await client.call_tool("finish_episode", {"episode_id": a})
        r = await client.call_tool("counter_add", {"episode_id": b, "amount": 1})
        assert r.structured_content["observation"] == {"value": 2}
        assert episodes.get(a).environments["embodied"].value == 11


async def test_resources(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        templates = {t.uri_template for t in (await client.list_resource_templates()).resource_templates}
        assert {"ewa://tasks/{task_id}", "ewa://episodes/{episode_id}/state",
                "ewa://episodes/{episode_id}/trajectory"} <= templates
        r = await client.read_resource("ewa://tasks/t-counter")
        public = json.loads(r.contents[0].text)
        assert public["intent"] == "count to three"
        assert "oracle" not in public and "answer" not in public  # goals never leak to the agent
        ep = await start(client)
        await client.call_tool("counter_add", {"episode_id": ep})
        r = await client.read_resource(f"ewa://episodes/{ep}/state")
        assert json.loads(r.contents[0].text)["steps"] == 1
        r = await client.read_resource(f"ewa://episodes/{ep}/trajectory")
        assert [json.loads(x)["tool"] for x in r.contents[0].text.splitlines()] == ["start_episode", "counter_add"]
        with pytest.raises(Exception, match="unknown task"):
            await client.read_resource("ewa://tasks/nope")


async def test_observation_images_are_returned_and_recorded(server):
    mcp, _, run = server
    async with Client(mcp) as client:
        ep = await start(client, "t-web")
        r = await client.call_tool("get_observation", {"episode_id": ep})
        assert [c.type for c in r.content] == ["text", "image", "resource_link"]
        assert r.content[1].mime_type == "image/png"
        link = r.content[2]
        assert str(link.uri) == f"ewa://episodes/{ep}/images/2-0.png" and link.mime_type == "image/png"
        # The link reads back the recorded image, byte for byte the inline one.
        fetched = await client.read_resource(str(link.uri))
        assert base64.b64decode(fetched.contents[0].blob) == base64.b64decode(r.content[1].data)
        assert fetched.contents[0].mime_type == "image/png"
        templates = {t.uri_template for t in (await client.list_resource_templates()).resource_templates}
        assert "ewa://episodes/{episode_id}/images/{image}" in templates
        for bad, why in ((f"ewa://episodes/{ep}/images/9-0.png", "no image 9-0.png"),
                         (f"ewa://episodes/{ep}/images/step.png", "bad image name"),
                         ("ewa://episodes/nope/images/2-0.png", "nope")):
            with pytest.raises(Exception, match=why):
                await client.read_resource(bad)
    lines = [json.loads(x) for x in (run / ep / "trajectory.jsonl").read_text().splitlines()]
    assert lines[1]["images"] == ["images/step-0002-0.png"]
    assert (run / ep / "images" / "step-0002-0.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
