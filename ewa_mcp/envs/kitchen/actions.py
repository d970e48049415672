"""The kitchen action table: one declaration per kitchen action.

Each ``KitchenAction`` says everything the rest of the kitchen needs: its tool (``kitchen_<name>``), title,
description and parameters (ewa_mcp/envs/kitchen/tools.py generates the MCP tools from them), the AI2-THOR action
names it answers to in an action string and the arguments each name fixes (``ToggleObjectOn`` fixes
``state="on"``), the short forms agents write (``cut`` for SliceObject), whether it only looks or also
destroys (its MCP annotations), and ``run``: what it does on a ``KitchenSession`` (ewa_mcp/envs/kitchen/session.py).
The command parser (commands.py), the session's ``run``, the environment's ``perform`` and the tools all read
this table, so adding an action is one entry here (plus, for an AI2-THOR action the built-in simulator does
not know yet, its handler in sim_hands.py or sim_moves.py). docs/extending.md walks through it.

This module imports no simulator: the server builds the kitchen tools from it at start.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Annotated, Any, Literal

from pydantic import Field

ObjectRef = Annotated[
    str,
    Field(
        min_length=1,
        max_length=200,
        description="the object: a handle from the observation (Apple_1, Cabinet_3), an objectId, or a type "
        "(Apple; exact AI2-THOR types only — Egg is not Eggplant)",
    ),
]


@dataclass(frozen=True)
class KitchenAction:
    name: str  # the tool is kitchen_<name>
    title: str  # the tool's human-readable title
    description: str  # the tool's description, shown to the model
    run: Callable[..., Any]  # (session, **params) -> ActionReport
    thor: dict[str, dict[str, Any]]  # AI2-THOR action name -> the parameters that name fixes
    params: dict[str, Any] = field(default_factory=dict)  # tool parameter -> type, in order
    target: str | None = None  # the parameter an action string's object fills ("PickupObject Apple")
    aliases: dict[str, str] = field(default_factory=dict)  # short form (lower case, no "_") -> AI2-THOR name
    destructive: bool = False  # cannot be undone (a slice, a cook): the tool's destructiveHint
    read_only: bool = False  # changes nothing in the kitchen: the tool's readOnlyHint
    tool: bool = True  # False: reachable only through kitchen_action strings

    @property
    def tool_name(self) -> str:
        return f"kitchen_{self.name}"


def _object(thor: str) -> Callable[..., Any]:
    return lambda session, object: session.object_action(thor, object)


ACTIONS: tuple[KitchenAction, ...] = (
    KitchenAction(
        "teleport", "Teleport to an object",
        "Teleport [object]: stand at the nearest spot facing the object, within reach "
        "(if it is inside a closed receptacle you face that receptacle).",
        lambda s, object: s.teleport(object), {"Teleport": {}}, {"object": ObjectRef}, target="object",
        aliases={"teleportobject": "Teleport", "navigateto": "Teleport", "goto": "Teleport"},
    ),
    KitchenAction(
        "move", "Step in the kitchen",
        "MoveAhead/MoveBack/MoveLeft/MoveRight: step 0.25 m (blocked by furniture).",
        lambda s, direction: s.move(direction),
        {"MoveAhead": {"direction": "ahead"}, "MoveBack": {"direction": "back"},
         "MoveLeft": {"direction": "left"}, "MoveRight": {"direction": "right"}},
        {"direction": Literal["ahead", "back", "left", "right"]},
    ),
    KitchenAction(
        "rotate", "Turn in the kitchen", "RotateLeft/RotateRight: turn 90 degrees.",
        lambda s, direction: s.rotate(direction),
        {"RotateLeft": {"direction": "left"}, "RotateRight": {"direction": "right"}},
        {"direction": Literal["left", "right"]},
    ),
    KitchenAction(
        "look", "Tilt the view", "LookUp/LookDown: tilt the view 30 degrees.",
        lambda s, direction: s.look(direction),
        {"LookUp": {"direction": "up"}, "LookDown": {"direction": "down"}},
        {"direction": Literal["up", "down"]}, tool=False,
    ),
    KitchenAction(
        "pickup", "Pick up an object", "PickupObject [object]: take an object in reach into your (empty) hand.",
        lambda s, object: s.pickup(object), {"PickupObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"pickup": "PickupObject", "pick": "PickupObject"},
    ),
    KitchenAction(
        "put", "Put the held object", "PutObject [receptacle]: put what you hold in/on a receptacle in reach "
        "(open it first if it is closed).",
        lambda s, receptacle: s.put(receptacle), {"PutObject": {}}, {"receptacle": ObjectRef}, target="receptacle",
        aliases={"put": "PutObject", "place": "PutObject"},
    ),
    KitchenAction(
        "drop", "Drop the held object",
        "DropHandObject: let go of what you hold (it lands on the surface ahead or the floor).",
        lambda s: s.drop(), {"DropHandObject": {}}, aliases={"drop": "DropHandObject"},
    ),
    KitchenAction(
        "open", "Open an object", "OpenObject [object]: open a fridge, cabinet, drawer or microwave in reach.",
        _object("OpenObject"), {"OpenObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"open": "OpenObject"},
    ),
    KitchenAction(
        "close", "Close an object",
        "CloseObject [object]: close an open fridge, cabinet, drawer or microwave in reach.",
        _object("CloseObject"), {"CloseObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"close": "CloseObject"},
    ),
    KitchenAction(
        "slice", "Slice food", "SliceObject [object]: slice food in reach while holding a Knife or ButterKnife "
        "(an Egg cracks into EggCracked).",
        _object("SliceObject"), {"SliceObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"slice": "SliceObject", "cut": "SliceObject", "crack": "SliceObject"}, destructive=True,
    ),
    KitchenAction(
        "cook", "Cook food", "CookObject [object]: cook food in reach at once (AI2-THOR's instant cook). Food also "
        "cooks in a Pan/Pot on a burner whose StoveKnob is on, in a running Microwave, or as BreadSliced in a "
        "running Toaster.",
        _object("CookObject"), {"CookObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"cook": "CookObject"}, destructive=True,
    ),
    KitchenAction(
        "break", "Break an object", "BreakObject [object]: break a breakable object in reach.",
        _object("BreakObject"), {"BreakObject": {}}, {"object": ObjectRef}, target="object",
        aliases={"break": "BreakObject"}, destructive=True, tool=False,
    ),
    KitchenAction(
        "toggle", "Switch an appliance", "ToggleObjectOn/Off [object]: switch a StoveKnob (lights its burner), "
        "Microwave, Toaster or CoffeeMachine in reach.",
        lambda s, object, state: s.toggle(object, state == "on"),
        {"ToggleObjectOn": {"state": "on"}, "ToggleObjectOff": {"state": "off"}},
        {"object": ObjectRef, "state": Literal["on", "off"]}, target="object",
        aliases={"toggleon": "ToggleObjectOn", "toggleoff": "ToggleObjectOff", "turnon": "ToggleObjectOn",
                 "turnoff": "ToggleObjectOff"},
    ),
)


class KitchenActionTable:
    """The actions by name, by AI2-THOR name and by short form; checked for clashes when built."""

    def __init__(self, actions: tuple[KitchenAction, ...]):
        self.actions = actions
        self.by_name: dict[str, KitchenAction] = {}
        self.by_thor: dict[str, KitchenAction] = {}
        self.aliases: dict[str, str] = {}
        for action in actions:
            self.add(action)

    def add(self, action: KitchenAction) -> None:
        if action.name in self.by_name:
            raise ValueError(f"two kitchen actions are named {action.name!r}")
        for thor, fixed in action.thor.items():
            if thor in self.by_thor:
                raise ValueError(f"AI2-THOR action {thor!r} is declared by {self.by_thor[thor].name!r} and "
                                 f"{action.name!r}")
            unknown = set(fixed) - set(action.params)
            if unknown:
                raise ValueError(f"{thor} fixes {sorted(unknown)}, which are not parameters of {action.name!r}")
            free = set(action.params) - set(fixed) - ({action.target} if action.target else set())
            if free:
                raise ValueError(f"{thor} leaves {sorted(free)} of {action.name!r} unset; an action string can "
                                 "only fill its object (``target``)")
        for alias, thor in action.aliases.items():
            if thor not in action.thor:
                raise ValueError(f"alias {alias!r} of {action.name!r} names {thor!r}, not one of its AI2-THOR names")
            if alias in self.aliases and self.aliases[alias] != thor:
                raise ValueError(f"alias {alias!r} is declared twice")
        self.by_name[action.name] = action
        for thor in action.thor:
            self.by_thor[thor] = action
        self.aliases.update(action.aliases)

    def remove(self, name: str) -> None:
        action = self.by_name.pop(name)
        for thor in action.thor:
            self.by_thor.pop(thor, None)
        for alias in action.aliases:
            self.aliases.pop(alias, None)

    def thor_for(self, name: str, args: dict[str, Any]) -> str:
        """The AI2-THOR name of action ``name`` that these arguments select (move, direction=ahead -> MoveAhead)."""
        action = self.by_name[name]
        for thor, fixed in action.thor.items():
            if all(args.get(key) == value for key, value in fixed.items()):
                return thor
        keys = sorted({key for fixed in action.thor.values() for key in fixed})
        choices = ["/".join(str(fixed.get(k)) for k in keys) for fixed in action.thor.values()]
        given = "/".join(repr(args.get(k))[:100] for k in keys)
        listed = ", ".join(choices[:-1]) + f" or {choices[-1]}" if len(choices) > 1 else choices[0]
        raise ValueError(f"unknown {'/'.join(keys)} {given} for {name}; use {listed}")

    def tools(self) -> list[KitchenAction]:
        return [a for a in self.by_name.values() if a.tool]

    def thor_names(self) -> list[str]:
        return list(self.by_thor)


TABLE = KitchenActionTable(ACTIONS)
