"""The embedded sites' server: each site listens on a port it holds from the start, and a port taken
elsewhere is a clear error that leaves nothing behind."""

from __future__ import annotations

import socket
import urllib.request

import pytest

from ewa_mcp.websites.serve import SiteServer


def test_each_site_holds_its_port_from_the_start_and_releases_it_when_stopped():
    server = SiteServer()
    # the ports are bound before the servers run: another process cannot take them in between
    for port in server.ports.values():
        with socket.socket() as probe, pytest.raises(OSError):
            probe.bind(("127.0.0.1", port))
    server.start()
    try:
        with urllib.request.urlopen(server.urls["wiki"] + "/", timeout=10) as page:
            assert page.status == 200
    finally:
        server.stop()
    for port in server.ports.values():
        with socket.socket() as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            probe.bind(("127.0.0.1", port))


def test_a_configured_port_in_use_names_the_port_and_the_fix():
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        with pytest.raises(RuntimeError, match=rf"cannot listen on 127.0.0.1:{port}.*leave site_ports unset"):
            SiteServer(ports={"wiki": port})
