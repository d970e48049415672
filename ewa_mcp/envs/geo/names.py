"""Place-name normalisation and alias tables for continents, countries, cities and streets.

Used both to validate a submission (an unknown country is refused with the valid forms)
and to grade it (Côte d'Ivoire = Ivory Coast = CI = CIV; New Delhi = Delhi; Chattogram =
Chittagong; Nevsky Prospect = Невский проспект).
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable
from functools import lru_cache

from . import gazetteer
from .cities import CITIES_LIST, City
from .countries import COUNTRIES_LIST

CONTINENTS = ("Africa", "Antarctica", "Asia", "Europe", "North America", "Oceania", "South America")

_CONTINENT_ALIASES: dict[str, str] = {
    "africa": "Africa", "antarctica": "Antarctica", "asia": "Asia", "europe": "Europe",
    "north america": "North America", "northern america": "North America", "central america": "North America",
    "caribbean": "North America", "the caribbean": "North America", "south america": "South America",
    "oceania": "Oceania", "australia": "Oceania", "australasia": "Oceania", "australia and oceania": "Oceania",
    "australia oceania": "Oceania", "pacific": "Oceania",
}
_CONTINENT_CODES = {code: name for code, name in gazetteer.CONTINENT_NAMES.items()}

# Countries whose continent is genuinely ambiguous: either answer is accepted.
AMBIGUOUS_CONTINENTS: dict[str, frozenset[str]] = {
    "TR": frozenset({"Europe", "Asia"}),
    "GE": frozenset({"Europe", "Asia"}),
    "AM": frozenset({"Europe", "Asia"}),
    "CY": frozenset({"Europe", "Asia"}),
}

# Country answers accepted for another country (a territory and its sovereign).
EQUIVALENT_COUNTRIES: dict[str, frozenset[str]] = {
    "HK": frozenset({"CN"}),
    "MO": frozenset({"CN"}),
}

# Common exonyms and former names of countries the location set does not use.
_EXTRA_COUNTRY_ALIASES: dict[str, tuple[str, ...]] = {
    "MM": ("Burma",), "SZ": ("Swaziland", "eSwatini"), "CV": ("Cape Verde", "Cabo Verde"),
    "TL": ("East Timor", "Timor-Leste", "Timor Leste"), "MK": ("Macedonia", "North Macedonia", "FYROM"),
    "CD": ("DR Congo", "DRC", "Congo-Kinshasa", "Zaire", "Democratic Republic of the Congo"),
    "CG": ("Congo-Brazzaville", "Republic of the Congo"), "KP": ("North Korea", "DPRK"),
    "PS": ("Palestine", "State of Palestine"), "VA": ("Vatican City", "Holy See"), "CZ": ("Czech Republic",),
    "BA": ("Bosnia", "Bosnia-Herzegovina"), "MD": ("Moldova", "Republic of Moldova"), "BY": ("Belarus", "Byelorussia"),
    "LA": ("Laos", "Lao PDR"), "SY": ("Syria",), "FM": ("Micronesia",), "BN": ("Brunei", "Brunei Darussalam"),
}
# Names that could mean more than one country.
_AMBIGUOUS_COUNTRY_NAMES: dict[str, frozenset[str]] = {
    "congo": frozenset({"CG", "CD"}),
    "guinea": frozenset({"GN"}),
}

_PUNCT = re.compile(r"[\s\-‐‑‒–—_/\\.,;:!?'’‘`\"“”()\[\]{}·|]+")


def normalize(text: str) -> str:
    """Accent-free, case-free, punctuation-free form ("Côte d'Ivoire" -> "cote d ivoire")."""
    text = unicodedata.normalize("NFKC", text).replace("&", " and ").replace("ß", "ss").replace("ı", "i")
    text = "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))
    text = _PUNCT.sub(" ", text.casefold()).strip()
    if text.startswith("the "):
        text = text[4:]
    return text


def squash(text: str) -> str:
    """normalize() without spaces, so "Ivory Coast" and "IvoryCoast", "Kuala Lumpur" and "KualaLumpur" meet."""
    return normalize(text).replace(" ", "")


# ------------------------------------------------------------------------------ continents
def resolve_continent(text: str) -> str | None:
    raw = text.strip()
    if raw.upper() in _CONTINENT_CODES and raw.isupper():
        return _CONTINENT_CODES[raw.upper()]
    return _CONTINENT_ALIASES.get(normalize(raw))


# ------------------------------------------------------------------------------ countries
@lru_cache(maxsize=1)
def _country_index() -> tuple[dict[str, frozenset[str]], dict[str, str]]:
    """(normalized name -> ISO codes, code (ISO2/ISO3, upper case) -> ISO2)."""
    names: dict[str, set[str]] = {}

    def add(name: str, iso: str) -> None:
        key = squash(name)
        if key:
            names.setdefault(key, set()).add(iso)

    codes: dict[str, str] = {}
    for iso, record in gazetteer.countries().items():
        add(record["name"], iso)
        codes[iso] = iso
        codes[record["iso3"]] = iso
    for country in COUNTRIES_LIST:
        add(country.name, country.iso)
        for alias in country.aliases:
            add(alias, country.iso)
    for iso, aliases in _EXTRA_COUNTRY_ALIASES.items():
        for alias in aliases:
            add(alias, iso)
    for name, isos in _AMBIGUOUS_COUNTRY_NAMES.items():
        names[squash(name)] = set(isos)
    return {k: frozenset(v) for k, v in names.items()}, codes


def resolve_country(text: str) -> frozenset[str]:
    """The ISO 3166 alpha-2 codes a country answer can mean (empty when unknown).

    Upper-case two- and three-letter answers are read as ISO codes ("CI", "CIV"); written
    any other way they are names, so "no" is not Norway."""
    raw = text.strip()
    names, codes = _country_index()
    if raw.isupper() and raw.isalpha() and len(raw) in (2, 3) and raw in codes:
        return frozenset({codes[raw]})
    return names.get(squash(raw), frozenset())


def country_suggestions(text: str, limit: int = 4) -> list[str]:
    import difflib

    pretty = sorted({c.name for c in COUNTRIES_LIST} | {r["name"] for r in gazetteer.countries().values()})
    by_key = {squash(p): p for p in pretty}
    hits = difflib.get_close_matches(squash(text), list(by_key), n=limit, cutoff=0.6)
    return [by_key[h] for h in hits]


def countries_match(answer: str, truth: str) -> bool:
    got, want = resolve_country(answer), resolve_country(truth)
    if not want:
        return squash(answer) == squash(truth) and bool(squash(truth))
    accepted = set(want)
    for iso in want:
        accepted |= EQUIVALENT_COUNTRIES.get(iso, frozenset())
    return bool(got & accepted)


# ------------------------------------------------------------------------------ cities
def _city_variants(name: str) -> set[str]:
    key = squash(name)
    out = {key}
    if key.endswith("city") and len(key) > 6:
        out.add(key[: -len("city")])
    return out


def _hand_city(name: str, isos: Iterable[str]) -> City | None:
    wanted = squash(name)
    for city in CITIES_LIST:
        if city.iso in isos and (squash(city.name) == wanted or wanted in {squash(a) for a in city.aliases}):
            return city
    return None


@lru_cache(maxsize=2048)
def city_names(name: str, country: str, lat: float, lng: float) -> frozenset[str]:
    """Every accepted spelling of the city ``name`` in ``country`` near (lat, lng), squashed."""
    from ewa_mcp.geometry import haversine_km

    isos = resolve_country(country)
    accepted: set[str] = set(_city_variants(name))
    hand = _hand_city(name, isos)
    gazetteer_ids: set[int] = set()
    if hand is not None:
        gazetteer_ids.add(hand.geonameid)
        for alias in (hand.name, *hand.aliases):
            accepted |= _city_variants(alias)
    wanted = squash(name)
    best: tuple[float, int] | None = None
    for gid, record in gazetteer.cities().items():
        if isos and record["countrycode"] not in isos:
            continue
        if squash(record["name"]) != wanted and wanted not in {squash(a) for a in record["alternatenames"]}:
            continue
        d = haversine_km(lat, lng, record["latitude"], record["longitude"])
        if d <= 60 and (best is None or d < best[0]):
            best = (d, gid)
    if best is not None:
        gazetteer_ids.add(best[1])
    for gid in gazetteer_ids:
        known = gazetteer.cities().get(gid)
        if known is None:
            continue
        accepted |= _city_variants(known["name"])
        for alt in known["alternatenames"]:
            accepted |= _city_variants(alt)
    accepted.discard("")
    return frozenset(accepted)


def cities_match(answer: str, truth: str, country: str, lat: float, lng: float) -> bool:
    if not squash(answer):
        return False
    accepted = city_names(truth, country, round(lat, 4), round(lng, 4))
    if _city_variants(answer) & accepted:
        return True
    # "Paris, France" in the city field is the city: what follows the first comma may only name the
    # answer's own country; "Paris, Texas" stays wrong.
    head, _, tail = answer.partition(",")
    if not squash(head) or not all(countries_match(part, country) for part in tail.split(",") if squash(part)):
        return False
    return bool(_city_variants(head) & accepted)


# ------------------------------------------------------------------------------ streets
_STREET_TYPES = frozenset("""
street st road rd avenue ave av avda avenida boulevard blvd bd bvd bulevar bulevard bulvari bulvar lane ln drive dr
way place pl plaza praca square sq piazza platz plac ploshchad meydani quay parade mall rue calle c carrer carrera cra
rua via viale corso strasse str gasse ulica ul ulitsa vulytsia vulitsa iela gatan gate gade katu vegur prospekt
prospect prospektas pr namesti jalan jl jiron jr marg sarani salai caddesi cad cd sokak dori lu dajie jie duong pho
thanon khiyaban shari sharia tariq gamziri poghots utca ut allee promenade esplanade terrace crescent row avinguda
paseo pasaje pje andador calzada tanav
""".split())
_STOPWORDS = frozenset("de del la las los le les du des da do dos das di dei degli della of the el al van von der "
                       "den y e and".split())
_ORDINAL = re.compile(r"^(\d+)(st|nd|rd|th|e|er|a|o|ª|º)$")


# Compass qualifiers, spelled out. A single letter is one only at either end ("E 42nd St", "Constitution
# Ave NW"); inside a name it is a word ("Rua Dom Pedro e Silva").
_COMPASS = {"n": "north", "s": "south", "e": "east", "w": "west", "ne": "northeast", "nw": "northwest",
            "se": "southeast", "sw": "southwest"}
COMPASS_WORDS = frozenset(_COMPASS.values())


def street_core(text: str) -> tuple[str, ...]:
    tokens = normalize(text).split()
    out: list[str] = []
    for i, tok in enumerate(tokens):
        if tok in _COMPASS and (i == 0 or i == len(tokens) - 1) and len(tokens) > 1:
            out.append(_COMPASS[tok])
            continue
        m = _ORDINAL.match(tok)
        if m:
            tok = m.group(1)
        if tok in ("st", "ste") and i < len(tokens) - 1:
            tok = "saint"  # "St. Catherine" but "Pike St"
        elif tok == "sainte":
            tok = "saint"
        if tok in _STREET_TYPES or tok in _STOPWORDS:
            continue
        out.append(tok)
    return tuple(out)


def streets_match(answer: str, truth: str, aliases: Iterable[str] = ()) -> bool:
    if not normalize(answer):
        return False
    candidates = [truth, *aliases]
    if squash(answer) in {squash(c) for c in candidates}:
        return True
    core = street_core(answer)
    cores = [c for c in map(street_core, candidates) if c]
    if core and core in cores:
        return True
    # A compass qualifier the answer adds to a street named without one is part of the same street's name
    # ("Constitution Ave NW" for Constitution Avenue); where the truth has one, it must agree.
    bare = tuple(t for t in core if t not in COMPASS_WORDS)
    return bool(bare) and any(bare == c for c in cores if not COMPASS_WORDS & set(c))
