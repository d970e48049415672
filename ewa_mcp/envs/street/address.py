"""Street-name normalisation and house-number rules, shared by the generator and the search.

"W. 23rd St", "west 23 street" and "West 23rd Street" all normalise to "west 23rd street";
"Avenue of the Americas" becomes "6th avenue" through the city's alias table.
"""

from __future__ import annotations

import math
import re
import unicodedata

ABBREVIATIONS = {
    "st": "street", "str": "street", "ave": "avenue", "av": "avenue", "avenue": "avenue", "blvd": "boulevard",
    "pl": "place", "sq": "square", "pkwy": "parkway", "pky": "parkway", "rd": "road", "dr": "drive",
    "w": "west", "e": "east", "n": "north", "s": "south", "ln": "lane", "hwy": "highway", "plz": "plaza",
}
ORDINAL_WORDS = {
    "first": "1st", "second": "2nd", "third": "3rd", "fourth": "4th", "fifth": "5th", "sixth": "6th",
    "seventh": "7th", "eighth": "8th", "ninth": "9th", "tenth": "10th", "eleventh": "11th", "twelfth": "12th",
}
DIRECTIONS = {"west", "east", "north", "south"}
STREET_TYPES = {"street", "avenue", "boulevard", "place", "square", "parkway", "road", "drive", "lane", "plaza"}


def ordinal(n: int) -> str:
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _tokens(text: str) -> list[str]:
    text = text.lower().replace("&", " and ").replace("’", "'")
    text = re.sub(r"[.,'()]", " ", text)
    return [t for t in text.split() if t]


def _normalize_tokens(tokens: list[str]) -> list[str]:
    out: list[str] = []
    for i, tok in enumerate(tokens):
        if tok == "st" and i == 0 and len(tokens) > 1 and not tokens[1][0].isdigit():
            out.append("saint")  # "St. James Place"
            continue
        tok = ABBREVIATIONS.get(tok, tok)
        tok = ORDINAL_WORDS.get(tok, tok)
        if tok.isdigit() and i + 1 < len(tokens) and ABBREVIATIONS.get(tokens[i + 1], tokens[i + 1]) in STREET_TYPES:
            tok = ordinal(int(tok))  # "23 street" -> "23rd street"
        out.append(tok)
    return out


def normalize_street(name: str, aliases: dict[str, str] | None = None) -> str:
    """A canonical key for a street name (lower case, abbreviations expanded, aliases applied)."""
    key = " ".join(_normalize_tokens(_tokens(name)))
    if aliases:
        for alias, canonical in aliases.items():
            if key == " ".join(_normalize_tokens(_tokens(alias))):
                return " ".join(_normalize_tokens(_tokens(canonical)))
    return key


def loose_street(key: str) -> str:
    """The key without a leading direction, so "23rd street" matches "west 23rd street"."""
    parts = key.split()
    return " ".join(parts[1:]) if len(parts) > 1 and parts[0] in DIRECTIONS else key


ADDRESS_RE = re.compile(r"^\s*(\d+)(?:\s*[-–]\s*\d+|\s+1/2)?\s+(.+?)\s*$")


def parse_address(text: str) -> tuple[int, str] | None:
    """"350 5th Ave" -> (350, "5th Ave"); None when the text does not start with a house number
    followed by a street (so "5th Ave & 23rd St" is not an address)."""
    if "&" in text or " and " in text.lower():
        return None
    m = ADDRESS_RE.match(text)
    if not m:
        return None
    street = m.group(2)
    toks = _normalize_tokens(_tokens(street))
    if not toks or toks[-1] not in STREET_TYPES and toks[0] not in DIRECTIONS and len(toks) < 2:
        return None
    return int(m.group(1)), street


# ---------------------------------------------------------------- house-number rules
# A rule turns (street key, number) into a block: the two cross streets bracketing the number and
# the fraction of the way between them. Cross streets are given as street keys (any direction).
Block = tuple[str, str, float]

MANHATTAN_WEST = ["5th avenue", "6th avenue", "7th avenue", "8th avenue", "9th avenue", "10th avenue",
                  "11th avenue", "12th avenue"]
MANHATTAN_EAST = [(0, "5th avenue"), (50, "madison avenue"), (100, "park avenue"), (140, "lexington avenue"),
                  (200, "3rd avenue"), (300, "2nd avenue"), (400, "1st avenue")]
