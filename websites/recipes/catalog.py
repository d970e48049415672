"""The recipe catalogue: loading, the URL query model, search and filters.

The site's whole browsing state lives in the URL (``/?q=salad&diet=vegetarian&include=Tomato``),
so ``parse_query`` turns query parameters into ``Filters`` (or a ``QueryError`` naming the bad
parameter and how to fix it) and ``Filters.to_query`` writes them back in one canonical order.
"""

from __future__ import annotations

import json
import re
import unicodedata
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import lru_cache
from pathlib import Path
from typing import Any
from urllib.parse import urlencode

from .vocabulary import DIETS, DIFFICULTIES, EQUIPMENT, KITCHEN_FOODS

DATA_PATH = Path(__file__).resolve().parent / "data" / "recipes.json"
PAGE_SIZE = 20
MAX_QUERY_CHARS = 200
MAX_VALUES_PER_FILTER = 8
MULTI_FILTERS = ("include", "exclude", "equipment")
SINGLE_FILTERS = ("q", "diet", "difficulty", "cuisine", "page")

DIET_LABELS = {"vegetarian": "Vegetarian", "vegan": "Vegan", "non-vegetarian": "Non-vegetarian"}
DIFFICULTY_LABELS = {d: d.capitalize() for d in DIFFICULTIES}
EQUIPMENT_LABELS = {e: ("Stove burner" if e == "StoveBurner" else e) for e in EQUIPMENT}


class QueryError(ValueError):
    """A query parameter the site cannot use; the message names it and the fix."""

    def __init__(self, message: str, status: int = 400) -> None:
        super().__init__(message)
        self.status = status


@dataclass(frozen=True)
class Filters:
    q: str = ""
    diet: str = ""
    difficulty: str = ""
    cuisine: str = ""
    include: tuple[str, ...] = ()
    exclude: tuple[str, ...] = ()
    equipment: tuple[str, ...] = ()
    page: int = 1

    @property
    def active(self) -> bool:
        return bool(self.q or self.diet or self.difficulty or self.cuisine or self.include or self.exclude
                    or self.equipment)

    def to_query(self, **changes: Any) -> str:
        """The canonical query string ("?..." or "") of these filters with ``changes`` applied."""
        f = replace(self, **changes)
        pairs: list[tuple[str, str]] = []
        for key in ("q", "diet", "difficulty", "cuisine"):
            if getattr(f, key):
                pairs.append((key, getattr(f, key)))
        for key in MULTI_FILTERS:
            pairs.extend((key, value) for value in getattr(f, key))
        if f.page != 1:
            pairs.append(("page", str(f.page)))
        return "?" + urlencode(pairs) if pairs else ""

    def without(self, key: str, value: str | None = None) -> str:
        """Query string with one filter (or one value of a multi-valued filter) removed, back to page 1."""
        if key in MULTI_FILTERS:
            return self.to_query(**{key: tuple(v for v in getattr(self, key) if v != value)}, page=1)
        return self.to_query(**{key: ""}, page=1)

    def as_event(self) -> dict[str, Any]:
        return {"diet": self.diet or None, "difficulty": self.difficulty or None, "cuisine": self.cuisine or None,
                "include": list(self.include), "exclude": list(self.exclude), "equipment": list(self.equipment)}


