"""The lamp's task models: the start of a lamp episode and its one goal kind. Declared on ``LAMP``
(``__init__.py``); the kernel assembles the task schema from them as from every world's."""

from __future__ import annotations

from typing import Literal

from ewa_mcp.core.taskmodel import StrictModel


class LampStart(StrictModel):
    kind: Literal["lamp"] = "lamp"
    lit: bool = False  # whether the lamp is on when the episode starts


class LampLit(StrictModel):
    """The lamp ends the episode on (or off, with ``lit: false``)."""

    kind: Literal["lamp_lit"] = "lamp_lit"
    lit: bool = True
