"""Builds the MCP server: one MCPServer, one EpisodeManager, the tool groups of the registry."""

from __future__ import annotations

import importlib
import logging
import uuid
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError, UnexpectedToolError
from pydantic import ValidationError

from . import __version__
from .core import registry
from .core.episodes import EpisodeManager
from .core.paths import check_run_dir, runs_dir, task_dirs
from .core.prompts import register_prompts
from .core.records import new_run_id
from .core.schemas import make_portable
from .core.services import Services
from .settings import Settings, load_settings
from .core.taskmodel import TaskStore
from .core.tool_table import check_declared

log = logging.getLogger("ewa_mcp")

def instructions() -> str:
    """The server's instructions: the episode protocol, with what each registered environment adds."""
    specs = registry.ordered_environments()
    web = " or ".join(e.hint() for e in specs if e.side == "web") or "none"
    embodied = " or ".join(e.hint() for e in specs if e.side == "embodied") or "none"
    extra = "".join(f" {e.instructions}" for e in specs if e.instructions)
    return (
        "ewa-mcp: embodied web agent tasks. Protocol:\n"
        "1. list_tasks, then start_episode(task_id) -> an episode_id, the task intent and the first observation.\n"
        f"2. Each episode has a web environment ({web}) and/or an embodied one ({embodied}).\n"
        "   Only the active one accepts actions; switch_environment(episode_id, target, message) changes it (it is a\n"
        "   recorded action, say why in message).\n"
        "3. Pass episode_id to every tool. get_observation shows the active environment again without acting.\n"
        f"4. finish_episode(episode_id, answer) ends the episode.{extra}\n"
        "5. Every call on a running episode is recorded and uses one step, failed calls included; steps are limited.\n"
    )


class EpisodeServer(MCPServer):
    """The SDK's server, plus one rule: a call the SDK refuses before the tool runs (arguments that fail
    the input schema, an unknown tool name) is still a step of the episode it names, recorded with its
    error like any failed call (docs/architecture.md, "The step rule")."""

    episodes: EpisodeManager

    async def call_tool(self, name: str, arguments: dict[str, Any], context: Any = None) -> Any:
        try:
            return await super().call_tool(name, arguments, context)
        except ToolError as exc:
            rejected_early = isinstance(exc.__cause__, ValidationError) or self._tool_manager.get_tool(name) is None
            if rejected_early and not isinstance(exc, UnexpectedToolError) and isinstance(arguments, dict):
                args = {k: v for k, v in arguments.items() if k != "episode_id"}
                await self.episodes.record_rejected(arguments.get("episode_id"), name[:100], args, str(exc))
            raise


@dataclass
class ServerConfig:
    settings: Settings | None = None  # default: load_settings() (the defaults and the EWA_* variables)
    task_dirs: list[Path] | None = None  # overrides settings.tasks_dir
    run_dir: Path | None = None  # overrides settings.run_dir: the directory episodes are written under (one run)
    environments: dict[str, Any] | None = None  # name -> class overrides (tests)

    def resolved_settings(self) -> Settings:
        overrides: dict[str, Any] = {"tasks_dir": self.task_dirs, "run_dir": self.run_dir}
        overrides = {k: v for k, v in overrides.items() if v is not None}
        if self.settings is None:
            return load_settings(overrides)
        return self.settings.model_copy(update=overrides)


def build_server(config: ServerConfig | None = None) -> tuple[MCPServer, EpisodeManager]:
    """The server, its episode manager and the shared services, all configured by one ``Settings``.

    Raises ``SettingsError`` (naming the variable and the fix) when an EWA_* variable is invalid or the run
    directory cannot be written (ewa_mcp/core/paths.py: a read-only working directory falls back to a per-user one)."""
    config = config or ServerConfig()
    settings = config.resolved_settings()
    tasks = TaskStore(task_dirs(settings), on_error=lambda err: log.warning("skipped a task file: %s", err))
    # Imported task directories carry their street graphs in a streets/ folder (ewa-mcp tasks import-ewa).
    streets = [Path(d) / "streets" for d in tasks.roots if (Path(d) / "streets").is_dir()]
    if streets:
        from .envs.street.world import use_street_data

        use_street_data(streets)
    run_dir = settings.run_dir or (runs_dir(settings) / new_run_id())
    check_run_dir(run_dir, settings)  # refused here, naming the setting, not at every start_episode
    services = Services(settings)
    episodes = EpisodeManager(tasks, run_dir, services, config.environments)
    # The embedded sites report per-episode events (orders, page views) through this sink.
    services.emit_event = episodes.emit_event

    connected = 0

    @asynccontextmanager
    async def lifespan(_: MCPServer) -> AsyncIterator[dict[str, str]]:
        # The tools reach the episode manager through register(); the lifespan state names the connection (the
        # per-client cap's client: tools/core.client_key). The SDK enters it once per server for HTTP, once per
        # connection in-process and over stdio: the episodes belong to the server, so they (and the browser)
        # end only when the last connection leaves, never when one client of several does.
        nonlocal connected
        connected += 1
        if connected == 1:
            episodes.start_reaper()
        try:
            yield {"connection": f"connection-{uuid.uuid4().hex[:12]}"}
        finally:
            connected -= 1
            if connected == 0:
                await episodes.aclose()
                await services.aclose()

    mcp = EpisodeServer("ewa-mcp", instructions=instructions(), version=__version__, lifespan=lifespan)
    mcp.episodes = episodes
    for module_name in registry.tool_groups():
        importlib.import_module(module_name).register(mcp, episodes)
    register_prompts(mcp)  # one prompt per domain: the agent instructions (ewa_mcp/core/prompts.py)
    check_declared(mcp)  # every tool has a title and annotations (ewa_mcp/core/tool_table.py)
    make_portable(mcp)  # no $ref/$defs, closed argument objects: every client's converter accepts them
    return mcp, episodes
