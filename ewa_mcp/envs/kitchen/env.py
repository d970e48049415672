"""The kitchen as an episode's embodied environment (the registry's ``KITCHEN`` environment, ewa_mcp/core/registry.py)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar, Literal

import anyio

from ewa_mcp.core.environment import EnvError, Environment, Observation
from .backends import backend_name, make_controller
from .observe import build_observation
from .camera3d import DEFAULT_SIZE, CameraUnavailable, check_size, render_png
from .kitchen_map import frame_png, png_bytes, render_topdown
from .scenes import SceneError, canonical_scene
from .session import ActionReport, KitchenSession

OBSERVATION_MODES = ("text", "vision", "both")
KITCHEN_VIEWS = ("first_person", "map")


class KitchenEnvironment(Environment):
    side: ClassVar[Literal["web", "embodied"]] = "embodied"
    name: ClassVar[str] = "kitchen"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.session: KitchenSession | None = None
        self.mode = "text"
        self.view = "first_person"
        self.camera_size = (DEFAULT_SIZE, DEFAULT_SIZE)
        self.last_error: str | None = None  # the last action's errorMessage, until an action succeeds

    # ------------------------------------------------------------------ lifecycle
    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        start = task.start.embodied
        if start is None or getattr(start, "kind", None) != "kitchen":
            raise EnvError(f"task {task.id} does not start in a kitchen (start.embodied.kind must be 'kitchen')")
        try:
            scene = canonical_scene(start.scene)
        except SceneError as exc:
            raise EnvError(f"task {task.id}: {exc}") from None
        seed = options.get("seed")
        seed = start.seed if seed is None else int(seed)
        self.mode = str(options.get("observation") or "text")
        if self.mode not in OBSERVATION_MODES:
            raise EnvError(f"unknown observation mode {self.mode!r}; use one of {', '.join(OBSERVATION_MODES)}")
        self.view = str(options.get("kitchen_view") or "first_person")
        if self.view not in KITCHEN_VIEWS:
            raise EnvError(f"unknown kitchen_view {self.view!r}; use one of {', '.join(KITCHEN_VIEWS)}")
        size = (options.get("kitchen_camera_width") or DEFAULT_SIZE, options.get("kitchen_camera_height") or DEFAULT_SIZE)
        try:
            check_size(*size)
        except ValueError as exc:
            raise EnvError(f"{exc} (episode options kitchen_camera_width/kitchen_camera_height)") from None
        self.camera_size = size
        settings = self.services.settings
        backend = backend_name(options, settings)
        want_frames = self.mode != "text"

        def build() -> KitchenSession:
            controller = make_controller(backend, scene, render_images=want_frames, settings=settings)
            session = KitchenSession(controller, backend, scene, seed)
            try:
                session.reset()
            except BaseException:
                close = getattr(controller, "close", None)
                if close is not None:
                    close()
                raise
            return session

        # A real AI2-THOR starts a process and talks over pipes: keep that off the event loop.
        self.session = build() if backend == "sim" else await anyio.to_thread.run_sync(build)
        self.last_error = None
        if want_frames:
            self.image_png()  # a missing OpenGL stops the episode at its start, with what to install

    async def close(self) -> None:
        session, self.session = self.session, None
        close = getattr(session.controller, "close", None) if session is not None else None
        if close is not None:
            await anyio.to_thread.run_sync(close)

    async def final_state(self) -> dict[str, Any]:
        return self._session().final_state()

    # ------------------------------------------------------------------ observing
    def _session(self) -> KitchenSession:
        if self.session is None:
            raise EnvError("the kitchen is not running (the episode has ended or failed to start)")
        return self.session

    def _deliver(self) -> None:
        self._session().receive_deliveries(self.episode.web_events)

    async def observe(self) -> Observation:
        await self._run(lambda s: self._deliver())
        return self._observation()

    def _observation(self) -> Observation:
        session = self._session()
        first_person = self.view == "first_person" and self._backend_frame() is None
        text, data = build_observation(session, self.mode, view="first_person" if first_person else "map",
                                       last_error=self.last_error)
        images = [self.image_png()] if self.mode in ("vision", "both") else []
        return Observation(text=text, data=data, images=images)

    def _backend_frame(self) -> Any:
        return getattr(self._session().controller.last_event, "frame", None)

    def image_png(self) -> bytes:
        session = self._session()
        frame = self._backend_frame()
        if frame is not None:  # a real (or stand-in) AI2-THOR frame
            return frame_png(frame)
        if self.view == "map":
            return png_bytes(render_topdown(session.meta, session.reachable, label=session.handle))
        width, height = self.camera_size
        try:
            return render_png(session.meta, session.reachable, width=width, height=height)
        except CameraUnavailable as exc:
            raise EnvError(str(exc)) from None

    async def _run(self, fn: Callable[[KitchenSession], Any]) -> Any:
        session = self._session()
        if session.backend == "sim":
            return fn(session)
        return await anyio.to_thread.run_sync(fn, session)

    async def _act(self, fn: Callable[[KitchenSession], ActionReport]) -> Observation:
        def step(session: KitchenSession) -> ActionReport:
            self._deliver()
            return fn(session)

        try:
            await self._run(step)
        except EnvError as exc:
            self.last_error = str(exc)
            raise
        self.last_error = None
        return self._observation()

    # ------------------------------------------------------------------ actions (the table in actions.py)
    async def perform(self, name: str, args: dict[str, Any]) -> Observation:
        """One action of the kitchen action table, e.g. perform("slice", {"object": "Tomato"})."""
        return await self._act(lambda s: s.perform(name, args))

    async def run(self, action: str) -> Observation:
        """One action written the AI2-THOR way ("SliceObject Tomato")."""
        return await self._act(lambda s: s.run(action))
