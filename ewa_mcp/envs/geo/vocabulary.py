"""The words a passer-by's view uses, so that the wiki can be kept from using them (issue 26, principle 4).

A view says what is seen ("trees whose bark flakes off in patches"); the encyclopedia says what the
convention is called ("London plane"). If both used the same distinctive words, matching words between a
view and the articles would find the city without any reasoning. ``distinctive_view_words()`` is the
vocabulary of every view of every location, outside quoted sign and plate text, less the words that the
views of many cities share (left, buildings, sky): the article writer drops free-text sentences that use
one of these words and writes its own lines in other words, and a test checks the written articles.
"""

from __future__ import annotations

import re
import unicodedata
from collections import Counter, defaultdict
from functools import lru_cache

from ewa_mcp.geometry import FOUR_DIRECTIONS
from .describe import describe_view
from .graph import build_graph
from .locations import LOCATIONS_LIST
from .scene import compose_view

# A word used by the views of more than this share of the cities says nothing about one place.
SHARED_SHARE = 0.2
_QUOTED = re.compile(r"'[^']*'(?=[\s.,;)]|$)")
# Function words say nothing about a place, however few views use them.
STOPWORDS = frozenset("""above all almost any back behind beside beyond both down either end every few from further
into its like many next one other out over same several some than them three times top towards upper very without""".split())


def fold(text: str) -> str:
    decomposed = unicodedata.normalize("NFKD", text)
    return "".join(c for c in decomposed if not unicodedata.combining(c)).casefold()


def words(text: str) -> set[str]:
    """Search-style words: accents and case folded, letters only, three characters or more."""
    return {w for w in re.findall(r"[a-z]+", fold(text)) if len(w) >= 3}


@lru_cache(maxsize=1)
def view_words_by_city() -> dict[str, frozenset[str]]:
    """Every word the views of each city's locations use outside quotes."""
    by_city: dict[str, set[str]] = defaultdict(set)
    for loc in LOCATIONS_LIST:
        for sp in build_graph(loc):
            for heading in FOUR_DIRECTIONS:
                text = _QUOTED.sub(" ", describe_view(compose_view(loc, sp, heading)))
                by_city[loc.city_key] |= words(text)
    return {k: frozenset(v) for k, v in by_city.items()}


@lru_cache(maxsize=1)
def distinctive_view_words() -> frozenset[str]:
    """The view words that only a few cities' views use."""
    by_city = view_words_by_city()
    df: Counter[str] = Counter(w for ws in by_city.values() for w in ws)
    return frozenset(w for w, n in df.items() if n <= SHARED_SHARE * len(by_city) and w not in STOPWORDS)


@lru_cache(maxsize=1)
def sign_words() -> frozenset[str]:
    """Every word a shop sign in any language can show (the views quote them; the wiki names the language)."""
    from .languages import COUNTRY_WORDS, LANGUAGES

    out: set[str] = set()
    english: set[str] = set()
    for lang in LANGUAGES.values():
        for native, latin in lang.words.values():
            (english if lang.code.startswith("en") else out).update(words(native) | words(latin))
    for by_language in COUNTRY_WORDS.values():
        for code, kinds in by_language.items():
            for own in kinds.values():
                (english if code.startswith("en") else out).update(w for x in own for w in words(x))
    # Words English signs share ("bank", "hotel", "shop") name no language; "the" is a Sinhala word's
    # transliteration and an English one.
    return frozenset(out - english - {"the"})


def banned_in_articles() -> frozenset[str]:
    """Words no sentence of a geolocation article may use: distinctive view words and sign words."""
    return distinctive_view_words() | sign_words()
