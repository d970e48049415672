"""Serving the MCP server over streamable HTTP, with a bearer token wherever it is reachable.

On the default addresses (127.0.0.1, localhost, ::1) the server answers without a token (only this
machine can reach it). Bound anywhere else — another loopback address such as 127.0.0.2, or past
loopback with ``--allow-remote`` — every request must carry ``Authorization: Bearer <token>``: the
token given with ``--token`` or ``EWA_MCP_TOKEN``, or one generated at start and printed once. A token
given on a default address is required there too. On every address the Host and Origin headers are
checked (``HostOriginGuard``), so a page on another site cannot reach the server by DNS rebinding.

The MCP SDK's own auth (``AuthSettings`` + a ``TokenVerifier``) is built for OAuth: it needs an
authorization server's issuer URL and publishes protected-resource metadata pointing at it. A
shared static token has no such server, so a small ASGI guard in front of the whole app checks it.
"""

from __future__ import annotations

import hmac
import ipaddress
import json
import secrets
import socket
import sys
from typing import Any

from .settings import Settings

TOKEN_ENV = "EWA_MCP_TOKEN"
MIN_TOKEN_CHARS = 16
HOW = ("send the header 'Authorization: Bearer <token>' with every request; the token is the one given to "
       f"`ewa-mcp serve` with --token or {TOKEN_ENV}, or the one it printed when it started")


class TokenError(ValueError):
    """A token that cannot be used; the message names the fix."""


def is_loopback_host(host: str) -> bool:
    if host.strip("[]").lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


# The binds that need no token: only these name exactly the one machine's own loopback interface by default.
DEFAULT_BINDS = ("127.0.0.1", "localhost", "::1")
WILDCARD_BINDS = ("0.0.0.0", "::", "")


def is_default_bind(host: str) -> bool:
    """True for 127.0.0.1, localhost and ::1: the addresses served without a token unless one is given."""
    return host.strip().strip("[]").lower() in DEFAULT_BINDS


def check_token(token: str) -> str:
    token = token.strip()
    if len(token) < MIN_TOKEN_CHARS:
        raise TokenError(f"the bearer token must have at least {MIN_TOKEN_CHARS} characters (it has {len(token)}); "
                         "use a long random one, e.g. `python -c 'import secrets; print(secrets.token_urlsafe(32))'`")
    if not token.isascii() or any(c.isspace() or not c.isprintable() for c in token):
        raise TokenError("the bearer token must be printable ASCII without spaces")
    return token


def choose_token(host: str, given: str | None) -> tuple[str | None, bool]:
    """(the token requests must carry or None, whether it was generated here). ``given`` is the
    mcp_token setting: ``--token`` or, when that is absent, ``EWA_MCP_TOKEN``."""
    if given is not None:
        return check_token(given), False
    if is_default_bind(host):
        return None, False
    return secrets.token_urlsafe(32), True


def _host_names(host: str) -> list[str]:
    """A bound address as a Host header may name it (IPv6 in brackets)."""
    bare = host.strip().strip("[]")
    return [f"[{bare}]" if ":" in bare else bare]


def allowed_hosts(host: str, extra: list[str] | None = None) -> list[str]:
    """The Host header values a server bound to ``host`` answers: the loopback names, the bound address, for
    a wildcard bind (0.0.0.0, ::) this machine's name and addresses, and the allowed_hosts setting."""
    names = ["127.0.0.1", "localhost", "[::1]"]
    bare = host.strip().strip("[]")
    if bare in WILDCARD_BINDS:
        machine = socket.gethostname()
        names += [machine, socket.getfqdn()]
        try:
            names += sorted({str(info[4][0]) for info in socket.getaddrinfo(machine, None)})
        except OSError:
            pass
    else:
        names.append(bare)
    names += [h.strip() for h in extra or [] if h.strip()]
    out: list[str] = []
    for name in names:
        for shown in _host_names(name):
            if shown.lower() not in out:
                out.append(shown.lower())
    return out


