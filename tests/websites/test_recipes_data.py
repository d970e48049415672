"""Content checks of the committed recipes: the kitchen op contract, diets, pairs, the generator."""

from __future__ import annotations

import copy
import json
import re
from collections import defaultdict
from pathlib import Path

import pytest

from ewa_mcp.websites.recipes import build_recipes
from ewa_mcp.websites.recipes.build_recipes import SpecError, build_all, parse_specs
from ewa_mcp.websites.recipes.catalog import Catalog, Filters
from ewa_mcp.websites.recipes.vocabulary import recipe_problems

RECIPES_DIR = Path(__file__).resolve().parents[2] / "websites" / "recipes"
DATA = json.loads((RECIPES_DIR / "data" / "recipes.json").read_text(encoding="utf-8"))

# The contract as the brief states it, written out here independently of vocabulary.py.
FOODS = {"Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato"}
PIECES = {"AppleSliced": "Apple", "BreadSliced": "Bread", "LettuceSliced": "Lettuce", "PotatoSliced": "Potato",
          "TomatoSliced": "Tomato", "EggCracked": "Egg"}
RECEPTACLES = {"Plate", "Bowl", "Pan", "Pot", "CounterTop", "DiningTable", "Fridge"}
PRODUCT_IDS = {
    "prod-cheddar-cheese", "prod-mozzarella", "prod-chicken-breast", "prod-butter", "prod-olive-oil",
    "prod-avocado", "prod-peanut-butter", "prod-salmon-fillet", "prod-bacon", "prod-sea-salt",
    "prod-black-pepper", "prod-garlic", "prod-onion", "prod-lemon", "prod-honey", "prod-basil",
}
FOOD_PRODUCTS = {"Apple": "prod-apple", "Bread": "prod-bread", "Egg": "prod-eggs", "Lettuce": "prod-lettuce",
                 "Potato": "prod-potato", "Tomato": "prod-tomato"}
MEAT = {"Chicken Breast", "Salmon Fillet", "Bacon"}
DAIRY_EGG_HONEY = {"Egg", "Butter", "Cheddar Cheese", "Mozzarella", "Honey"}


def test_there_are_at_least_200_recipes_with_unique_ids():
    assert len(DATA) >= 200
    ids = [r["id"] for r in DATA]
    assert len(set(ids)) == len(ids)
    assert all(re.fullmatch(r"r\d{3}", i) for i in ids)


def test_committed_json_is_what_the_generator_builds():
    spec = (RECIPES_DIR / "dishes.txt").read_text(encoding="utf-8")
    assert build_recipes.render(build_all(spec)) == (RECIPES_DIR / "data" / "recipes.json").read_text(
        encoding="utf-8"), "data/recipes.json is stale: run python -m ewa_mcp.websites.recipes.build_recipes"


@pytest.mark.parametrize("recipe", DATA, ids=[r["id"] for r in DATA])
def test_recipe_keeps_the_kitchen_contract(recipe):
    assert recipe_problems(recipe) == []
    equipment = set(recipe["equipment"])
    ingredient_names = {i["name"] for i in recipe["ingredients"]}
    kitchen = {i["kitchen_type"] for i in recipe["ingredients"] if i["kitchen_type"]}
    assert kitchen and kitchen <= FOODS
    for item in recipe["ingredients"]:
        if item["kitchen_type"]:
            assert item["product_id"] == FOOD_PRODUCTS[item["kitchen_type"]]
        else:
            assert item["product_id"] in PRODUCT_IDS
    assert 2 <= len(recipe["steps"]) <= 14
    assert sum(1 for s in recipe["steps"] if s["ops"]) >= 2
    cut: set[str] = set()
    for step in recipe["steps"]:
        assert step["text"].strip()
        for op in step["ops"]:
            kind, obj = op["op"], op["object"]
            if kind == "slice":
                assert obj in FOODS - {"Egg"} and "Knife" in equipment and obj not in cut
                cut.add(obj)
            elif kind == "crack":
                assert obj == "Egg" and obj not in cut
                cut.add(obj)
            elif kind == "cook":
                method = op["method"]
                assert method in {"stove", "microwave", "toaster"}
                assert obj in FOODS | set(PIECES)
                if method == "stove":
                    assert "StoveBurner" in equipment and equipment & {"Pan", "Pot"}
                if method == "toaster":
                    assert obj == "BreadSliced" and "Toaster" in equipment
                if method == "microwave":
                    assert "Microwave" in equipment
            elif kind == "put":
                assert op["receptacle"] in RECEPTACLES
                if op["receptacle"] not in {"CounterTop", "DiningTable"}:
                    assert op["receptacle"] in equipment
            else:
                assert kind in {"open", "close", "toggle_on", "toggle_off"} and obj in equipment
            if kind in {"cook", "put"}:
                if obj in PIECES:  # pieces exist only after their source was cut
                    assert PIECES[obj] in cut, (recipe["id"], op)
                    assert PIECES[obj] in kitchen
                else:
                    assert obj in kitchen and obj not in cut, (recipe["id"], op)
    # Diet labels follow from the ingredients.
    if ingredient_names & MEAT:
        assert recipe["diet"] == "non-vegetarian"
    elif ingredient_names & DAIRY_EGG_HONEY:
        assert recipe["diet"] == "vegetarian"
    else:
        assert recipe["diet"] == "vegan"