# The well-known Manhattan "drop the last digit, halve, add the key" rule for avenue numbers.
MANHATTAN_AVENUE_KEYS = {
    "6th avenue": -12, "7th avenue": 12, "8th avenue": 10, "9th avenue": 13, "10th avenue": 14,
    "11th avenue": 15, "1st avenue": 3, "2nd avenue": 3, "3rd avenue": 10, "lexington avenue": 22,
    "madison avenue": 26, "park avenue": 35, "park avenue south": 8,
}
FIFTH_AVENUE_KEYS = [(200, 13), (400, 16), (600, 18), (775, 20)]
PHILADELPHIA_NS = [(0, "market street"), (100, "chestnut street"), (200, "walnut street"), (250, "locust street"),
                   (300, "spruce street"), (400, "pine street"), (500, "lombard street"), (600, "south street")]
PHILADELPHIA_NN = [(0, "market street"), (100, "arch street"), (200, "race street"), (300, "vine street"),
                   (400, "callowhill street"), (500, "spring garden street")]
PHILADELPHIA_EW = {"market street", "chestnut street", "walnut street", "locust street", "spruce street",
                   "pine street", "lombard street", "south street", "arch street", "race street", "vine street",
                   "callowhill street", "spring garden street", "sansom street", "john f kennedy boulevard"}


def _bracket(number: float, anchors: list[tuple[float, str]]) -> Block | None:
    for (n0, s0), (n1, s1) in zip(anchors, anchors[1:]):
        if n0 <= number <= n1:
            return s0, s1, (number - n0) / (n1 - n0)
    return None


def _cross_street(n: int) -> str:
    return f"{ordinal(n)} street"


def manhattan_block(street: str, number: int) -> Block | None:
    loose = loose_street(street)
    m = re.fullmatch(r"(\d+)(st|nd|rd|th) street", loose)
    if m:
        if street.startswith("west"):
            k = number / 100.0
            i = int(math.floor(k))
            if 0 <= i < len(MANHATTAN_WEST) - 1:
                return MANHATTAN_WEST[i], MANHATTAN_WEST[i + 1], k - i
            return None
        if street.startswith("east"):
            return _bracket(float(number), [(float(n), s) for n, s in MANHATTAN_EAST])
        return None
    if street == "5th avenue":
        key = next((k for limit, k in FIFTH_AVENUE_KEYS if number <= limit), None)
    else:
        key = MANHATTAN_AVENUE_KEYS.get(street)
    if key is None:
        return None
    cross = number / 10.0 / 2.0 + key
    lo = int(math.floor(cross))
    if not 14 <= lo < 59:
        return None
    return _cross_street(lo), _cross_street(lo + 1), cross - lo


def philadelphia_block(street: str, number: int) -> Block | None:
    if street in PHILADELPHIA_EW:
        k = number / 100.0
        i = int(math.floor(k))
        if not 1 <= i < 23:
            return None

        def name(j: int) -> str:
            return "front street" if j == 1 else "broad street" if j == 14 else _cross_street(j)

        return name(i), name(i + 1), k - i
    if street.startswith("south "):
        return _bracket(float(number), [(float(n), s) for n, s in PHILADELPHIA_NS])
    if street.startswith("north "):
        return _bracket(float(number), [(float(n), s) for n, s in PHILADELPHIA_NN])
    return None


BLOCK_RULES = {"manhattan": manhattan_block, "philadelphia": philadelphia_block}


def fold(text: str) -> str:
    """Case-, accent- and punctuation-insensitive form for matching names."""
    # Dashes part words ("14 St–Union Square" is "14 St-Union Square"); the ASCII fold would drop an en
    # dash and run the words together.
    text = re.sub("[\u2010-\u2015\u2212]", " ", text)
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode()
    text = text.lower().replace("&", " and ").replace("'", "").replace("’", "")
    return " ".join("".join(c if c.isalnum() else " " for c in text).split())


def same_address(address: str, number: int, street: str, aliases: dict[str, str]) -> bool:
    """Whether ``address`` is number ``number`` on ``street`` (street names compared normalised, then loosely)."""
    parsed = parse_address(address)
    if parsed is None or parsed[0] != number:
        return False
    a, b = normalize_street(parsed[1], aliases), normalize_street(street, aliases)
    return a == b or loose_street(a) == loose_street(b) and (a.split()[0] not in ("west", "east") or
                                                             b.split()[0] not in ("west", "east"))