class HostOriginGuard:
    """ASGI middleware on every bind: a request whose Host header is not one of ``hosts`` (with any port) is
    refused with 421, one whose Origin header names another host with 403, each with a JSON body saying what
    to change. A browser page of another site (DNS rebinding) sends its own name in both; MCP clients that are
    not browsers send the Host they connected to and no Origin."""

    def __init__(self, app: Any, hosts: list[str]):
        self.app = app
        self.hosts = {h.lower() for h in hosts}

    def _known(self, hostport: str) -> bool:
        hostport = hostport.strip().lower()
        if hostport.startswith("["):
            name = hostport[: hostport.find("]") + 1] if "]" in hostport else hostport
        else:
            name = hostport.rsplit(":", 1)[0] if hostport.count(":") == 1 else hostport
        return name in self.hosts

    async def __call__(self, scope: dict[str, Any], receive: Any, send: Any) -> None:
        if scope["type"] not in ("http", "websocket"):
            await self.app(scope, receive, send)
            return
        headers = {k.lower(): v for k, v in scope.get("headers", [])}
        host = headers.get(b"host", b"").decode("latin-1")
        origin = headers.get(b"origin")
        fix = ("connect by one of the names this server answers to (" + ", ".join(sorted(self.hosts)) + "), "
               "or add the name to EWA_ALLOWED_HOSTS (comma-separated) when starting `ewa-mcp serve`")
        if not host or not self._known(host):
            await self._refuse(scope, send, 421, "misdirected_request",
                               f"the Host header {host[:100]!r} is not a name of this ewa-mcp server: {fix}")
            return
        if origin is not None:
            text = origin.decode("latin-1")
            scheme, sep, rest = text.partition("://")
            if not sep or scheme.lower() not in ("http", "https") or not self._known(rest.split("/", 1)[0]):
                await self._refuse(scope, send, 403, "forbidden_origin",
                                   f"requests from the web page origin {text[:100]!r} are refused (a page of "
                                   f"another site must not drive this server); {fix}")
                return
        await self.app(scope, receive, send)

    async def _refuse(self, scope: dict[str, Any], send: Any, status: int, error: str, message: str) -> None:
        if scope["type"] == "websocket":
            await send({"type": "websocket.close", "code": 1008, "reason": message[:120]})
            return
        body = json.dumps({"error": error, "error_description": message}).encode()
        await send({"type": "http.response.start", "status": status,
                    "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]})
        await send({"type": "http.response.body", "body": body})


class BearerTokenGuard:
    """ASGI middleware: refuses every HTTP request without ``Authorization: Bearer <token>`` with
    401 and a JSON body that says what to send."""

    def __init__(self, app: Any, token: str):
        self.app = app
        self._token = token.encode()  # compared in constant time

    async def __call__(self, scope: dict[str, Any], receive: Any, send: Any) -> None:
        if scope["type"] not in ("http", "websocket"):  # lifespan events carry no request
            await self.app(scope, receive, send)
            return
        values = [v for k, v in scope.get("headers", []) if k.lower() == b"authorization"]
        if len(values) == 1:
            scheme, _, presented = values[0].strip().partition(b" ")
            if scheme.lower() == b"bearer" and hmac.compare_digest(presented.strip(), self._token):
                await self.app(scope, receive, send)
                return
            problem = ("the Authorization header is not 'Bearer <token>'" if scheme.lower() != b"bearer"
                       else "the bearer token is wrong")
        elif values:
            problem = "the request has more than one Authorization header"
        else:
            problem = "the request has no Authorization header"
        await self._refuse(scope, send, problem, presented_credentials=bool(values))

    async def _refuse(self, scope: dict[str, Any], send: Any, problem: str, presented_credentials: bool) -> None:
        message = f"this ewa-mcp server requires a bearer token and {problem}: {HOW}"
        if scope["type"] == "websocket":
            await send({"type": "websocket.close", "code": 1008, "reason": message[:120]})
            return
        body = json.dumps({"error": "invalid_token" if presented_credentials else "unauthorized",
                           "error_description": message}).encode()
        challenge = 'Bearer realm="ewa-mcp"' + (', error="invalid_token"' if presented_credentials else "")
        await send({"type": "http.response.start", "status": 401,
                    "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()),
                                (b"www-authenticate", challenge.encode())]})
        await send({"type": "http.response.body", "body": body})


KEEP_ALIVE_S = 120


def serve_http(mcp: Any, settings: Settings) -> int:
    """Run the streamable HTTP app on ``settings.host``/``port`` until interrupted; 2 for a refused configuration."""
    import anyio
    import uvicorn

    host, port, allow_remote, token = settings.host, settings.port, settings.allow_remote, settings.token()

    if not is_loopback_host(host) and not allow_remote:
        print(f"refusing to listen on {host}: the server drives a browser and records runs; "
              "pass --allow-remote if you really mean it (every request then needs a bearer token)", file=sys.stderr)
        return 2
    try:
        required, generated = choose_token(host, token)
    except TokenError as exc:
        print(f"ewa-mcp serve: {exc}", file=sys.stderr)
        return 2
    # The SDK guards only the default loopback binds by the Host header; HostOriginGuard checks Host and Origin
    # on every bind (127.0.0.2 and 0.0.0.0 included), and the SDK is given the same names.
    from mcp.server.transport_security import TransportSecuritySettings

    hosts = allowed_hosts(host, settings.allowed_hosts)
    security = TransportSecuritySettings(allowed_hosts=[f"{h}:*" for h in hosts] + hosts,
                                         allowed_origins=[f"{s}://{h}{p}" for s in ("http", "https") for h in hosts
                                                          for p in (":*", "")])
    app: Any = mcp.streamable_http_app(host=host, transport_security=security)
    if required is not None:
        app = BearerTokenGuard(app, required)
        if generated:
            print(f"bearer token (shown once; clients send 'Authorization: Bearer <token>'): {required}",
                  file=sys.stderr)
        else:
            print("every request must carry the bearer token given with --token or "
                  f"{TOKEN_ENV} ('Authorization: Bearer <token>')", file=sys.stderr)
    app = HostOriginGuard(app, hosts)  # outermost: a request from a rebound name is refused before anything else
    print(f"MCP endpoint: http://{host}:{port}/mcp", file=sys.stderr)
    # uvicorn closes a connection idle for 5 s by default. A client that sends its next call just as that close
    # is under way gets a reset connection (a ReadError that ends its MCP session): under load (256 sessions on
    # 2 cores, benchmarks/bench_load.py) one in five sessions died that way. Agents often think longer than 5 s
    # between calls, so connections are kept for as long as a slow turn takes.
    config = uvicorn.Config(app, host=host, port=port, log_level="warning", timeout_keep_alive=KEEP_ALIVE_S)
    anyio.run(uvicorn.Server(config).serve)
    return 0
