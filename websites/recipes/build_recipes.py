"""Build data/recipes.json from the hand-written dish specs in dishes.txt.

    python -m ewa_mcp.websites.recipes.build_recipes          # rewrite data/recipes.json
    python -m ewa_mcp.websites.recipes.build_recipes --check  # exit 1 if the committed file is stale

dishes.txt format (one dish per "==" block; two "--" variants make a look-alike pair):

    == Garlic Tomato Toast | Spanish          name | cuisine
    ~ Crisp bread rubbed with garlic.          summary shared by the variants
    -- novice | serves 1 | 10 min             a variant: difficulty, optional servings and minutes
    ~ The quick toaster version.               sentence appended to this variant's summary
    + Olive Oil = 2 tbsp                       amount of an ingredient (or an extra one)
    slice Bread                                a step from op codes (default wording) ...
    toast: Toast the slices until crisp.       ... or with its own wording after ": "
    slice Tomato + plate TomatoSliced: ...     several op codes in one step
    : Rub the toast with garlic.               a plain step without kitchen ops

Ingredients are derived: kitchen foods from the ops, shop products from the words of the steps
(so the list can never disagree with the text); equipment from the ops; diet from the ingredients.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import zlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .vocabulary import (
    COOKABLE,
    DIFFICULTIES,
    EQUIPMENT,
    KITCHEN_FOODS,
    KITCHEN_PRODUCTS,
    ONLINE_PRODUCTS,
    diet_of,
    recipe_problems,
    required_equipment,
    source_of,
)

HERE = Path(__file__).resolve().parent
SPEC_PATH = HERE / "dishes.txt"
DATA_PATH = HERE / "data" / "recipes.json"


class SpecError(ValueError):
    """A problem in dishes.txt, with the line it was found on."""


# ------------------------------------------------------------------ wording
NOUN = {
    "Apple": "apple", "AppleSliced": "apple slices", "Bread": "bread", "BreadSliced": "bread slices",
    "Egg": "egg", "EggCracked": "egg", "Lettuce": "lettuce", "LettuceSliced": "lettuce",
    "Potato": "potato", "PotatoSliced": "potato slices", "Tomato": "tomato", "TomatoSliced": "tomato slices",
}
SLICE_WORDS = {
    "Apple": ["Slice the apple into thin wedges.", "Core the apple and cut it into slices."],
    "Bread": ["Cut the bread into slices.", "Slice the bread."],
    "Lettuce": ["Chop the lettuce into ribbons.", "Slice the lettuce."],
    "Potato": ["Slice the potato into thin rounds.", "Cut the potato into slices."],
    "Tomato": ["Slice the tomato into rounds.", "Cut the tomato into slices."],
}
WORDING = {
    "crack": ["Crack the egg.", "Crack the egg open."],
    "fry": ["Cook the {x} in the pan on the stove.", "Fry the {x} in the pan on the stove until golden."],
    "boil": ["Cook the {x} in the pot on the stove.", "Boil the {x} in the pot on the stove until tender."],
    "toast": ["Toast the bread slices in the toaster.", "Toast the bread in the toaster until golden."],
    "microwave": ["Cook the {x} in the microwave.", "Microwave the {x} until cooked through."],
    "plate": ["Put the {x} on a plate.", "Arrange the {x} on a plate."],
    "bowl": ["Put the {x} in a bowl.", "Place the {x} in a bowl."],
    "pan": ["Put the {x} in the pan."],
    "pot": ["Put the {x} in the pot."],
    "counter": ["Set the {x} on the counter."],
    "chill": ["Chill the {x} in the fridge.", "Put the {x} in the fridge to cool."],
    "fetch": ["Take the {x} out of the fridge and set it on the counter."],
    "stoveoff": ["Turn off the stove."],
    "stoveon": ["Turn on the stove."],
}
EGG_WORDING = {
    "fry": ["Fry the egg in the pan on the stove until the white sets."],
    "boil": ["Poach the egg in the pot on the stove."],
}


def _op_code(code: str, arg: str | None, where: str) -> tuple[list[dict[str, Any]], set[str]]:
    """Expand one op code into kitchen ops plus the equipment it implies."""
    def need_arg() -> str:
        if not arg:
            raise SpecError(f"{where}: '{code}' needs an object type, e.g. '{code} PotatoSliced'")
        if arg not in NOUN:
            raise SpecError(f"{where}: unknown object type {arg!r}; use one of {', '.join(NOUN)}")
        return arg

    if code == "slice":
        return [{"op": "slice", "object": need_arg()}], set()
    if code == "crack":
        return [{"op": "crack", "object": "Egg"}], set()
    if code == "fry":
        return [{"op": "cook", "object": need_arg(), "method": "stove", "vessel": "Pan"}], {"Pan"}
    if code == "boil":
        return [{"op": "cook", "object": need_arg(), "method": "stove", "vessel": "Pot"}], {"Pot"}
    if code == "toast":
        return [{"op": "cook", "object": "BreadSliced", "method": "toaster"}], set()
    if code == "microwave":
        return [{"op": "cook", "object": need_arg(), "method": "microwave"}], set()
    receptacle = {"plate": "Plate", "bowl": "Bowl", "pan": "Pan", "pot": "Pot", "counter": "CounterTop"}
    if code in receptacle:
        return [{"op": "put", "object": need_arg(), "receptacle": receptacle[code]}], set()
    if code == "chill":
        obj = need_arg()
        return [{"op": "open", "object": "Fridge"}, {"op": "put", "object": obj, "receptacle": "Fridge"},
                {"op": "close", "object": "Fridge"}], set()
    if code == "fetch":
        obj = need_arg()
        return [{"op": "open", "object": "Fridge"}, {"op": "put", "object": obj, "receptacle": "CounterTop"},
                {"op": "close", "object": "Fridge"}], set()
    if code == "stoveoff":
        return [{"op": "toggle_off", "object": "StoveBurner"}], set()
    if code == "stoveon":
        return [{"op": "toggle_on", "object": "StoveBurner"}], set()
    raise SpecError(f"{where}: unknown op code {code!r}; use slice, crack, fry, boil, toast, microwave, plate, "
                    "bowl, pan, pot, counter, chill, fetch, stoveon, stoveoff, or ': text' for a plain step")


def left_in_heat(ops: list[dict[str, Any]]) -> list[tuple[int, str, str]]:
    """(index of a stove cook op in a pan or pot, a food the ops put in that vessel earlier and left there,
    the vessel): what the heat of that op cooks besides its own object."""
    inside: dict[str, list[str]] = {}
    found: list[tuple[int, str, str]] = []
    for at, op in enumerate(ops):
        if op["op"] == "put":
            for held in inside.values():
                if op["object"] in held:
                    held.remove(op["object"])
            if op["receptacle"] in ("Pan", "Pot"):
                inside.setdefault(op["receptacle"], []).append(op["object"])
        elif op["op"] == "cook" and op.get("vessel") in ("Pan", "Pot"):
            found += [(at, food, op["vessel"]) for food in inside.get(op["vessel"], []) if food != op["object"]]
    return found


# Codes that move a food somewhere: their wording names the food with the state the kitchen goal
# checks there (cooked, cut), so a goal never asks for more than the step says (issue: "the egg" in a
# bowl must be the fried egg; "some slices" must say that one slice is enough).
PLACING = ("plate", "bowl", "pan", "pot", "counter", "chill", "fetch")
COOKED_WORD = {"fry": "fried", "boil": "boiled", "toast": "toasted", "microwave": "microwaved"}
SLICE_NOUN = {"AppleSliced": "apple slices", "BreadSliced": "bread slices", "LettuceSliced": "lettuce slices",
              "PotatoSliced": "potato slices", "TomatoSliced": "tomato slices"}


def placed_noun(arg: str, cooked: dict[str, str]) -> str:
    """How a placing step names a food: 'fried egg', 'toasted bread slices (one slice or more)'."""
    noun = SLICE_NOUN.get(arg, NOUN.get(arg, ""))
    if arg in cooked:
        noun = f"{cooked[arg]} {noun}"
    if arg in SLICE_NOUN:
        noun += " (one slice or more)"
    return noun


def _default_text(code: str, arg: str | None, salt: str, cooked: dict[str, str] | None = None) -> str:
    if code == "slice":
        options = SLICE_WORDS[arg or ""]
    elif arg == "EggCracked" and code in EGG_WORDING:
        options = EGG_WORDING[code]
    else:
        options = WORDING[code]
    choice = options[zlib.crc32(salt.encode()) % len(options)]
    noun = placed_noun(arg or "", cooked or {}) if code in PLACING else NOUN.get(arg or "", "")
    return choice.format(x=noun)


# ------------------------------------------------------------------ ingredients from text
# Longest phrases first so "peanut butter" is not also read as "butter".
PRODUCT_PHRASES: list[tuple[str, str]] = sorted(
    [
        ("peanut butter", "Peanut Butter"), ("butter", "Butter"),
        ("cheddar cheese", "Cheddar Cheese"), ("cheddar", "Cheddar Cheese"), ("mozzarella", "Mozzarella"),
        ("chicken breast", "Chicken Breast"), ("chicken", "Chicken Breast"),
        ("olive oil", "Olive Oil"), ("avocados", "Avocado"), ("avocado", "Avocado"),
        ("salmon fillet", "Salmon Fillet"), ("salmon", "Salmon Fillet"), ("bacon", "Bacon"),
        ("sea salt", "Sea Salt"), ("salt", "Sea Salt"), ("black pepper", "Black Pepper"), ("pepper", "Black Pepper"),
        ("garlic", "Garlic"), ("onions", "Onion"), ("onion", "Onion"), ("lemons", "Lemon"), ("lemon", "Lemon"),
        ("honey", "Honey"), ("basil", "Basil"),
    ],
    key=lambda pair: -len(pair[0]),
)
# Words that would name an ingredient the shop does not sell under that name.
AMBIGUOUS_WORDS = {"cheese": "say 'cheddar cheese' or 'mozzarella'", "oil": "say 'olive oil'"}
KITCHEN_WORDS = {"apple": "Apple", "apples": "Apple", "bread": "Bread", "egg": "Egg", "eggs": "Egg",
                 "lettuce": "Lettuce", "potato": "Potato", "potatoes": "Potato", "tomato": "Tomato",
                 "tomatoes": "Tomato"}
DEFAULT_AMOUNTS = {
    "Apple": "1", "Bread": "2 slices", "Egg": "1", "Lettuce": "1 head", "Potato": "1", "Tomato": "1",
    "Cheddar Cheese": "40 g", "Mozzarella": "60 g", "Chicken Breast": "1", "Butter": "1 tbsp",
    "Olive Oil": "1 tbsp", "Avocado": "1", "Peanut Butter": "2 tbsp", "Salmon Fillet": "1", "Bacon": "2 rashers",
    "Sea Salt": "1 pinch", "Black Pepper": "1 pinch", "Garlic": "1 clove", "Onion": "1/2", "Lemon": "1/2",
    "Honey": "1 tsp", "Basil": "6 leaves",
}
MINUTES = {"slice": 2, "crack": 1, "toast": 3, "microwave": 5, "fry": 8, "boil": 12}


def products_in(text: str, where: str) -> list[str]:
    lowered = text.lower()
    found: list[str] = []
    for phrase, product in PRODUCT_PHRASES:
        pattern = rf"\b{re.escape(phrase)}\b"
        if re.search(pattern, lowered):
            if product not in found:
                found.append(product)
            lowered = re.sub(pattern, " ", lowered)
    for word, fix in AMBIGUOUS_WORDS.items():
        if re.search(rf"\b{word}\b", lowered):
            raise SpecError(f"{where}: the word {word!r} is ambiguous; {fix}")
    return found


def kitchen_words_in(text: str) -> set[str]:
    return {KITCHEN_WORDS[w] for w in re.findall(r"[a-z]+", text.lower()) if w in KITCHEN_WORDS}


# ------------------------------------------------------------------ parsing
@dataclass
class Variant:
    difficulty: str
    line: int
    servings: int = 2
    minutes: int | None = None
    note: str = ""
    amounts: dict[str, str] = field(default_factory=dict)
    extra_equipment: list[str] = field(default_factory=list)
    steps: list[tuple[str, list[tuple[str, str | None]], int]] = field(default_factory=list)


@dataclass
class Dish:
    name: str
    cuisine: str
    line: int
    summary: str = ""
    variants: list[Variant] = field(default_factory=list)


def parse_specs(text: str, source: str = "dishes.txt") -> list[Dish]:
    dishes: list[Dish] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        where = f"{source}:{number}"
        if not line or line.startswith("#"):
            continue
        if line.startswith("== "):
            name, sep, cuisine = (part.strip() for part in line[3:].partition("|"))
            if not sep or not name or not cuisine:
                raise SpecError(f"{where}: a dish line is '== Name | Cuisine'")
            dishes.append(Dish(name=name, cuisine=cuisine, line=number))
            continue
        if not dishes:
            raise SpecError(f"{where}: text before the first '== Name | Cuisine' line")
        dish = dishes[-1]
        variant = dish.variants[-1] if dish.variants else None
        if line.startswith("~ "):
            if variant is None:
                dish.summary = (dish.summary + " " + line[2:].strip()).strip()
            else:
                variant.note = (variant.note + " " + line[2:].strip()).strip()
        elif line.startswith("-- "):
            dish.variants.append(_parse_variant(line[3:], number, where))
        elif variant is None:
            raise SpecError(f"{where}: steps must follow a '-- difficulty' variant line")
        elif line.startswith("+ "):
            name, sep, amount = (part.strip() for part in line[2:].partition("="))
            if not sep or not amount:
                raise SpecError(f"{where}: an amount line is '+ Ingredient = amount'")
            if name not in KITCHEN_FOODS and name not in ONLINE_PRODUCTS:
                raise SpecError(f"{where}: {name!r} is neither a kitchen food nor a shop product")
            variant.amounts[name] = amount
        elif line.startswith("@ "):
            for item in line[2:].split(","):
                if item.strip() not in EQUIPMENT:
                    raise SpecError(f"{where}: unknown equipment {item.strip()!r}; use one of {', '.join(EQUIPMENT)}")
                variant.extra_equipment.append(item.strip())
        elif line.startswith(":"):
            variant.steps.append((line[1:].strip(), [], number))
        else:
            codes_part, _, custom = line.partition(":")
            codes = []
            for chunk in codes_part.split("+"):
                words = chunk.split()
                if not words or len(words) > 2:
                    raise SpecError(f"{where}: cannot read op code {chunk.strip()!r}")
                codes.append((words[0], words[1] if len(words) == 2 else None))
            variant.steps.append((custom.strip(), codes, number))
    for dish in dishes:
        if not 1 <= len(dish.variants) <= 2:
            raise SpecError(f"{source}:{dish.line}: a dish has one variant, or two for a look-alike pair")
    return dishes


def _parse_variant(body: str, number: int, where: str) -> Variant:
    parts = [p.strip() for p in body.split("|")]
    if parts[0] not in DIFFICULTIES:
        raise SpecError(f"{where}: difficulty {parts[0]!r} is not one of {', '.join(DIFFICULTIES)}")
    variant = Variant(difficulty=parts[0], line=number)
    for part in parts[1:]:
        if m := re.fullmatch(r"serves (\d+)", part):
            variant.servings = int(m.group(1))
        elif m := re.fullmatch(r"(\d+) min", part):
            variant.minutes = int(m.group(1))
        else:
            raise SpecError(f"{where}: cannot read {part!r}; use 'serves N' or 'N min'")
    return variant


# ------------------------------------------------------------------ building
def build_recipe(dish: Dish, variant: Variant, recipe_id: str, source: str = "dishes.txt") -> dict[str, Any]:
    steps: list[dict[str, Any]] = []
    kitchen: list[str] = []
    products: list[str] = []
    equipment: set[str] = set(variant.extra_equipment)
    minutes = 5
    cooked: dict[str, str] = {}  # piece or food type -> how it was cooked ("fried"), for later placing steps
    # The kitchen cooks what can cook in a pan or pot on a lit burner: a cookable food the steps leave in the
    # vessel while they cook something else there is cooked with it, and says so (its own cook op and a
    # sentence). Tomato slices do not cook (AI2-THOR's cookable types), so they are left as they are.
    so_far: list[dict[str, Any]] = []  # every op of the earlier steps and of this one so far
    cooks_itself = {arg or "BreadSliced" for _, codes, _ in variant.steps for code, arg in codes if code in COOKED_WORD}
    for index, (custom, codes, number) in enumerate(variant.steps, start=1):
        where = f"{source}:{number}"
        ops: list[dict[str, Any]] = []
        texts: list[str] = []
        along: list[str] = []  # "The bread slices in the pot cook with it."
        for code, arg in codes:
            expanded, vessels = _op_code(code, arg, where)
            for op in expanded:
                heated = [(food, vessel) for at, food, vessel in left_in_heat([*so_far, op]) if at == len(so_far)]
                for food, vessel in heated:
                    if food in COOKABLE and food not in cooks_itself and food not in cooked:
                        extra = {"op": "cook", "object": food, "method": "stove", "vessel": vessel}
                        ops.append(extra)
                        so_far.append(extra)
                        cooked[food] = COOKED_WORD[code]
                        along.append(f"The {SLICE_NOUN.get(food, NOUN.get(food, ''))} in the {vessel.lower()} cook with it.")
                so_far.append(op)
            ops.extend(expanded)
            equipment |= vessels
            for op in expanded:
                equipment |= required_equipment(op)
                if op["op"] in ("slice", "crack", "cook", "put") and source_of(op["object"]) not in kitchen:
                    kitchen.append(source_of(op["object"]))
            texts.append(_default_text(code, arg, f"{dish.name}|{recipe_id}|{index}|{code}", cooked))
            if code in COOKED_WORD:
                cooked[arg or "BreadSliced"] = COOKED_WORD[code]
            minutes += MINUTES.get(code, 1)
        same_put = len(codes) > 1 and len({c for c, _ in codes}) == 1 and codes[0][0] in ("plate", "bowl")
        generated: str | None = None  # the step in the kitchen's own words, from its ops alone
        if same_put:
            # "Put the egg and the potato slices on a plate." rather than one clause per piece.
            things = [f"the {placed_noun(arg or '', cooked)}" for _, arg in codes]
            where = "on a plate" if codes[0][0] == "plate" else "in a bowl"
            generated = f"Put {', '.join(things[:-1])} and {things[-1]} {where}."
        elif texts:
            if len(codes) > 1 and codes[0][0] == "crack":  # "Crack the egg, then fry it ..."
                texts[1] = texts[1].replace("the egg", "it", 1)
            # "Slice the bread. / Toast it." reads as one instruction: "Slice the bread, then toast it."
            parts = [texts[0].rstrip(".")] + [t[0].lower() + t[1:].rstrip(".") for t in texts[1:]]
            generated = ", then ".join(parts) + "."
        if along and generated:
            generated = " ".join([generated, *along])
        text = custom or generated
        if not text:
            raise SpecError(f"{where}: a step needs op codes or text")
        if not codes:
            minutes += 2
        if not text.endswith((".", "!")):
            raise SpecError(f"{where}: step text must be a sentence ending with a full stop")
        stray = kitchen_words_in(text) - {source_of(op["object"]) for op in ops} - set(kitchen)
        if stray:
            raise SpecError(f"{where}: the text names {sorted(stray)} but no op so far uses it; "
                            "add the op (e.g. 'slice Tomato') or reword")
        named = products_in(text, where)
        for product in named:
            if product not in products:
                products.append(product)
        # What of this step the kitchen can do: its ops, in the kitchen's words (None: nothing, the
        # step is not part of the kitchen goal); and the shop ingredients it names, which the kitchen
        # does not have (part of the dish, not of the kitchen goal).
        steps.append({"text": text, "ops": ops, "kitchen": generated, "not_in_kitchen": named})
    for name in variant.amounts:
        if name not in kitchen and name not in products:
            if name in KITCHEN_FOODS:
                raise SpecError(f"{source}:{variant.line}: {name} has an amount but no op uses it")
            products.append(name)
    ingredients: list[dict[str, Any]] = [
        {"name": name, "kitchen_type": name, "product_id": KITCHEN_PRODUCTS[name],
         "amount": variant.amounts.get(name, DEFAULT_AMOUNTS[name])}
        for name in kitchen
    ] + [
        {"name": name, "kitchen_type": None, "product_id": ONLINE_PRODUCTS[name],
         "amount": variant.amounts.get(name, DEFAULT_AMOUNTS[name])}
        for name in products
    ]
    summary = " ".join(part for part in (dish.summary, variant.note) if part)
    if not summary:
        raise SpecError(f"{source}:{dish.line}: {dish.name} needs a '~ summary' line")
    return {
        "id": recipe_id,
        "name": dish.name,
        "pair_id": None,
        "diet": diet_of([i["name"] for i in ingredients]),
        "difficulty": variant.difficulty,
        "cuisine": dish.cuisine,
        "summary": summary,
        "servings": variant.servings,
        "time_minutes": variant.minutes or int(5 * round(minutes / 5)) or 5,
        "ingredients": ingredients,
        "equipment": [item for item in EQUIPMENT if item in equipment],
        "steps": steps,
    }


def pair_difference(a: dict[str, Any], b: dict[str, Any]) -> list[str]:
    """The filterable attributes that tell two look-alike recipes apart (empty: indistinguishable)."""
    differences = []
    if a["diet"] != b["diet"]:
        differences.append("diet")
    if a["difficulty"] != b["difficulty"]:
        differences.append("difficulty")
    if {i["name"] for i in a["ingredients"]} != {i["name"] for i in b["ingredients"]}:
        differences.append("ingredients")
    if set(a["equipment"]) != set(b["equipment"]):
        differences.append("equipment")
    return differences


def build_all(spec_text: str, source: str = "dishes.txt") -> list[dict[str, Any]]:
    dishes = parse_specs(spec_text, source)
    names = [d.name.lower() for d in dishes]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise SpecError(f"dish names repeat across '==' blocks: {duplicates}; write a pair as two variants of one dish")
    recipes: list[dict[str, Any]] = []
    problems: list[str] = []
    pair_count = 0
    for dish in dishes:
        members = []
        for variant in dish.variants:
            recipe = build_recipe(dish, variant, f"r{len(recipes) + 1:03d}", source)
            problems.extend(f"{p} ({source}:{variant.line})" for p in recipe_problems(recipe))
            recipes.append(recipe)
            members.append(recipe)
        if len(members) == 2:
            pair_count += 1
            for recipe in members:
                recipe["pair_id"] = f"p{pair_count:02d}"
            if not pair_difference(*members):
                problems.append(f"{dish.name} ({source}:{dish.line}): the two variants differ in no filter "
                                "(diet, difficulty, ingredients, equipment)")
    if problems:
        raise SpecError("the dish specs break the recipe contract:\n  " + "\n  ".join(problems))
    return recipes


def render(recipes: list[dict[str, Any]]) -> str:
    return json.dumps(recipes, indent=1, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="fail if data/recipes.json is not up to date")
    args = parser.parse_args(argv)
    try:
        recipes = build_all(SPEC_PATH.read_text(encoding="utf-8"))
    except SpecError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    text = render(recipes)
    pairs = len({r["pair_id"] for r in recipes if r["pair_id"]})
    if args.check:
        current = DATA_PATH.read_text(encoding="utf-8") if DATA_PATH.exists() else ""
        if current != text:
            print("data/recipes.json is stale; run python -m ewa_mcp.websites.recipes.build_recipes", file=sys.stderr)
            return 1
        print(f"ok: {len(recipes)} recipes, {pairs} look-alike pairs")
        return 0
    DATA_PATH.parent.mkdir(parents=True, exist_ok=True)
    DATA_PATH.write_text(text, encoding="utf-8")
    print(f"wrote {DATA_PATH} ({len(recipes)} recipes, {pairs} look-alike pairs)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
