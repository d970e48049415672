"""The homepage: a hub linking to every embedded site (the paper's homepage)."""

from __future__ import annotations

from pathlib import Path

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.routing import Route

from ..common import SiteContext, episode_of, exception_handlers, make_templates

SITE_DIR = Path(__file__).resolve().parent

DESCRIPTIONS = {
    "recipes": "Find recipes by diet, difficulty, ingredients and equipment, and follow them step by step.",
    "shop": "Buy groceries and household items for pickup at a store in Manhattan.",
    "map": "Search places and get walking directions in New York, Boston, Philadelphia and Pittsburgh.",
    "wiki": "An encyclopedia of landmarks, cities, countries, dishes and ingredients.",
}


def create_app(ctx: SiteContext) -> Starlette:
    templates = make_templates(SITE_DIR, ctx, "home")

    async def index(request: Request):
        ctx.emit(episode_of(request), {"site": "home", "type": "page_view", "path": "/"})
        sites = [(name, desc) for name, desc in DESCRIPTIONS.items() if name in ctx.urls]
        return templates.TemplateResponse(request, "index.html", {"sites": sites})

    return Starlette(routes=[Route("/", index)], exception_handlers=exception_handlers(ctx))
