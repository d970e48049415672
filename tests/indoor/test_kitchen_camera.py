"""The first-person kitchen camera (indoor/camera3d.py, scene3d.py) and the vision-only kitchen observation.

These tests render real frames with OpenGL on EGL (Mesa's llvmpipe on a machine without a GPU). Where no EGL
context can be made they fail, naming the packages to install: CI installs them (`make install` runs
scripts/ensure-egl.sh), so a skip would hide a broken camera.
"""

from __future__ import annotations

import json
from collections import Counter
import math
from pathlib import Path

import pytest
from mcp import Client
from PIL import Image

from ewa_mcp.envs.kitchen import camera3d
from ewa_mcp.envs.kitchen.env import KitchenEnvironment
from ewa_mcp.envs.kitchen.observe import build_observation
from ewa_mcp.envs.kitchen.scene3d import SceneBuilder, front_direction
from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.server import ServerConfig, build_server

from .conftest import new_session


@pytest.fixture(scope="module", autouse=True)
def egl() -> str:
    try:
        return camera3d.renderer_name()
    except camera3d.CameraUnavailable as exc:
        pytest.fail(f"the kitchen camera cannot render here: {exc}", pytrace=False)


def frame(s: KitchenSession) -> Image.Image:
    return camera3d.render_frame(s.meta, s.reachable)


def count(image: Image.Image, test) -> int:
    return sum(1 for pixel in image.get_flattened_data() if test(*pixel))


def red(r: int, g: int, b: int) -> bool:  # a tomato or an apple
    return r > 120 and r > 2.2 * g and r > 2.2 * b


def food(r: int, g: int, b: int) -> bool:  # red tomatoes and apples, green lettuce
    return red(r, g, b) or (g > 100 and g > 1.4 * r and g > 1.6 * b)


def glow(r: int, g: int, b: int) -> bool:  # a lit burner's ring
    return r == 255 and 85 <= g <= 103 and b <= 30


def face(s: KitchenSession, handle: str, distance: float = 0.9) -> None:
    """Stand about ``distance`` in front of a piece of furniture's doors, facing it."""
    obj = s.objects[s.by_handle[handle.lower()]]
    box = obj["axisAlignedBoundingBox"]
    c = (box["center"]["x"], box["center"]["y"], box["center"]["z"])
    size = (box["size"]["x"], box["size"]["y"], box["size"]["z"])
    bounds = s.meta["sceneBounds"]["center"]
    fx, fz = front_direction(c, size, s.reachable, (bounds["x"], bounds["z"]))
    half = (size[0] if fx else size[2]) / 2
    want = (c[0] + fx * (half + distance), c[2] + fz * (half + distance))
    x, z = min(s.reachable, key=lambda p: (math.hypot(p[0] - want[0], p[1] - want[1]), p))
    rotation = (math.degrees(math.atan2(-fx, -fz))) % 360
    s._step("TeleportFull", x=x, y=s.agent["position"]["y"], z=z, rotation={"x": 0.0, "y": rotation, "z": 0.0},
            horizon=30.0, standing=True)


# ------------------------------------------------------------------ a first-person view
def test_the_frame_is_the_configured_size_and_the_same_state_gives_the_same_bytes():
    s = new_session("FloorPlan12")
    s.teleport("Tomato")
    first = camera3d.render_png(s.meta, s.reachable)
    s.plain_action("RotateRight")
    other = camera3d.render_png(s.meta, s.reachable)
    s.plain_action("RotateLeft")
    assert camera3d.render_png(s.meta, s.reachable) == first != other
    assert frame(s).size == (300, 300)
    assert camera3d.render_frame(s.meta, s.reachable, width=400, height=224).size == (400, 224)
    with pytest.raises(ValueError, match="width must be a whole number of pixels"):
        camera3d.render_frame(s.meta, s.reachable, width=0)


def test_turning_around_changes_most_of_the_frame():
    s = new_session("FloorPlan1")
    before = frame(s)
    s.plain_action("RotateRight")
    s.plain_action("RotateRight")
    after = frame(s)
    changed = sum(1 for a, b in zip(before.get_flattened_data(), after.get_flattened_data()) if sum(abs(x - y) for x, y in zip(a, b)) > 30)
    assert changed > 0.6 * before.width * before.height


def test_moving_ahead_towards_an_object_makes_it_larger():
    s = new_session("FloorPlan1")
    s.teleport("Tomato")
    s.plain_action("MoveBack")
    s.plain_action("MoveBack")
    far = count(frame(s), red)
    s.plain_action("MoveAhead")
    near = count(frame(s), red)
    assert 0 < far and near > 1.5 * far


@pytest.mark.parametrize("scene", ["FloorPlan5", "FloorPlan10", "FloorPlan23"])
def test_a_closed_fridge_hides_its_contents_and_opening_it_shows_them(scene):
    s = new_session(scene)
    face(s, "Fridge_1")
    closed = count(frame(s), food)
    s._step("OpenObject", s.by_handle["fridge_1"])
    opened = count(frame(s), food)
    assert opened > closed + 20, (closed, opened)