@dataclass
class Catalog:
    recipes: list[dict[str, Any]]
    by_id: dict[str, dict[str, Any]] = field(init=False)
    cuisines: list[str] = field(init=False)
    ingredients: list[str] = field(init=False)
    _index: dict[str, dict[str, Any]] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.by_id = {r["id"]: r for r in self.recipes}
        self.cuisines = sorted({r["cuisine"] for r in self.recipes})
        names = {i["name"] for r in self.recipes for i in r["ingredients"]}
        # Kitchen foods first (what the kitchen has), then the shop ingredients alphabetically.
        self.ingredients = [k for k in KITCHEN_FOODS if k in names] + sorted(names - set(KITCHEN_FOODS))
        self._index = {
            r["id"]: {
                "name": _fold(r["name"]),
                "text": _fold(" ".join([r["name"], r["cuisine"]] + [i["name"] for i in r["ingredients"]])),
                "ingredients": {i["name"] for i in r["ingredients"]},
                "equipment": set(r["equipment"]),
            }
            for r in self.recipes
        }

    # ------------------------------------------------------------ queries
    def search(self, filters: Filters) -> list[dict[str, Any]]:
        tokens = _tokens(filters.q)
        phrase = " ".join(_fold(filters.q).split())
        ranked: list[tuple[int, str, str, dict[str, Any]]] = []
        for recipe in self.recipes:
            entry = self._index[recipe["id"]]
            if filters.diet and recipe["diet"] != filters.diet:
                continue
            if filters.difficulty and recipe["difficulty"] != filters.difficulty:
                continue
            if filters.cuisine and recipe["cuisine"] != filters.cuisine:
                continue
            if not set(filters.include) <= entry["ingredients"]:
                continue
            if set(filters.exclude) & entry["ingredients"]:
                continue
            if not set(filters.equipment) <= entry["equipment"]:
                continue
            if tokens and not all(_token_in(t, entry["text"]) for t in tokens):
                continue
            rank = 0
            if phrase:
                if entry["name"] == phrase:
                    rank = 0
                elif phrase in entry["name"]:
                    rank = 1
                elif all(_token_in(t, entry["name"]) for t in tokens):
                    rank = 2
                else:
                    rank = 3
            ranked.append((rank, recipe["name"].lower(), recipe["id"], recipe))
        ranked.sort(key=lambda item: item[:3])
        return [item[3] for item in ranked]

    def page_of(self, results: Sequence[dict[str, Any]], page: int) -> tuple[list[dict[str, Any]], int]:
        pages = max(1, -(-len(results) // PAGE_SIZE))
        if page > pages:
            raise QueryError(f"Page {page} does not exist: these results have {pages} page(s). "
                             "Go back to page 1.", status=404)
        start = (page - 1) * PAGE_SIZE
        return list(results[start:start + PAGE_SIZE]), pages

    # ------------------------------------------------------------ query parsing
    def parse_query(self, params: Mapping[str, Sequence[str]]) -> Filters:
        """Validate query parameters (name -> list of values) into Filters."""
        values: dict[str, Any] = {}
        for key in SINGLE_FILTERS:
            given = [v.strip() for v in params.get(key, []) if v.strip()]
            if len(set(given)) > 1:
                raise QueryError(f"The '{key}' parameter was given {len(given)} different values; give it once.")
            values[key] = given[0] if given else ""
        q = " ".join(values["q"].split())
        if len(q) > MAX_QUERY_CHARS:
            raise QueryError(f"The search text is {len(q)} characters long; use at most {MAX_QUERY_CHARS}.")
        diet = _choose("diet", values["diet"], list(DIETS))
        difficulty = _choose("difficulty", values["difficulty"], list(DIFFICULTIES))
        cuisine = _choose("cuisine", values["cuisine"], self.cuisines)
        page = 1
        if values["page"]:
            if not values["page"].isdigit() or int(values["page"]) < 1 or len(values["page"]) > 6:
                raise QueryError(f"page must be a whole number from 1 up, not {values['page'][:20]!r}.")
            page = int(values["page"])
        multi: dict[str, tuple[str, ...]] = {}
        for key, options in (("include", self.ingredients), ("exclude", self.ingredients),
                             ("equipment", list(EQUIPMENT))):
            given = [v.strip() for v in params.get(key, []) if v.strip()]
            if len(given) > MAX_VALUES_PER_FILTER:
                raise QueryError(f"Too many '{key}' values ({len(given)}); use at most {MAX_VALUES_PER_FILTER}.")
            chosen: list[str] = []
            for value in given:
                canonical = _choose(key, value, options)
                if canonical not in chosen:
                    chosen.append(canonical)
            multi[key] = tuple(chosen)
        both = set(multi["include"]) & set(multi["exclude"])
        if both:
            raise QueryError(f"{', '.join(sorted(both))} is both included and excluded; remove one of the two filters.")
        return Filters(q=q, diet=diet, difficulty=difficulty, cuisine=cuisine, page=page, **multi)


def _squash(value: str) -> str:
    return re.sub(r"[\s_-]+", "", value.lower())


def _choose(key: str, value: str, options: list[str]) -> str:
    """Match a parameter value to one of the options, ignoring case, spaces, '-' and '_'."""
    if not value:
        return ""
    for option in options:
        if _squash(option) == _squash(value):
            return option
    shown = value if len(value) <= 40 else value[:40] + "…"
    raise QueryError(f"Unknown {key} {shown!r}. Use one of: {', '.join(options)} (or leave it empty).")


def _fold(text: str) -> str:
    """Lower case without accents, so "Rösti" and "rosti" are one word (and "ö" never splits it in two:
    an ASCII-only split once made "sti" a word of "Potato Rösti")."""
    decomposed = unicodedata.normalize("NFKD", text.lower().replace("ø", "o").replace("ß", "ss"))
    return "".join(c for c in decomposed if not unicodedata.combining(c))


def _tokens(q: str) -> list[str]:
    return re.findall(r"[^\W_]+", _fold(q))


def _token_in(token: str, text: str) -> bool:
    # Accept simple plurals ("potatoes", "eggs") without a stemming library.
    variants = {token}
    if len(token) > 3 and token.endswith("es"):
        variants.add(token[:-2])
    if len(token) > 3 and token.endswith("s"):
        variants.add(token[:-1])
    return any(v in text for v in variants)


@lru_cache(maxsize=1)
def load_recipes() -> tuple[dict[str, Any], ...]:
    """The committed recipes (read once). The task generator and graders use this too."""
    return tuple(json.loads(DATA_PATH.read_text(encoding="utf-8")))


@lru_cache(maxsize=1)
def load_catalog() -> Catalog:
    return Catalog(list(load_recipes()))

