"""Parsing actions written the paper's way: ``"PickupObject Apple"``, ``"Teleport [Pan]"``, ``"MoveAhead"``.

The names and short forms come from the kitchen action table (actions.py).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from .actions import TABLE, KitchenAction


class CommandError(ValueError):
    """An action string that cannot be understood; the message shows the accepted forms."""


@dataclass(frozen=True)
class Command:
    action: str  # AI2-THOR name (PickupObject)
    kitchen_action: KitchenAction  # its entry in the table
    target: str | None  # the object named, if any
    args: dict[str, Any] = field(default_factory=dict)  # the parameters for KitchenAction.run


_PATTERN = re.compile(r"^\s*([A-Za-z_]+)\s*(?:[\[(]\s*(.*?)\s*[\])]|\s+(.+?))?\s*$")


def _thor_name(name: str) -> str | None:
    exact = next((a for a in TABLE.by_thor if a.lower() == name.lower()), None)
    return exact or TABLE.aliases.get(name.lower().replace("_", ""))


def parse_command(text: str) -> Command:
    match = _PATTERN.match(text or "")
    if not match:
        raise CommandError(
            f"cannot read the action {text!r}; write an AI2-THOR action and its object, "
            "e.g. 'PickupObject Apple', 'Teleport [Pan]', 'MoveAhead'"
        )
    name, bracketed, plain = match.group(1), match.group(2), match.group(3)
    target = (bracketed if bracketed is not None else plain) or None
    thor = _thor_name(name)
    if thor is None:
        raise CommandError(f"unknown action {name!r}; the actions are: {', '.join(TABLE.thor_names())}")
    action = TABLE.by_thor[thor]
    if action.target is not None and not target:
        raise CommandError(
            f"{thor} needs an object, e.g. '{thor} Apple' (a type, a handle like Apple_1, or an objectId)"
        )
    if action.target is None and target:
        raise CommandError(f"{thor} takes no object; write just '{thor}'")
    target = target.strip().strip("'\"") if target else None
    args = dict(action.thor[thor])
    if action.target is not None:
        args[action.target] = target
    return Command(action=thor, kitchen_action=action, target=target, args=args)
