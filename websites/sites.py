"""The one declaration of the embedded web sites: each site's app, default port, title, homepage
description and search page. serve.py, common.py (page titles) and the homepage read it; adding a site
is a package under websites/ plus one entry here (docs/extending.md)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Site:
    name: str  # the URL scheme tasks use: "recipes:/recipe/12"
    app: str  # "module:create_app"; a site whose module is missing in this build is skipped
    port: int  # default port of `ewa-mcp sites` (the MCP server picks free ports)
    title: str  # shown in every page's title and header
    description: str = ""  # the homepage's line for it ("" = not listed on the homepage)
    search_path: str | None = None  # the page the homepage's search box sends a query to (None = no search)


DECLARED: tuple[Site, ...] = (
    Site("home", "ewa_mcp.websites.home.app:create_app", 8701, "EWA Home"),
    Site("recipes", "ewa_mcp.websites.recipes.app:create_app", 8702, "Recipes",
         "Find recipes by diet, difficulty, ingredients and equipment, and follow them step by step.", "/"),
    Site("shop", "ewa_mcp.websites.shop.app:create_app", 8703, "Shop",
         "Buy groceries and household items for pickup at a store in Manhattan.", "/search"),
    Site("map", "ewa_mcp.websites.map.app:create_app", 8704, "Map",
         "Search places and get walking directions in New York, Boston, Philadelphia and Pittsburgh.", "/search"),
    Site("wiki", "ewa_mcp.websites.wiki.app:create_app", 8705, "Wiki",
         "An encyclopedia of landmarks, cities, countries, dishes and ingredients.", "/search"),
)
