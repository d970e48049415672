"""A counter's room (play-test round 9: "a counter refused a plate as full with few items on it"): an
appliance standing on a counter takes its length off the counter's room once, not twice, and a full
receptacle's refusal names where else the object can go."""

from __future__ import annotations

import pytest

from .conftest import new_session


@pytest.mark.parametrize("scene", ["FloorPlan9", "FloorPlan10"])
def test_a_counter_with_appliances_takes_what_its_free_length_allows(scene):
    """A counter crowded with a microwave, a toaster and a coffee machine kept room for two more objects, yet
    refused the first one: the appliances were counted twice (off its capacity and as objects on it)."""
    s = new_session(scene)
    counter = next(i for i, o in s.objects.items() if o["objectType"] == "CounterTop"
                   and {s.objects[c]["objectType"] for c in o["receptacleObjectIds"] or []}
                   >= {"Microwave", "Toaster", "CoffeeMachine"})
    on_it = [c for c in s.objects[counter]["receptacleObjectIds"] if s.objects[c]["pickupable"]]
    sim = s.controller
    room = sim._room(sim.by_id[counter])
    assert room == 2 - len(on_it) and room >= 0
    small = [i for i, o in s.objects.items() if o["objectType"] in ("Spoon", "Fork", "Spatula", "Ladle", "Cup", "Mug",
                                                                     "SaltShaker", "PepperShaker", "Apple", "Tomato")
             and s.parent_of(o) not in (None, counter)
             and s.objects[s.parent_of(o)]["objectType"] in ("CounterTop", "DiningTable", "Shelf")]
    for obj in small[:room]:
        s.teleport(s.handle(obj))
        s.pickup(s.handle(obj))
        s.teleport(s.handle(counter))
        s.put(s.handle(counter))
        assert s.parent_of(s.objects[obj]) == counter
    # full now: the refusal says where else to put it, and the kitchen is unchanged
    extra = small[room]
    s.teleport(s.handle(extra))
    s.pickup(s.handle(extra))
    s.teleport(s.handle(counter))
    with pytest.raises(Exception, match=r"is full; put it on another one with room \(CounterTop_\d"):
        s.put(s.handle(counter))
    assert s.held_id == extra
