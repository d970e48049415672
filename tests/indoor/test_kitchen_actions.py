"""Every simulator action: what success changes, and that each refusal names why and changes nothing."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.kitchen.session import KitchenActionError, KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim
from ewa_mcp.envs.kitchen.vocabulary import PIECE_COUNT

from .conftest import new_session

SCENE = "FloorPlan12"  # holds every food, Pan, Pot, Knife, ButterKnife, Microwave, Toaster, CoffeeMachine


@pytest.fixture
def s() -> KitchenSession:
    return new_session(SCENE)


def sim(session: KitchenSession) -> KitchenSim:
    assert isinstance(session.controller, KitchenSim)
    return session.controller


def refused(session: KitchenSession, action: str, object_id: str | None = None, **args) -> str:
    """Run a raw AI2-THOR action that must fail; prove the kitchen is unchanged; return the message."""
    before = sim(session).snapshot()
    if object_id is not None:
        args["objectId"] = object_id
    event = sim(session).step(action=action, **args)
    assert event.metadata["lastActionSuccess"] is False
    assert event.metadata["errorMessage"]
    assert sim(session).snapshot() == before
    return event.metadata["errorMessage"]


def first(session: KitchenSession, object_type: str) -> str:
    return next(i for i, o in session.objects.items() if o["objectType"] == object_type)


def parent_type(session: KitchenSession, object_id: str) -> str | None:
    parent = session.parent_of(session.objects[object_id])
    return session.objects[parent]["objectType"] if parent else None


def hold(session: KitchenSession, object_id: str) -> None:
    """Get ``object_id`` into the hand the way an agent would."""
    if session.held_id is not None:
        session.teleport("CounterTop")
        session.put("CounterTop")
    hider = session.hidden_by(session.objects[object_id])
    if hider is not None:  # behind a door never opened, no name finds it: open the door first
        session.teleport(hider)
        session.open(hider)
    session.teleport(object_id)
    container = session.parent_of(session.objects[object_id])
    if container and session.objects[container]["openable"] and not session.objects[container]["isOpen"]:
        session.open(container)
    session.pickup(object_id)


# ------------------------------------------------------------------ navigation
def test_move_steps_a_grid_cell_and_walls_block(s):
    import math

    for _ in range(4):
        before = dict(s.agent["position"])
        heading = math.radians(s.agent["rotation"]["y"])
        try:
            s.move("ahead")
            break
        except KitchenActionError:
            s.rotate("right")
    else:
        pytest.fail("the agent could not move in any direction")
    after = s.agent["position"]
    assert after["x"] - before["x"] == pytest.approx(0.25 * round(math.sin(heading)))
    assert after["z"] - before["z"] == pytest.approx(0.25 * round(math.cos(heading)))
    # walk until something blocks: the refusal names it and the agent stays put
    for _ in range(100):
        try:
            s.move("ahead")
        except KitchenActionError as exc:
            assert "blocked" in str(exc)
            break
    else:
        pytest.fail("the agent walked through the kitchen wall")
    message = refused(s, "MoveAhead")
    assert "blocked" in message and ("wall" in message or "|" in message)


def test_move_back_and_sideways_undo_each_other(s):
    s.teleport("Fridge")
    for there, back in (("left", "right"), ("right", "left"), ("back", "ahead"), ("ahead", "back")):
        before = dict(s.agent["position"])
        try:
            s.move(there)
        except KitchenActionError:
            continue
        s.move(back)
        assert s.agent["position"] == before


def test_rotate_turns_ninety_degrees_and_bad_degrees_refused(s):
    start = s.agent["rotation"]["y"]
    s.rotate("right")
    assert s.agent["rotation"]["y"] == (start + 90) % 360
    s.rotate("left")
    s.rotate("left")
    assert s.agent["rotation"]["y"] == (start - 90) % 360
    assert "multiple of 90" in refused(s, "RotateRight", degrees=45)
    with pytest.raises(KitchenActionError, match="left or right"):
        s.rotate("up")


def test_teleport_refuses_unreachable_positions(s):
    counter = s.objects[first(s, "CounterTop")]
    c = counter["axisAlignedBoundingBox"]["center"]
    assert "not a reachable position" in refused(s, "TeleportFull", x=c["x"], y=0.9, z=c["z"], rotation=0)
    x, z = s.reachable[0]
    assert "multiple of 90" in refused(s, "TeleportFull", x=x, y=0.9, z=z, rotation=45)


def test_teleport_to_an_object_faces_it_within_reach(s):
    for kind in ("Fridge", "StoveKnob", "Knife", "SinkBasin"):
        object_id = first(s, kind)
        s.teleport(object_id)
        assert s.objects[object_id]["visible"], kind
        assert s.objects[object_id]["distance"] <= 1.5


# ------------------------------------------------------------------ pickup / put / drop
def test_pickup_moves_the_object_into_the_hand(s):
    knife = first(s, "Knife")
    old_parent = s.parent_of(s.objects[knife])
    hold(s, knife)
    obj = s.objects[knife]
    assert obj["isPickedUp"] and obj["parentReceptacles"] is None
    assert knife not in (s.objects[old_parent]["receptacleObjectIds"] or [])
    assert s.meta["inventoryObjects"] == [{"objectId": knife, "objectType": "Knife"}]


def test_pickup_refusals(s):
    counter = first(s, "CounterTop")
    assert "not pickupable" in refused(s, "PickupObject", counter, forceAction=True)
    assert "invalid" in refused(s, "PickupObject", "Apple|+09.99|+09.99|+09.99")
    assert "required" in refused(s, "PickupObject")
    far = max((o for o in s.objects.values() if o["pickupable"] and not o["visible"]
               and not (s.objects.get(s.parent_of(o) or "", {}).get("openable"))), key=lambda o: o["distance"])
    assert "reach is 1.5 m" in refused(s, "PickupObject", far["objectId"])
    inside = next(o for o in s.objects.values() if o["pickupable"] and s.parent_of(o)
                  and s.objects[s.parent_of(o)]["openable"])
    s.teleport(s.parent_of(inside))  # what a closed door hides has no name yet: go to the door
    assert "closed" in refused(s, "PickupObject", inside["objectId"])
    hold(s, first(s, "Knife"))
    assert "already holding" in refused(s, "PickupObject", first(s, "Bowl"), forceAction=True)


def test_put_places_the_held_object_and_refusals(s):
    assert "Nothing is in the agent's hand" in refused(s, "PutObject", first(s, "CounterTop"), forceAction=True)
    apple = first(s, "Apple")
    hold(s, apple)
    burner = first(s, "StoveBurner")
    assert "cannot be placed" in refused(s, "PutObject", burner, forceAction=True)
    assert "not a receptacle" in refused(s, "PutObject", apple, forceAction=True)
    fridge = first(s, "Fridge")
    s.teleport(fridge)
    assert "closed; open it first" in refused(s, "PutObject", fridge)
    s.open(fridge)
    s.put(fridge)
    assert parent_type(s, apple) == "Fridge" and not s.objects[apple]["isPickedUp"]
    assert s.objects[apple]["temperature"] == "Cold"
    assert apple in s.objects[fridge]["receptacleObjectIds"]
    bowl = first(s, "Bowl")
    hold(s, bowl)
    assert "itself" in refused(s, "PutObject", bowl, forceAction=True)


def test_a_burner_holds_one_vessel(s):
    pan, pot = first(s, "Pan"), first(s, "Pot")
    burners = [i for i, o in s.objects.items() if o["objectType"] == "StoveBurner"]
    occupied = [b for b in burners if s.objects[b]["receptacleObjectIds"]]
    target = occupied[0] if occupied else burners[0]
    if not occupied:
        hold(s, pan)
        s.teleport(target)
        s.put(target)
    vessel = pot if parent_type(s, pan) == "StoveBurner" and s.parent_of(s.objects[pan]) == target else pan
    hold(s, vessel)
    s.teleport(target)
    assert "full" in refused(s, "PutObject", target)


def test_drop_lets_go_onto_the_surface_ahead_or_the_floor(s):
    assert "Nothing" in refused(s, "DropHandObject")
    spoon = first(s, "Spoon")
    hold(s, spoon)
    s.teleport("CounterTop")
    report = s.drop()
    assert not s.objects[spoon]["isPickedUp"] and s.parent_of(s.objects[spoon]) is not None
    assert report.notes and "landed" in report.notes[0]


# ------------------------------------------------------------------ open / close / toggle
def test_open_and_close(s):
    fridge = first(s, "Fridge")
    s.teleport(fridge)
    assert "already closed" in refused(s, "CloseObject", fridge)
    s.open(fridge)
    assert s.objects[fridge]["isOpen"] and s.objects[fridge]["openness"] == 1.0
    assert "already open" in refused(s, "OpenObject", fridge)
    s.close(fridge)
    assert not s.objects[fridge]["isOpen"]
    assert "not openable" in refused(s, "OpenObject", first(s, "CounterTop"), forceAction=True)


def test_contents_of_a_closed_receptacle_become_visible_when_opened(s):
    inside = next(o for o in s.objects.values() if o["pickupable"] and s.parent_of(o)
                  and s.objects[s.parent_of(o)]["objectType"] in ("Fridge", "Cabinet", "Drawer"))
    with pytest.raises(KitchenActionError, match="no object in sight has the id"):
        s.teleport(inside["objectId"])  # behind a door never opened: not known to be there
    s.teleport(s.parent_of(inside))
    assert not s.objects[inside["objectId"]]["visible"]
    s.open(s.parent_of(inside))
    assert s.objects[inside["objectId"]]["visible"]
    s.teleport(inside["objectId"])  # once seen, its id resolves


def test_stove_knob_lights_its_burner_and_cooks_what_is_in_the_pan(s):
    burner_pan = next(((b, c) for b, o in s.objects.items() if o["objectType"] == "StoveBurner"
                       for c in o["receptacleObjectIds"] or [] if s.objects[c]["objectType"] in ("Pan", "Pot")), None)
    if burner_pan is None:
        pan = first(s, "Pan")
        hold(s, pan)
        burner = first(s, "StoveBurner")
        s.teleport(burner)
        s.put(burner)
        burner_pan = (burner, pan)
    burner, pan = burner_pan
    knob = next(i for i, o in s.objects.items() if burner in (o["controlledObjects"] or []))
    s.teleport(burner)
    message = refused(s, "ToggleObjectOn", burner)
    assert "not toggleable" in message and knob in message
    egg = first(s, "Egg")
    hold(s, egg)
    s.teleport(pan)
    s.put(pan)
    assert not s.objects[egg]["isCooked"]
    s.teleport(knob)
    report = s.toggle(knob, True)
    assert s.objects[knob]["isToggled"] and s.objects[burner]["isToggled"]
    assert s.objects[egg]["isCooked"] and s.objects[egg]["temperature"] == "Hot"
    assert any("cooked" in e for e in report.effects)
    assert "already on" in refused(s, "ToggleObjectOn", knob)
    # food put into a pan on a lit burner cooks as it lands
    potato = first(s, "Potato")
    hold(s, potato)
    s.teleport(pan)
    s.put(pan)
    assert s.objects[potato]["isCooked"]
    s.teleport(knob)
    s.toggle(knob, False)
    assert not s.objects[burner]["isToggled"]


def test_microwave_runs_only_closed_cooks_and_cannot_open_while_running(s):
    microwave = first(s, "Microwave")
    tomato = first(s, "Tomato")
    hold(s, tomato)
    s.teleport(microwave)
    s.open(microwave)
    assert "close it before" in refused(s, "ToggleObjectOn", microwave)
    s.put(microwave)
    s.close(microwave)
    s.toggle(microwave, True)
    assert s.objects[tomato]["isCooked"]
    assert "turn it off" in refused(s, "OpenObject", microwave)
    s.toggle(microwave, False)
    s.open(microwave)


def test_toaster_toasts_bread_slices_only(s):
    toaster = first(s, "Toaster")
    bread = first(s, "Bread")
    hold(s, bread)
    s.teleport(toaster)
    assert "cannot be placed" in refused(s, "PutObject", toaster)
    s.teleport("CounterTop")
    s.put("CounterTop")
    hold(s, first(s, "Knife"))
    s.teleport(bread)
    s.slice(bread)
    piece = next(i for i, o in s.objects.items() if o["objectType"] == "BreadSliced")
    hold(s, piece)
    s.teleport(toaster)
    s.put(toaster)
    s.toggle(toaster, True)
    assert s.objects[piece]["isCooked"]


def test_coffee_machine_fills_a_mug(s):
    machine = first(s, "CoffeeMachine")
    mug = first(s, "Mug")
    if s.parent_of(s.objects[mug]) != machine:
        hold(s, mug)
        s.teleport(machine)
        s.put(machine)
    s.teleport(machine)
    s.toggle(machine, True)
    assert s.objects[mug]["isFilledWithLiquid"] and s.objects[mug]["fillLiquid"] == "coffee"


# ------------------------------------------------------------------ slice / cook / break
def test_slice_needs_a_knife_and_makes_pieces(s):
    tomato = first(s, "Tomato")
    s.teleport(tomato)
    container = s.parent_of(s.objects[tomato])
    if s.objects[container]["openable"]:
        s.open(container)
    assert "Knife or ButterKnife" in refused(s, "SliceObject", tomato)
    hold(s, first(s, "Knife"))
    s.teleport(tomato)
    if s.objects[container]["openable"] and not s.objects[container]["isOpen"]:
        s.open(container)
    report = s.slice(tomato)
    assert tomato not in s.objects
    pieces = [o for o in s.objects.values() if o["objectType"] == "TomatoSliced"]
    assert len(pieces) == PIECE_COUNT["Tomato"]
    assert all(p["sourceType"] == "Tomato" and p["sourceObjectId"] == tomato and p["isSliced"] for p in pieces)
    assert all(p["objectId"].startswith(tomato + "|TomatoSliced_") for p in pieces)
    assert all(s.parent_of(p) == container for p in pieces)
    assert "TomatoSliced_1–5" in report.effects[0]
    assert "not sliceable" in refused(s, "SliceObject", pieces[0]["objectId"], forceAction=True)


def test_cracking_an_egg_makes_one_cracked_egg(s):
    hold(s, first(s, "ButterKnife"))
    egg = first(s, "Egg")
    s.teleport(egg)
    container = s.parent_of(s.objects[egg])
    if s.objects[container]["openable"]:
        s.open(container)
    s.slice(egg)
    cracked = [o for o in s.objects.values() if o["objectType"] == "EggCracked"]
    assert len(cracked) == 1 and cracked[0]["sourceType"] == "Egg"


def test_cook_object_is_instant_and_refusals(s):
    potato = first(s, "Potato")
    container = s.parent_of(s.objects[potato])
    s.teleport(container if s.objects[container]["openable"] else potato)
    if s.objects[container]["openable"]:
        s.open(container)
    s.cook(potato)
    assert s.objects[potato]["isCooked"]
    assert "already cooked" in refused(s, "CookObject", potato)
    assert "not cookable" in refused(s, "CookObject", first(s, "Knife"), forceAction=True)


def test_break_object(s):
    plate = first(s, "Plate")
    assert "not breakable" in refused(s, "BreakObject", first(s, "Knife"), forceAction=True)
    sim(s).step(action="BreakObject", objectId=plate, forceAction=True)
    assert sim(s).last_event.metadata["lastActionSuccess"]
    assert "already broken" in refused(s, "BreakObject", plate, forceAction=True)


def test_unknown_actions_fail_with_invalid_action_code(s):
    before = sim(s).snapshot()
    event = sim(s).step(action="Fly")
    assert event.metadata["errorCode"] == "InvalidAction" and sim(s).snapshot() == before


# ------------------------------------------------------------------ scene edits
def test_initial_random_spawn_is_seeded(s):
    a = new_session(SCENE, seed=3)
    b = new_session(SCENE, seed=3)
    c = new_session(SCENE, seed=4)

    def placement(session: KitchenSession) -> list[tuple[str, str | None]]:
        return [(o["objectType"], session.parent_of(o)) for o in session.objects.values() if o["pickupable"]]

    assert placement(a) == placement(b)
    assert placement(a) != placement(c)
    assert placement(a) != placement(s)


def test_create_object_at_location_lands_on_a_surface(s):
    counter = s.objects[first(s, "CounterTop")]
    c = counter["axisAlignedBoundingBox"]["center"]
    event = sim(s).step(action="CreateObjectAtLocation", objectType="Potato", position={"x": c["x"], "y": 1.0, "z": c["z"]})
    assert event.metadata["lastActionSuccess"]
    new_id = event.metadata["actionReturn"]
    new = next(o for o in event.metadata["objects"] if o["objectId"] == new_id)
    assert new["parentReceptacles"][0] == counter["objectId"]
    assert "cannot be created" in refused(s, "CreateObjectAtLocation", objectType="Fridge",
                                          position={"x": c["x"], "y": 1.0, "z": c["z"]})
