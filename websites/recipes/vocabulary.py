"""The recipe vocabulary shared with the kitchen: food types, equipment, products and step ops.

Every recipe step may carry machine-readable ``ops`` that the kitchen planner executes exactly,
so the rules here are the contract: ``recipe_problems`` lists every way a recipe breaks it
(the generator refuses such recipes, the content test re-checks the committed data).
"""

from __future__ import annotations

import re
from typing import Any

# The kitchen's food types (AI2-THOR object types) a recipe can be cooked from.
KITCHEN_FOODS: tuple[str, ...] = ("Apple", "Bread", "Egg", "Lettuce", "Potato", "Tomato")
SLICEABLE: frozenset[str] = frozenset({"Apple", "Bread", "Lettuce", "Potato", "Tomato"})
# Piece type -> the food it comes from (slicing or cracking destroys the source object).
PIECE_SOURCE: dict[str, str] = {
    "AppleSliced": "Apple",
    "BreadSliced": "Bread",
    "LettuceSliced": "Lettuce",
    "PotatoSliced": "Potato",
    "TomatoSliced": "Tomato",
    "EggCracked": "Egg",
}
# Only these become isCooked in AI2-THOR; cooking anything else would be a step the kitchen cannot show.
COOKABLE: frozenset[str] = frozenset({"Potato", "PotatoSliced", "BreadSliced", "EggCracked"})
COOK_METHODS: tuple[str, ...] = ("stove", "microwave", "toaster")
STOVE_VESSELS: tuple[str, ...] = ("Pan", "Pot")  # what a stove cook op may name as its "vessel"
RECEPTACLES: tuple[str, ...] = ("Plate", "Bowl", "Pan", "Pot", "CounterTop", "DiningTable", "Fridge")
OPENABLE: tuple[str, ...] = ("Fridge", "Microwave")
TOGGLEABLE: tuple[str, ...] = ("StoveBurner", "Microwave", "Toaster")
# What a recipe may list as equipment (the site's equipment filter offers exactly these).
EQUIPMENT: tuple[str, ...] = ("Knife", "Pan", "Pot", "StoveBurner", "Toaster", "Microwave", "Plate", "Bowl", "Fridge")
# Receptacles every kitchen has as furniture, so a recipe does not list them as equipment.
FURNITURE: frozenset[str] = frozenset({"CounterTop", "DiningTable"})
OPS: tuple[str, ...] = ("slice", "crack", "cook", "put", "open", "close", "toggle_on", "toggle_off")

DIETS: tuple[str, ...] = ("vegetarian", "vegan", "non-vegetarian")
DIFFICULTIES: tuple[str, ...] = ("novice", "simple", "intermediate", "hard")

# Shop product ids (fixed with the shop engineer). Kitchen foods are sold too, for kitchens that lack one.
KITCHEN_PRODUCTS: dict[str, str] = {
    "Apple": "prod-apple",
    "Bread": "prod-bread",
    "Egg": "prod-eggs",
    "Lettuce": "prod-lettuce",
    "Potato": "prod-potato",
    "Tomato": "prod-tomato",
}
ONLINE_PRODUCTS: dict[str, str] = {
    "Cheddar Cheese": "prod-cheddar-cheese",
    "Mozzarella": "prod-mozzarella",
    "Chicken Breast": "prod-chicken-breast",
    "Butter": "prod-butter",
    "Olive Oil": "prod-olive-oil",
    "Avocado": "prod-avocado",
    "Peanut Butter": "prod-peanut-butter",
    "Salmon Fillet": "prod-salmon-fillet",
    "Bacon": "prod-bacon",
    "Sea Salt": "prod-sea-salt",
    "Black Pepper": "prod-black-pepper",
    "Garlic": "prod-garlic",
    "Onion": "prod-onion",
    "Lemon": "prod-lemon",
    "Honey": "prod-honey",
    "Basil": "prod-basil",
}
MEAT_OR_FISH: frozenset[str] = frozenset({"Chicken Breast", "Salmon Fillet", "Bacon"})
ANIMAL_PRODUCTS: frozenset[str] = MEAT_OR_FISH | {"Egg", "Butter", "Cheddar Cheese", "Mozzarella", "Honey"}

