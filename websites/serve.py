"""Serve all embedded sites on loopback ports, in a background thread of the calling process.

The MCP server starts this lazily (the first web episode); ``ewa-mcp sites`` starts it for
people. Each site gets its own port so URLs, cookies and the browser's origin checks behave
like separate web sites.
"""

from __future__ import annotations

import asyncio
import importlib
import logging
import socket
import threading
from pathlib import Path
from typing import Any

import uvicorn

from .common import NoStoreHtml, SiteContext
from .sites import DECLARED

log = logging.getLogger("ewa_mcp.websites")

# site name -> "module:create_app" (from sites.py); a site whose module is missing in this build is skipped.
# Tests and benchmarks may replace this mapping to serve a fixture site.
SITES: dict[str, str] = {site.name: site.app for site in DECLARED}
DEFAULT_PORTS = {site.name: site.port for site in DECLARED}


def _listening_socket(host: str, port: int) -> socket.socket:
    """A socket bound and listening on (host, port); port 0 takes a free one. The socket is held from here
    to the site's server: asking for a free port, closing it and binding it again later let another
    process on the machine take it in between (seen as "address already in use" with many servers
    starting at once)."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
        sock.listen(2048)
    except OSError as exc:
        sock.close()
        raise RuntimeError(f"cannot listen on {host}:{port} for an embedded web site ({exc.strerror}); "
                           "leave site_ports unset to take free ports, or free that port") from exc
    return sock


def available_sites() -> dict[str, Any]:
    apps = {}
    for name, path in SITES.items():
        module_name, _, attr = path.partition(":")
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as exc:
            if exc.name and module_name.startswith(exc.name):
                continue  # this site has not landed in this build
            raise
        apps[name] = getattr(module, attr)
    return apps


class SiteServer:
    def __init__(self, host: str = "127.0.0.1", ports: dict[str, int] | None = None,
                 emit: Any = None, data_dir: Path | None = None):
        self.host = host
        factories = available_sites()
        ports = ports or {}
        self._sockets: dict[str, socket.socket] = {}
        try:
            for name in factories:
                self._sockets[name] = _listening_socket(host, ports.get(name) or 0)
        except RuntimeError:
            self._close_sockets()
            raise
        self.ports = {name: sock.getsockname()[1] for name, sock in self._sockets.items()}
        self.urls = {name: f"http://{host}:{port}" for name, port in self.ports.items()}
        kwargs: dict[str, Any] = {"urls": self.urls, "data_dir": data_dir}
        if emit is not None:
            kwargs["emit"] = emit
        self.context = SiteContext(**kwargs)
        self.apps = {name: NoStoreHtml(factory(self.context)) for name, factory in factories.items()}
        self._servers: list[uvicorn.Server] = []
        self._thread: threading.Thread | None = None
        self._ready = threading.Event()
        self._error: BaseException | None = None

    # ------------------------------------------------------------ lifecycle
    def start(self, timeout: float = 15.0) -> "SiteServer":
        self._thread = threading.Thread(target=self._run, name="ewa-websites", daemon=True)
        self._thread.start()
        if not self._ready.wait(timeout):
            self.stop()  # nothing is left listening for a start that is given up
            raise RuntimeError(f"the embedded web sites did not start within {timeout}s")
        if self._error is not None:
            self.stop()
            raise RuntimeError(f"the embedded web sites failed to start: {self._error}") from self._error
        return self

    def _run(self) -> None:
        try:
            asyncio.run(self._serve())
        except BaseException as exc:  # surfaced to start()
            self._error = exc
            self._ready.set()

    async def _serve(self) -> None:
        for name, app in self.apps.items():
            config = uvicorn.Config(app, host=self.host, port=self.ports[name], log_level="warning",
                                    access_log=False, lifespan="on")
            self._servers.append(uvicorn.Server(config))
        tasks = [asyncio.create_task(s.serve(sockets=[self._sockets[name]]))
                 for name, s in zip(self.apps, self._servers)]
        while not all(s.started for s in self._servers):
            if any(t.done() for t in tasks):
                for t in tasks:
                    if t.done() and t.exception():
                        raise t.exception()  # type: ignore[misc]
                raise RuntimeError("a site server exited during start-up (port in use?)")
            await asyncio.sleep(0.01)
        self._ready.set()
        await asyncio.gather(*tasks)

    def stop(self) -> None:
        for server in self._servers:
            server.should_exit = True
        if self._thread is not None:
            self._thread.join(timeout=10)
        self._close_sockets()

    def _close_sockets(self) -> None:
        for sock in self._sockets.values():
            sock.close()

    close = stop

    def origins(self) -> list[str]:
        return list(self.urls.values())


def site_service(services: Any) -> SiteServer:
    """Services factory: ``await services.get("websites", site_service)``.

    Uses ``services.emit_event`` (the episode manager's event sink) and the settings' optional
    ``site_ports`` / ``site_data_dir``."""
    return SiteServer(
        ports=services.settings.site_ports,
        emit=services.emit_event,
        data_dir=services.settings.site_data_dir,
    ).start()
