"""What every embedded site shares: the episode identity, event emission, templates, errors.

Each site is a Starlette app built by ``create_app(ctx: SiteContext)``. The MCP server runs all
of them in-process on loopback ports (websites/serve.py); the browser context of an episode
adds the ``X-EWA-Episode`` header to every request, so per-episode state (carts, orders, event
logs) is keyed by it and concurrent episodes never see each other.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from jinja2 import ChoiceLoader, Environment, FileSystemLoader, select_autoescape
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import HTMLResponse, Response
from starlette.templating import Jinja2Templates

from .sites import DECLARED

EPISODE_HEADER = "x-ewa-episode"
ANONYMOUS = "anonymous"
WEBSITES_DIR = Path(__file__).resolve().parent
COMMON_TEMPLATES = WEBSITES_DIR / "templates"

SITE_TITLES = {site.name: site.title for site in DECLARED}


@dataclass
class SiteContext:
    """Handed to every site's create_app."""

    # site name -> base URL without trailing slash, e.g. {"recipes": "http://127.0.0.1:40123"}
    urls: dict[str, str] = field(default_factory=dict)
    # emit(episode_id, event): per-episode event sink (the episode's web_events.jsonl when served by the MCP server)
    emit: Callable[[str, dict[str, Any]], None] = lambda episode_id, event: None
    # where sites keep SQLite files; None means in-memory databases
    data_dir: Path | None = None

    def url(self, site: str, path: str = "/") -> str:
        return self.urls.get(site, "") + path


def episode_of(request: Request) -> str:
    value = request.headers.get(EPISODE_HEADER, "").strip()
    # Episode ids are short tokens; anything else is treated as anonymous rather than trusted.
    if value and len(value) <= 64 and all(c.isalnum() or c in "-_." for c in value):
        return value
    return ANONYMOUS


class SiteEvents:
    """A site's event emitter: every event names its site and goes to the requesting episode's log."""

    def __init__(self, ctx: SiteContext, site: str):
        self.ctx, self.site = ctx, site

    def __call__(self, request: Request, type: str, **fields: Any) -> None:  # noqa: A002 - the event's key
        self.ctx.emit(episode_of(request), {"site": self.site, "type": type, **fields})

    def page_view(self, request: Request, **fields: Any) -> None:
        if request.url.query:
            fields.setdefault("query", request.url.query)
        self(request, "page_view", path=request.url.path, **fields)


def make_templates(site_dir: Path, ctx: SiteContext, site: str) -> Jinja2Templates:
    loader = ChoiceLoader([FileSystemLoader(site_dir / "templates"), FileSystemLoader(COMMON_TEMPLATES)])
    env = Environment(loader=loader, autoescape=select_autoescape(["html", "xml"]))
    env.globals.update(site_urls=ctx.urls, site=site, site_title=SITE_TITLES.get(site, site), site_titles=SITE_TITLES)
    return Jinja2Templates(env=env)


def error_page(status: int, message: str, ctx: SiteContext | None = None) -> HTMLResponse:
    home = ctx.url("home", "/") if ctx else "/"
    body = (
        "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>"
        f"{status} error</title></head><body><main><h1>Error {status}</h1><p role='alert'>{html.escape(message)}</p>"
        f"<p><a href='{html.escape(home)}'>Back to the homepage</a></p></main></body></html>"
    )
    return HTMLResponse(body, status_code=status)


def exception_handlers(ctx: SiteContext) -> dict[Any, Callable[..., Any]]:
    async def http_error(request: Request, exc: HTTPException) -> Response:
        return error_page(exc.status_code, str(exc.detail), ctx)

    async def server_error(request: Request, exc: Exception) -> Response:  # never leak a traceback
        return error_page(500, "The site hit an internal error.", ctx)

    return {HTTPException: http_error, Exception: server_error}


class NoStoreHtml:
    """ASGI wrapper: every HTML page goes out with ``Cache-Control: no-store``.

    The pages are per episode (a cart, an order) and each view of one is an event the graders read
    (``page_view``), so the browser must fetch every page it shows, going back and forward included,
    as sites with per-user pages ask. Images keep their own caching headers."""

    def __init__(self, app: Any):
        self.app = app

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return

        async def send_no_store(message: Any) -> None:
            if message["type"] == "http.response.start":
                headers = list(message.get("headers", []))
                content_type = next((v for k, v in headers if k.lower() == b"content-type"), b"")
                if content_type.startswith(b"text/html") and not any(k.lower() == b"cache-control" for k, _ in headers):
                    message = {**message, "headers": [*headers, (b"cache-control", b"no-store")]}
            await send(message)

        await self.app(scope, receive, send_no_store)