def test_a_lit_burner_glows():
    s = new_session("FloorPlan1")
    s.teleport("StoveBurner")
    assert count(frame(s), glow) == 0
    burner = s.resolve("StoveBurner", "interact")[0]
    knob = next(i for i, o in s.objects.items() if burner in (o.get("controlledObjects") or []))
    s._step("ToggleObjectOn", knob)
    assert count(frame(s), glow) > 30


def test_the_held_object_is_at_the_bottom_of_the_frame():
    s = new_session("FloorPlan1")
    s.teleport("Tomato")
    s.pickup("Tomato")
    s.plain_action("RotateRight")  # whatever the view, the hand is in it
    image = frame(s)
    bottom = image.crop((0, image.height * 2 // 3, image.width, image.height))
    top = image.crop((0, 0, image.width, image.height // 3))
    assert count(bottom, red) > 200 and count(top, red) == 0


# ------------------------------------------------------------------ what is drawn (no GL)
def test_closed_receptacles_hide_contents_and_cooked_food_is_darker():
    from collections import Counter

    from ewa_mcp.envs.kitchen.scene3d import FOOD_COLOURS, browned

    s = new_session("FloorPlan5")
    fridge = s.by_handle["fridge_1"]
    assert any(fridge in (o.get("parentReceptacles") or []) and o["objectType"] == "Tomato" for o in s.objects.values())
    lettuce, tomato = FOOD_COLOURS["Lettuce"], FOOD_COLOURS["Tomato"]

    def drawn() -> Counter:
        world, _ = SceneBuilder().build(s.meta, s.reachable)
        return Counter(p.colour for p in world)

    closed = drawn()
    s._step("OpenObject", fridge, forceAction=True)
    opened = drawn()
    assert opened[lettuce] > closed[lettuce] and opened[tomato] > closed[tomato]
    inside = next(i for i, o in s.objects.items() if o["objectType"] == "Tomato" and fridge in o["parentReceptacles"])
    s._step("CookObject", inside, forceAction=True)
    cooked = drawn()
    assert cooked[tomato] == closed[tomato] and cooked[browned(tomato)] > 0
    assert sum(browned(tomato)) < sum(tomato)


def test_each_knob_wears_the_colour_of_the_burner_it_lights():
    from ewa_mcp.envs.kitchen.scene3d import BURNER_MARKS, burner_marks

    for scene in ("FloorPlan1", "FloorPlan12", "FloorPlan23"):
        s = new_session(scene)
        marks = burner_marks(s.objects.values())
        burners = [i for i, o in s.objects.items() if o["objectType"] == "StoveBurner"]
        knobs = [o for o in s.objects.values() if o["objectType"] == "StoveKnob" and o.get("controlledObjects")]
        assert burners and knobs
        assert len({marks[b] for b in burners}) == min(len(burners), len(BURNER_MARKS)), scene
        for knob in knobs:
            assert marks[knob["objectId"]] == marks[knob["controlledObjects"][0]]
        # and both are drawn: the ring of every burner and the face of every knob in that colour
        world, _ = SceneBuilder().build(s.meta, s.reachable)
        drawn = Counter(p.colour for p in world)
        for knob in knobs:
            assert drawn[marks[knob["objectId"]]] >= 2, scene


def test_a_cooked_slice_is_brown_with_sear_stripes_not_a_darker_red():
    from ewa_mcp.envs.kitchen.scene3d import FOOD_COLOURS, SEAR, browned

    s = new_session("FloorPlan1")
    s._step("PickupObject", s.resolve("Knife", "interact")[0], forceAction=True)
    s._step("SliceObject", s.resolve("Tomato", "interact")[0], forceAction=True)
    piece = next(i for i, o in s.objects.items() if o["objectType"] == "TomatoSliced")

    def stripes() -> int:
        world, _ = SceneBuilder().build(s.meta, s.reachable)
        return sum(1 for p in world if p.colour == SEAR)

    assert stripes() == 0
    s._step("CookObject", piece, forceAction=True)
    assert stripes() == 3
    assert not red(*(int(255 * c) for c in browned(FOOD_COLOURS["Tomato"])))  # a cooked tomato no longer reads as red


# ------------------------------------------------------------------ vision-only observation
def test_vision_observation_is_the_image_plus_what_a_camera_cannot_give():
    s = new_session("FloorPlan12")
    first, _ = build_observation(s, "vision", view="first_person")
    assert "colour of the ring round the burner it lights" in first  # the frame's conventions, once
    for leak in ("In reach", "CounterTop", "Fridge", "Tomato", "x="):
        assert leak not in first, leak
    s.teleport("Knife")
    s.pickup("Knife")
    text, data = build_observation(s, "vision", view="first_person")
    assert "colour of the ring" not in text
    assert text.splitlines()[0].endswith("Holding: Knife_1.")
    assert "Last action succeeded. Done: PickupObject Knife_1." in text
    for leak in ("In reach", "CounterTop", "Fridge", "Tomato", "x=", "facing", "m away"):
        assert leak not in text, leak
    assert data["lastActionSuccess"] is True and data["holding"] == "Knife_1"
    assert not {"objects", "in_reach", "agent"} & set(data)
    text, data = build_observation(s, "vision", view="first_person", last_error="PickupObject Apple_1 failed: busy")
    assert "Last action failed: PickupObject Apple_1 failed: busy" in text and data["lastActionSuccess"] is False


@pytest.mark.anyio
async def test_vision_episode_through_the_server(tmp_path: Path, monkeypatch):
    monkeypatch.delenv("EWA_KITCHEN_BACKEND", raising=False)
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    start = {"environment": "embodied", "embodied": {"kind": "kitchen", "scene": "FloorPlan12", "seed": 0}}
    (tasks / "k.json").write_text(json.dumps([{"id": "k-1", "domain": "cooking", "intent": "Slice a tomato",
                                               "start": start, "step_limit": 50}]))
    mcp, _ = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "runs",
                                       environments={"kitchen": KitchenEnvironment}))
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "k-1", "options": {"observation": "vision"}})
        ep = r.structured_content["episode_id"]
        r = await client.call_tool("kitchen_pickup", {"episode_id": ep, "object": "Tomato"})
        assert r.is_error
        r = await client.call_tool("get_observation", {"episode_id": ep})
        assert "Last action failed:" in r.content[0].text and r.structured_content["observation"]["lastActionSuccess"] is False
        r = await client.call_tool("kitchen_teleport", {"episode_id": ep, "object": "Tomato"})
        text = r.content[0].text
        assert [c.type for c in r.content] == ["text", "image", "resource_link"] and "Last action succeeded" in text
        assert "In reach" not in text and "You stand at" not in text
        r = await client.call_tool("start_episode", {"task_id": "k-1", "options": {
            "observation": "both", "kitchen_view": "map"}})
        assert "In reach" in r.content[0].text and r.content[1].type == "image"
        r = await client.call_tool("start_episode", {"task_id": "k-1", "options": {
            "observation": "vision", "kitchen_camera_width": 10}})
        assert r.is_error and "kitchen_camera_width" in r.content[0].text