# Words in step text that name equipment; a step may only mention equipment the recipe lists.
EQUIPMENT_WORDS: dict[str, str] = {
    "knife": "Knife",
    "pan": "Pan",
    "pot": "Pot",
    "stove": "StoveBurner",
    "toaster": "Toaster",
    "microwave": "Microwave",
    "plate": "Plate",
    "bowl": "Bowl",
    "fridge": "Fridge",
}


def diet_of(ingredient_names: set[str] | list[str]) -> str:
    names = set(ingredient_names)
    if names & MEAT_OR_FISH:
        return "non-vegetarian"
    if names & ANIMAL_PRODUCTS:
        return "vegetarian"
    return "vegan"


def source_of(object_type: str) -> str:
    return PIECE_SOURCE.get(object_type, object_type)


def required_equipment(op: dict[str, Any]) -> set[str]:
    """The equipment an op needs, beyond the food itself."""
    kind = op.get("op")
    if kind == "slice":
        return {"Knife"}
    if kind == "cook":
        method = op.get("method")
        if method == "toaster":
            return {"Toaster"}
        if method == "microwave":
            return {"Microwave"}
        # the vessel the step names ("fry" -> Pan, "boil" -> Pot); without one, a Pan or a Pot, checked separately
        return {"StoveBurner"} | ({op["vessel"]} if op.get("vessel") in STOVE_VESSELS else set())
    if kind == "put":
        receptacle = op.get("receptacle", "")
        return set() if receptacle in FURNITURE else {receptacle}
    if kind in ("open", "close", "toggle_on", "toggle_off"):
        return {op.get("object", "")}
    return set()


def _op_problems(op: Any) -> list[str]:
    """Shape problems of one op, independent of the rest of the recipe."""
    if not isinstance(op, dict):
        return [f"op {op!r} is not an object"]
    kind = op.get("op")
    if kind not in OPS:
        return [f"unknown op {kind!r}; use one of {', '.join(OPS)}"]
    expected = {"slice": {"op", "object"}, "crack": {"op", "object"}, "cook": {"op", "object", "method"},
                "put": {"op", "object", "receptacle"}}.get(kind, {"op", "object"})
    if kind == "cook" and op.get("method") == "stove" and "vessel" in op:
        expected = expected | {"vessel"}
        if op["vessel"] not in STOVE_VESSELS:
            return [f"a stove cook op's vessel is one of {', '.join(STOVE_VESSELS)}, not {op['vessel']!r}"]
    if set(op) != expected:
        return [f"{kind} op must have exactly the keys {sorted(expected)}, got {sorted(op)}"]
    obj = op["object"]
    if kind == "slice" and obj not in SLICEABLE:
        return [f"cannot slice {obj!r}; sliceable foods are {', '.join(sorted(SLICEABLE))}"]
    if kind == "crack" and obj != "Egg":
        return [f"only an Egg can be cracked, not {obj!r}"]
    if kind == "cook":
        if op["method"] not in COOK_METHODS:
            return [f"unknown cook method {op['method']!r}; use one of {', '.join(COOK_METHODS)}"]
        if obj not in COOKABLE:
            return [f"{obj!r} cannot be cooked in the kitchen; cookable types are {', '.join(sorted(COOKABLE))}"]
        if op["method"] == "toaster" and obj != "BreadSliced":
            return [f"only BreadSliced goes in the toaster, not {obj!r}"]
    if kind == "put":
        if obj not in KITCHEN_FOODS and obj not in PIECE_SOURCE:
            return [f"put moves a food or a piece; {obj!r} is neither"]
        if op["receptacle"] not in RECEPTACLES:
            return [f"unknown receptacle {op['receptacle']!r}; use one of {', '.join(RECEPTACLES)}"]
    if kind in ("open", "close") and obj not in OPENABLE:
        return [f"cannot {kind} {obj!r}; openable objects are {', '.join(OPENABLE)}"]
    if kind in ("toggle_on", "toggle_off") and obj not in TOGGLEABLE:
        return [f"cannot {kind} {obj!r}; toggleable objects are {', '.join(TOGGLEABLE)}"]
    return []


