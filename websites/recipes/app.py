"""The recipes site: search with filters, a recipe page with a step viewer, generated images.

Routes
  /                       search and filters; all state in the URL (q, diet, difficulty, cuisine,
                          include*, exclude*, equipment*, page)
  /recipe/<id>?step=k     one recipe, showing step k of n with Previous / Next
  /image/<id>.svg         the recipe's generated illustration

Events (per episode): page_view, search {"query", "filters", "results"} and, on every step view,
recipe_step {"recipe_id", "step", "of"} — graders read "step == of" as "reached the last step".
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import RedirectResponse, Response
from starlette.routing import Route

from ..common import SiteContext, SiteEvents, exception_handlers, make_templates
from .catalog import (
    DIET_LABELS,
    DIFFICULTY_LABELS,
    EQUIPMENT_LABELS,
    MAX_QUERY_CHARS,
    PAGE_SIZE,
    QueryError,
    load_catalog,
)
from .illustrate import describe, recipe_svg

SITE = "recipes"
SITE_DIR = Path(__file__).resolve().parent
# Representative pages for benchmarks/bench_websites.py.
BENCH_URLS = [
    "/",
    "/?q=salad&diet=vegetarian",
    "/?q=toast&include=Tomato&exclude=Egg&equipment=Toaster",
    "/?difficulty=simple&page=2",
    "/recipe/r001",
    "/recipe/r002?step=6",
    "/image/r010.svg",
]


def _query_lists(request: Request) -> dict[str, list[str]]:
    return {key: request.query_params.getlist(key) for key in request.query_params.keys()}


def create_app(ctx: SiteContext) -> Starlette:
    templates = make_templates(SITE_DIR, ctx, SITE)
    templates.env.globals.update(diet_labels=DIET_LABELS, difficulty_labels=DIFFICULTY_LABELS,
                                 equipment_labels=EQUIPMENT_LABELS, max_query_chars=MAX_QUERY_CHARS)
    catalog = load_catalog()
    svg_cache: dict[str, bytes] = {}

    events = SiteEvents(ctx, SITE)

    def emit(request: Request, event: dict[str, Any]) -> None:
        events(request, **event)

    async def index(request: Request) -> Response:
        try:
            filters = catalog.parse_query(_query_lists(request))
            results = catalog.search(filters)
            shown, pages = catalog.page_of(results, filters.page)
        except QueryError as exc:
            raise HTTPException(exc.status, str(exc)) from None
        canonical = filters.to_query()
        if request.url.query != canonical.lstrip("?"):
            # Forms submit empty selects ("diet=&cuisine=") and any letter case; one clean URL per state
            # keeps what the agent reads (and what the events record) short and comparable.
            return RedirectResponse("/" + canonical, status_code=302)
        emit(request, {"type": "page_view", "path": request.url.path, "query": filters.to_query().lstrip("?")})
        if filters.active:
            emit(request, {"type": "search", "query": filters.q, "filters": filters.as_event(),
                           "results": len(results)})
        first = (filters.page - 1) * PAGE_SIZE + 1
        return templates.TemplateResponse(request, "index.html", {
            "filters": filters, "results": shown, "total": len(results), "pages": pages,
            "first": first, "last": first + len(shown) - 1, "catalog": catalog,
        })

    def recipe_or_404(recipe_id: str) -> dict[str, Any]:
        recipe = catalog.by_id.get(recipe_id)
        if recipe is None:
            shown = recipe_id if len(recipe_id) <= 40 else recipe_id[:40] + "…"
            raise HTTPException(404, f"There is no recipe with id {shown!r}. Search the recipes from the front page.")
        return recipe

    async def recipe_page(request: Request) -> Response:
        recipe = recipe_or_404(request.path_params["recipe_id"])
        n = len(recipe["steps"])
        given = request.query_params.getlist("step")
        raw = given[0].strip() if given else "1"
        if len(set(given)) > 1:
            raise HTTPException(400, "The 'step' parameter was given more than once; give one step number.")
        if not raw.isdigit() or len(raw) > 4:
            raise HTTPException(400, f"step must be a whole number from 1 to {n}, e.g. ?step=1.")
        step = int(raw)
        if not 1 <= step <= n:
            raise HTTPException(404, f"{recipe['name']} has {n} steps; step {step} does not exist. "
                                     f"Use a step from 1 to {n}.")
        emit(request, {"type": "page_view", "path": request.url.path, "query": f"step={step}"})
        emit(request, {"type": "recipe_step", "recipe_id": recipe["id"], "name": recipe["name"],
                       "step": step, "of": n})
        return templates.TemplateResponse(request, "recipe.html", {
            "recipe": recipe, "step": step, "of": n, "text": recipe["steps"][step - 1]["text"],
            "current": recipe["steps"][step - 1], "alt": describe(recipe),
        })

    async def image(request: Request) -> Response:
        recipe = recipe_or_404(request.path_params["recipe_id"])
        body = svg_cache.get(recipe["id"])
        if body is None:
            body = svg_cache.setdefault(recipe["id"], recipe_svg(recipe).encode())
        # The picture is a pure function of committed data, so browsers may keep it.
        return Response(body, media_type="image/svg+xml", headers={"Cache-Control": "public, max-age=86400"})

    routes = [
        Route("/", index),
        Route("/recipe/{recipe_id}", recipe_page),
        Route("/image/{recipe_id}.svg", image),
    ]
    return Starlette(routes=routes, exception_handlers=exception_handlers(ctx))
