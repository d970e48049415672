"""The kitchen action table (ewa_mcp/envs/kitchen/actions.py) is consistent and is what the parser and the
session read."""

from __future__ import annotations

import pytest

from ewa_mcp.envs.kitchen.actions import ACTIONS, TABLE, KitchenAction, KitchenActionTable, ObjectRef
from ewa_mcp.envs.kitchen.commands import parse_command
from ewa_mcp.envs.kitchen.session import KitchenActionError

from .conftest import new_session


def test_every_thor_name_and_alias_parses_to_its_entry():
    for action in ACTIONS:
        for thor, fixed in action.thor.items():
            text = f"{thor} Apple" if action.target else thor
            command = parse_command(text)
            assert command.kitchen_action is action and command.action == thor
            assert {k: command.args[k] for k in fixed} == fixed
        for alias, thor in action.aliases.items():
            assert parse_command(f"{alias} Apple" if action.target else alias).action == thor


def test_the_table_refuses_clashes_and_unreachable_parameters():
    pickup = TABLE.by_name["pickup"]
    with pytest.raises(ValueError, match="PickupObject"):
        KitchenActionTable((*ACTIONS, KitchenAction("grab", "Grab", "x", pickup.run, {"PickupObject": {}},
                                                    {"object": ObjectRef}, target="object")))
    with pytest.raises(ValueError, match="not one of its AI2-THOR names"):
        KitchenActionTable((KitchenAction("grab", "Grab", "x", pickup.run, {"GrabObject": {}}, {"object": ObjectRef},
                                          target="object", aliases={"take": "PickupObject"}),))
    with pytest.raises(ValueError, match="unset"):
        KitchenActionTable((KitchenAction("spin", "Spin", "x", lambda s, way: None, {"Spin": {}},
                                          {"way": str}),))


def test_the_session_takes_thor_names_from_the_table():
    assert TABLE.thor_for("toggle", {"state": "off"}) == "ToggleObjectOff"
    s = new_session("FloorPlan12")
    assert s.rotate("right").action == "RotateRight"
    with pytest.raises(KitchenActionError, match="unknown direction 'up' for move; use ahead, back, left or right"):
        s.move("up")
    assert s.perform("look", {"direction": "down"}).action == "LookDown"
    with pytest.raises(KitchenActionError, match="unknown kitchen action 'fly'"):
        s.perform("fly", {})
