"""The shopping site: search, categories, product pages, cart, wishlist, checkout and orders.

State (carts, wishlists, orders) is server-side per episode (``X-EWA-Episode``), so any number
of tabs see the same cart. Every change is a POST answered by a redirect to a page (so reloads
never repeat an order); refused changes re-render the page with the reason and a 4xx status.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any
from urllib.parse import urlencode

from starlette.applications import Starlette
from starlette.datastructures import FormData
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import RedirectResponse, Response
from starlette.routing import Route

from ..common import SiteContext, SiteEvents, episode_of, exception_handlers, make_templates
from . import catalog
from .state import FULFILMENTS, MAX_QUANTITY, ShopError, ShopState

SITE_DIR = Path(__file__).resolve().parent
SORTS = {"relevance": "Best match", "name": "Name (A-Z)", "price": "Lowest price", "calories": "Fewest calories"}
MAX_FIELD_CHARS = 100


def _cents(amount_cents: int) -> str:
    return f"${amount_cents / 100:,.2f}"


def _dollars(amount: float) -> str:
    return f"${amount:,.2f}"


async def _form(request: Request) -> FormData:
    try:
        return await request.form()
    except Exception:  # malformed bodies (bad multipart boundary, wrong content type)
        raise HTTPException(400, "The form could not be read; submit it from the page's own form.") from None


def _text(form: FormData, name: str, required: bool = True) -> str:
    value = form.get(name)
    if value is None or not isinstance(value, str) or (required and not value.strip()):
        if required:
            raise HTTPException(400, f"The form is missing the field {name!r}; submit it from the page's own form.")
        return ""
    if len(value) > MAX_FIELD_CHARS:
        raise HTTPException(400, f"The field {name!r} is too long (at most {MAX_FIELD_CHARS} characters).")
    return value.strip()


def _int(form: FormData, name: str) -> int:
    raw = _text(form, name)
    try:
        return int(raw)
    except ValueError:
        raise HTTPException(400, f"The field {name!r} must be a whole number, not {raw!r}.") from None


def create_app(ctx: SiteContext) -> Starlette:
    templates = make_templates(SITE_DIR, ctx, "shop")
    templates.env.filters["cents"] = _cents  # state keeps integer cents
    templates.env.filters["dollars"] = _dollars  # the catalogue's shelf prices are dollars
    db_path = ctx.data_dir / "shop.sqlite3" if ctx.data_dir is not None else None
    if db_path is not None:
        db_path.parent.mkdir(parents=True, exist_ok=True)
    state = ShopState(db_path)
    categories = catalog.load_categories()
    category_names = {c.slug: c.name for c in categories}
    stores = catalog.load_stores()

    emit = SiteEvents(ctx, "shop")
    page_view = emit.page_view

    def render(request: Request, template: str, status: int = 200, **context: Any) -> Response:
        episode = episode_of(request)
        context.update(categories=categories, category_names=category_names, stores=stores,
                       cart_count=state.cart_count(episode), max_quantity=MAX_QUANTITY, map_url=ctx.url("map", ""))
        return templates.TemplateResponse(request, template, context, status_code=status)

    def product_or_404(product_id: str) -> catalog.Product:
        try:
            return catalog.get_product(product_id)
        except catalog.CatalogError:
            raise HTTPException(404, f"There is no product {product_id!r}. Search the shop to find products.") from None

    # ------------------------------------------------------------ browsing
    async def home(request: Request) -> Response:
        page_view(request)
        featured = [catalog.get_product(pid) for pid in
                    ("prod-apple", "prod-cheddar-cheese", "prod-olive-oil", "prod-salmon-fillet", "prod-eggs",
                     "prod-paper-towels")]
        return render(request, "home.html", featured=featured)

    async def search(request: Request) -> Response:
        query = request.query_params.get("q", "")
        category = request.query_params.get("category", "")
        sort = request.query_params.get("sort", "relevance") or "relevance"
        if len(query) > catalog.MAX_QUERY_CHARS:
            raise HTTPException(400, f"The search text is too long ({len(query)} characters); "
                                     f"use at most {catalog.MAX_QUERY_CHARS}.")
        if category and category not in category_names:
            raise HTTPException(400, f"Unknown category {category!r}; choose one of: {', '.join(category_names)}.")
        if sort not in SORTS:
            raise HTTPException(400, f"Unknown sort order {sort!r}; choose one of: {', '.join(SORTS)}.")
        page_view(request)
        results: list[catalog.Product] = []
        if query.strip() or category:
            results = _sorted(catalog.search_products(query, category or None), sort)
            emit(request, "search", query=query, category=category or None, results=len(results))
        return render(request, "search.html", query=query, category=category, sort=sort, sorts=SORTS,
                      results=results, searched=bool(query.strip() or category))

    async def category_page(request: Request) -> Response:
        slug = request.path_params["slug"]
        if slug not in category_names:
            raise HTTPException(404, f"There is no category {slug!r}; the categories are listed on the shop's "
                                     f"homepage.")
        sort = request.query_params.get("sort", "name") or "name"
        if sort not in SORTS:
            raise HTTPException(400, f"Unknown sort order {sort!r}; choose one of: {', '.join(SORTS)}.")
        page_view(request)
        return render(request, "category.html", category=catalog.get_category(slug), sort=sort, sorts=SORTS,
                      results=_sorted(catalog.products_in_category(slug), sort))

    async def product_page(request: Request) -> Response:
        product = product_or_404(request.path_params["product_id"])
        page_view(request)
        return render_product(request, product)

    def render_product(request: Request, product: catalog.Product, error: str | None = None, status: int = 200,
                       notice: str | None = None) -> Response:
        episode = episode_of(request)
        table = []
        for store in stores:
            cells = []
            for size in product.sizes:
                offer = product.offer(size.label, store.id)
                left = state.available(episode, product.id, size.label, store.id) if offer else 0
                cells.append({"size": size.label, "offer": offer, "left": left})
            table.append({"store": store, "cells": cells})
        return render(request, "product.html", status=status, product=product, table=table, error=error,
                      notice=notice, sold_at=[s for s in stores if s.id in product.store_ids])

    async def stores_page(request: Request) -> Response:
        page_view(request)
        return render(request, "stores.html")

    async def store_page(request: Request) -> Response:
        store_id = request.path_params["store_id"]
        try:
            store = catalog.get_store(store_id)
        except catalog.CatalogError:
            raise HTTPException(404, f"There is no store {store_id!r}; see the Stores page.") from None
        page_view(request)
        return render(request, "store.html", store=store,
                      product_count=sum(1 for p in catalog.load_products() if store.id in p.store_ids))

    # ------------------------------------------------------------ cart
    async def cart_add(request: Request) -> Response:
        form = await _form(request)
        product = product_or_404(_text(form, "product_id"))
        size, store_id, quantity = _text(form, "size"), _text(form, "store_id"), _int(form, "quantity")
        try:
            line = state.add_to_cart(episode_of(request), product.id, size, store_id, quantity)
        except ShopError as exc:
            return render_product(request, product, error=exc.message, status=exc.status)
        emit(request, "add_to_cart", product_id=product.id, size=size, quantity=quantity, store_id=store_id,
             line_quantity=line.quantity)
        return RedirectResponse(f"/cart?{urlencode({'added': line.line_id})}", status_code=303)

    async def cart_page(request: Request) -> Response:
        page_view(request)
        return render_cart(request)

    def render_cart(request: Request, error: str | None = None, status: int = 200) -> Response:
        episode = episode_of(request)
        lines = state.cart(episode)
        added = request.query_params.get("added", "")
        added_line = next((line for line in lines if str(line.line_id) == added), None)
        return render(request, "cart.html", status=status, lines=lines, error=error, added_line=added_line,
                      total=sum(line.subtotal_cents for line in lines))

    async def cart_update(request: Request) -> Response:
        form = await _form(request)
        line_id, quantity = _int(form, "line_id"), _int(form, "quantity")
        episode = episode_of(request)
        try:
            line = (state.remove_cart_line(episode, line_id) if quantity == 0
                    else state.update_cart_line(episode, line_id, quantity))
        except ShopError as exc:
            if exc.status == 404:
                raise HTTPException(404, exc.message) from None
            return render_cart(request, error=exc.message, status=exc.status)
        emit(request, "cart_update", product_id=line.product.id, size=line.size, store_id=line.store.id,
             quantity=quantity)
        return RedirectResponse("/cart", status_code=303)

    async def cart_remove(request: Request) -> Response:
        form = await _form(request)
        try:
            line = state.remove_cart_line(episode_of(request), _int(form, "line_id"))
        except ShopError as exc:
            raise HTTPException(exc.status, exc.message) from None
        emit(request, "cart_remove", product_id=line.product.id, size=line.size, store_id=line.store.id)
        return RedirectResponse("/cart", status_code=303)

    # ------------------------------------------------------------ wishlist
    async def wishlist_add(request: Request) -> Response:
        form = await _form(request)
        product = product_or_404(_text(form, "product_id"))
        size = _text(form, "size", required=False)
        try:
            state.add_to_wishlist(episode_of(request), product.id, size)
        except ShopError as exc:
            return render_product(request, product, error=exc.message, status=exc.status)
        emit(request, "add_to_wishlist", product_id=product.id, size=size or None)
        return RedirectResponse("/wishlist", status_code=303)

    async def wishlist_remove(request: Request) -> Response:
        form = await _form(request)
        try:
            item = state.remove_from_wishlist(episode_of(request), _int(form, "item_id"))
        except ShopError as exc:
            raise HTTPException(exc.status, exc.message) from None
        emit(request, "remove_from_wishlist", product_id=item.product.id, size=item.size or None)
        return RedirectResponse("/wishlist", status_code=303)

    async def wishlist_page(request: Request) -> Response:
        page_view(request)
        return render(request, "wishlist.html", items=state.wishlist(episode_of(request)))

    # ------------------------------------------------------------ checkout and orders
    def render_checkout(request: Request, selected: str = "", error: str | None = None,
                        status: int = 200, fulfilment: str = "pickup") -> Response:
        """The order summary priced at ONE pickup store, the one chosen (as a real store's checkout does):
        that store's prices, stock and total only. Other stores' prices are on each product page; comparing
        stores is the buyer's work, so no page lists every store's total or which stores can fill the cart."""
        episode = episode_of(request)
        lines = state.cart(episode)
        line_stores = {line.store.id for line in lines}
        preselected = None
        if not selected and len(line_stores) == 1:
            selected = next(iter(line_stores))  # everything was added for one store: preselect it
            preselected = next(line.store for line in lines)  # and say so on the page
        quote = state.quote(episode, selected) if lines and selected in {s.id for s in stores} else None
        return render(request, "checkout.html", status=status, lines=lines, quote=quote, selected=selected,
                      error=error, fulfilment=fulfilment, preselected=preselected)

    async def checkout_page(request: Request) -> Response:
        store_id = request.query_params.get("store_id", "")
        fulfilment = request.query_params.get("fulfilment", "") or "pickup"
        if len(store_id) > MAX_FIELD_CHARS or (store_id and store_id not in {s.id for s in stores}):
            raise HTTPException(400, f"Unknown pickup store {store_id[:40]!r}; choose one of the stores listed "
                                     f"on the checkout page.")
        if fulfilment not in FULFILMENTS:
            raise HTTPException(400, f"Unknown fulfilment {fulfilment[:40]!r}; choose pickup or delivery.")
        page_view(request)  # its query names the store looked at
        return render_checkout(request, selected=store_id, fulfilment=fulfilment)

    async def checkout_submit(request: Request) -> Response:
        form = await _form(request)
        store_id = _text(form, "store_id", required=False)
        fulfilment = _text(form, "fulfilment", required=False) or "pickup"
        episode = episode_of(request)
        if fulfilment not in FULFILMENTS:
            return render_checkout(request, selected=store_id, status=400,
                                   error=f"Unknown fulfilment {fulfilment[:40]!r}; choose pickup or delivery.")
        if not store_id:
            return render_checkout(request, error="Choose a pickup store before placing the order.", status=400)
        if store_id not in {s.id for s in stores}:
            return render_checkout(request, error=f"Unknown pickup store {store_id!r}; choose one of the listed "
                                                  f"stores.", status=400)
        try:
            order = state.place_order(episode, store_id, fulfilment)
        except ShopError as exc:
            emit(request, "checkout_failed", store_id=store_id, reason=exc.message)
            return render_checkout(request, selected=store_id, error=exc.message, status=exc.status,
                                   fulfilment=fulfilment)
        emit(request, "order_placed", order=order.event_payload())
        return RedirectResponse(f"/orders/{order.order_id}?placed=1", status_code=303)

    async def orders_page(request: Request) -> Response:
        page_view(request)
        return render(request, "orders.html", orders=state.orders(episode_of(request)))

    async def order_page(request: Request) -> Response:
        try:
            order = state.order(episode_of(request), request.path_params["order_id"])
        except ShopError as exc:
            raise HTTPException(exc.status, exc.message) from None
        page_view(request)
        return render(request, "order.html", order=order, placed=request.query_params.get("placed") == "1")

    routes = [
        Route("/", home),
        Route("/search", search),
        Route("/category/{slug}", category_page),
        Route("/product/{product_id}", product_page),
        Route("/stores", stores_page),
        Route("/store/{store_id}", store_page),
        Route("/cart", cart_page),
        Route("/cart/add", cart_add, methods=["POST"]),
        Route("/cart/update", cart_update, methods=["POST"]),
        Route("/cart/remove", cart_remove, methods=["POST"]),
        Route("/wishlist", wishlist_page),
        Route("/wishlist/add", wishlist_add, methods=["POST"]),
        Route("/wishlist/remove", wishlist_remove, methods=["POST"]),
        Route("/checkout", checkout_page),
        Route("/checkout", checkout_submit, methods=["POST"]),
        Route("/orders", orders_page),
        Route("/orders/{order_id}", order_page),
    ]
    app = Starlette(routes=routes, exception_handlers=exception_handlers(ctx))
    app.state.shop = state  # reset_episode(episode_id) and snapshot(episode_id) for the server
    app.state.reset_episode = state.reset_episode
    return app


def _sorted(products: list[catalog.Product], sort: str) -> list[catalog.Product]:
    if sort == "name":
        return sorted(products, key=lambda p: p.name)
    if sort == "price":
        return sorted(products, key=lambda p: (p.lowest_price, p.name))
    if sort == "calories":  # products without nutrition (non-food) go last
        return sorted(products, key=lambda p: (p.nutrition is None, p.nutrition.calories if p.nutrition else 0,
                                               p.name))
    return products  # relevance: search order