class _KitchenTrace:
    """Follows a recipe's ops in order to catch physically impossible sequences."""

    def __init__(self) -> None:
        self.destroyed: set[str] = set()  # whole foods already sliced or cracked
        self.open: set[str] = set()
        self.on: set[str] = set()
        self.stove_used = False

    def apply(self, op: dict[str, Any]) -> str | None:
        kind, obj = op["op"], op["object"]
        if kind in ("slice", "crack"):
            if obj in self.destroyed:
                return f"the {obj} is already {'cracked' if obj == 'Egg' else 'sliced'}"
            self.destroyed.add(obj)
            return None
        if kind in ("cook", "put"):
            source = source_of(obj)
            if obj in PIECE_SOURCE and source not in self.destroyed:
                verb = "cracked" if source == "Egg" else "sliced"
                return f"{obj} is used before the {source} is {verb}"
            if obj not in PIECE_SOURCE and obj in self.destroyed:
                return f"the whole {obj} is used after it was cut up; use the pieces ({obj}Sliced)"
            if kind == "put" and op["receptacle"] == "Fridge" and "Fridge" not in self.open:
                return "something is put in the Fridge while it is closed; open the Fridge first"
            if kind == "cook" and op["method"] == "stove":
                self.stove_used = True
            return None
        if kind == "open":
            self.open.add(obj)
        elif kind == "close":
            if obj not in self.open:
                return f"the {obj} is closed before it was opened"
            self.open.discard(obj)
        elif kind == "toggle_on":
            self.on.add(obj)
            if obj == "StoveBurner":
                self.stove_used = True
        elif kind == "toggle_off" and obj not in self.on and not (obj == "StoveBurner" and self.stove_used):
            return f"the {obj} is switched off but was never on"
        return None


def _words(text: str) -> set[str]:
    return set(re.findall(r"[a-z]+", text.lower()))


