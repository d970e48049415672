"""Text normalisation for answer checks: case, accents, punctuation, whitespace, digit grouping."""

from __future__ import annotations

import re
import unicodedata

# "1,454", "1 454" (also with no-break or thin spaces) and "1'454" all mean 1454; a separator
# counts as digit grouping only when exactly three digits follow, so "3,5" and "1, 2" are untouched.
_DIGIT_GROUP = re.compile(r"(?<=\d)[,'\u00a0\u202f\u2009 ](?=\d{3}(?!\d))")
_NON_WORD = re.compile(r"[^0-9a-z]+")
# Tokens: a number (decimal point and a fraction kept: "33.8", "1/3"), a word, "%", or a slash
# between words ("Georgian/Federal" offers two answers).
_TOKEN = re.compile(r"\d+(?:\.\d+)?(?:/\d+)?|[a-z]+|%|/")
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
    "storeys", "stories", "floors",
})
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
    folded = _fold(text).replace("&", " and ")
    out: list[str] = []
    for match in _TOKEN.finditer(folded):
        token = match.group(0)
        if token == "/" and (match.start() > 0 and folded[match.start() - 1].isdigit()):
            continue  # "24/7": a number's slash, not a choice between words
        out.append(_canonical_number(token) if token[0].isdigit() else token)
    return out


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
