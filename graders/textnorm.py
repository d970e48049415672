"""Text normalisation for answer checks: case, accents, punctuation, whitespace, digit grouping."""

from __future__ import annotations

import re
import unicodedata

# "1,454", "1 454" (also with no-break or thin spaces) and "1'454" all mean 1454; a separator
# counts as digit grouping only when exactly three digits follow, so "3,5" and "1, 2" are untouched.
_DIGIT_GROUP = re.compile(r"(?<=\d)[,'\u00a0\u202f\u2009 ](?=\d{3}(?!\d))")
_NON_WORD = re.compile(r"[^0-9a-z]+")


def normalize(text: str) -> str:
    decomposed = unicodedata.normalize("NFKD", text)
    no_accents = "".join(ch for ch in decomposed if not unicodedata.combining(ch))
    lowered = no_accents.casefold().replace("ß", "ss")
    ungrouped = _DIGIT_GROUP.sub("", lowered)
    return " ".join(_NON_WORD.sub(" ", ungrouped).split())


def contains_phrase(haystack: str, phrase: str) -> bool:
    """Whole-word containment after normalisation: "2008" is in "built in 2008" but not in "12008"."""
    needle = normalize(phrase)
    if not needle:
        return True
    return f" {needle} " in f" {normalize(haystack)} "
