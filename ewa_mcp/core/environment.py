"""What every environment (kitchen, street, browser, geolocation world) offers an episode.

An environment is owned by exactly one episode. Tools reach it only through
``EpisodeManager.act`` so that the active-environment rule, the step limit and the
trajectory record are enforced in one place.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar, Literal



class EnvError(Exception):
    """An action the environment refused. The message names the problem and how to fix it;
    the environment's state is unchanged. Environments know nothing of MCP: the episode manager
    turns this into the tool error the client sees (``EpisodeManager.act`` and ``start``)."""


@dataclass
class Observation:
    text: str  # the short rendering the model reads
    data: dict[str, Any] = field(default_factory=dict)  # the same, structured (JSON-serializable)
    images: list[bytes] = field(default_factory=list)  # PNG bytes, sent as MCP image content


class Environment:
    """Base class; subclasses set ``side`` and ``name`` (its registry name) and implement the async hooks.
    ``check_environment`` (conformance.py) checks the contract."""

    side: ClassVar[Literal["web", "embodied"]]  # the slot it fills in an episode
    name: ClassVar[str]

    async def reset(self, task: Any, options: dict[str, Any]) -> None:  # task: taskmodel.Task
        raise NotImplementedError

    async def observe(self) -> Observation:
        raise NotImplementedError

    def status(self) -> dict[str, Any]:
        """Values of the status fields its registry entry declares (``episode_status``), e.g. whether a walk
        was stopped."""
        return {}

    async def final_state(self) -> dict[str, Any]:
        """A JSON-serializable snapshot that graders read from final_state.json."""
        raise NotImplementedError

    async def close(self) -> None:
        return None
