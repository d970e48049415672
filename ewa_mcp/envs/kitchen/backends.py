"""Choosing and building the kitchen backend: the built-in simulator or a real AI2-THOR build.

    episode option kitchen_backend = "sim" | "ai2thor"     (wins)
    setting        kitchen_backend (EWA_KITCHEN_BACKEND) = sim | ai2thor      (default: sim)
    setting        ai2thor_executable (EWA_AI2THOR_EXECUTABLE) = <path to an AI2-THOR Unity build> | standin

The settings come from ``services.settings`` (ewa_mcp/settings.py), read once at server start.

The ai2thor backend never downloads a build: it needs a local executable. ``standin`` runs the
project's headless stand-in (``python -m ewa_mcp.envs.kitchen.standin``), which speaks ai2thor's FIFO
protocol and is backed by the simulator.
"""

from __future__ import annotations

from typing import Any

from ewa_mcp.core.environment import EnvError
from ewa_mcp.settings import Settings
from .sim import KitchenSim

BACKENDS = ("sim", "ai2thor")


def backend_name(options: dict[str, Any] | None = None, settings: Settings | None = None) -> str:
    chosen = (options or {}).get("kitchen_backend") or (settings.kitchen_backend if settings else "sim")
    chosen = str(chosen).strip().lower()
    if chosen not in BACKENDS:
        raise EnvError(f"unknown kitchen backend {chosen!r} (from the kitchen_backend option or EWA_KITCHEN_BACKEND); "
                       f"use one of {', '.join(BACKENDS)}")
    return chosen


def ai2thor_executable(settings: Settings | None = None) -> str:
    value = settings.ai2thor_executable if settings else None
    if not value:
        raise EnvError(
            "kitchen_backend=ai2thor needs a local AI2-THOR build (nothing is downloaded at run time): set "
            "EWA_AI2THOR_EXECUTABLE to the path of the Unity executable, or to 'standin' for the headless "
            "stand-in that runs on any machine"
        )
    if value.strip().lower() == "standin":
        from .standin import standin_command

        return standin_command()
    return value


def make_controller(backend: str, scene: str, *, render_images: bool = False,
                    settings: Settings | None = None) -> Any:
    """A controller for ``backend`` with ``scene`` loaded (blocking: it may start a process)."""
    if backend == "sim":
        return KitchenSim(scene)
    from .ai2thor_backend import Ai2ThorController

    return Ai2ThorController(ai2thor_executable(settings), scene, render_images=render_images)
