"""Build the shop catalogue (data/products.json) from the hand-written specs (data/specs.json).

The specs give each product its sizes with a reference price; this generator turns them into
explicit per-store, per-size prices and stock so that the committed JSON is what the site,
the task generator and the graders all read. It is deterministic (hash-based, no RNG state)
and enforces the invariants the shopping task templates rely on:

* every (product, size) has exactly one cheapest store, and that store has it in stock;
* a larger size of a product costs more than a smaller one at the same store.

Run ``python -m ewa_mcp.websites.shop.catalog_build`` after editing specs.json.
"""

from __future__ import annotations

import hashlib
import json
import re
import sys
from pathlib import Path
from typing import Any

DATA_DIR = Path(__file__).resolve().parent / "data"
SPECS_PATH = DATA_DIR / "specs.json"
PRODUCTS_PATH = DATA_DIR / "products.json"

# Unit conversions for size labels such as "16 oz", "1.5 qt", "500 ml".
GRAMS_PER_UNIT = {"oz": 28.3495, "lb": 453.592, "g": 1.0, "kg": 1000.0}
ML_PER_UNIT = {"fl oz": 29.5735, "gal": 3785.41, "qt": 946.353, "pt": 473.176, "ml": 1.0, "l": 1000.0}
COUNT_UNITS = {"ct"}
_LABEL = re.compile(r"^(?P<amount>\d+(?:\.\d+)?)\s*(?P<unit>fl oz|[a-z]+)(?:\s+[a-z]+)?$")

# Per-product price offsets spread stores apart so the cheapest store varies by product.
MAX_OFFSET = 0.10
OUT_OF_STOCK_PERCENT = 12
PRICE_STEP = 0.10


class SpecError(ValueError):
    """The specs break a rule; the message names the product and what to change."""


def _fraction(*parts: str) -> float:
    """A stable number in [0, 1) derived from the parts (same on every machine and run)."""
    digest = hashlib.sha256("|".join(parts).encode()).digest()
    return int.from_bytes(digest[:8], "big") / 2**64


def parse_size(spec: dict[str, Any], product_id: str) -> dict[str, Any]:
    """Size label -> {label, grams, ml, count}; explicit fields in the spec win over the label."""
    label = spec["label"]
    size: dict[str, Any] = {"label": label, "grams": None, "ml": None, "count": None}
    match = _LABEL.match(label.lower())
    if match:
        amount, unit = float(match["amount"]), match["unit"]
        if unit in GRAMS_PER_UNIT:
            size["grams"] = round(amount * GRAMS_PER_UNIT[unit])
        elif unit in ML_PER_UNIT:
            size["ml"] = round(amount * ML_PER_UNIT[unit])
        elif unit in COUNT_UNITS:
            size["count"] = int(amount)
    for key in ("grams", "ml", "count"):
        if key in spec:
            size[key] = spec[key]
    if size["grams"] is None and size["ml"] is None and size["count"] is None and "sq ft" not in label:
        raise SpecError(f"{product_id}: size {label!r} has no amount; give grams, ml or count in specs.json")
    return size


def _shelf_price(value: float) -> float:
    """Round to a shelf price ending in 9 cents (3.839 -> 3.79), never below 0.19."""
    return max(0.19, round(round(value * 10) / 10 - 0.01, 2))


def _store_prices(product: dict[str, Any], size_price: float, stores: list[str],
                  factors: dict[str, dict[str, float]]) -> dict[str, float]:
    prices = {}
    for store_id in stores:
        offset = (_fraction(product["id"], store_id) * 2 - 1) * MAX_OFFSET
        prices[store_id] = _shelf_price(size_price * factors[store_id][product["category"]] * (1 + offset))
    # A unique cheapest store: nudge ties upward (in store order) until the minimum is unique.
    while True:
        low = min(prices.values())
        tied = [s for s in stores if prices[s] == low]
        if len(tied) == 1:
            return prices
        prices[tied[-1]] = round(prices[tied[-1]] + PRICE_STEP, 2)


def _stock(product_id: str, store_id: str, size: str, cheapest: bool) -> int:
    if not cheapest and _fraction("out", product_id, store_id, size) * 100 < OUT_OF_STOCK_PERCENT:
        return 0
    return 4 + int(_fraction("stock", product_id, store_id, size) * 37)


def build_catalog(specs: dict[str, Any]) -> dict[str, Any]:
    categories = {c["slug"]: c for c in specs["categories"]}
    factors = specs["store_price_factors"]
    seen: set[str] = set()
    products = []
    for spec in specs["products"]:
        pid = spec["id"]
        if pid in seen or not re.fullmatch(r"prod-[a-z0-9-]+", pid):
            raise SpecError(f"{pid}: product ids must be unique and look like prod-<slug>")
        seen.add(pid)
        if spec["category"] not in categories:
            raise SpecError(f"{pid}: unknown category {spec['category']!r}; use one of {sorted(categories)}")
        stores = spec.get("stores") or categories[spec["category"]]["stores"]
        if len(stores) < 2:
            raise SpecError(f"{pid}: sell it in at least two stores so 'the cheapest store' means something")
        sizes = [parse_size(s, pid) for s in spec["sizes"]]
        offers = []
        previous: dict[str, float] = {}
        for size_spec, size in zip(spec["sizes"], sizes):
            prices = _store_prices(spec, size_spec["price"], stores, factors)
            cheapest = min(prices, key=prices.__getitem__)
            for store_id in stores:
                if store_id in previous and prices[store_id] <= previous[store_id]:
                    raise SpecError(f"{pid}: size {size['label']!r} is not dearer than the size before it at "
                                    f"{store_id}; raise its reference price")
                offers.append({"store_id": store_id, "size": size["label"], "price": prices[store_id],
                               "stock": _stock(pid, store_id, size["label"], store_id == cheapest)})
            previous = prices
        products.append({
            "id": pid,
            "name": spec["name"],
            "brand": spec["brand"],
            "category": spec["category"],
            "description": spec["description"],
            "tags": spec.get("tags", []),
            "kitchen_type": spec.get("kitchen_type"),
            "sizes": sizes,
            "nutrition": spec.get("nutrition"),
            "offers": offers,
        })
    return {
        "generated_by": "python -m ewa_mcp.websites.shop.catalog_build (edit specs.json, not this file)",
        "categories": [{k: c[k] for k in ("slug", "name", "description")} for c in specs["categories"]],
        "products": products,
    }


def render(catalog: dict[str, Any]) -> str:
    return json.dumps(catalog, indent=1, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    specs = json.loads(SPECS_PATH.read_text(encoding="utf-8"))
    text = render(build_catalog(specs))
    PRODUCTS_PATH.write_text(text, encoding="utf-8")
    print(f"wrote {PRODUCTS_PATH} ({len(specs['products'])} products)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
