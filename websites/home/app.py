"""The homepage: a hub linking to every embedded site (the paper's homepage), with one search box
that forwards the query to the chosen site's own search page."""

from __future__ import annotations

from pathlib import Path
from urllib.parse import urlencode

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import RedirectResponse, Response
from starlette.routing import Route

from ..common import SiteContext, episode_of, exception_handlers, make_templates
from ..sites import DECLARED

SITE_DIR = Path(__file__).resolve().parent
MAX_QUERY_CHARS = 200

DESCRIPTIONS = {site.name: site.description for site in DECLARED if site.description}
# Each site's search page, sent the query as ?q= (declared in sites.py).
SEARCH_PATHS = {site.name: site.search_path for site in DECLARED if site.search_path is not None}
BENCH_URLS = ["/", "/go?site=recipes&q=toast"]


def create_app(ctx: SiteContext) -> Starlette:
    templates = make_templates(SITE_DIR, ctx, "home")

    def served() -> list[str]:
        return [name for name in DESCRIPTIONS if name in ctx.urls]

    async def index(request: Request) -> Response:
        ctx.emit(episode_of(request), {"site": "home", "type": "page_view", "path": "/"})
        sites = [(name, DESCRIPTIONS[name]) for name in served()]
        return templates.TemplateResponse(request, "index.html", {"sites": sites, "max_query_chars": MAX_QUERY_CHARS})

    async def go(request: Request) -> Response:
        """Forward the homepage search to a site: /go?site=wiki&q=Flatiron -> wiki:/search?q=Flatiron."""
        site = request.query_params.get("site", "").strip().lower()
        query = " ".join(request.query_params.get("q", "").split())
        choices = served()
        if site not in SEARCH_PATHS:
            raise HTTPException(400, f"Unknown site {site[:40]!r}; choose one of {', '.join(choices) or 'none'}.")
        if site not in choices:
            raise HTTPException(404, f"The {site} site is not running in this build; choose one of "
                                     f"{', '.join(choices) or 'none'}.")
        if len(query) > MAX_QUERY_CHARS:
            raise HTTPException(400, f"The search text is {len(query)} characters long; use at most "
                                     f"{MAX_QUERY_CHARS}.")
        ctx.emit(episode_of(request), {"site": "home", "type": "search", "query": query, "target": site})
        target = ctx.url(site, SEARCH_PATHS[site] if query else "/")
        if query:
            target += "?" + urlencode({"q": query})
        return RedirectResponse(target, status_code=303)

    return Starlette(routes=[Route("/", index), Route("/go", go)], exception_handlers=exception_handlers(ctx))