def recipe_problems(recipe: dict[str, Any]) -> list[str]:
    """Everything wrong with one recipe record; an empty list means it keeps the contract."""
    problems: list[str] = []
    rid = recipe.get("id", "?")

    def bad(message: str) -> None:
        problems.append(f"{rid}: {message}")

    for key in ("id", "name", "diet", "difficulty", "cuisine", "summary", "servings", "time_minutes",
                "ingredients", "equipment", "steps"):
        if key not in recipe:
            bad(f"missing field {key!r}")
    if problems:
        return problems
    if recipe["diet"] not in DIETS:
        bad(f"diet {recipe['diet']!r} is not one of {DIETS}")
    if recipe["difficulty"] not in DIFFICULTIES:
        bad(f"difficulty {recipe['difficulty']!r} is not one of {DIFFICULTIES}")

    names = [item["name"] for item in recipe["ingredients"]]
    if len(set(names)) != len(names):
        bad("an ingredient is listed twice")
    kitchen = {item["kitchen_type"] for item in recipe["ingredients"] if item.get("kitchen_type")}
    for item in recipe["ingredients"]:
        kt, pid = item.get("kitchen_type"), item.get("product_id")
        if kt is not None and (kt not in KITCHEN_FOODS or item["name"] != kt or pid != KITCHEN_PRODUCTS[kt]):
            bad(f"ingredient {item['name']!r} has an inconsistent kitchen type/product ({kt}, {pid})")
        if kt is None and ONLINE_PRODUCTS.get(item["name"]) != pid:
            bad(f"ingredient {item['name']!r} is not a shop product (expected one of the fixed product ids)")
        if not str(item.get("amount", "")).strip():
            bad(f"ingredient {item['name']!r} has no amount")
    if not kitchen:
        bad("uses no kitchen food; every recipe needs at least one of " + ", ".join(KITCHEN_FOODS))
    if recipe["diet"] in DIETS and diet_of(names) != recipe["diet"]:
        bad(f"diet says {recipe['diet']} but the ingredients make it {diet_of(names)}")

    equipment = set(recipe["equipment"])
    unknown = equipment - set(EQUIPMENT)
    if unknown:
        bad(f"unknown equipment {sorted(unknown)}; use only {', '.join(EQUIPMENT)}")
    if len(recipe["equipment"]) != len(equipment):
        bad("a piece of equipment is listed twice")

    steps = recipe["steps"]
    if not 2 <= len(steps) <= 14:
        bad(f"has {len(steps)} steps; a recipe has 2 to 14")
    op_steps = 0
    used_foods: set[str] = set()
    needed: set[str] = set()
    trace = _KitchenTrace()
    for index, step in enumerate(steps, start=1):
        text = str(step.get("text", "")).strip()
        if not text:
            bad(f"step {index} has no text")
        ops = step.get("ops", [])
        op_steps += bool(ops)
        for op in ops:
            shape = _op_problems(op)
            if shape:
                problems.extend(f"{rid}: step {index}: {p}" for p in shape)
                continue
            needed |= required_equipment(op)
            if op["op"] in ("slice", "crack", "cook", "put"):
                used_foods.add(source_of(op["object"]))
            if op["op"] == "cook" and op["method"] == "stove" and not equipment & {"Pan", "Pot"}:
                bad(f"step {index}: cooking on the stove needs a Pan or a Pot in the equipment")
            sequence = trace.apply(op)
            if sequence:
                bad(f"step {index}: {sequence}")
        mentioned = {EQUIPMENT_WORDS[w] for w in _words(text) if w in EQUIPMENT_WORDS}
        if mentioned - equipment:
            bad(f"step {index} mentions {sorted(mentioned - equipment)} which the equipment list lacks")
    # A food put somewhere and then cooked has left that place (the kitchen moves it to the pan,
    # pot, toaster or microwave); the recipe must say where it ends up, or the put is a lie at the end.
    flat = [op for step in steps for op in step.get("ops", []) if not _op_problems(op)]
    for i, op in enumerate(flat):
        if op["op"] != "put" or op["receptacle"] in ("Pan", "Pot"):
            continue
        later = flat[i + 1:]
        cooked_at = next((j for j, o in enumerate(later) if o["op"] == "cook" and o["object"] == op["object"]), None)
        if cooked_at is not None and not any(o["op"] == "put" and o["object"] == op["object"]
                                             for o in later[cooked_at + 1:]):
            bad(f"{op['object']} is put in the {op['receptacle']} and later cooked, but never placed again; "
                f"add where it ends up (e.g. 'plate {op['object']}')")
    if op_steps < 2:
        bad(f"only {op_steps} step(s) with kitchen ops; a recipe needs at least 2")
    if needed - equipment:
        bad(f"ops need {sorted(needed - equipment)} which the equipment list lacks")
    if used_foods - kitchen:
        bad(f"ops use {sorted(used_foods - kitchen)} which the ingredients lack")
    if kitchen - used_foods:
        bad(f"kitchen ingredients {sorted(kitchen - used_foods)} are never used by an op")
    stove_vessel = {"Pan", "Pot"} & equipment
    for vessel in stove_vessel:
        in_text = any(vessel.lower() in _words(s.get("text", "")) for s in steps)
        if vessel not in needed and not in_text:
            bad(f"{vessel} is listed as equipment but no step uses it")
    for item in equipment - needed - stove_vessel:
        if not any(any(EQUIPMENT_WORDS.get(w) == item for w in _words(s.get("text", ""))) for s in steps):
            bad(f"{item} is listed as equipment but no step uses it")
    return problems
