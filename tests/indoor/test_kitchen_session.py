"""Object references, the observation, deliveries from the shop and the final state."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.kitchen.commands import CommandError, parse_command
from ewa_mcp.envs.kitchen.observe import build_observation
from ewa_mcp.envs.kitchen.session import KitchenActionError

from .conftest import new_session


def ids_of(session, object_type):
    return [i for i, o in session.objects.items() if o["objectType"] == object_type]


def look_into(session, object_id):
    """Open the closed receptacle that hides ``object_id`` from the agent, as an agent must before naming it."""
    hider = session.hidden_by(session.objects[object_id])
    if hider is not None:
        session.teleport(session.handle(hider))
        session.open(session.handle(hider))
    assert session.hidden_by(session.objects[object_id]) is None


# ------------------------------------------------------------------ references
def test_handles_are_per_type_and_stable():
    s = new_session("FloorPlan2")
    tomatoes = ids_of(s, "Tomato")
    assert [s.handle(i) for i in tomatoes] == ["Tomato_1", "Tomato_2"]
    assert s.resolve("Tomato_2", "interact") == (tomatoes[1], [])
    assert s.resolve("tomato_2", "interact")[0] == tomatoes[1]
    assert s.resolve(tomatoes[1], "interact") == (tomatoes[1], [])
    # Tomato_1 lies in the closed fridge, not yet looked into: the list names only what the agent has seen
    with pytest.raises(KitchenActionError, match=r"no Tomato_3 in sight; the Tomato objects you have seen are: "
                                                 r"Tomato_2\. Closed cabinets, drawers and the fridge"):
        s.resolve("Tomato_3", "interact")
    with pytest.raises(KitchenActionError, match="no object in sight has the id"):
        s.resolve("Tomato|+09.00|+00.00|+00.00", "interact")


def test_exact_types_only():
    s = new_session("FloorPlan2")
    with pytest.raises(KitchenActionError, match="Did you mean Egg"):
        s.resolve("Eggplant", "interact")
    # Knife is not ButterKnife: FloorPlan2 has only a ButterKnife
    assert not ids_of(s, "Knife") and ids_of(s, "ButterKnife")
    with pytest.raises(KitchenActionError, match="No Knife in sight"):
        s.resolve("Knife", "teleport")
    # "Pot" never means Potato (FloorPlan2's Pot is in a cabinet: look inside first)
    assert s.hidden_by(s.objects[ids_of(s, "Pot")[0]]) is not None
    look_into(s, ids_of(s, "Pot")[0])
    assert s.objects[s.resolve("Pot", "teleport")[0]]["objectType"] == "Pot"


def test_bare_type_rule():
    s = new_session("FloorPlan2")  # Tomato_1 is in the closed fridge, Tomato_2 on CounterTop_1
    a, b = ids_of(s, "Tomato")
    # Tomato_1 is behind the fridge door, never opened: only Tomato_2 is known, so teleport takes it, no note
    assert s.hidden_by(s.objects[a]) is not None
    assert s.resolve("Tomato", "teleport") == (b, [])
    s.teleport("Fridge")  # at the shut door, Tomato still names the only one seen
    assert s.resolve("Tomato", "interact") == (b, [])
    s.open("Fridge")
    assert s.resolve("Tomato", "interact") == (a, [])  # the only one in reach: no note needed
    # interacting needs one in reach; otherwise the error lists where each one is. Seen open once, the
    # fridge's tomato stays known behind the shut door, and is listed there
    s.close("Fridge")
    with pytest.raises(KitchenActionError, match=r"no Tomato is within reach; they are: .*Tomato_1 in/on Fridge_1 \(closed\)"):
        s.resolve("Tomato", "interact")
    # both known now: teleport picks the nearest and says which, listing the other
    nearest = min((a, b), key=lambda t: s.objects[t]["distance"])
    other = b if nearest == a else a
    chosen, notes = s.resolve("Tomato", "teleport")
    assert chosen == nearest and "nearest" in notes[0] and s.handle(other) in notes[0]
    s.teleport("Fridge")
    s.open("Fridge")
    s.teleport("Tomato_2")
    assert s.resolve("Tomato", "interact")[0] == b
    # several in reach: the nearest, and the reply names the others
    look_into(s, ids_of(s, "ButterKnife")[0])  # in a drawer: a name finds it once the drawer was opened
    s.teleport("ButterKnife")
    s.pickup("ButterKnife")
    s.teleport("Tomato_2")
    s.slice("Tomato_2")
    piece, notes = s.resolve("TomatoSliced", "interact")
    visible = sorted((o["distance"], i) for i, o in s.objects.items() if o["objectType"] == "TomatoSliced" and o["visible"])
    assert len(visible) > 1 and piece == visible[0][1] and "in reach (others:" in notes[0]
    # a type with a single instance always resolves to it, whatever the case
    fridge = ids_of(s, "Fridge")[0]
    assert s.resolve("fridge", "interact") == (fridge, [])


def test_sliced_food_and_pieces_are_addressable():
    s = new_session("FloorPlan12")
    s.teleport("Knife")
    s.pickup("Knife")
    s.teleport("Lettuce")
    lettuce = s.resolve("Lettuce", "interact")[0]
    container = s.parent_of(s.objects[lettuce])
    if s.objects[container]["openable"]:
        s.open(container)
    s.slice("Lettuce")
    with pytest.raises(KitchenActionError, match="no longer exists"):
        s.resolve("Lettuce_1", "interact")
    piece, notes = s.resolve("Lettuce", "interact")
    assert s.objects[piece]["objectType"] == "LettuceSliced" and "cut into LettuceSliced" in notes[0]
    assert s.resolve("LettuceSliced_3", "interact")[0] in s.objects
    s.teleport("CounterTop")
    s.put("CounterTop")
    s.teleport("LettuceSliced_2")
    s.pickup("LettuceSliced_2")
    assert s.handle(s.held_id) == "LettuceSliced_2"


def test_action_strings():
    assert parse_command("Teleport [Pan]").target == "Pan"
    assert parse_command("pickupobject Apple_1").action == "PickupObject"
    assert parse_command("toggle_on StoveKnob_2").action == "ToggleObjectOn"
    with pytest.raises(CommandError, match="needs an object"):
        parse_command("PickupObject")
    with pytest.raises(CommandError, match="takes no object"):
        parse_command("MoveAhead Fridge")
    with pytest.raises(CommandError, match="unknown action 'Fly'"):
        parse_command("Fly Apple")
    s = new_session("FloorPlan12")
    report = s.run("Teleport [Fridge]")
    assert report.action == "Teleport" and s.objects[report.target]["objectType"] == "Fridge"
    with pytest.raises(KitchenActionError, match="unknown action"):
        s.run("Jump")


# ------------------------------------------------------------------ observation
def test_observation_shows_pose_holding_reach_and_states():
    s = new_session("FloorPlan12")
    s.teleport("Fridge")
    s.open("Fridge")
    text, data = build_observation(s, "text")
    lines = text.splitlines()
    assert lines[0].startswith("Kitchen FloorPlan12 (sim). You stand at") and "holding nothing" in lines[0]
    assert lines[1] == "Done: OpenObject Fridge_1."
    assert "Fridge_1" in next(line for line in lines if line.startswith("In reach:"))
    assert any(line.startswith("- Fridge_1 (open)") for line in lines)
    assert any("StoveBurner_1 (off, knob StoveKnob_" in line for line in lines)
    assert "(closed" in text  # cabinets and drawers show their state
    assert data["in_reach"] and data["holding"] is None
    fridge = next(o for o in data["objects"] if o["handle"] == "Fridge_1")
    assert fridge["states"] == ["open"] and fridge["visible"] is True
    vision_text, vision_data = build_observation(s, "vision")
    assert "In reach" not in vision_text and "objects" not in vision_data


def test_an_appliance_that_holds_nothing_says_so():
    """Appliances are listed even when empty; without a mark a closed, empty fridge read as 'not looked into'
    (play-testers opened it to find out). One that holds something lists it in braces instead."""
    s = new_session("FloorPlan12")  # its fridge starts empty
    fridge = s.by_handle["fridge_1"]
    assert not any(fridge in (obj.get("parentReceptacles") or []) for obj in s.objects.values())
    s.teleport("Fridge_1")
    s.open("Fridge_1")
    s.close("Fridge_1")  # looked into once: its emptiness is known
    text, _ = build_observation(s, "text")
    line = next(line for line in text.splitlines() if line.startswith("- Fridge_1"))
    assert "{empty}" in line and "(closed)" in line
    assert "Fridge_1" not in next((ln for ln in text.splitlines() if ln.startswith("Empty:")), "")
    full = new_session("FloorPlan5")
    full.teleport("Fridge_1")
    full.open("Fridge_1")
    text, _ = build_observation(full, "text")
    line = next(line for line in text.splitlines() if line.startswith("- Fridge_1"))
    assert "{empty}" not in line and "{" in line


def test_held_object_and_its_contents_are_shown():
    s = new_session("FloorPlan12")
    look_into(s, ids_of(s, "Plate")[0])  # in a cabinet
    s.teleport("Plate")
    s.pickup("Plate")
    text, _ = build_observation(s, "text")
    assert "holding Plate_1 {}" in text.splitlines()[0]


# ------------------------------------------------------------------ deliveries
def order(items, order_id="o1", fulfilment="delivery"):
    return {"site": "shop", "type": "order_placed",
            "order": {"order_id": order_id, "store_id": "s1", "fulfilment": fulfilment, "items": items}}


def test_only_an_order_for_delivery_reaches_the_kitchen():
    s = new_session("FloorPlan3")  # no Potato here
    events = [order([{"product_id": "p1", "kitchen_type": "Potato", "quantity": 1}], "o1", fulfilment="pickup")]
    notes = s.receive_deliveries(events)
    assert not ids_of(s, "Potato") and s.final_state()["deliveries"] == []
    assert notes == ["Order o1 (Potato) is for pickup at the store, so nothing arrives in this kitchen; to get "
                     "groceries here, order them with 'Deliver to my kitchen' at checkout."]
    # An order without a fulfilment (not a delivery) delivers nothing either; a delivery order does.
    events.append({"site": "shop", "type": "order_placed",
                   "order": {"order_id": "o2", "items": [{"product_id": "p1", "kitchen_type": "Potato"}]}})
    assert "nothing arrives" in s.receive_deliveries(events)[0] and not ids_of(s, "Potato")
    events.append(order([{"product_id": "p1", "kitchen_type": "Potato", "quantity": 1}], "o3"))
    assert s.receive_deliveries(events)[0].startswith("A delivery arrived: Potato_1 on CounterTop_")


def test_groceries_arrive_on_a_counter_once():
    s = new_session("FloorPlan3")  # no Potato, no Bread here
    assert not ids_of(s, "Potato")
    events = [{"site": "shop", "type": "page_view"},
              order([{"product_id": "p1", "kitchen_type": "Potato", "size": "large", "quantity": 2},
                     {"product_id": "p2", "quantity": 1},
                     {"product_id": "p3", "kitchen_type": "Cheese", "quantity": 1}])]
    notes = s.receive_deliveries(events)
    potatoes = ids_of(s, "Potato")
    assert len(potatoes) == 2
    assert all(s.objects[s.parent_of(s.objects[p])]["objectType"] == "CounterTop" for p in potatoes)
    assert notes[0].startswith("A delivery arrived: Potato_1 on CounterTop_")
    assert any("Cheese" in n for n in notes)
    # the same events again deliver nothing new; a new order does
    assert s.receive_deliveries(events) == []
    events.append(order([{"product_id": "p4", "kitchen_type": "bread", "quantity": 1}], "o2"))
    assert s.receive_deliveries(events)[0].startswith("A delivery arrived: Bread_1")
    state = s.final_state()
    kinds = [(d["kitchen_type"], d["status"], len(d["objectIds"])) for d in state["deliveries"]]
    assert kinds == [("Potato", "delivered", 2), ("Cheese", "not_a_kitchen_object", 0), ("Bread", "delivered", 1)]
    # the observation says so once
    text, _ = build_observation(s, "text")
    assert "A delivery arrived: Potato_1" in text
    assert "A delivery arrived" not in build_observation(s, "text")[0]


def test_deliveries_are_deterministic():
    events = [order([{"product_id": "p1", "kitchen_type": "Potato", "quantity": 1}])]
    a, b = new_session("FloorPlan3"), new_session("FloorPlan3")
    a.receive_deliveries(events)
    b.receive_deliveries(events)
    assert a.final_state()["deliveries"] == b.final_state()["deliveries"]


# ------------------------------------------------------------------ final state
def test_final_state_contract():
    s = new_session("FloorPlan12")
    s.teleport("Knife")
    s.pickup("Knife")
    s.teleport("Tomato")
    tomato = s.resolve("Tomato", "interact")[0]
    container = s.parent_of(s.objects[tomato])
    if s.objects[container]["openable"]:
        s.open(container)
    s.slice("Tomato")
    state = s.final_state()
    assert state["backend"] == "sim" and state["scene"] == "FloorPlan12" and state["held"] == s.held_id
    assert set(state) >= {"objects", "agent", "held", "deliveries"}
    required = {"objectType", "objectId", "parentReceptacles", "isSliced", "isCooked", "isBroken", "isToggled",
                "isOpen", "isPickedUp", "handle"}
    for obj in state["objects"]:
        assert required <= set(obj)
    pieces = [o for o in state["objects"] if o["objectType"] == "TomatoSliced"]
    assert pieces and all(p["sourceType"] == "Tomato" and p["parentReceptacles"][0] == container for p in pieces)
    knife = next(o for o in state["objects"] if o["objectId"] == s.held_id)
    assert knife["isPickedUp"] and knife["parentReceptacles"] is None


def test_a_missing_type_is_called_buyable_only_when_the_shop_sells_it():
    """The shop sells food only: a missing Pan is not 'bought on the shopping site'; the error names what to
    use instead when the kitchen has it, and says plainly that the shop does not sell it otherwise."""
    from ewa_mcp.envs.kitchen.vocabulary import SHOP_SOLD_TYPES
    from ewa_mcp.websites.shop.catalog import load_products

    assert SHOP_SOLD_TYPES == {p.kitchen_type for p in load_products() if p.kitchen_type}

    s = new_session("FloorPlan27")  # a Pot but no Pan, no SaltShaker; the Pot is in a closed cabinet
    assert not ids_of(s, "Pan") and ids_of(s, "Pot")
    pot = ids_of(s, "Pot")[0]
    cabinet = s.hidden_by(s.objects[pot])
    assert cabinet is not None
    # the stand-in is offered only once seen: a Pot behind a door not yet opened is not known to be there
    with pytest.raises(KitchenActionError) as err:
        s.resolve("Pan", "teleport")
    assert "bought" not in str(err.value) and "Pot" not in str(err.value) and "may hold one" in str(err.value)
    s.teleport(s.handle(cabinet))
    s.open(s.handle(cabinet))
    with pytest.raises(KitchenActionError) as err:
        s.resolve("Pan", "teleport")
    # other doors still unopened: the Pan may yet turn up, so the stand-in is a fallback, not a verdict
    assert s.unlooked_receptacles()
    assert "bought" not in str(err.value) and "If none turns up, use a Pot instead." in str(err.value)
    with pytest.raises(KitchenActionError) as err:
        s.resolve("SaltShaker", "teleport")
    assert "bought" not in str(err.value) and "does not sell" in str(err.value)
    s = new_session("FloorPlan3")  # no Potato: food the shop sells
    with pytest.raises(KitchenActionError, match="can be bought on the shopping site"):
        s.resolve("Potato", "teleport")


# ------------------------------------------------------------------ what is seen: closed doors hide contents
def _fridge_line(text: str) -> str:
    return next(line for line in text.splitlines() if line.startswith("- Fridge_1"))


def test_a_closed_fridge_never_opened_hides_its_contents_everywhere():
    """Issue 26, principle 4: the first observation shows what is seen. FloorPlan2's fridge holds Tomato_1;
    until the fridge is opened neither the text, the data, "In reach" nor the Empty line tells of it."""
    s = new_session("FloorPlan2")
    fridge = s.by_handle["fridge_1"]
    inside = [s.handle(i) for i, o in s.objects.items() if fridge in (o.get("parentReceptacles") or [])]
    assert "Tomato_1" in inside
    text, data = build_observation(s, "text")
    assert _fridge_line(text).startswith("- Fridge_1 (closed) {not looked inside: open it to see}")
    for handle in inside:
        assert handle not in text
        assert handle not in {o["handle"] for o in data["objects"]}
    assert not set(inside) & set(data["in_reach"])
    assert next(o for o in data["objects"] if o["handle"] == "Fridge_1")["looked_inside"] is False
    empty = next((ln for ln in text.splitlines() if ln.startswith("Empty:")), "")
    assert "(closed)" not in empty  # no closed cabinet is called empty before it is looked into
    unlooked = next(ln for ln in text.splitlines() if ln.startswith("Not looked inside"))
    assert "Cabinet_" in unlooked and "Fridge_1" not in unlooked  # the fridge has its own line
    # standing at the fridge with its door shut shows nothing inside either
    s.teleport("Fridge_1")
    text, data = build_observation(s, "text")
    assert "Tomato_1" not in text and "Tomato_1" not in data["in_reach"]


def test_opening_shows_the_contents_and_closing_again_keeps_them_known():
    s = new_session("FloorPlan2")
    s.teleport("Fridge_1")
    s.open("Fridge_1")
    text, data = build_observation(s, "text")
    assert "Tomato_1" in _fridge_line(text) and "(open)" in _fridge_line(text)
    assert "Tomato_1" in {o["handle"] for o in data["objects"]}
    s.close("Fridge_1")
    text, data = build_observation(s, "text")
    line = _fridge_line(text)
    assert "(closed)" in line and "Tomato_1" in line and "not looked inside" not in line
    tomato = next(o for o in data["objects"] if o["handle"] == "Tomato_1")
    assert tomato["parent"] == "Fridge_1"
    # a new episode forgets what was seen
    s.reset()
    text, _ = build_observation(s, "text")
    assert "not looked inside" in _fridge_line(text) and "Tomato_1" not in text


def test_a_cabinet_looked_into_and_found_empty_is_listed_empty():
    s = new_session("FloorPlan2")
    before = s.unlooked_receptacles()
    cabinet = next(h for h in ("Cabinet_%d" % n for n in range(1, 40))
                   if h.lower() in s.by_handle and not s.objects[s.by_handle[h.lower()]].get("receptacleObjectIds")
                   and s.objects[s.by_handle[h.lower()]].get("openable"))
    s.teleport(cabinet)
    s.open(cabinet)
    s.close(cabinet)
    text, data = build_observation(s, "text")
    empty = next(ln for ln in text.splitlines() if ln.startswith("Empty:"))
    assert "(closed)" in empty
    assert next(o for o in data["objects"] if o["handle"] == cabinet)["looked_inside"] is True
    assert len(s.unlooked_receptacles()) == len(before) - 1 and cabinet not in s.unlooked_receptacles()


def test_picking_up_from_a_closed_receptacle_says_to_open_it():
    s = new_session("FloorPlan2")
    s.teleport("Fridge_1")
    s.open("Fridge_1")
    s.close("Fridge_1")
    with pytest.raises(KitchenActionError, match="closed Fridge_1"):
        s.pickup("Tomato_1")


def test_the_nearest_of_many_names_how_many_others_it_leaves_out():
    """Naming a type many objects have picks the nearest and lists five others; a longer list says how many
    more there are (a vision player read six cabinet handles as all of them and hunted the rest by number)."""
    s = new_session("FloorPlan27")
    cabinets = ids_of(s, "Cabinet")
    assert len(cabinets) > 6
    _, notes = s.resolve("Cabinet", "teleport")
    assert notes[0].endswith(f"and {len(cabinets) - 6} more); name a handle to choose.")
