"""Text normalisation for answer checks: case, accents, punctuation, whitespace, digit grouping."""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

# "1,454", "1 454" (also with no-break or thin spaces) and "1'454" all mean 1454; a separator
# counts as digit grouping only when exactly three digits follow, so "3,5" and "1, 2" are untouched.
_DIGIT_GROUP = re.compile(r"(?<=\d)[,'\u00a0\u202f\u2009 ](?=\d{3}(?!\d))")
_NON_WORD = re.compile(r"[^0-9a-z]+")
# Tokens: a number (decimal point and a fraction kept: "33.8", "1/3"), a word, "%", or a slash
# between words ("Georgian/Federal" offers two answers).
# Also kept: a currency sign ("$3.49" is a price) and "#" ("#1001" is a number, not a value), and an
# identifier of letters, a hyphen and digits ("EWA-1001", an order number) as one token.
_TOKEN = re.compile(r"[a-z]+-\d+\b|\d+(?:\.\d+)?(?:/\d+)?|[a-z]+|%|/|[$\u20ac\u00a3\u00a5#]")
_NUMBER = re.compile(r"\d+(?:\.\d+)?(?:/\d+)?")

# Units the grader recognises after a number: a number followed by one of these is a quantity of
# that unit, not a bare value (so "Oat Milk (1 L), 120 kcal" holds one calorie value, not two).
KNOWN_UNITS = frozenset({
    "g", "gram", "grams", "kg", "mg", "oz", "ounce", "ounces", "lb", "lbs", "pound", "pounds", "ml", "l",
    "litre", "litres", "liter", "liters", "fl", "gal", "gallon", "gallons", "qt", "quart", "quarts", "pt",
    "pint", "pints", "ct", "count", "pack", "pk", "x", "cup", "cups", "tbsp", "tsp", "sq", "ft", "feet", "foot",
    "m", "metre", "metres", "meter", "meters", "km", "mi", "miles", "inch", "inches", "kcal", "cal",
    "cals", "calorie", "calories", "kj", "%", "percent", "rolls", "boxes", "box", "bag", "bags",
    "slice", "slices", "serving", "servings", "st", "th", "nd", "rd", "am", "pm", "h", "hours", "min",
    "storeys", "stories", "floors", "dollar", "dollars", "usd", "cent", "cents", "eur", "euro", "euros",
    "yd", "yard", "yards",
})
# Words after which a number names a thing, not a value: "order 1001", "order no. 1001", "#1001".
IDENTIFIER_WORDS = frozenset({"order", "number", "no", "id", "ref", "reference", "confirmation", "#", "suite",
                              "room", "gate", "pier", "route"})
CURRENCY = frozenset({"$", "\u20ac", "\u00a3", "\u00a5"})
# Street-type words: "1401 Chestnut Street", "350 5th Ave", "1 Broadway" are addresses.
STREET_WORDS = frozenset({"street", "st", "avenue", "ave", "av", "broadway", "boulevard", "blvd", "road", "rd",
                          "pl", "square", "sq", "plaza", "lane", "ln", "drive", "dr", "parkway", "pkwy",
                          "terrace", "wharf", "alley", "highway", "hwy", "bowery"})
# Words that end an address's name: "1883 on Market Street" is a year, then a street.
_NOT_IN_A_NAME = frozenset({"on", "in", "at", "near", "by", "of", "from", "and", "the", "was", "is", "built",
                            "opened", "since", "until", "to", "with", "for", "a", "an", "it", "its", "which", "that",
                            "about", "approximately", "around", "some", "ago", "years"})
# Words by which an answer hedges between candidates or denies one; see docs/grading.md.
HEDGES = frozenset({"or", "either", "maybe", "perhaps", "possibly", "probably", "might", "unsure", "not", "nor",
                    "neither", "never", "unless", "/"})


def _fold(text: str) -> str:
    decomposed = unicodedata.normalize("NFKD", text)
    no_accents = "".join(ch for ch in decomposed if not unicodedata.combining(ch))
    return _DIGIT_GROUP.sub("", no_accents.casefold().replace("ß", "ss"))


def normalize(text: str) -> str:
    ungrouped = _fold(text).replace("&", " and ")
    return " ".join(_NON_WORD.sub(" ", ungrouped).split())


def contains_phrase(haystack: str, phrase: str) -> bool:
    """Whole-word containment after normalisation: "2008" is in "built in 2008" but not in "12008"."""
    needle = normalize(phrase)
    if not needle:
        return True
    return f" {needle} " in f" {normalize(haystack)} "


def _canonical_number(token: str) -> str:
    if "/" in token:
        return token
    whole, _, frac = token.partition(".")
    frac = frac.rstrip("0")
    return (whole.lstrip("0") or "0") + ("." + frac if frac else "")


def tokens(text: str) -> list[str]:
    """The answer as comparable tokens: numbers canonical ("120.0" = "120", "1,454" = "1454"), words
    case- and accent-folded, "&" read as "and", other punctuation dropped except "%" and a word slash."""
    return list(_tokens(text))


@lru_cache(maxsize=65536)  # a task's distractors are read once per answer graded: hundreds of phrases
def _tokens(text: str) -> tuple[str, ...]:
    folded = _fold(text).replace("&", " and ")
    out: list[str] = []
    for match in _TOKEN.finditer(folded):
        token = match.group(0)
        if token == "/" and _per_slash(folded, match.start(), out):
            continue  # "24/7", "45 cal/serving", "151 m/495 ft": a rate or a conversion, not a choice of words
        out.append(_canonical_number(token) if token[0].isdigit() else token)
    return tuple(out)


def _per_slash(folded: str, at: int, before: list[str]) -> bool:
    """Whether the slash at ``folded[at]`` joins a number or a unit (not two words offered as choices)."""
    if at > 0 and folded[at - 1].isdigit():
        return True
    if before and before[-1] in KNOWN_UNITS and len(before) > 1 and is_number(before[-2]):
        return True
    return bool(re.match(r"\s*\d", folded[at + 1:]))


def non_value(toks: list[str], i: int) -> bool:
    """Whether the number at ``toks[i]`` is a price, an identifier or a street address: never a value of
    the asked kind, whatever its unit and range ("$1.40", "order #1001", "1500 Market Street")."""
    if i > 0 and (toks[i - 1] in CURRENCY or toks[i - 1] in IDENTIFIER_WORDS):
        return True
    if i > 1 and toks[i - 2] in IDENTIFIER_WORDS and toks[i - 1] in ("no", "number", "#"):
        return True
    for j in range(i + 1, min(len(toks), i + 6)):
        if toks[j] in STREET_WORDS:
            return True
        if toks[j] in _NOT_IN_A_NAME or toks[j] in CURRENCY or "/" == toks[j]:
            return False
        if is_number(toks[j]) and toks[j + 1:j + 2] not in (["st"], ["nd"], ["rd"], ["th"]):
            return False  # the address is that number's ("1883 (206 Washington St)")
    return False


def is_number(token: str) -> bool:
    return bool(_NUMBER.fullmatch(token))


def number_value(token: str) -> float:
    if "/" in token:
        num, _, den = token.partition("/")
        return int(num) / int(den) if int(den) else float("inf")
    return float(token)


def find_spans(haystack: list[str], needle: list[str]) -> list[tuple[int, int]]:
    """Every [start, end) where the token list ``needle`` occurs in ``haystack``."""
    n = len(needle)
    if n == 0:
        return []
    return [(i, i + n) for i in range(len(haystack) - n + 1) if haystack[i:i + n] == needle]
