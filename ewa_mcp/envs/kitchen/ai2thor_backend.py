"""The real AI2-THOR behind the session's controller interface.

``ai2thor.controller.Controller`` already has the shape the session needs (``step``, ``reset``,
``last_event``); this adapter starts it from a local build with the benchmark's settings and
turns the exceptions ai2thor raises for invalid actions into failed events, so that a bad
action reads the same on both backends. Requires the optional extra: ``pip install ewa-mcp[ai2thor]``.
"""

from __future__ import annotations

import copy
import os
from typing import Any

from ewa_mcp.core.environment import EnvError

GRID_SIZE = 0.25
VISIBILITY_DISTANCE = 1.5


class _FailedEvent:
    """A failed step, shaped like an ai2thor Event (metadata of the last good state)."""

    def __init__(self, last: Any, action: str, message: str, code: str):
        self.metadata = copy.copy(dict(last.metadata)) if last is not None else {"objects": []}
        self.metadata.update(lastAction=action, lastActionSuccess=False, errorMessage=message, errorCode=code,
                             actionReturn=None)
        self.frame = getattr(last, "frame", None)


class Ai2ThorController:
    def __init__(self, executable: str, scene: str, *, render_images: bool = False, width: int = 300,
                 height: int = 300, timeout: float = 60.0):
        try:
            from ai2thor.controller import Controller
        except ImportError as exc:
            raise EnvError("kitchen_backend=ai2thor needs the ai2thor package: pip install 'ewa-mcp[ai2thor]' "
                           "(or use the built-in simulator: kitchen_backend=sim)") from exc
        try:
            self._controller = Controller(
                local_executable_path=executable,
                # ai2thor insists on an X display value for Linux builds even when rendering headless.
                x_display=os.environ.get("DISPLAY") or ":0",
                headless=not render_images,
                width=width,
                height=height,
                scene=scene,
                gridSize=GRID_SIZE,
                visibilityDistance=VISIBILITY_DISTANCE,
                renderDepthImage=False,
                renderInstanceSegmentation=False,
                server_timeout=timeout,
                server_start_timeout=timeout,
            )
        except Exception as exc:
            raise EnvError(f"could not start AI2-THOR from {executable!r}: {type(exc).__name__}: {exc}. "
                           "Check EWA_AI2THOR_EXECUTABLE (a Unity build, or 'standin').") from exc

    @property
    def last_event(self) -> Any:
        return self._controller.last_event

    def reset(self, scene: str) -> Any:
        return self._controller.reset(scene)

    def step(self, action: Any = None, **args: Any) -> Any:
        name = action.get("action") if isinstance(action, dict) else action
        try:
            return self._controller.step(action=action, **args)
        except ValueError as exc:  # ai2thor raises for InvalidAction / InvalidArgument / MissingArguments
            code = self._controller.last_event.metadata.get("errorCode", "InvalidArgument")
            return _FailedEvent(self._controller.last_event, str(name), str(exc), code)
        except (TimeoutError, RuntimeError) as exc:
            raise EnvError(f"the AI2-THOR process stopped answering during {name}: {exc}") from exc

    def close(self) -> None:
        self._controller.stop()
