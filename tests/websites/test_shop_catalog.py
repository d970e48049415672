"""The shop catalogue: the data invariants the shopping task templates rely on, and the Python API."""

from __future__ import annotations

import copy
import json
from collections import defaultdict

import pytest

from ewa_mcp.websites.shop import catalog, catalog_build

KITCHEN_FOODS = {"prod-apple": "Apple", "prod-bread": "Bread", "prod-eggs": "Egg", "prod-lettuce": "Lettuce",
                 "prod-potato": "Potato", "prod-tomato": "Tomato"}
BUY_ONLINE = ["prod-cheddar-cheese", "prod-mozzarella", "prod-chicken-breast", "prod-butter", "prod-olive-oil",
              "prod-avocado", "prod-peanut-butter", "prod-salmon-fillet", "prod-bacon", "prod-sea-salt",
              "prod-black-pepper", "prod-garlic", "prod-onion", "prod-lemon", "prod-honey", "prod-basil"]
STORE_IDS = {"store-wholefoods-union-square", "store-traderjoes-chelsea", "store-target-herald-square",
             "store-cvs-midtown"}


def test_committed_products_json_is_the_generator_output():
    specs = json.loads(catalog_build.SPECS_PATH.read_text(encoding="utf-8"))
    expected = catalog_build.render(catalog_build.build_catalog(specs))
    assert catalog_build.PRODUCTS_PATH.read_text(encoding="utf-8") == expected, (
        "products.json is stale: run python -m ewa_mcp.websites.shop.catalog_build")


def test_catalogue_size_and_fixed_ids():
    products = {p.id: p for p in catalog.load_products()}
    assert len(products) >= 60
    for pid in [*KITCHEN_FOODS, *BUY_ONLINE]:
        assert pid in products, pid
    assert {pid: p.kitchen_type for pid, p in products.items() if p.kitchen_type} == KITCHEN_FOODS
    assert any(p.nutrition is None for p in products.values()), "the catalogue should include non-food items"
    assert {s.id for s in catalog.load_stores()} == STORE_IDS


def test_every_size_has_one_cheapest_store_in_stock():
    for product in catalog.load_products():
        for size in product.sizes:
            offers = product.offers_for_size(size.label)
            assert len(offers) >= 2, (product.id, size.label)
            low = min(o.price for o in offers)
            cheapest = [o for o in offers if o.price == low]
            assert len(cheapest) == 1, (product.id, size.label, cheapest)
            assert cheapest[0].stock > 0
            assert catalog.cheapest_store(product.id, size.label) == cheapest[0].store_id


def test_price_depends_on_size_and_store():
    distinct_store_prices = 0
    for product in catalog.load_products():
        for store_id in product.store_ids:
            prices = [product.offer(s.label, store_id).price for s in product.sizes]
            assert prices == sorted(prices) and len(set(prices)) == len(prices), (product.id, store_id, prices)
        first = product.sizes[0].label
        distinct_store_prices += len({o.price for o in product.offers_for_size(first)}) > 1
    assert distinct_store_prices == len(catalog.load_products())
    # The cheapest store varies across the catalogue, so "the cheapest store" is a real question.
    winners = {catalog.cheapest_store(p.id, s.label) for p in catalog.load_products() for s in p.sizes}
    assert winners == STORE_IDS


def test_sizes_have_distinct_amounts_for_size_questions():
    for product in catalog.load_products():
        for unit in ("grams", "ml", "count"):
            amounts = [getattr(s, unit) for s in product.sizes if getattr(s, unit) is not None]
            assert len(amounts) == len(set(amounts)), (product.id, unit, amounts)
        assert len({s.label for s in product.sizes}) == len(product.sizes)
    cheddar = catalog.get_product("prod-cheddar-cheese")
    assert [s.grams for s in cheddar.sizes] == [227, 454, 907]  # 8, 16, 32 oz
    assert catalog.get_product("prod-whole-milk").size("1 gal").ml == 3785


