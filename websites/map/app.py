"""The map site: place search and walking directions over the outdoor world's street graphs.

Pages are URL-addressable (``/search?q=``, ``/place/<id>``, ``/directions?from=&to=``); the
directions form takes free text (a place name, an address, an intersection) or a place / node
id, and resolves it to one place. Directions are the outdoor world's own shortest walking path,
so the turn-by-turn list the agent reads is exactly the street graph it then walks.
"""

from __future__ import annotations

import math
import threading
from urllib.parse import urlencode
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import Response
from starlette.routing import Route

from ..common import SiteContext, SiteEvents, exception_handlers, make_templates
from .places import Resolution, WorldAdapter
from .svgmap import Marker, render_map_svg

SITE_DIR = Path(__file__).resolve().parent
# Pages benchmarks/bench_websites.py times: search, a short route, and a long cross-town one
# (the SVG map is what makes directions pages the site's slowest).
BENCH_URLS = ["/", "/search?q=museum", "/directions?from=Empire+State+Building&to=Times+Square",
              "/directions?from=Intrepid+Museum&to=Stuyvesant+Square"]
MAX_QUERY_CHARS = 200
SEARCH_LIMIT = 10
START_COLOR, END_COLOR, PLACE_COLOR = "#1f8a3b", "#c62828", "#c62828"
# Facts a street map would show; encyclopedic facts (year built, architect, height) belong to the wiki.
MAP_FACTS = {"opening_hours": "Opening hours", "chain": "Operator", "sells": "Sells", "cuisine": "Cuisine"}


def walking_minutes(duration_s: float) -> int:
    return max(1, math.ceil(duration_s / 60))


def directions_query(origin: str, destination: str, via: str = "") -> str:
    """The query string of a directions page (``via`` only when there is one)."""
    return urlencode([("from", origin), *([("via", via)] if via else []), ("to", destination)])


def record_id(place: Any) -> str:
    """The id a site event records for a place: an address place's point of interest, else its own id."""
    return getattr(place, "refers_to", None) or place.id


