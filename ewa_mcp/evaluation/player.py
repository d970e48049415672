"""An episode player for plain threads: one MCP client session (its own server, browser and sites) kept open in
a background event loop, so a worker process or a Ray actor can call `play(task)` from any thread."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from anyio.from_thread import start_blocking_portal

from ewa_mcp.core.taskmodel import Task
from .outcomes import EpisodeOutcome
from .playing import connect, play_episode


class EpisodePlayer:
    def __init__(self, agent: Any, *, transport: str, task_dirs: list[Path], run_dir: Path):
        self.agent = agent
        self.run_dir = run_dir
        run_dir.mkdir(parents=True, exist_ok=True)
        self._portal_cm = start_blocking_portal()
        self._portal = self._portal_cm.__enter__()
        try:
            # Entered and left in one task of the portal's loop, as the client's task group requires.
            self._session_cm = self._portal.wrap_async_context_manager(connect(transport, task_dirs, run_dir))
            self._client = self._session_cm.__enter__()
        except BaseException:
            self._portal_cm.__exit__(None, None, None)
            raise

    def play(self, task: Task, on_start: Callable[[str], None] | None = None) -> EpisodeOutcome:
        """Play one episode (blocking; safe to call from several threads at once)."""
        return self._portal.call(play_episode, self._client, task, self.agent, on_start)

    def close(self) -> None:
        """End the session: the server aborts (and records) any episode still running, then stops."""
        try:
            self._session_cm.__exit__(None, None, None)
        finally:
            self._portal_cm.__exit__(None, None, None)