def test_without_egl_the_error_names_the_packages(monkeypatch):
    import moderngl

    def no_egl(*args, **kwargs):
        raise Exception("eglInitialize failed (0x3001)")

    monkeypatch.setattr(camera3d, "_renderer", None)
    monkeypatch.setattr(moderngl, "create_context", no_egl)
    s = new_session("FloorPlan12")
    with pytest.raises(camera3d.CameraUnavailable, match="libegl1 libgl1-mesa-dri libegl-mesa0") as info:
        frame(s)
    assert "kitchen_view='map'" in str(info.value) and "eglInitialize failed" in str(info.value)


@pytest.mark.anyio
@pytest.mark.parametrize("observation", ["vision", "both"])
async def test_the_planner_oracle_plays_in_vision_modes(tmp_path: Path, monkeypatch, observation):
    """The oracle's tool calls name handles, which work whatever the agent sees: every call succeeds and the
    recipe's end state is reached, with a frame in every reply."""
    from ewa_mcp.envs.kitchen.planner import plan_ops

    monkeypatch.delenv("EWA_KITCHEN_BACKEND", raising=False)
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    start = {"environment": "embodied", "embodied": {"kind": "kitchen", "scene": "FloorPlan12", "seed": 0}}
    (tasks / "k.json").write_text(json.dumps([{"id": "k-1", "domain": "cooking", "intent": "Fry tomato slices",
                                               "start": start, "step_limit": 200}]))
    mcp, _ = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "runs",
                                       environments={"kitchen": KitchenEnvironment}))
    ops = [{"op": "slice", "object": "Tomato"}, {"op": "cook", "object": "TomatoSliced", "method": "stove"},
           {"op": "put", "object": "TomatoSliced", "receptacle": "Plate"}]
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "k-1", "options": {"observation": observation}})
        ep = r.structured_content["episode_id"]
        for call in plan_ops("FloorPlan12", ops):
            r = await client.call_tool(call["tool"], {"episode_id": ep, **call["args"]})
            assert not r.is_error and [c.type for c in r.content[-2:]] == ["image", "resource_link"], (call, r.content[0].text)
        await client.call_tool("finish_episode", {"episode_id": ep})
    objects = json.loads((tmp_path / "runs" / ep / "final_state.json").read_text())["environments"]["embodied"][
        "objects"]
    by_id = {o["objectId"]: o for o in objects}
    assert any(o["objectType"] == "TomatoSliced" and o["isCooked"]
               and by_id[o["parentReceptacles"][0]]["objectType"] == "Plate" for o in objects)
