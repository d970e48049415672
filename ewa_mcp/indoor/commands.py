"""Parsing actions written the paper's way: ``"PickupObject Apple"``, ``"Teleport [Pan]"``, ``"MoveAhead"``."""

from __future__ import annotations

import re
from dataclasses import dataclass

# AI2-THOR action name -> (session verb, needs an object)
ACTIONS: dict[str, tuple[str, bool]] = {
    "Teleport": ("teleport", True),
    "MoveAhead": ("move:ahead", False),
    "MoveBack": ("move:back", False),
    "MoveLeft": ("move:left", False),
    "MoveRight": ("move:right", False),
    "RotateLeft": ("rotate:left", False),
    "RotateRight": ("rotate:right", False),
    "LookUp": ("look:up", False),
    "LookDown": ("look:down", False),
    "PickupObject": ("pickup", True),
    "PutObject": ("put", True),
    "DropHandObject": ("drop", False),
    "OpenObject": ("open", True),
    "CloseObject": ("close", True),
    "SliceObject": ("slice", True),
    "CookObject": ("cook", True),
    "BreakObject": ("break", True),
    "ToggleObjectOn": ("toggle:on", True),
    "ToggleObjectOff": ("toggle:off", True),
}
# Short forms agents often write; each maps to one AI2-THOR action.
ALIASES: dict[str, str] = {
    "teleportobject": "Teleport", "navigateto": "Teleport", "goto": "Teleport",
    "pickup": "PickupObject", "pick": "PickupObject", "put": "PutObject", "place": "PutObject",
    "drop": "DropHandObject", "open": "OpenObject", "close": "CloseObject", "slice": "SliceObject",
    "cut": "SliceObject", "crack": "SliceObject", "cook": "CookObject", "break": "BreakObject",
    "toggleon": "ToggleObjectOn", "toggleoff": "ToggleObjectOff", "turnon": "ToggleObjectOn",
    "turnoff": "ToggleObjectOff",
}


class CommandError(ValueError):
    """An action string that cannot be understood; the message shows the accepted forms."""


@dataclass(frozen=True)
class Command:
    action: str  # AI2-THOR name
    verb: str  # session verb (teleport, pickup, move:ahead, ...)
    target: str | None


_PATTERN = re.compile(r"^\s*([A-Za-z_]+)\s*(?:[\[(]\s*(.*?)\s*[\])]|\s+(.+?))?\s*$")


def parse_command(text: str) -> Command:
    match = _PATTERN.match(text or "")
    if not match:
        raise CommandError(
            f"cannot read the action {text!r}; write an AI2-THOR action and its object, "
            "e.g. 'PickupObject Apple', 'Teleport [Pan]', 'MoveAhead'"
        )
    name, bracketed, plain = match.group(1), match.group(2), match.group(3)
    target = (bracketed if bracketed is not None else plain) or None
    action = next((a for a in ACTIONS if a.lower() == name.lower()), None) or ALIASES.get(name.lower().replace("_", ""))
    if action is None:
        raise CommandError(f"unknown action {name!r}; the actions are: {', '.join(ACTIONS)}")
    verb, needs_object = ACTIONS[action]
    if needs_object and not target:
        raise CommandError(
            f"{action} needs an object, e.g. '{action} Apple' (a type, a handle like Apple_1, or an objectId)"
        )
    if not needs_object and target:
        raise CommandError(f"{action} takes no object; write just '{action}'")
    return Command(action=action, verb=verb, target=target.strip().strip("'\"") if target else None)
