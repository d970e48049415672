"""The browser world's task models: the start of a web episode and the web goal kinds it owns (graded by
checks.py from the sites' events). Declared on ``BROWSER`` (``__init__.py``), from which the kernel assembles the
task schema (ewa_mcp/core/taskmodel.py)."""

from __future__ import annotations

from typing import Literal

from ewa_mcp.core.taskmodel import StrictModel


class WebStart(StrictModel):
    # Site-relative URL such as "recipes:/" or "shop:/product/7"; the server maps site names
    # to the loopback ports it serves them on, so tasks never hard-code a host.
    start_url: str = "home:/"


class RecipeCompleted(StrictModel):
    """Web: the right recipe's last step was displayed."""

    kind: Literal["recipe_completed"] = "recipe_completed"
    recipe_id: str


class RecipesCompleted(StrictModel):
    """Web: the recipes the episode chose (the last ones it followed to their last step) are exactly these."""

    kind: Literal["recipes_completed"] = "recipes_completed"
    recipe_ids: list[str]


class OrderPlaced(StrictModel):
    """Web: an order exists with this product (and size, quantity, pickup store when given)."""

    kind: Literal["order_placed"] = "order_placed"
    product_id: str
    size: str | None = None
    quantity: int = 1
    store_id: str | None = None


class ItemRef(StrictModel):
    """One product and size of a shopping list."""

    product_id: str
    size: str


class OrdersSplit(StrictModel):
    """Web: the list was bought in exactly one order at each of ``store_ids`` (no other order), each item
    once in all (quantity 1, at either store: any split is fine), nothing else, and the orders' totals add
    up to at most ``max_total`` dollars."""

    kind: Literal["orders_split"] = "orders_split"
    items: list[ItemRef]
    store_ids: list[str]
    max_total: float


class DirectionsShown(StrictModel):
    """Web: the map site showed walking directions between these two places."""

    kind: Literal["directions_shown"] = "directions_shown"
    origin: str
    destination: str


class PageVisited(StrictModel):
    """Web: a page of a site whose path starts with ``path_prefix`` was viewed."""

    kind: Literal["page_visited"] = "page_visited"
    site: str
    path_prefix: str
