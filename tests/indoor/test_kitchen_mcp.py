"""The kitchen through the MCP server: tools, refusals, images, deliveries, the run directory."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from mcp import Client

from ewa_mcp.core.environment import Environment, Observation
from ewa_mcp.envs.kitchen.env import KitchenEnvironment
from ewa_mcp.envs.kitchen.planner import plan_ops
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.settings import SettingsError

KITCHEN_TOOLS = {"kitchen_teleport", "kitchen_move", "kitchen_rotate", "kitchen_pickup", "kitchen_put", "kitchen_drop",
                 "kitchen_open", "kitchen_close", "kitchen_slice", "kitchen_cook", "kitchen_toggle", "kitchen_action"}


class StubWeb(Environment):
    """A web environment that does nothing: these tests are about the kitchen."""

    side = "web"
    name = "browser"

    def __init__(self, episode: Any, services: Any):
        pass

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        return None

    async def observe(self) -> Observation:
        return Observation(text="a web page")

    async def final_state(self) -> dict[str, Any]:
        return {}


def task(task_id: str, start: str = "embodied", scene: str = "FloorPlan12", step_limit: int = 200) -> dict[str, Any]:
    start_state: dict[str, Any] = {"environment": start, "embodied": {"kind": "kitchen", "scene": scene, "seed": 0}}
    if start == "web":
        start_state["web"] = {"start_url": "recipes:/"}
    return {"id": task_id, "domain": "cooking", "intent": "Make a tomato salad", "start": start_state,
            "step_limit": step_limit}


@pytest.fixture
def server(tmp_path: Path, monkeypatch):
    # The settings are read once, when the server is built: no kitchen variable of the caller's may leak in.
    monkeypatch.delenv("EWA_AI2THOR_EXECUTABLE", raising=False)
    monkeypatch.delenv("EWA_KITCHEN_BACKEND", raising=False)
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "kitchen.json").write_text(json.dumps([
        task("kitchen-only"), task("kitchen-after-web", start="web"), task("kitchen-no-potato", scene="FloorPlan3"),
    ]))
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "runs",
                                              environments={"browser": StubWeb, "kitchen": KitchenEnvironment}))
    return mcp, episodes, tmp_path / "runs"


async def start(client: Client, task_id: str, **options: Any) -> str:
    result = await client.call_tool("start_episode", {"task_id": task_id, "options": options})
    assert not result.is_error, result.content
    return result.structured_content["episode_id"]


@pytest.mark.anyio
async def test_kitchen_tools_act_and_report(server):
    mcp, episodes, runs = server
    async with Client(mcp) as client:
        names = {t.name for t in (await client.list_tools()).tools}
        assert KITCHEN_TOOLS <= names
        ep = await start(client, "kitchen-only")
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Knife"})
        assert not r.is_error and "Done: Teleport Knife_1." in r.content[0].text
        assert r.structured_content["steps"] == 1 and "Knife_1" in r.structured_content["observation"]["in_reach"]
        assert len(r.content) == 1  # text mode: no image
        r = await client.call_tool("kitchen_action", {"episode_id": ep, "action": "PickupObject Knife"})
        assert not r.is_error and r.structured_content["observation"]["holding"] == "Knife_1"
        # a refused action is an error result that names the problem, and changes nothing
        env = episodes.get(ep).environments["embodied"]
        before = env.session.controller.snapshot()
        r = await client.call_tool("kitchen_pickup", {"episode_id": ep, "object": "Eggplant"})
        assert r.is_error and "Did you mean Egg" in r.content[0].text
        r = await client.call_tool("kitchen_slice", {"episode_id": ep, "object": "Fridge"})
        assert r.is_error and "not sliceable" in r.content[0].text
        assert env.session.controller.snapshot() == before
        r = await client.call_tool("kitchen_move", {"episode_id": ep, "direction": "up"})
        assert r.is_error  # schema validation: ahead/back/left/right only
        await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Tomato"})
        r = await client.call_tool("kitchen_open", {"episode_id": ep, "object": "Fridge"})
        r = await client.call_tool("kitchen_slice", {"episode_id": ep, "object": "Tomato"})
        assert not r.is_error and "Tomato_1 became TomatoSliced_1–5" in r.content[0].text
        await client.call_tool("finish_episode", {"episode_id": ep})
    final = json.loads((runs / ep / "final_state.json").read_text())
    kitchen = final["environments"]["embodied"]
    assert kitchen["name"] == "kitchen" and kitchen["backend"] == "sim" and kitchen["scene"] == "FloorPlan12"
    pieces = [o for o in kitchen["objects"] if o["objectType"] == "TomatoSliced"]
    assert len(pieces) == 5 and all(p["sourceType"] == "Tomato" for p in pieces)
    lines = [json.loads(line) for line in (runs / ep / "trajectory.jsonl").read_text().splitlines()]
    tools = [line["tool"] for line in lines]
    assert "kitchen_slice" in tools and any(not line["ok"] for line in lines if line["tool"] == "kitchen_pickup")


@pytest.mark.anyio
async def test_kitchen_tools_are_refused_while_the_web_is_active(server):
    mcp, episodes, _ = server
    async with Client(mcp) as client:
        ep = await start(client, "kitchen-after-web")
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Fridge"})
        assert r.is_error and "switch_environment" in r.content[0].text
        r = await client.call_tool("switch_environment", {"episode_id": ep, "target": "embodied", "message": "cook"})
        assert not r.is_error and "Kitchen FloorPlan12" in r.content[0].text
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Fridge"})
        assert not r.is_error


@pytest.mark.anyio
async def test_vision_mode_sends_an_image_and_the_resource_serves_it(server):
    mcp, _, _ = server
    async with Client(mcp) as client:
        ep = await start(client, "kitchen-only", observation="vision")
        r = await client.call_tool("kitchen_rotate", {"episode_id": ep, "direction": "left"})
        kinds = [c.type for c in r.content]
        assert kinds == ["text", "image", "resource_link"] and r.content[1].mime_type == "image/png"
        assert "In reach" not in r.content[0].text and "objects" not in r.structured_content["observation"]
        resource = await client.read_resource(f"ewa://episodes/{ep}/kitchen.png")
        assert resource.contents[0].mime_type == "image/png"
        import base64

        assert base64.b64decode(resource.contents[0].blob)[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.anyio
async def test_groceries_ordered_online_arrive_in_the_kitchen(server):
    mcp, episodes, runs = server
    async with Client(mcp) as client:
        ep = await start(client, "kitchen-no-potato")
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Potato"})
        assert r.is_error and "shopping site" in r.content[0].text
        episodes.emit_event(ep, {"site": "shop", "type": "order_placed", "order": {
            "order_id": "o-1", "store_id": "store-2", "fulfilment": "delivery",
            "items": [{"product_id": "potato-russet", "kitchen_type": "Potato", "size": "1 lb", "quantity": 1}]}})
        r = await client.call_tool("get_observation", {"episode_id": ep})
        assert "A delivery arrived: Potato_1 on CounterTop_" in r.content[0].text
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Potato"})
        assert not r.is_error
        await client.call_tool("finish_episode", {"episode_id": ep})
    deliveries = json.loads((runs / ep / "final_state.json").read_text())["environments"]["embodied"]["deliveries"]
    assert deliveries[0]["order_id"] == "o-1" and deliveries[0]["handles"] == ["Potato_1"]


@pytest.mark.anyio
async def test_planner_oracle_replays_through_the_server(server):
    mcp, _, runs = server
    ops = [{"op": "slice", "object": "Tomato"}, {"op": "cook", "object": "TomatoSliced", "method": "stove"},
           {"op": "put", "object": "TomatoSliced", "receptacle": "Plate"}]
    calls = plan_ops("FloorPlan12", ops)
    async with Client(mcp) as client:
        ep = await start(client, "kitchen-only")
        for call in calls:
            r = await client.call_tool(call["tool"], {"episode_id": ep, **call["args"]})
            assert not r.is_error, (call, r.content[0].text)
        await client.call_tool("finish_episode", {"episode_id": ep})
    objects = json.loads((runs / ep / "final_state.json").read_text())["environments"]["embodied"]["objects"]
    by_id = {o["objectId"]: o for o in objects}
    assert any(o["objectType"] == "TomatoSliced" and o["isCooked"]
               and by_id[o["parentReceptacles"][0]]["objectType"] == "Plate" for o in objects)


@pytest.mark.anyio
async def test_bad_start_options_are_explained(server, monkeypatch, tmp_path):
    mcp, _, _ = server
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "kitchen-only", "options": {"kitchen_backend": "ai2thor"}})
        assert r.is_error and "EWA_AI2THOR_EXECUTABLE" in r.content[0].text
    # A bad backend variable stops the server from starting, naming the variable and its values.
    monkeypatch.setenv("EWA_KITCHEN_BACKEND", "unity")
    with pytest.raises(SettingsError, match="EWA_KITCHEN_BACKEND='unity' is not valid.*sim or ai2thor"):
        build_server(ServerConfig(task_dirs=[tmp_path / "tasks"], run_dir=tmp_path / "runs"))
