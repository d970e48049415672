"""End to end through the MCP client: a navigation task file, the street tools, the run record."""

import json

import pytest
from mcp import Client

from ewa_mcp.core import registry
from ewa_mcp.server import ServerConfig, build_server


@pytest.fixture
def street_only(monkeypatch):
    # Only the groups this part needs, so the test does not depend on the browser/kitchen parts.
    monkeypatch.setattr(registry, "tool_groups", lambda: ["ewa_mcp.core.lifecycle", "ewa_mcp.envs.street.tools"])


def write_task(tmp_path, world):
    start = world.search("6th Ave & W 33rd St", city="manhattan")[0]
    target = world.place("store-target-herald-square")
    task = {
        "id": "nav-mcp-test", "domain": "navigation", "intent": "Walk to the Target store on West 34th Street.",
        "start": {"environment": "embodied",
                  "embodied": {"kind": "street", "city": "manhattan", "node": start.node, "heading": 29.0}},
        "embodied_goals": [{"kind": "reached_place", "city": "manhattan", "node": target.node,
                            "lat": target.lat, "lng": target.lng, "place_id": target.id}],
        "step_limit": 40,
    }
    (tmp_path / "tasks").mkdir()
    (tmp_path / "tasks" / "nav.json").write_text(json.dumps(task))
    return task


@pytest.mark.anyio
async def test_walk_to_a_store_over_mcp(tmp_path, world, street_only):
    task = write_task(tmp_path, world)
    server, _ = build_server(ServerConfig(task_dirs=[tmp_path / "tasks"], run_dir=tmp_path / "run"))
    async with Client(server) as c:
        tools = {t.name for t in (await c.list_tools()).tools}
        assert {"street_observe", "street_move", "street_stop"} <= tools
        r = await c.call_tool("start_episode", {"task_id": "nav-mcp-test", "options": {"observation": "both"}})
        assert not r.is_error
        ep = r.structured_content["episode_id"]
        r = await c.call_tool("street_observe", {"episode_id": ep})
        assert not r.is_error and len([x for x in r.content if x.type == "image"]) == 4
        obs = r.structured_content["observation"]
        assert obs["neighbours"] and task["embodied_goals"][0]["node"] not in json.dumps(r.structured_content)
        # Follow the map directions step by step, choosing neighbours by id.
        directions = world.directions(obs["node"], "store-target-herald-square")
        for node in directions.nodes[1:]:
            r = await c.call_tool("street_move", {"episode_id": ep, "neighbour": node})
            assert not r.is_error, r.content[0].text
        r = await c.call_tool("street_move", {"episode_id": ep, "direction": "sideways"})
        assert r.is_error  # input validation names the allowed values
        r = await c.call_tool("episode_status", {"episode_id": ep})
        assert r.structured_content["walk_stopped"] is False and "walk not stopped" in r.content[0].text
        r = await c.call_tool("street_stop", {"episode_id": ep})
        assert not r.is_error
        r = await c.call_tool("episode_status", {"episode_id": ep})
        assert r.structured_content["status"] == "running" and r.structured_content["walk_stopped"] is True
        assert "walk stopped" in r.content[0].text
        r = await c.call_tool("street_move", {"episode_id": ep, "direction": "forward"})
        assert r.is_error and "the walk is over" in r.content[0].text
        r = await c.call_tool("finish_episode", {"episode_id": ep})
        assert not r.is_error
    final = json.loads((tmp_path / "run" / ep / "final_state.json").read_text())
    street = final["environments"]["embodied"]
    assert street["name"] == "street" and street["stopped"] is True
    assert street["node"] == task["embodied_goals"][0]["node"]
    assert street["path"] == directions.nodes
    lines = (tmp_path / "run" / ep / "trajectory.jsonl").read_text().splitlines()
    moves = [json.loads(line) for line in lines if json.loads(line)["tool"] == "street_move"]
    # every walked step, the invalid "sideways" (refused by the schema, still a recorded step) and the
    # refused move after stop
    assert len(moves) == len(directions.nodes) - 1 + 2
    assert [m["ok"] for m in moves] == [True] * (len(directions.nodes) - 1) + [False, False]
    assert moves[-2]["args"] == {"direction": "sideways"} and moves[-2]["counted"] is True


def test_the_move_tool_offers_exactly_the_environments_labels():
    from typing import get_args

    from ewa_mcp.envs.street import env
    from ewa_mcp.envs.street import actions as street

    assert get_args(street.Direction) == get_args(env.Direction)
