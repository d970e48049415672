"""The shop's catalogue: products, sizes, nutrition, stores and per-store prices and stock.

Read-only and shared by the web site, the task generator and the graders::

    from ewa_mcp.websites.shop import catalog
    catalog.load_products(); catalog.load_stores()
    catalog.price("prod-cheddar-cheese", "16 oz", "store-target-herald-square")
    catalog.cheapest_store("prod-cheddar-cheese", "16 oz")

Prices and stock come from data/products.json (built by catalog_build.py from specs.json).
Store coordinates come from the outdoor world's POIs when that data exists, so a store is
where the street agent can actually walk to.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from ewa_mcp.core.paths import PACKAGE_DIR

DATA_DIR = Path(__file__).resolve().parent / "data"
PRODUCTS_PATH = DATA_DIR / "products.json"
STORES_PATH = DATA_DIR / "stores.json"
# The outdoor world's points of interest (owned by the outdoor package; may not exist in every build).
POIS_PATH = PACKAGE_DIR / "envs" / "street" / "data" / "pois.json"


class CatalogError(LookupError):
    """An unknown product, size or store; the message lists what exists."""


@dataclass(frozen=True)
class Size:
    label: str
    grams: int | None = None
    ml: int | None = None
    count: int | None = None

    @property
    def amount_text(self) -> str:
        """Metric amount for display, e.g. "454 g", "946 ml", "12 items"."""
        parts = []
        if self.grams is not None:
            parts.append(f"{self.grams} g")
        if self.ml is not None:
            parts.append(f"{self.ml} ml")
        if self.count is not None and not self.label.lower().startswith(f"{self.count} ct"):
            parts.append(f"{self.count} {'item' if self.count == 1 else 'items'}")
        return ", ".join(parts)


@dataclass(frozen=True)
class Nutrition:
    serving_size: str
    calories: int
    protein_g: float
    fat_g: float
    carbs_g: float
    sugar_g: float
    fiber_g: float
    sodium_mg: float

    ROWS = (("Calories", "calories", ""), ("Protein", "protein_g", " g"), ("Total fat", "fat_g", " g"),
            ("Carbohydrates", "carbs_g", " g"), ("Sugars", "sugar_g", " g"), ("Dietary fiber", "fiber_g", " g"),
            ("Sodium", "sodium_mg", " mg"))

    def rows(self) -> list[tuple[str, str]]:
        out = []
        for label, attr, unit in self.ROWS:
            value = getattr(self, attr)
            text = f"{value:g}" if isinstance(value, float) else str(value)
            out.append((label, text + unit))
        return out


@dataclass(frozen=True)
class Offer:
    store_id: str
    size: str
    price: float
    stock: int


@dataclass(frozen=True)
class Category:
    slug: str
    name: str
    description: str


@dataclass(frozen=True)
class Product:
    id: str
    name: str
    brand: str
    category: str
    description: str
    tags: tuple[str, ...]
    kitchen_type: str | None
    sizes: tuple[Size, ...]
    nutrition: Nutrition | None
    offers: tuple[Offer, ...]

    def size(self, label: str) -> Size:
        for size in self.sizes:
            if size.label == label:
                return size
        raise CatalogError(f"{self.id} has no size {label!r}; its sizes are {[s.label for s in self.sizes]}")

    def offer(self, size: str, store_id: str) -> Offer | None:
        for offer in self.offers:
            if offer.size == size and offer.store_id == store_id:
                return offer
        return None

    def offers_for_size(self, size: str) -> list[Offer]:
        return [o for o in self.offers if o.size == size]

    @property
    def store_ids(self) -> list[str]:
        return list(dict.fromkeys(o.store_id for o in self.offers))

    @property
    def lowest_price(self) -> float:
        return min(o.price for o in self.offers)


@dataclass(frozen=True)
class Store:
    id: str
    name: str
    chain: str
    address: str
    neighborhood: str
    hours: str
    phone: str
    pickup_note: str
    lat: float | None = None  # from the outdoor world's POI of the same id
    lng: float | None = None


# ---------------------------------------------------------------- loading
@lru_cache(maxsize=1)
def _catalog_json() -> dict[str, Any]:
    return json.loads(PRODUCTS_PATH.read_text(encoding="utf-8"))


def _product_from_json(item: dict[str, Any]) -> Product:
    nutrition = item.get("nutrition")
    return Product(
        id=item["id"], name=item["name"], brand=item["brand"], category=item["category"],
        description=item["description"], tags=tuple(item.get("tags", [])), kitchen_type=item.get("kitchen_type"),
        sizes=tuple(Size(**s) for s in item["sizes"]),
        nutrition=Nutrition(**nutrition) if nutrition else None,
        offers=tuple(Offer(**o) for o in item["offers"]),
    )


@lru_cache(maxsize=1)
def _products() -> dict[str, Product]:
    return {item["id"]: _product_from_json(item) for item in _catalog_json()["products"]}


def load_products() -> list[Product]:
    return list(_products().values())


def load_categories() -> list[Category]:
    return [Category(**c) for c in _catalog_json()["categories"]]


def _poi_records() -> dict[str, dict[str, Any]]:
    """Store POIs of the outdoor world keyed by id ({} until the outdoor data exists)."""
    if not POIS_PATH.exists():
        return {}
    return {r["id"]: r for r in json.loads(POIS_PATH.read_text(encoding="utf-8"))}


@lru_cache(maxsize=1)
def _stores() -> dict[str, Store]:
    pois = _poi_records()
    stores = {}
    for item in json.loads(STORES_PATH.read_text(encoding="utf-8"))["stores"]:
        poi = pois.get(item["id"], {})
        lat, lng = poi.get("lat"), poi.get("lng")
        stores[item["id"]] = Store(**item, lat=float(lat) if lat is not None else None,
                                   lng=float(lng) if lng is not None else None)
    return stores


def load_stores() -> list[Store]:
    return list(_stores().values())


# ---------------------------------------------------------------- look-ups
def get_product(product_id: str) -> Product:
    try:
        return _products()[product_id]
    except KeyError:
        raise CatalogError(f"no product {product_id!r}; product ids look like 'prod-apple' "
                           f"(see load_products())") from None


def get_store(store_id: str) -> Store:
    try:
        return _stores()[store_id]
    except KeyError:
        raise CatalogError(f"no store {store_id!r}; stores are {sorted(_stores())}") from None


def get_category(slug: str) -> Category:
    for category in load_categories():
        if category.slug == slug:
            return category
    raise CatalogError(f"no category {slug!r}; categories are {[c.slug for c in load_categories()]}")


def _offer(product_id: str, size: str, store_id: str) -> Offer:
    product = get_product(product_id)
    product.size(size)
    get_store(store_id)
    offer = product.offer(size, store_id)
    if offer is None:
        raise CatalogError(f"{store_id} does not sell {product_id}; it is sold at {product.store_ids}")
    return offer


def price(product_id: str, size: str, store_id: str) -> float:
    """Shelf price in dollars of one unit of this size at this store."""
    return _offer(product_id, size, store_id).price


def stock(product_id: str, size: str, store_id: str) -> int:
    """Units on the shelf before any order (orders reduce it per episode on the site)."""
    return _offer(product_id, size, store_id).stock


def cheapest_store(product_id: str, size: str) -> str:
    """The store with the lowest price for this size; unique and in stock by construction."""
    product = get_product(product_id)
    product.size(size)
    offers = [o for o in product.offers_for_size(size) if o.stock > 0]
    return min(offers, key=lambda o: o.price).store_id


def products_in_category(slug: str) -> list[Product]:
    get_category(slug)
    return sorted((p for p in load_products() if p.category == slug), key=lambda p: p.name)


# ---------------------------------------------------------------- search
_WORD = re.compile(r"[a-z0-9]+")
MAX_QUERY_CHARS = 200


def normalize_word(word: str) -> str:
    """Crude singular form so "tomatoes" finds "tomato" and "berries" finds "berry"."""
    if len(word) > 4 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 4 and word.endswith(("oes", "shes", "ches", "xes")):
        return word[:-2]
    if len(word) > 3 and word.endswith("s") and not word.endswith("ss"):
        return word[:-1]
    return word


def words(text: str) -> list[str]:
    return [normalize_word(w) for w in _WORD.findall(text.lower())]


_STOPWORDS = {"a", "an", "the", "of", "and", "with", "for", "in", "to", "some"}


def head_noun(name: str) -> str:
    """The word a product name ends with before any comma: what the product is ("Tomato Basil
    Marinara" is a marinara, "Oat Milk, Original" a milk)."""
    found = words(name.split(",")[0])
    return found[-1] if found else ""


def search_products(query: str, category: str | None = None) -> list[Product]:
    """Products matching every word of the query (prefix match), best first.

    A word found in the name scores more than one found in the brand, tags or category, and
    those more than one found only in the description; a word naming what the product is (its
    head noun or kitchen type) scores a bonus, so "tomato" lists tomatoes before marinara."""
    terms = [w for w in words(query) if w not in _STOPWORDS]
    categories = {c.slug: c.name for c in load_categories()}
    scored = []
    for product in load_products():
        if category and product.category != category:
            continue
        fields = (
            (3, words(product.name) + words(product.kitchen_type or "")),
            (2, words(product.brand) + words(" ".join(product.tags)) + words(categories[product.category])),
            (1, words(product.description)),
        )
        what = {head_noun(product.name), normalize_word((product.kitchen_type or "").lower())}
        score = 0
        for term in terms:
            best = max((weight for weight, field_words in fields if any(w.startswith(term) for w in field_words)),
                       default=0)
            if best == 0:
                break
            score += best + (1 if term in what else 0)
        else:
            scored.append((-score, product.name, product))
    return [p for _, _, p in sorted(scored, key=lambda t: (t[0], t[1]))]
