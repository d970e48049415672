"""Cooking and heating rules of the built-in kitchen: what running appliances and the fridge do to their contents.

Applied after every successful action (``SimWorld._update_heat``): food in a Pan/Pot on a burner whose StoveKnob
is on, in a running Microwave, on a lit burner, or bread slices in a running Toaster become hot and, if cookable,
cooked; a cup in a running CoffeeMachine fills with coffee; what is in the Fridge is cold.
"""

from __future__ import annotations

from .sim_world import SimWorld


def apply_heat(world: SimWorld) -> None:
    """Apply what running heat sources and the fridge do to the objects in them."""
    for obj in world.objects:
        if not obj.active or obj.box is not None:
            continue
        parent = obj.parent
        hot = cold = False
        if parent is not None and obj is not world.held:
            kind = parent.object_type
            if kind == "Microwave" and parent.is_toggled:
                hot = True
            elif kind == "Toaster" and parent.is_toggled and obj.object_type == "BreadSliced":
                hot = True
            elif kind == "StoveBurner" and world.burner_lit(parent):
                hot = True
            elif kind in ("Pan", "Pot") and parent.parent is not None and parent is not world.held \
                    and parent.parent.object_type == "StoveBurner" and world.burner_lit(parent.parent):
                hot = True
            elif kind == "CoffeeMachine" and parent.is_toggled and obj.spec.can_fill:
                obj.is_filled = True
                obj.fill_liquid = "coffee"
                hot = True
            elif kind == "Fridge":
                cold = True
        obj.temperature = "Hot" if hot else "Cold" if cold else "RoomTemp"
        if hot and obj.spec.cookable:
            obj.is_cooked = True


class HeatRules(SimWorld):
    """Mixed into KitchenSim: heat spreads after every action."""

    def _update_heat(self) -> None:
        apply_heat(self)
