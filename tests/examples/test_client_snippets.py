"""The MCP parts of examples/README.md's "OpenAI Agents SDK" and "LangChain" snippets, run against a real
`ewa-mcp serve --transport http` without any LLM.

OpenAI Agents SDK: `pip install -e ".[clients]"`; skipped when `agents` is not installed.
LangChain: langchain-mcp-adapters needs mcp<2 and this server runs on mcp 2, so the client lives in its own
environment; set EWA_LANGCHAIN_PYTHON to that environment's python (skipped otherwise).
"""

from __future__ import annotations

import asyncio
import json
import os
import re
import subprocess

import pytest

from core.servers import serve, stop  # tests/ is on sys.path (rootdir-relative packages)

TASK_ID = "cooking-cook-0001"


def _text(result) -> str:
    return "\n".join(getattr(block, "text", "") for block in result.content)


def test_openai_agents_sdk_strict_tools_and_calls(tmp_path):
    pytest.importorskip("agents", reason="the OpenAI Agents SDK is not installed: pip install -e '.[clients]'")
    from agents import Agent, RunContextWrapper
    from agents.mcp import MCPServerStreamableHttp, MCPUtil

    proc, port = serve(tmp_path)
    try:
        async def main():
            async with MCPServerStreamableHttp(params={"url": f"http://127.0.0.1:{port}/mcp"},
                                               client_session_timeout_seconds=30, cache_tools_list=True) as ewa:
                listed = await ewa.list_tools()
                assert {"list_tasks", "start_episode", "finish_episode"} <= {t.name for t in listed}
                # What the SDK does for a strict-schema agent; a tool whose schema cannot be made strict is kept
                # silently as non-strict, so check the flag on every converted tool.
                agent = Agent(name="ewa", mcp_servers=[ewa], mcp_config={"convert_schemas_to_strict": True})
                converted = await agent.get_mcp_tools(RunContextWrapper(context=None))
                assert len(converted) == len(listed)
                non_strict = [t.name for t in converted if not t.strict_json_schema]
                assert non_strict == [], f"tools the SDK could not make strict: {non_strict}"
                for tool in listed:  # the public helper, directly
                    assert MCPUtil.to_function_tool(tool, ewa, convert_schemas_to_strict=True).strict_json_schema
                schemas = {t.name: t.params_json_schema for t in converted}

                # A strict-mode model sends every property, null for the ones it leaves out.
                assert set(schemas["list_tasks"]["required"]) == set(schemas["list_tasks"]["properties"])
                tasks = await ewa.call_tool("list_tasks", {"domain": "cooking", "difficulty": None, "limit": 3})
                assert not tasks.is_error and "tasks in cooking" in _text(tasks), _text(tasks)[:300]
                args = {name: None for name in schemas["start_episode"]["properties"]} | {"task_id": TASK_ID}
                started = await ewa.call_tool("start_episode", args)
                assert not started.is_error, _text(started)
                episode = re.search(r"\bep-[0-9a-f]+", _text(started)).group(0)
                finished = await ewa.call_tool("finish_episode", {"episode_id": episode, "answer": None})
                assert not finished.is_error, _text(finished)

        asyncio.run(main())
    finally:
        stop(proc)


LANGCHAIN_CLIENT = """
import asyncio, json, re, sys
from langchain_mcp_adapters.client import MultiServerMCPClient
from langchain_mcp_adapters.tools import load_mcp_tools

def text(result):
    return "\\n".join(b["text"] if isinstance(b, dict) else str(b) for b in result) if isinstance(result, list) else str(result)

async def main(url, task_id):
    out = {}
    client = MultiServerMCPClient({"ewa": {"transport": "streamable_http", "url": url}})
    tools = {t.name: t for t in await client.get_tools()}   # a new connection per call
    started = text(await tools["start_episode"].ainvoke({"task_id": task_id}))
    episode = re.search(r"\\bep-[0-9a-f]+", started).group(0)
    out["status"] = text(await tools["episode_status"].ainvoke({"episode_id": episode}))
    async with client.session("ewa") as session:              # one held session
        held = {t.name: t for t in await load_mcp_tools(session)}
        out["held_status"] = text(await held["episode_status"].ainvoke({"episode_id": episode}))
        out["finished"] = text(await held["finish_episode"].ainvoke({"episode_id": episode}))
    out["episode"], out["tools"] = episode, sorted(tools)
    print(json.dumps(out))

asyncio.run(main(sys.argv[1], sys.argv[2]))
"""


def _langchain_python() -> str:
    python = os.environ.get("EWA_LANGCHAIN_PYTHON")
    if not python:
        pytest.skip("langchain-mcp-adapters (0.3.2) requires mcp<2, this server mcp 2: install it in its own "
                    "environment and set EWA_LANGCHAIN_PYTHON to that environment's python")
    check = subprocess.run([python, "-c", "import langchain_mcp_adapters"], capture_output=True, text=True)
    if check.returncode != 0:
        pytest.fail(f"EWA_LANGCHAIN_PYTHON={python[:200]} cannot import langchain_mcp_adapters: "
                    f"{check.stderr[-200:]}; pip install langchain-mcp-adapters there")
    return python


def test_langchain_tools_keep_the_episode_between_calls(tmp_path):
    python = _langchain_python()
    proc, port = serve(tmp_path)
    try:
        run = subprocess.run([python, "-c", LANGCHAIN_CLIENT, f"http://127.0.0.1:{port}/mcp", TASK_ID],
                             capture_output=True, text=True, timeout=240)
        assert run.returncode == 0, run.stderr[-2000:]
        out = json.loads(run.stdout.strip().splitlines()[-1])
    finally:
        stop(proc)
    assert {"start_episode", "episode_status", "finish_episode"} <= set(out["tools"])
    # The episode started by one tool call is still there for the next (new connection, then a held session).
    for status in (out["status"], out["held_status"]):
        assert out["episode"] in status and "unknown episode" not in status.lower(), status[:300]
    assert out["episode"] in out["finished"] or "finish" in out["finished"].lower(), out["finished"][:300]
    episodes = list((tmp_path / "runs").rglob("final_state.json"))
    assert len(episodes) == 1, episodes
