"""The HTTP server keeps an idle client connection open past uvicorn's 5 s default. With the default, a call sent
just as the server closed the connection was reset (a ReadError that ended the client's MCP session): 54 of 256
sessions under load (benchmarks/bench_load.py, docs/performance.md)."""

from __future__ import annotations

import socket
import time

from ewa_mcp.http_serve import KEEP_ALIVE_S

from .servers import serve, stop

REQUEST = (b"GET /mcp HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept: application/json\r\nConnection: keep-alive\r\n\r\n")


def _response(sock: socket.socket) -> bytes:
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = sock.recv(65536)
        assert chunk, "the server closed the connection"
        data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    length = next((int(line.split(b":")[1]) for line in head.split(b"\r\n")
                   if line.lower().startswith(b"content-length:")), 0)
    while len(body) < length:
        body += sock.recv(65536)
    return head


def test_an_idle_connection_outlives_uvicorns_default_keep_alive(tmp_path):
    assert KEEP_ALIVE_S >= 60
    proc, port = serve(tmp_path)
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
            sock.sendall(REQUEST)
            first = _response(sock)
            assert first.startswith(b"HTTP/1.1 ")
            time.sleep(7)  # idle past the 5 s default, as an agent thinking
            sock.sendall(REQUEST)
            assert _response(sock).split(b"\r\n")[0] == first.split(b"\r\n")[0]  # same connection, answered
    finally:
        stop(proc)
