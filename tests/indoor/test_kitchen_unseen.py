"""Names and closed doors (issue 26, principle 4): a tool call neither finds nor rules out what lies behind a
door the agent has not opened. FloorPlan8's only Egg is in its closed fridge; FloorPlan6 has no Egg at all:
every name-taking tool must answer the two kitchens alike, and find the egg once the fridge has been opened."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.kitchen.session import KitchenActionError, KitchenSession

from .conftest import new_session

HIDDEN_EGG, NO_EGG = "FloorPlan8", "FloorPlan6"


def ids_of(session: KitchenSession, object_type: str) -> list[str]:
    return [i for i, o in session.objects.items() if o["objectType"] == object_type]


def refusal(session: KitchenSession, name: str, args: dict) -> str:
    """The error a table action gives, checking that it changed nothing."""
    pose, held = dict(session.agent["position"]), session.held_id
    with pytest.raises(KitchenActionError) as err:
        session.perform(name, args)
    assert session.agent["position"] == pose and session.held_id == held
    return str(err.value)


def test_the_scenes_are_what_the_tests_need():
    hidden, none = new_session(HIDDEN_EGG), new_session(NO_EGG)
    eggs = ids_of(hidden, "Egg")
    assert len(eggs) == 1 and hidden.objects[hidden.hidden_by(hidden.objects[eggs[0]])]["objectType"] == "Fridge"
    assert not ids_of(none, "Egg")


@pytest.mark.parametrize("name,args", [
    ("teleport", {"object": "Egg"}),
    ("pickup", {"object": "Egg"}),
    ("open", {"object": "Egg"}),
    ("close", {"object": "Egg"}),
    ("slice", {"object": "Egg"}),
    ("cook", {"object": "Egg"}),
    ("break", {"object": "Egg"}),
    ("toggle", {"object": "Egg", "state": "on"}),
    ("teleport", {"object": "EggCracked"}),  # the piece's name: nothing to crack into it is known either
])
def test_a_hidden_egg_is_neither_found_nor_denied(name, args):
    hidden, none = new_session(HIDDEN_EGG), new_session(NO_EGG)
    reply = refusal(hidden, name, args)
    assert reply == refusal(none, name, args)
    kind = args["object"]
    assert reply.startswith(f"No {kind} in sight: you have seen none in this kitchen. Closed cabinets, drawers "
                            "and the fridge you have not looked into may hold one: open them with kitchen_open")
    assert "there is no" not in reply and "Fridge" not in reply


def test_the_action_string_form_answers_alike():
    hidden, none = new_session(HIDDEN_EGG), new_session(NO_EGG)
    for command in ("Teleport Egg", "PickupObject [Egg]", "BreakObject Egg"):
        with pytest.raises(KitchenActionError) as a:
            hidden.run(command)
        with pytest.raises(KitchenActionError) as b:
            none.run(command)
        assert str(a.value) == str(b.value) and "No Egg in sight" in str(a.value)


def test_a_hidden_receptacle_is_no_place_to_put_things():
    s = new_session("FloorPlan3")  # its Bowls are all in closed cabinets
    assert ids_of(s, "Bowl") and all(s.hidden_by(s.objects[b]) for b in ids_of(s, "Bowl"))
    tomato = next(i for i in ids_of(s, "Tomato") if s.hidden_by(s.objects[i]) is None)
    s.teleport(s.handle(tomato))
    s.pickup(s.handle(tomato))
    reply = refusal(s, "put", {"receptacle": "Bowl"})
    assert reply.startswith("No Bowl in sight") and "may hold one" in reply


def test_a_hidden_objects_handle_and_id_answer_as_names_of_nothing():
    s = new_session(HIDDEN_EGG)
    egg = ids_of(s, "Egg")[0]
    assert s.handle(egg) == "Egg_1"
    by_handle = refusal(s, "teleport", {"object": "Egg_1"})
    assert by_handle == refusal(s, "teleport", {"object": "Egg_2"}).replace("Egg_2", "Egg_1")
    assert by_handle.startswith("no Egg_1 in sight; the Egg objects you have seen are: none.")
    by_id = refusal(s, "pickup", {"object": egg})
    fake = "Egg|+09.00|+00.00|+09.00"
    assert by_id == refusal(s, "pickup", {"object": fake}).replace(fake, egg)
    assert by_id.startswith("no object in sight has the id")


def test_a_typo_still_gets_the_list_of_types():
    s = new_session(HIDDEN_EGG)
    reply = refusal(s, "teleport", {"object": "Eggs"})
    assert "is not an object type" in reply and "Did you mean Egg" in reply


def test_opening_the_fridge_makes_the_egg_resolve_and_closing_keeps_it_known():
    s = new_session(HIDDEN_EGG)
    egg = ids_of(s, "Egg")[0]
    s.teleport("Fridge")
    with pytest.raises(KitchenActionError, match="No Egg in sight"):
        s.resolve("Egg", "interact")  # standing at the shut door is not looking inside
    s.open("Fridge")
    assert s.resolve("Egg", "interact") == (egg, [])
    assert s.resolve("Egg_1", "teleport") == (egg, []) and s.resolve(egg, "teleport") == (egg, [])
    s.close("Fridge")
    s.teleport("Sink")
    assert s.resolve("Egg", "teleport") == (egg, [])
    report = s.teleport("Egg")
    assert report.target == egg and any("closed Fridge_1" in n for n in report.notes)
    s.open("Fridge")
    s.pickup("Egg")
    assert s.held_id == egg
    s.reset()  # a new episode has seen nothing
    with pytest.raises(KitchenActionError, match="No Egg in sight"):
        s.resolve("Egg", "teleport")


def test_once_every_door_was_opened_the_reply_rules_out():
    """The hint names closed doors only while some are unopened (the observation lists them too): a kitchen
    looked through says plainly that it has none."""
    s = new_session(NO_EGG)
    for _ in range(60):
        todo = s.unlooked_receptacles()
        if not todo:
            break
        s.teleport(todo[0])
        s.open(todo[0])
    assert not s.unlooked_receptacles()
    reply = refusal(s, "teleport", {"object": "Egg"})
    assert reply == "No Egg in sight: you have seen none in this kitchen. It can be bought on the shopping site; " \
                    "deliveries arrive on a CounterTop."
