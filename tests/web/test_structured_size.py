"""Structured content is never larger than the text it accompanies unless the episode asks for the full data
(issue 29): every kind of result a bound agent gets (the first observation, each action, get_observation,
episode_status, finish_episode, submit_location), over one oracle-played task of every domain, and the text of
finish_episode carries the facts of its structured content. Real Chromium, real sites."""

from __future__ import annotations

import json

import pytest
from mcp_types import CallToolResult, TextContent

from ewa_mcp.bound import BoundServer
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio


def _text(result: CallToolResult) -> str:
    return "\n".join(c.text for c in result.content if isinstance(c, TextContent))


def _structured(result: CallToolResult) -> str:
    return json.dumps(result.structured_content, ensure_ascii=False, separators=(",", ":"))


def _one_task_per_domain() -> list[str]:
    chosen: dict[str, str] = {}
    for task in sorted(TaskStore([tasks_dir()]).all(), key=lambda t: t.id):
        if task.domain != "demo" and task.oracle and task.domain not in chosen:
            chosen[task.domain] = task.id
    return [chosen[d] for d in sorted(chosen)]


async def test_no_structured_content_is_larger_than_its_text_for_a_bound_agent(tmp_path, chromium_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    larger: list[str] = []
    seen: set[str] = set()
    try:
        for task_id in _one_task_per_domain():
            task = episodes.tasks.get(task_id)
            bound = BoundServer(full, task_id=task_id)
            results = [("start", await bound.start())]
            status = "running"
            for call in task.oracle:
                if status != "running":
                    break
                if call.tool == "finish_episode":  # played last, after the status and observation kinds
                    continue
                result = await bound.call_tool(call.tool, dict(call.args))
                results.append((call.tool, result))
                status = result.structured_content.get("status", status)
            if status == "running":
                for tool in ("get_observation", "episode_status", "finish_episode"):
                    results.append((tool, await bound.call_tool(tool, {})))
            results.append(("episode_status (ended)", await bound.call_tool("episode_status", {})))
            for kind, result in results:
                assert not result.is_error, (task_id, kind, _text(result))
                seen.add(kind.split(" ")[0])
                if len(_structured(result)) > len(_text(result)):
                    larger.append(f"{task_id} {kind}: structured {len(_structured(result))} > text "
                                  f"{len(_text(result))}: {_structured(result)[:300]}")
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
    assert {"start", "browser_click", "submit_location", "finish_episode", "episode_status",
            "get_observation"} <= seen, seen
    assert larger == []


async def test_finish_episode_says_in_words_what_its_structured_content_holds(tmp_path, chromium_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        bound = BoundServer(full, task_id="geo-0001-embodied")
        await bound.start()
        result = await bound.call_tool("finish_episode", {"answer": 'near the "obelisk"'})
        data, text = result.structured_content, _text(result)
        assert len(_structured(result)) <= len(text)
        for fact in (data["task_id"], data["domain"], data["status"], data["end_reason"],
                     json.dumps(data["answer"]), f"{data['steps']} of the {data['step_limit']} allowed",
                     f"{data['steps_left']} left", f"switches: {data['switches']}"):
            assert str(fact) in text, (fact, text)
        # Compact: no null field the schema does not require; the episode's environments' status fields stay.
        assert None not in [v for k, v in data.items() if k != "answer"]
        # The control plane's default (structured "full") keeps every field, nulls included.
        started = await full.call_tool("start_episode", {"task_id": "geo-0001-embodied"})
        episode_id = started.structured_content["episode_id"]
        finished = await full.call_tool("finish_episode", {"episode_id": episode_id})
        assert set(finished.structured_content) >= set(data) | {"answer"}
        assert finished.structured_content["answer"] is None and "Answer: none given" in _text(finished)
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