def test_at_least_60_lookalike_pairs_and_no_other_repeated_names():
    by_pair: dict[str, list[dict]] = defaultdict(list)
    by_name: dict[str, list[dict]] = defaultdict(list)
    for recipe in DATA:
        by_name[recipe["name"].lower()].append(recipe)
        if recipe["pair_id"]:
            by_pair[recipe["pair_id"]].append(recipe)
    assert len(by_pair) >= 60
    for members in by_pair.values():
        assert len(members) == 2 and members[0]["name"] == members[1]["name"]
    for name, members in by_name.items():
        assert len(members) == 1 or (len(members) == 2 and members[0]["pair_id"]
                                     and members[0]["pair_id"] == members[1]["pair_id"]), name


def test_every_pair_is_told_apart_by_a_site_filter():
    """For each pair, some single filter on the site shows exactly one of the two recipes."""
    catalog = Catalog(DATA)
    by_pair: dict[str, list[dict]] = defaultdict(list)
    for recipe in DATA:
        if recipe["pair_id"]:
            by_pair[recipe["pair_id"]].append(recipe)
    for pair_id, (a, b) in by_pair.items():
        candidates: list[Filters] = []
        for r in (a, b):
            candidates += [Filters(q=r["name"], diet=r["diet"]), Filters(q=r["name"], difficulty=r["difficulty"])]
        ing_a, ing_b = ({i["name"] for i in r["ingredients"]} for r in (a, b))
        for name in ing_a ^ ing_b:
            candidates += [Filters(q=a["name"], include=(name,)), Filters(q=a["name"], exclude=(name,))]
        for item in set(a["equipment"]) ^ set(b["equipment"]):
            candidates.append(Filters(q=a["name"], equipment=(item,)))
        separating = [f for f in candidates
                      if len({r["id"] for r in catalog.search(f)} & {a["id"], b["id"]}) == 1]
        assert separating, f"pair {pair_id} ({a['name']}) cannot be told apart with any filter"


def test_pairs_cover_every_kind_of_difference():
    by_pair: dict[str, list[dict]] = defaultdict(list)
    for recipe in DATA:
        if recipe["pair_id"]:
            by_pair[recipe["pair_id"]].append(recipe)
    kinds = defaultdict(int)
    for a, b in by_pair.values():
        for kind in build_recipes.pair_difference(a, b):
            kinds[kind] += 1
    assert all(kinds[k] >= 10 for k in ("diet", "difficulty", "ingredients", "equipment")), dict(kinds)


# ---------------------------------------------------------------- the validator refuses broken recipes
def _base() -> dict:
    return copy.deepcopy(next(r for r in DATA if r["id"] == "r001"))  # slice bread, toast, slice tomato, plate


