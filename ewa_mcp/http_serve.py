"""Serving the MCP server over streamable HTTP, with a bearer token wherever it is reachable.

On a loopback address the server answers without a token (only this machine can reach it).
Bound past loopback (``--allow-remote``) every request must carry ``Authorization: Bearer
<token>``: the token given with ``--token`` or ``EWA_MCP_TOKEN``, or one generated at start and
printed once. A token given on loopback is required there too.

The MCP SDK's own auth (``AuthSettings`` + a ``TokenVerifier``) is built for OAuth: it needs an
authorization server's issuer URL and publishes protected-resource metadata pointing at it. A
shared static token has no such server, so a small ASGI guard in front of the whole app checks it.
"""

from __future__ import annotations

import hmac
import ipaddress
import json
import secrets
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
    if is_loopback_host(host):
        return None, False
    return secrets.token_urlsafe(32), True


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
    # The SDK guards loopback hosts against DNS rebinding by the Host header; past loopback the
    # Host header is the machine's name, and the token is what keeps other pages out.
    app: Any = mcp.streamable_http_app(host=host)
    if required is not None:
        app = BearerTokenGuard(app, required)
        if generated:
            print(f"bearer token (shown once; clients send 'Authorization: Bearer <token>'): {required}",
                  file=sys.stderr)
        else:
            print("every request must carry the bearer token given with --token or "
                  f"{TOKEN_ENV} ('Authorization: Bearer <token>')", file=sys.stderr)
    print(f"MCP endpoint: http://{host}:{port}/mcp", file=sys.stderr)
    config = uvicorn.Config(app, host=host, port=port, log_level="warning")
    anyio.run(uvicorn.Server(config).serve)
    return 0
