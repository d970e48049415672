"""The thirty generated kitchens: deterministic, varied, valid, every object reachable."""

from __future__ import annotations

from collections import Counter

import pytest

from ewa_mcp.envs.kitchen.planner import scene_inventory
from ewa_mcp.envs.kitchen.scenes import SCENE_NAMES, SceneError, _generate, build_scene, scene_number
from ewa_mcp.envs.kitchen.sim import KitchenSim, format_object_id
from ewa_mcp.envs.kitchen.vocabulary import FOOD_TYPES

from .conftest import new_session


def test_thirty_named_kitchens_and_bad_names_rejected():
    assert len(SCENE_NAMES) == 30 and SCENE_NAMES[0] == "FloorPlan1" and SCENE_NAMES[-1] == "FloorPlan30"
    assert scene_number("FloorPlan7_physics") == 7
    for bad in ("FloorPlan0", "FloorPlan31", "floorplan3", "Kitchen1", ""):
        with pytest.raises(SceneError, match="FloorPlan1 … FloorPlan30"):
            scene_number(bad)


def test_generation_is_deterministic():
    for number in (1, 17, 30):
        first = _generate(number, build_scene(f"FloorPlan{number}").notes["attempt"])
        again = _generate(number, build_scene(f"FloorPlan{number}").notes["attempt"])
        assert first is not None and again is not None
        assert [(o.object_type, o.box, o.parent) for o in first.objects] == \
            [(o.object_type, o.box, o.parent) for o in again.objects]
    a, b = KitchenSim("FloorPlan12"), KitchenSim("FloorPlan12")
    assert a.last_event.metadata["objects"] == b.last_event.metadata["objects"]


def test_some_objects_start_inside_closed_receptacles():
    hidden = 0
    for name in SCENE_NAMES[:10]:
        sim = KitchenSim(name)
        for o in sim.last_event.metadata["objects"]:
            parent = sim.find(o["parentReceptacles"][0]) if o["parentReceptacles"] else None
            if o["pickupable"] and parent is not None and parent.spec.openable:
                assert not o["visible"], "an object inside a closed receptacle cannot be seen"
                hidden += 1
    assert hidden >= 10


def test_kitchens_differ_in_food_and_equipment():
    foods = {name: frozenset(scene_inventory(name)["food"]) for name in SCENE_NAMES}
    assert len(set(foods.values())) >= 8, "kitchens should hold different food"
    assert any(len(f) < len(FOOD_TYPES) for f in foods.values()), "some recipes must need shopping"
    counts = Counter(t for name in SCENE_NAMES for t in scene_inventory(name)["tools"])
    assert 0 < counts["Pot"] < 30 and 0 < counts["Kettle"] < 30
    appliances = Counter(t for name in SCENE_NAMES for t in scene_inventory(name)["receptacles"])
    assert 0 < appliances["Microwave"] < 30 and 0 < appliances["Toaster"] < 30
    for name in SCENE_NAMES:
        inv = scene_inventory(name)
        assert len(inv["food"]) >= 3
        assert inv["tools"] & {"Knife", "ButterKnife"} and inv["tools"] & {"Pan", "Pot"} and "Plate" in inv["tools"]
        assert {"Fridge", "StoveBurner", "SinkBasin", "CounterTop", "Cabinet"} <= inv["receptacles"]


@pytest.mark.parametrize("scene", SCENE_NAMES)
def test_scene_is_valid_and_every_object_reachable(scene):
    sim = KitchenSim(scene)
    objects = sim.last_event.metadata["objects"]
    ids = [o["objectId"] for o in objects]
    assert len(ids) == len(set(ids))
    for o in objects:  # AI2-THOR's objectId: Type|+x.xx|+y.yy|+z.zz
        p = o["position"]
        assert o["objectId"] == format_object_id(o["objectType"], p["x"], p["y"], p["z"])
        if o["pickupable"]:
            assert o["parentReceptacles"], f"{o['objectId']} must start in/on a receptacle"
    # agent positions lie on the 0.25 m grid and are connected
    cells = sim.reachable_cells()
    assert sim.cell in cells and len(cells) > 100
    # every object can be reached: a teleport pose exists, and it is in view once its container is open
    session = new_session(scene)
    for object_id, obj in list(session.objects.items()):
        if obj["openable"]:
            session.controller.step(action="OpenObject", objectId=object_id, forceAction=True)
    session._refresh(session.controller.last_event.metadata)
    for object_id in list(session.objects):
        if session.objects[object_id]["objectType"] == "Floor":
            continue
        session.teleport(object_id)
        assert session.objects[object_id]["visible"], f"{scene}: {session.handle(object_id)} not in view"
