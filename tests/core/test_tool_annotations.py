"""Every listed tool has a title and MCP annotations declared through the tool adapter
(ewa_mcp/core/tool_table.py); looks are read-only, actions are not, nothing is open-world."""

from __future__ import annotations

import pytest
from mcp.server.mcpserver import MCPServer


from .fixtures import listed_tools
from ewa_mcp.core.tool_table import check_declared, define_tool, tool_annotations

LOOKS = {"get_observation", "street_observe", "geo_look", "browser_snapshot", "browser_screenshot",
         "episode_status", "list_tasks"}
# Changes that cannot be undone: graded as they are left.
DESTRUCTIVE = {"finish_episode", "submit_location", "street_stop", "kitchen_slice", "kitchen_cook", "kitchen_action"}



def test_every_tool_has_a_title_and_closed_world_annotations(tmp_path):
    tools = listed_tools(tmp_path)
    assert len(tools) > 30
    for tool in tools:
        assert tool.title and tool.title.strip(), tool.name
        a = tool.annotations
        assert a is not None, tool.name
        assert a.read_only_hint is not None and a.destructive_hint is not None, tool.name
        assert a.open_world_hint is False, tool.name


def test_looks_are_read_only_and_actions_are_not(tmp_path):
    tools = {t.name: t.annotations for t in listed_tools(tmp_path)}
    assert LOOKS <= set(tools)
    for name, a in tools.items():
        assert a.read_only_hint is (name in LOOKS), name
        if name in LOOKS:
            assert a.destructive_hint is False, name
    for name in DESTRUCTIVE:
        assert tools[name].destructive_hint is True, name
    assert tools["kitchen_move"].destructive_hint is False and tools["street_move"].destructive_hint is False
    assert tools["list_tasks"].idempotent_hint is True  # reads the task store only, not a step


def test_a_tool_declared_without_the_adapter_is_refused():
    mcp = MCPServer("t")

    @define_tool(mcp, title="Fine", effect="look", description="declared")
    def fine() -> str:
        return "ok"

    check_declared(mcp)

    @mcp.tool(description="bare")
    def bare() -> str:
        return "no"

    with pytest.raises(RuntimeError, match="bare"):
        check_declared(mcp)
    with pytest.raises(ValueError, match="unknown tool effect"):
        tool_annotations("readonly")  # type: ignore[arg-type]
