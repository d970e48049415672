"""Random action sequences keep the kitchen's invariants (hypothesis)."""

from __future__ import annotations

from collections import Counter

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ewa_mcp.envs.kitchen.session import KitchenActionError, KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim
from ewa_mcp.envs.kitchen.vocabulary import PIECE_COUNT

from .conftest import new_session

VERBS = ["teleport", "teleport", "pickup", "pickup", "put", "put", "drop", "open", "close", "slice", "slice",
         "cook", "toggle_on", "toggle_off", "break", "grab_knife", "move_ahead", "move_left", "rotate_right"]
# the property an object needs for a verb to have a chance of succeeding
SUITS = {"pickup": "pickupable", "put": "receptacle", "open": "openable", "close": "openable", "slice": "sliceable",
         "cook": "cookable", "toggle_on": "toggleable", "toggle_off": "toggleable", "break": "breakable"}
step = st.tuples(st.sampled_from(VERBS), st.integers(min_value=0, max_value=10_000))


def act(s: KitchenSession, verb: str, index: int) -> None:
    ids = sorted(s.objects)
    ref = ids[index % len(ids)]
    # mostly pick an object in reach that suits the verb, sometimes any object (to exercise refusals)
    suitable = [i for i in ids if s.objects[i]["visible"] and s.objects[i].get(SUITS.get(verb, ""), True)]
    if suitable and index % 4:
        ref = suitable[index % len(suitable)]
    if verb == "teleport":
        s.teleport(ref)
    elif verb == "grab_knife":
        knives = [i for i in ids if s.objects[i]["objectType"] in ("Knife", "ButterKnife")]
        if s.held_id is None and knives:
            s.teleport(knives[0])
            container = s.parent_of(s.objects[knives[0]])
            if container and s.objects[container]["openable"] and not s.objects[container]["isOpen"]:
                s.open(container)
            s.pickup(knives[0])
    elif verb == "pickup":
        s.pickup(ref)
    elif verb == "put":
        s.put(ref)
    elif verb == "drop":
        s.drop()
    elif verb == "open":
        s.open(ref)
    elif verb == "close":
        s.close(ref)
    elif verb == "slice":
        s.slice(ref)
    elif verb == "cook":
        s.cook(ref)
    elif verb == "break":
        s.break_(ref)
    elif verb.startswith("toggle"):
        s.toggle(ref, verb == "toggle_on")
    elif verb.startswith("move"):
        s.move(verb.split("_")[1])
    else:
        s.rotate("right")


def check_invariants(sim: KitchenSim, meta: dict) -> None:
    objects = {o.object_id: o for o in sim.objects}
    # each object is in exactly one place: the hand, or the children of exactly one receptacle
    listed = Counter(c.object_id for o in sim.objects for c in o.children)
    for obj in sim.objects:
        if obj is sim.held:
            assert obj.parent is None and listed[obj.object_id] == 0
        elif obj.spec.pickupable:
            assert obj.parent is not None and listed[obj.object_id] == 1
            assert obj in obj.parent.children and obj.parent.object_id in objects
        # no containment cycles
        seen, node = set(), obj.parent
        while node is not None:
            assert node.object_id not in seen
            seen.add(node.object_id)
            node = node.parent
    # the metadata says the same
    by_id = {o["objectId"]: o for o in meta["objects"]}
    held = [o for o in meta["objects"] if o["isPickedUp"]]
    assert len(held) <= 1
    for o in held:
        assert o["parentReceptacles"] is None and meta["inventoryObjects"][0]["objectId"] == o["objectId"]
    for o in meta["objects"]:
        if o["parentReceptacles"]:
            assert o["objectId"] in by_id[o["parentReceptacles"][0]]["receptacleObjectIds"]
    # slices conserve their source: all pieces stay, and the whole food is gone
    pieces = Counter(o["sourceObjectId"] for o in meta["objects"] if "sourceObjectId" in o)
    for source, count in pieces.items():
        assert source not in by_id
        assert count == PIECE_COUNT[source.split("|")[0]]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scene=st.sampled_from(["FloorPlan2", "FloorPlan12", "FloorPlan19"]), steps=st.lists(step, max_size=30))
def test_random_action_sequences_keep_invariants(scene, steps):
    s = new_session(scene)
    sim = s.controller
    assert isinstance(sim, KitchenSim)
    check_invariants(sim, sim.last_event.metadata)
    for verb, index in steps:
        before = sim.snapshot()
        try:
            act(s, verb, index)
        except KitchenActionError:
            assert sim.snapshot() == before, f"a refused {verb} changed the kitchen"
        check_invariants(sim, sim.last_event.metadata)