def test_calories_answer_which_is_lower():
    by_category: dict[str, list[int]] = defaultdict(list)
    for product in catalog.load_products():
        if product.category not in ("household", "personal-care"):
            assert product.nutrition is not None, f"{product.id} is food and needs nutrition facts"
        if product.nutrition and product.nutrition.calories > 0:
            by_category[product.category].append(product.nutrition.calories)
    for category, calories in by_category.items():
        assert len(calories) == len(set(calories)), f"two {category} products share a calorie count: {calories}"


def test_stock_includes_some_out_of_stock_offers():
    offers = [o for p in catalog.load_products() for o in p.offers]
    assert 0 < sum(o.stock == 0 for o in offers) < len(offers) // 4


def test_store_coordinates_come_from_the_outdoor_pois():
    if not catalog.POIS_PATH.exists():
        pytest.skip("the outdoor world's pois.json is not in this build")
    pois = {p["id"]: p for p in json.loads(catalog.POIS_PATH.read_text(encoding="utf-8"))}
    for store in catalog.load_stores():
        poi = pois[store.id]
        assert poi["kind"] == "store"
        assert (store.lat, store.lng) == (poi["lat"], poi["lng"])
        assert store.name == poi["name"]
        assert store.address.startswith(poi["address"])


def test_lookup_errors_name_the_problem():
    with pytest.raises(catalog.CatalogError, match="no product 'prod-unicorn'"):
        catalog.price("prod-unicorn", "1 lb", "store-cvs-midtown")
    with pytest.raises(catalog.CatalogError, match="sizes are"):
        catalog.price("prod-apple", "9 lb bag", "store-cvs-midtown")
    with pytest.raises(catalog.CatalogError, match="stores are"):
        catalog.price("prod-apple", "1 each", "store-nowhere")
    with pytest.raises(catalog.CatalogError, match="does not sell"):
        catalog.price("prod-salmon-fillet", "1 lb", "store-cvs-midtown")
    assert catalog.price("prod-apple", "1 each", "store-cvs-midtown") > 0


def test_search_finds_products_by_name_plural_and_prefix():
    assert catalog.search_products("tomatoes")[0].id == "prod-tomato"
    assert catalog.search_products("choc")[0].id == "prod-dark-chocolate"
    assert {p.id for p in catalog.search_products("cheese")} >= {"prod-cheddar-cheese", "prod-mozzarella",
                                                                 "prod-parmesan"}
    assert [p.id for p in catalog.search_products("cheese", category="snacks")] == []
    assert catalog.search_products("zzzz") == []
    assert catalog.search_products("'; DROP TABLE orders; --") == []
    for pid in [*KITCHEN_FOODS, *BUY_ONLINE]:
        name = catalog.get_product(pid).name
        assert catalog.search_products(name)[0].id == pid, name


def test_generator_rejects_broken_specs():
    specs = json.loads(catalog_build.SPECS_PATH.read_text(encoding="utf-8"))
    broken = copy.deepcopy(specs)
    broken["products"].append(copy.deepcopy(broken["products"][0]))
    with pytest.raises(catalog_build.SpecError, match="unique"):
        catalog_build.build_catalog(broken)
    broken = copy.deepcopy(specs)
    broken["products"][0]["stores"] = ["store-cvs-midtown"]
    with pytest.raises(catalog_build.SpecError, match="at least two stores"):
        catalog_build.build_catalog(broken)
    broken = copy.deepcopy(specs)
    broken["products"][0]["sizes"][1]["price"] = 0.10  # a bigger bag cheaper than a single apple
    with pytest.raises(catalog_build.SpecError, match="not dearer"):
        catalog_build.build_catalog(broken)
    broken = copy.deepcopy(specs)
    broken["products"][0]["sizes"].append({"label": "a crate", "price": 99})
    with pytest.raises(catalog_build.SpecError, match="no amount"):
        catalog_build.build_catalog(broken)
