"""The browser tools end to end through an MCP client, with the real embedded sites."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from mcp import Client

from ewa_mcp.server import ServerConfig, build_server

pytestmark = [pytest.mark.anyio, pytest.mark.browser]

BROWSER_TOOLS = {"browser_click", "browser_type", "browser_hover", "browser_press", "browser_scroll",
                 "browser_new_tab", "browser_close_tab", "browser_tab_focus", "browser_goto", "browser_go_back",
                 "browser_go_forward", "browser_snapshot", "browser_screenshot"}


def _text(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


@pytest.fixture
def server(tmp_path: Path, chromium_path: str):
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "web.json").write_text(json.dumps(
        {"id": "web-home", "domain": "demo", "intent": "Look around the homepage.", "step_limit": 20,
         "start": {"environment": "web", "web": {"start_url": "home:/"}}}))
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "run"))
    return mcp, tmp_path / "run"


async def test_browser_tools_through_mcp(server):
    mcp, run_dir = server
    async with Client(mcp) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        assert BROWSER_TOOLS <= set(tools)
        assert all(tools[name].output_schema for name in BROWSER_TOOLS)

        started = await client.call_tool("start_episode", {"task_id": "web-home"})
        assert not started.is_error, _text(started)
        episode = started.structured_content["episode_id"]
        first = started.structured_content["observation"]
        assert first["site_url"] == "home:/" and "RootWebArea" in first["tree"]
        assert "Tab 0 (current):" in _text(started)

        snap = await client.call_tool("browser_snapshot", {"episode_id": episode, "viewport_only": True})
        assert not snap.is_error and snap.structured_content["steps"] == 1  # every call is a step, looks too

        refused = await client.call_tool("browser_goto", {"episode_id": episode, "url": "file:///etc/passwd"})
        assert refused.is_error and "file: URLs are refused" in _text(refused)
        missing = await client.call_tool("browser_click", {"episode_id": episode, "element": "99999"})
        assert missing.is_error and "no element [99999]" in _text(missing)

        # Follow the first link to another embedded site, by the id the observation shows.
        links = re.finditer(r"\[(\d+)\] link '([^']+)' url: (http://127\.0\.0\.1:\d+/)", first["tree"])
        match = next((m for m in links if m.group(3) != first["url"]), None)
        assert match, first["tree"]
        clicked = await client.call_tool("browser_click", {"episode_id": episode, "element": match.group(1)})
        assert not clicked.is_error, _text(clicked)
        assert clicked.structured_content["observation"]["url"] == match.group(3)
        assert clicked.structured_content["steps"] == 4  # the snapshot, two refused actions and the click

        back = await client.call_tool("browser_go_back", {"episode_id": episode})
        assert not back.is_error, _text(back)
        assert back.structured_content["observation"]["site_url"] == "home:/"

        shot = await client.call_tool("browser_screenshot", {"episode_id": episode})
        images = [c for c in shot.content if getattr(c, "type", "") == "image"]
        assert len(images) == 1 and images[0].mime_type == "image/png"

        done = await client.call_tool("finish_episode", {"episode_id": episode})
        assert not done.is_error

    final = json.loads((run_dir / episode / "final_state.json").read_text())
    web = final["environments"]["web"]
    assert web["name"] == "browser" and web["active_tab"] == 0
    assert web["tabs"][0]["site_url"] == "home:/"
    assert web["site_history"][0] == "home:/" and web["history"][1] == match.group(3)
    # The homepage saw this episode's header: its page views landed in this episode's event log.
    events = [json.loads(line) for line in (run_dir / episode / "web_events.jsonl").read_text().splitlines()]
    assert sum(1 for e in events if e.get("site") == "home" and e.get("type") == "page_view") >= 2
    # The start page, loaded while the episode was being started, is recorded too (nothing is lost).
    assert (events[0]["site"], events[0]["type"], events[0]["path"]) == ("home", "page_view", "/")
    steps = [json.loads(line) for line in (run_dir / episode / "trajectory.jsonl").read_text().splitlines()]
    assert [s["tool"] for s in steps if s["tool"].startswith("browser_")][:3] == [
        "browser_snapshot", "browser_goto", "browser_click"]


async def test_vision_episodes_get_set_of_marks_images(server):
    mcp, _ = server
    async with Client(mcp) as client:
        started = await client.call_tool("start_episode", {"task_id": "web-home", "options": {"observation": "vision"}})
        assert not started.is_error, _text(started)
        assert any(getattr(c, "type", "") == "image" for c in started.content)
        assert "Marked elements" in _text(started)
        episode = started.structured_content["episode_id"]
        scrolled = await client.call_tool("browser_scroll", {"episode_id": episode, "direction": "down"})
        assert any(getattr(c, "type", "") == "image" for c in scrolled.content)
        await client.call_tool("finish_episode", {"episode_id": episode})
