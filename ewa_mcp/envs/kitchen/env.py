"""The kitchen as an episode's embodied environment (the registry's ``KITCHEN`` environment, ewa_mcp/core/registry.py)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar, Literal

import anyio

from ewa_mcp.core.environment import EnvError, Environment, Observation
from .backends import backend_name, make_controller
from .observe import build_observation
from .kitchen_map import frame_png, png_bytes, render_topdown
from .scenes import SceneError, canonical_scene
from .session import ActionReport, KitchenSession

OBSERVATION_MODES = ("text", "vision", "both")


class KitchenEnvironment(Environment):
    side: ClassVar[Literal["web", "embodied"]] = "embodied"
    name: ClassVar[str] = "kitchen"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.session: KitchenSession | None = None
        self.mode = "text"

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
        text, data = build_observation(session, self.mode)
        images = [self.image_png()] if self.mode in ("vision", "both") else []
        return Observation(text=text, data=data, images=images)

    def image_png(self) -> bytes:
        session = self._session()
        frame = getattr(session.controller.last_event, "frame", None)
        if frame is not None:  # a real (or stand-in) AI2-THOR frame
            return frame_png(frame)
        return png_bytes(render_topdown(session.meta, session.reachable, label=session.handle))

    async def _run(self, fn: Callable[[KitchenSession], Any]) -> Any:
        session = self._session()
        if session.backend == "sim":
            return fn(session)
        return await anyio.to_thread.run_sync(fn, session)

    async def _act(self, fn: Callable[[KitchenSession], ActionReport]) -> Observation:
        def step(session: KitchenSession) -> ActionReport:
            self._deliver()
            return fn(session)

        await self._run(step)
        return self._observation()

    # ------------------------------------------------------------------ actions (the table in actions.py)
    async def perform(self, name: str, args: dict[str, Any]) -> Observation:
        """One action of the kitchen action table, e.g. perform("slice", {"object": "Tomato"})."""
        return await self._act(lambda s: s.perform(name, args))

    async def run(self, action: str) -> Observation:
        """One action written the AI2-THOR way ("SliceObject Tomato")."""
        return await self._act(lambda s: s.run(action))
