"""The ai2thor backend, run for real: the ai2thor client library drives the project's FIFO stand-in.

No Unity is needed: ``Controller(local_executable_path=standin_command())`` starts the stand-in,
which speaks ai2thor's FIFO protocol backed by the simulator. So the real client, its protocol
handling and our adapter all run; only the renderer behind the pipes is ours.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("ai2thor")

from ai2thor.controller import Controller  # noqa: E402
from mcp import Client  # noqa: E402

from ewa_mcp.envs.kitchen.ai2thor_backend import Ai2ThorController  # noqa: E402
from ewa_mcp.envs.kitchen.env import KitchenEnvironment  # noqa: E402
from ewa_mcp.envs.kitchen.planner import plan_ops  # noqa: E402
from ewa_mcp.envs.kitchen.session import KitchenActionError, KitchenSession  # noqa: E402
from ewa_mcp.envs.kitchen.sim import KitchenSim  # noqa: E402
from ewa_mcp.envs.kitchen.standin import standin_command  # noqa: E402
from ewa_mcp.server import ServerConfig, build_server  # noqa: E402

from .test_kitchen_mcp import StubWeb, task  # noqa: E402
from .test_kitchen_planner import SALAD, replay  # noqa: E402


def strip_volatile(objects: list[dict]) -> list[dict]:
    return [{k: v for k, v in o.items() if k not in ("distance",)} for o in objects]


def test_existing_ai2thor_code_runs_on_the_standin():
    controller = Controller(local_executable_path=standin_command(), x_display=":0", scene="FloorPlan5",
                            gridSize=0.25, visibilityDistance=1.5, width=200, height=160)
    try:
        sim = KitchenSim("FloorPlan5")
        event = controller.last_event
        assert event.metadata["sceneName"] == "FloorPlan5_physics"
        assert event.frame.shape == (160, 200, 3)  # frames arrive through the RGB_IMAGE field
        assert "FloorPlan5_physics" in controller.scenes_in_build
        assert strip_volatile(event.metadata["objects"]) == strip_volatile(sim.last_event.metadata["objects"])
        for action in ("MoveAhead", "RotateRight", "MoveAhead", "LookDown"):
            real = controller.step(action=action)
            local = sim.step(action=action)
            assert real.metadata["lastActionSuccess"] == local.metadata["lastActionSuccess"]
            assert real.metadata["agent"] == local.metadata["agent"]
        knob = next(o for o in controller.last_event.metadata["objects"] if o["objectType"] == "StoveKnob")
        real = controller.step(action="ToggleObjectOn", objectId=knob["objectId"], forceAction=True)
        assert real.metadata["lastActionSuccess"]
        burner = next(o for o in real.metadata["objects"] if o["objectId"] == knob["controlledObjects"][0])
        assert burner["isToggled"]
        failed = controller.step(action="PickupObject", objectId=knob["objectId"])
        assert not failed.metadata["lastActionSuccess"] and "not pickupable" in failed.metadata["errorMessage"]
        with pytest.raises(ValueError, match="Invalid action"):  # errorCode InvalidAction makes ai2thor raise
            controller.step(action="Fly")
        reach = controller.step(action="GetReachablePositions").metadata["actionReturn"]
        assert len(reach) == len(sim.reachable_cells())
    finally:
        controller.stop()


def test_adapter_session_matches_the_simulator():
    adapter = Ai2ThorController(standin_command(), "FloorPlan12")
    try:
        remote = KitchenSession(adapter, "ai2thor", "FloorPlan12", seed=2)
        remote.reset()
        local = KitchenSession(KitchenSim(None), "sim", "FloorPlan12", seed=2)
        local.reset()
        calls = plan_ops("FloorPlan12", SALAD, seed=2)
        replay(remote, calls)
        replay(local, calls)
        a, b = remote.final_state(), local.final_state()
        assert a["backend"] == "ai2thor" and a["scene"] == "FloorPlan12"
        assert strip_volatile(a["objects"]) == strip_volatile(b["objects"])
        # an action ai2thor itself rejects (InvalidArgument raises in the client) comes back as a refusal
        event = adapter.step(action="RotateRight", degrees=45)
        assert not event.metadata["lastActionSuccess"] and "multiple of 90" in event.metadata["errorMessage"]
    finally:
        adapter.close()


def test_a_hidden_egg_on_the_ai2thor_backend():
    """The rule that a name does not find or rule out what a closed door hides is the session's, over AI2-THOR
    metadata: the ai2thor client answers as the simulator does (FloorPlan8's only Egg is in its fridge)."""
    adapter = Ai2ThorController(standin_command(), "FloorPlan8")
    try:
        remote = KitchenSession(adapter, "ai2thor", "FloorPlan8")
        remote.reset()
        local = KitchenSession(KitchenSim(None), "sim", "FloorPlan8")
        local.reset()
        replies = []
        for session in (remote, local):
            with pytest.raises(KitchenActionError) as err:
                session.teleport("Egg")
            replies.append(str(err.value))
        assert replies[0] == replies[1] and replies[0].startswith("No Egg in sight")
        remote.teleport("Fridge")
        remote.open("Fridge")
        remote.pickup("Egg")
        assert remote.objects[remote.held_id]["objectType"] == "Egg"
    finally:
        adapter.close()


@pytest.mark.anyio
async def test_episode_on_the_ai2thor_backend(tmp_path: Path, monkeypatch):
    monkeypatch.setenv("EWA_AI2THOR_EXECUTABLE", "standin")
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "t.json").write_text(json.dumps([task("kitchen-thor")]))
    mcp, _ = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "runs",
                                       environments={"browser": StubWeb, "kitchen": KitchenEnvironment}))
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "kitchen-thor",
                                                     "options": {"kitchen_backend": "ai2thor", "observation": "both"}})
        assert not r.is_error, r.content
        ep = r.structured_content["episode_id"]
        assert "(ai2thor)" in r.content[0].text and r.content[1].type == "image"
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Knife"})
        assert not r.is_error and r.content[1].type == "image"
        r = await client.call_tool("kitchen_pickup", {"episode_id": ep, "object": "Fridge"})
        assert r.is_error and "not pickupable" in r.content[0].text
        await client.call_tool("finish_episode", {"episode_id": ep})
    final = json.loads((tmp_path / "runs" / ep / "final_state.json").read_text())
    assert final["environments"]["embodied"]["backend"] == "ai2thor"