@pytest.mark.parametrize(
    ("mutate", "phrase"),
    [
        (lambda r: r["equipment"].remove("Knife"), "Knife"),
        (lambda r: r["steps"][1]["ops"][0].update(object="Tomato", method="stove"), "cannot be cooked"),
        (lambda r: r["steps"].insert(0, {"text": "Put the tomato slices on a plate.",
                                         "ops": [{"op": "put", "object": "TomatoSliced", "receptacle": "Plate"}]}),
         "before the Tomato is sliced"),
        (lambda r: r["steps"].append({"text": "Slice the bread again.", "ops": [{"op": "slice", "object": "Bread"}]}),
         "already sliced"),
        (lambda r: r.update(diet="vegetarian"), "diet says vegetarian"),
        (lambda r: r.update(steps=r["steps"][:1]), "steps"),
        (lambda r: r["steps"][3].update(text="Rub the toast with garlic in the pan."), "mentions ['Pan']"),
        (lambda r: r["equipment"].append("Microwave"), "Microwave is listed as equipment but no step uses it"),
        (lambda r: r["steps"][0]["ops"].append({"op": "put", "object": "Bread", "receptacle": "Sink"}),
         "unknown receptacle"),
        (lambda r: r["steps"][0]["ops"].append({"op": "fry", "object": "Bread"}), "unknown op"),
        (lambda r: r["ingredients"].append({"name": "Caviar", "kitchen_type": None, "product_id": "prod-caviar",
                                             "amount": "1"}), "not a shop product"),
        (lambda r: r["steps"][0]["ops"].append({"op": "toggle_off", "object": "Toaster"}), "never on"),
        (lambda r: r["steps"].append({"text": "Toast the bread again.",
                                      "ops": [{"op": "cook", "object": "BreadSliced", "method": "toaster"}]}),
         "never placed again"),
    ],
)
def test_validator_names_what_is_wrong(mutate, phrase):
    recipe = _base()
    assert recipe_problems(recipe) == []
    mutate(recipe)
    problems = recipe_problems(recipe)
    assert any(phrase in p for p in problems), problems


@pytest.mark.parametrize(
    ("spec", "phrase"),
    [
        ("== A | X\n~ s.\n-- easy\nslice Bread\n", "difficulty 'easy'"),
        ("== A | X\n~ s.\n-- simple\nchop Bread\n", "unknown op code 'chop'"),
        ("== A | X\n~ s.\n-- simple\nslice Bread\n: Add some cheese.\n", "'cheese' is ambiguous"),
        ("== A | X\n~ s.\n-- simple\nslice Bread\n: Add the tomato.\n", "names ['Tomato']"),
        ("== A | X\n~ s.\n-- simple\nslice Bread\ntoast: Toast it\n", "full stop"),
        ("slice Bread\n", "before the first"),
        ("== A | X\n~ s.\n-- simple\nslice Bread\nplate BreadSliced\n-- simple\nslice Bread\nplate BreadSliced\n",
         "differ in no filter"),
    ],
)
def test_generator_rejects_bad_specs_with_a_located_message(spec, phrase):
    with pytest.raises(SpecError) as info:
        build_all(spec, source="spec.txt")
    assert phrase in str(info.value)


def test_generator_derives_ingredients_equipment_and_diet_from_the_steps():
    spec = ("== Test Toast | Testish\n~ A test.\n-- simple | serves 3 | 12 min\n+ Butter = 2 tbsp\n"
            "slice Bread\nfry BreadSliced: Fry the bread in butter in the pan on the stove.\n"
            "plate BreadSliced: Serve with a pinch of sea salt.\n")
    (recipe,) = build_all(spec)
    assert [i["name"] for i in recipe["ingredients"]] == ["Bread", "Butter", "Sea Salt"]
    assert recipe["ingredients"][1]["amount"] == "2 tbsp"
    assert recipe["equipment"] == ["Knife", "Pan", "StoveBurner", "Plate"]
    assert recipe["diet"] == "vegetarian" and recipe["servings"] == 3 and recipe["time_minutes"] == 12
    assert parse_specs(spec)[0].variants[0].difficulty == "simple"


def test_a_food_left_in_a_heated_vessel_is_cooked_there_and_the_step_says_so():
    """The kitchen cooks what can cook in a pan or pot on a lit burner: a recipe that leaves a cookable food
    in the vessel while it cooks something else there cooks that food too (its own op, so the goals want it
    cooked) and its kitchen note says so. A play-tester followed 'put the bread in the pot, then poach the
    egg in the pot' and was failed for serving the bread cooked, when only a fresh slice was raw."""
    cookable = {"Potato", "PotatoSliced", "BreadSliced", "EggCracked"}
    checked = 0
    for recipe in DATA:
        ops = [(step, op) for step in recipe["steps"] for op in step["ops"]]
        for at, food, vessel in build_recipes.left_in_heat([op for _, op in ops]):
            if food not in cookable:
                continue
            checked += 1
            earlier = [(step, op) for step, op in ops[:at] if op["op"] == "cook" and op["object"] == food]
            assert earlier, (recipe["id"], food, vessel)
            step = ops[at][0]
            assert earlier[-1][0] is not step or "cook with it" in step["kitchen"], (recipe["id"], step["kitchen"])
    assert checked >= 1  # the garlic soup's bread