def create_app(ctx: SiteContext, world: Any = None) -> Starlette:
    """``world`` defaults to the process-wide outdoor world, loaded in the background from here on."""
    templates = make_templates(SITE_DIR, ctx, "map")
    places = WorldAdapter(world)
    if world is None:
        # Load the street graphs in the background now, so the first map page does not pay for it.
        threading.Thread(target=lambda: places.world, name="ewa-map-world", daemon=True).start()

    emit = SiteEvents(ctx, "map")
    page_view = emit.page_view

    def render(request: Request, template: str, status: int = 200, **context: Any) -> Response:
        context.setdefault("cities", places.cities())
        context.setdefault("directions_query", directions_query)
        return templates.TemplateResponse(request, template, context, status_code=status)

    def text_param(request: Request, name: str) -> str:
        value = request.query_params.get(name, "").strip()
        if len(value) > MAX_QUERY_CHARS:
            raise HTTPException(400, f"The {name!r} text is too long ({len(value)} characters); use at most "
                                     f"{MAX_QUERY_CHARS}.")
        return value

    def city_param(request: Request) -> str | None:
        city = text_param(request, "city")
        if city and city not in places.cities():
            raise HTTPException(400, f"Unknown city {city!r}; choose one of: {', '.join(places.cities())}.")
        return city or None

    # ------------------------------------------------------------ pages
    async def home(request: Request) -> Response:
        page_view(request)
        return render(request, "home.html")

    async def search(request: Request) -> Response:
        query, city = text_param(request, "q"), city_param(request)
        page_view(request)
        results = places.search(query, city, SEARCH_LIMIT) if query else []
        if query:
            emit(request, "search", query=query, city=city, results=len(results))
        return render(request, "search.html", query=query, city=city or "", results=results, searched=bool(query))

    async def place_page(request: Request) -> Response:
        place = places.place(request.path_params["place_id"])
        if place is None:
            raise HTTPException(404, f"There is no place {request.path_params['place_id']!r}; search for it by "
                                     f"name on the map's search page.")
        page_view(request)
        svg = render_map_svg(
            title=f"Map around {place.name}",
            description=f"Streets around {place.name}, {place.address}; the red marker is the place.",
            streets=places.segments(place.city), markers=[Marker((place.lat, place.lng), "P", place.name, PLACE_COLOR)],
            margin_m=200)
        facts = [(MAP_FACTS[k], v) for k, v in (place.facts or {}).items() if k in MAP_FACTS]
        return render(request, "place.html", place=place, facts=facts, svg=svg)

    async def directions(request: Request) -> Response:
        origin_text, destination_text = text_param(request, "from"), text_param(request, "to")
        via_text = text_param(request, "via")
        page_view(request)
        context: dict[str, Any] = {"origin_text": origin_text, "destination_text": destination_text,
                                   "via_text": via_text, "route": None, "errors": [], "choices": {}, "via": None}
        # A field sent as a place id (a link from the shop, a did-you-mean choice) shows that place's name in
        # the form, never the internal id; the id still travels in the page's links.
        sent = {"from": origin_text, "to": destination_text, "via": via_text}
        context["shown"] = {field: place.name for field, text in sent.items()
                            if text and (place := places.place(text)) is not None}
        if not origin_text or not destination_text:
            return render(request, "directions.html", **context)  # an empty or half-filled form
        resolved: dict[str, Resolution] = {"from": places.resolve(origin_text), "to": places.resolve(destination_text)}
        if via_text:
            resolved["via"] = places.resolve(via_text)
        # A field sent as a place id (a link from the shop, a did-you-mean choice) shows that place's name in
        # the form, never the internal id; the id still travels in the page's links.
        for field, res in resolved.items():
            label = {"from": "Start", "to": "Destination", "via": "Via"}[field]
            if res.error:
                context["errors"].append(f"{label}: {res.error}")
            elif res.choices:
                context["choices"][field] = res.choices
        if context["errors"] or context["choices"]:
            return render(request, "directions.html", status=404 if context["errors"] else 200, **context)
        origin, destination = resolved["from"].place, resolved["to"].place
        via = resolved["via"].place if "via" in resolved else None
        for other in [p for p in (via, destination) if p is not None]:
            if origin.city != other.city:
                context["errors"].append(
                    f"{origin.name} is in {places.city_name(origin.city)} and {other.name} is in "
                    f"{places.city_name(other.city)}; walking directions need all places in the same city.")
                return render(request, "directions.html", status=422, **context)
        try:
            route = places.directions(origin, destination, via)
        except ValueError as exc:  # WorldError: e.g. no connected walking route
            context["errors"].append(str(exc))
            return render(request, "directions.html", status=422, **context)
        # An address stands for the place there in the record (a task may name it either way); the page
        # itself shows only the address. A route via a waypoint is recorded as its two legs.
        legs = [(origin, destination)] if via is None else [(origin, via), (via, destination)]
        for start, end in legs:
            emit(request, "directions", origin=record_id(start), destination=record_id(end), city=route.city,
                 distance_m=route.distance_m, **({"via": record_id(via)} if via is not None else {}))
        coords = places.route_coordinates(route)
        svg = render_map_svg(
            title=f"Walking route from {origin.name} to {destination.name}",
            description=(f"Map of the {round(route.distance_m)} metre walking route, drawn in blue from the green "
                         f"marker A ({origin.name}) to the red marker B ({destination.name}). The numbered "
                         f"directions list on this page describes the same route step by step."),
            streets=places.segments(origin.city), route=coords, label_first=[step.street for step in route.steps],
            markers=[Marker(coords[0], "A", origin.name, START_COLOR), Marker(coords[-1], "B", destination.name,
                                                                                   END_COLOR)])
        context.update(route=route, origin=origin, destination=destination, via=via, svg=svg,
                       minutes=walking_minutes(route.duration_s), city_name=places.city_name(origin.city))
        return render(request, "directions.html", **context)

    routes = [
        Route("/", home),
        Route("/search", search),
        Route("/place/{place_id}", place_page),
        Route("/directions", directions),
    ]
    return Starlette(routes=routes, exception_handlers=exception_handlers(ctx))
