"""Writes the wiki articles of the geolocation domain: one per country and one per city.

The articles state the same street-level facts the scenes use (sign language and script,
shop words, driving side, road markings, plates, telephone area codes, building style,
trees, local transport, notable streets with their sign text), so an agent can match what
it sees against them. Facts such as capitals, calling codes and populations come from the
gazetteer. Cities or countries that already have an article in another group of the wiki
(e.g. the navigation cities) are not written again; aliases that another article already
uses are left out of the front matter (graders still accept them).

``write_articles(out_dir)`` returns the number of files written; run it with
``python -m ewa_mcp.envs.geo.articles``.
"""

from __future__ import annotations

from typing import Any

import json
import random
import re
import unicodedata
from collections import defaultdict
from collections.abc import Set as AbstractSet
from pathlib import Path

from . import gazetteer
from .cities import CITIES, City
from .climates import CLIMATE_ARTICLES
from .countries import COUNTRIES, Country
from .languages import language
from .locations import LOCATIONS_LIST, Location
from .rival_cities import RIVAL_CITIES_LIST
from .plates import colour_name
from .styles import ARCH, CLIMATE, TREE_NAMES, vehicle_name
from .vocabulary import banned_in_articles

GROUP = "geo"
CAPITAL_OVERRIDES = {"KZ": "Astana"}  # the gazetteer still has the 2019-2022 name
CLIMATE_WORDS = {
    "oceanic": "oceanic: mild, cloudy and rainy all year",
    "continental": "continental: warm summers and cold winters",
    "nordic": "cool: short summers, long dark winters",
    "mediterranean": "Mediterranean: hot dry summers and mild wet winters",
    "humid_subtropical": "humid subtropical: hot humid summers, mild winters",
    "tropical": "tropical: hot and humid all year, with a rainy season",
    "arid": "desert: hot, dry and dusty",
    "semi_arid": "semi-arid: sunny and dry, with a short rainy season",
    "highland": "highland: mild days and cool nights at altitude",
}


def slugify(title: str) -> str:
    ascii_text = unicodedata.normalize("NFKD", title).encode("ascii", "ignore").decode("ascii")
    return "-".join(re.findall(r"[a-z0-9]+", ascii_text.lower()))


def _key(text: str) -> str:
    from ewa_mcp.websites.wiki.store import normalize_title

    return normalize_title(text)


def _existing_names(articles_root: Path) -> tuple[set[str], set[str]]:
    """(title keys, alias keys) of the articles outside the geo group."""
    from ewa_mcp.websites.wiki.store import read_articles

    titles: set[str] = set()
    aliases: set[str] = set()
    articles, _problems = read_articles(articles_root)
    for article in articles:
        if article.group == GROUP:
            continue
        titles.add(_key(article.title))
        aliases.update(_key(a) for a in article.aliases)
    return titles, aliases


def country_title(country: Country) -> str:
    return "Georgia (country)" if country.iso == "GE" else country.name


def _front_matter(title: str, category: str, aliases: list[str], infobox: dict[str, str],
                  coordinates: dict[str, float] | None = None) -> str:
    lines = ["---", f"title: {title}", f"category: {category}"]
    if aliases:
        lines.append(f"aliases: {json.dumps(aliases, ensure_ascii=False)}")
    lines.append(f"infobox: {json.dumps(infobox, ensure_ascii=False)}")
    if coordinates:
        lines.append(f"coordinates: {json.dumps(coordinates)}")
    lines.append("---")
    return "\n".join(lines)


def _plate_line(country: Country, example_region: str | None) -> str:
    style = country.plate
    parts = [f"Registration: {colour_name(style.fg)} lettering on {colour_name(style.bg)}"]
    if style.rear_bg:
        parts[0] += f" ({colour_name(style.rear_bg)} at the back)"
    if style.band:
        parts.append(f"the country-identifier field at the start gives the code {style.band}")
    if style.caption:
        parts.append("the country's name is printed over the registration")
    # The example never carries a real region code or caption: the code of one of the location
    # cities would tie a string seen on a plate to that city.
    shape = None
    if example_region and example_region.isascii() and not style.region_caption:
        shape = "".join("@" if c.isalpha() else "#" if c.isdigit() else c for c in example_region)
    example = style.text(random.Random(f"wiki-plate-{country.iso}"), shape)
    if style.region_caption:
        parts.append("the registering region's name is printed over the registration")
    elif style.has_region:
        parts.append("the leading code identifies the registering region")
    return "- " + "; ".join(parts) + f"; format example {example}."


def local_area_code(city: City) -> str | None:
    """The area code as local numbers show it: with the trunk prefix the country's format
    puts before it ("0" + "31" in Chattogram -> "031")."""
    if not city.area_code:
        return None
    template = COUNTRIES[city.iso].phone
    before = template.split("{a}")[0] if "{a}" in template else ""
    prefix = before[-1] if before[-1:].isdigit() else ""
    return prefix + city.area_code


def _fmt_int(value: int | float | str) -> str:
    try:
        return f"{int(value):,}"
    except (TypeError, ValueError):
        return str(value)


def country_article(country: Country, cities: list[City], names: dict[str, str], aliases: list[str],
                    extra: list[str], banned: AbstractSet[str] = frozenset(), city_state: bool = False) -> str:
    record = gazetteer.countries()[country.iso]
    continent = gazetteer.country_continent(country.iso)
    capital = CAPITAL_OVERRIDES.get(country.iso, record["capital"])
    phone = record["phone"] if str(record["phone"]).startswith("+") else f"+{record['phone']}"
    infobox = {
        "Capital": capital,
        "Continent": continent,
        "Official languages": country.official_languages or ", ".join(language(c).name for c in country.langs),
        "Scripts": country.scripts,
        "Drives on the": country.drive,
        "Calling code": phone,
        "Currency": f"{record['currencyname']} ({record['currencycode']})",
        "Population": _fmt_int(record["population"]),
        "Area": f"{_fmt_int(record['areakm2'])} km²",
        "Internet domain": record["tld"],
        "ISO code": f"{country.iso} / {record['iso3']}",
    }
    title = country_title(country)
    arch = ARCH[country.arch]
    example_region = next((c.plate_region for c in cities if c.plate_region), None)
    capital_ref = f"[[{capital}]]" if _key(capital) in names else capital
    body = [f"**{title}** is a country in {continent}. Its capital is {capital_ref}."]
    body.append("## What a visitor notices")
    # The languages are named, never listed as the words a shop sign shows: recognising a language
    # from a sign is the reader's work (issue 26, principle 4).
    language_names = [f"{language(c).name} ({language(c).script} script)" for c in country.langs]
    body.append("- Shop and street signs are written in " + " and ".join(language_names) + ".")
    body.append(f"- Vehicles drive on the **{country.drive}**-hand side.")
    body.append(f"- Lane markings: {country.centre_line} dividing line"
                + (f", {country.edge_line} edge lines." if country.edge_line != "white" else "."))
    body.append(_plate_line(country, example_region))
    body.append(f"- Typical city streets: {architecture_words(arch)}.")
    facts = [without_view_words(fact, banned | banned_in_articles()) for fact in country.facts]
    body += [f"- {fact}" for fact in facts if fact]
    others = [c for c in cities if _key(c.name) != _key(title)]
    if others:
        body.append("## Cities")
        for city in sorted(others, key=lambda c: c.name):
            body.append(f"- [[{city.name}]]")
    body += extra
    return _front_matter(title, "Countries", aliases, infobox) + "\n" + "\n\n".join(_paragraphs(body)) + "\n"


def climate_article(key: str, cities: list[City], aliases: list[str]) -> str:
    """A climate's article: how its weather looks overhead (``climates.py``) and the cities that have it."""
    art = CLIMATE_ARTICLES[key]
    body = [f"A **{art.title[0].lower() + art.title[1:]}** is one of the climates the wiki's city articles name.",
            "## What the weather looks like", art.overhead, "## Seasons", art.seasons]
    if cities:
        body.append("## Cities with this climate")
        body += [f"- [[{city.name}]]" for city in sorted(cities, key=lambda c: c.name)]
    return _front_matter(art.title, "Climates", aliases, {"Seasons": art.seasons}) + "\n" \
        + "\n\n".join(_paragraphs(body)) + "\n"


def _paragraphs(lines: list[str]) -> list[str]:
    """Join consecutive list items into one block; other lines are paragraphs of their own."""
    blocks: list[str] = []
    for line in lines:
        if line.startswith("- ") and blocks and blocks[-1].startswith("- "):
            blocks[-1] += "\n" + line
        else:
            blocks.append(line)
    return blocks


# Words that sit on many signs and say nothing about one place; everything else a view of a
# city can quote (street names, sign lines, the area code, the plate code) is kept out of the
# articles, so that searching a string seen in a view never lands on the answer.
GENERIC_WORDS = frozenset(
    "a an and the of de del della dei di da do dos das du des la le les el il lo los las van von der den het "
    "st street road avenue ave rd square place plaza platz piazza rue via calle carrer rua strasse straße "
    "ulitsa ulica lane way boulevard blvd".split())


def _fold(text: str) -> str:
    decomposed = unicodedata.normalize("NFKD", text)
    return "".join(c for c in decomposed if not unicodedata.combining(c)).casefold()


def words_of(text: str) -> set[str]:
    """The search words of a text (as the wiki's search tokenises it, accents and case folded)."""
    return set(re.findall(r"\w+", _fold(text)))


def view_words(city: City, locations: list[Location]) -> set[str]:
    """Distinctive words that the views of a city's locations quote: street names and sign lines,
    the telephone area code and the plate region code."""
    words: set[str] = set()
    for loc in locations:
        for text in (loc.street, *loc.sign, *loc.street_aliases):
            words |= words_of(text)
    if city.area_code:
        words |= words_of(city.area_code) | words_of(local_area_code(city) or "")
    if city.plate_region:
        words |= words_of(city.plate_region.replace("#", " ").replace("@", " "))
    return words - GENERIC_WORDS


def without_view_words(text: str, banned: AbstractSet[str]) -> str:
    """The sentences of ``text`` that quote none of the banned words."""
    sentences = re.split(r"(?<=[.!?])\s+", text.strip())
    return " ".join(s for s in sentences if s and not (words_of(s) & banned))


def area_code_words(city: City) -> str | None:
    """The area code as an encyclopedia gives it: its length and the numbering block it belongs
    to (all digits but the last), never the code itself."""
    local = local_area_code(city)
    if not local:
        return None
    digits = re.sub(r"\D", "", local)
    n = len(digits)
    words = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five"}.get(n, str(n))
    if n >= 3:
        return f"a {words}-digit area code of the {digits[:-1]}x block"
    if digits[0] == "0":
        return f"a {words}-digit area code (the trunk prefix 0 and one digit)"
    return f"a {words}-digit area code" + (f" beginning with {digits[0]}" if n == 2 else "")


def population_words(population: int | float | str) -> str:
    """Rounded, as an encyclopedia's lead gives it (and no long digit groups that a phone number could share)."""
    try:
        value = float(population)
    except (TypeError, ValueError):
        return str(population)
    return f"about {value / 1e6:.2g} million" if value >= 1e5 else f"about {value / 1e3:.2g} thousand"


def _char_kinds(code: str) -> str:
    kinds = []
    for ch in code:
        kind = ("letter" if ch.isascii() and ch.isalpha() else "digit" if ch.isdigit() or ch == "#"
                else "letter" if ch == "@" else None if ch in " -" else "local-script character")
        if kind and kind not in kinds:
            kinds.append(kind)
    return " and ".join(f"{k}s" for k in kinds)


def plate_words(city: City) -> str | None:
    """How the city's plates differ from the country's, described, not quoted."""
    region = city.plate_region
    style = COUNTRIES[city.iso].plate
    if not region or not style.has_region:
        return None
    if style.region_caption:
        return "Vehicles registered here carry the region's name printed over the registration"
    if not region.isascii():
        return "Vehicles registered here carry the region's name, in the local script, beside the registration"
    length = len(region.replace(" ", "").replace("-", ""))
    size = {1: "one", 2: "two", 3: "three", 4: "four"}.get(length, str(length))
    return (f"Vehicles registered here carry a {size}-character region code ({_char_kinds(region)}) in "
            f"place of the country's generic registration prefix")


# The encyclopedia's names for what the views describe by sight (a test checks that none of these
# words is one a view uses): "Mansart roofs" where a view sees steep grey roofs with windows in them.
ROOF_WORDS = {"mansard": "Mansart roofing", "pitched": "sloping roofing", "flat": "walkable roofing",
              "gabled": "street-facing peaked roofing", "curved_tile": "upturned eaves"}
MATERIAL_WORDS = {"plaster": "rendered masonry", "brick": "fired-clay masonry", "stone": "ashlar masonry",
                  "wood": "weatherboarded framing", "concrete": "reinforced-concrete framing",
                  "glass": "curtain-walled framing"}


def architecture_words(arch: Any) -> str:
    """The city's buildings as an encyclopedia summarises them: construction, height, roofing and common
    features, by name, in words of its own; the views describe the same things by sight, in other words."""
    low, high = arch.floors
    height = f"{low} stories" if low == high else f"{low} to {high} stories"
    features = [word for flag, word in (
        (arch.balconies, "loggias"), (arch.dormers, "lucarnes"), (arch.chimneys, "coal-era flues"),
        (arch.fire_escapes, "external emergency stairways"), (arch.arcade, "porticoes"),
        (arch.veranda, "covered sidewalks"), (arch.shutters, "louvred persiennes"),
        (arch.water_tanks, "cisterns"), (arch.ac_units, "wall-mounted coolers"),
        (arch.wires, "aerial wiring"), (arch.awnings, "shop sunshades"),
        (arch.soot, "coal-smoke blackening"), (arch.corrugated, "galvanised-iron sheet roofing"),
        (arch.vertical_signs, "perpendicular signage"), (bool(arch.tiled_colours), "azulejo tilework")) if flag]
    text = f"the typical street building is of {MATERIAL_WORDS.get(arch.material, arch.material)}, {height}, " \
           f"with {ROOF_WORDS.get(arch.roof, arch.roof)}"
    if features:
        listed = features[0] if len(features) == 1 else ", ".join(features[:-1]) + " and " + features[-1]
        text += f"; {listed} are common"
    return text


def _city_sections(city: City, locations: list[Location]) -> list[str]:
    country = COUNTRIES[city.iso]
    arch = ARCH[city.arch or country.arch]
    climate = CLIMATE[city.climate]
    body = ["## What the city looks like"]
    if city.langs:
        names = [f"{language(c).name} ({language(c).script} script)" for c in city.langs]
        body.append("- Shop and street signs are written in " + " and ".join(names) + ".")
    body.append(f"- Architecture: {architecture_words(arch)}.")
    trees = city.trees or climate.trees
    body.append("- Street trees: " + ", ".join(TREE_NAMES[t] for t in trees) + ".")
    name, _, seasons = CLIMATE_WORDS[city.climate].partition(":")
    body.append(f"- Climate: [[{CLIMATE_ARTICLES[city.climate].title}|{name}]]:{seasons}.")
    for feature in city.transport:
        kind, _, colour = feature.partition(":")
        body.append("- Often seen: " + vehicle_name(kind, colour) + ".")
    phone = area_code_words(city)
    if phone:
        body.append(f"- Local telephone numbers carry {phone}.")
    plate = plate_words(city)
    if plate:
        body.append(f"- {plate}.")
    banned = view_words(city, locations)
    places = [(place, without_view_words(looks, set(banned_in_articles())))
              for place, looks in city.places.items() if not (words_of(place) | words_of(looks)) & banned]
    if places:
        body.append("## Landmarks")
        for place, looks in places:
            body.append(f"- **{place}**" + (f": {looks}" if looks else "") + ".")
    return body


def city_article(city: City, locations: list[Location], aliases: list[str]) -> str:
    record = gazetteer.city(city.geonameid)
    country = COUNTRIES[city.iso]
    ctitle = country_title(country)
    infobox = {
        "Country": ctitle,
        "Continent": locations[0].continent if locations and locations[0].continent
        else gazetteer.country_continent(city.iso),
        "Population": population_words(record["population"]),
        "Time zone": record["timezone"],
        "Climate": CLIMATE_WORDS[city.climate].split(":")[0].capitalize(),
    }
    about = without_view_words(city.about, view_words(city, locations) | banned_in_articles())
    body = [f"**{city.name}** is a city in [[{ctitle}]]." + (f" {about}" if about else ""),
            *_city_sections(city, locations)]
    coordinates = {"lat": round(record["latitude"], 4), "lng": round(record["longitude"], 4)}
    return (_front_matter(city.name, "Cities", aliases, infobox, coordinates) + "\n"
            + "\n\n".join(_paragraphs(body)) + "\n")


def write_articles(out_dir: Path, articles_root: Path | None = None) -> int:
    """Write the geo articles into ``out_dir`` (normally websites/wiki/articles/geo)."""
    root = articles_root or out_dir.parent
    taken_titles, taken_aliases = _existing_names(root)
    by_city: dict[str, list[Location]] = defaultdict(list)
    for loc in LOCATIONS_LIST:
        by_city[loc.city_key].append(loc)
    cities_by_country: dict[str, list[City]] = defaultdict(list)
    for key in by_city:
        cities_by_country[CITIES[key].iso].append(CITIES[key])
    # Rival cities (rival_cities.py) have an article and no location: the hard cities' look-alikes.
    rivals = [city for city in RIVAL_CITIES_LIST if city.iso in cities_by_country]
    for city in rivals:
        cities_by_country[city.iso].append(city)

    # Titles this writer will create, to decide links and drop clashing aliases.
    planned: dict[str, str] = {}
    for iso in cities_by_country:
        planned[_key(country_title(COUNTRIES[iso]))] = country_title(COUNTRIES[iso])
    for title in [CITIES[key].name for key in by_city] + [city.name for city in rivals]:
        if _key(title) not in planned:
            planned[_key(title)] = title
    for art in CLIMATE_ARTICLES.values():
        planned[_key(art.title)] = art.title
    names = dict(planned)
    names.update({t: t for t in taken_titles})
    blocked = set(names) | taken_aliases

    used_aliases: set[str] = set()

    def free_aliases(candidates: tuple[str, ...], title: str) -> list[str]:
        # An alias another article already uses as title or alias would make lookups ambiguous.
        out = []
        for alias in candidates:
            key = _key(alias)
            if key and key != _key(title) and key not in blocked and key not in used_aliases:
                out.append(alias)
                used_aliases.add(key)
        return out

    out_dir.mkdir(parents=True, exist_ok=True)
    written = 0
    files: dict[str, str] = {}
    for iso in sorted(cities_by_country):
        country = COUNTRIES[iso]
        title = country_title(country)
        if _key(title) in taken_titles:
            continue
        # A city-state (Singapore, Hong Kong) shares its country's article.
        extra: list[str] = []
        same = [c for c in cities_by_country[iso] if _key(c.name) == _key(title)]
        banned: set[str] = set()
        for city in cities_by_country[iso]:
            banned |= view_words(city, by_city.get(city.key, []))
        for city in same:
            about = without_view_words(city.about, banned | banned_in_articles())
            extra += [*(["## The city", about] if about else []), *_city_sections(city, by_city[city.key])]
        cand = tuple(country.aliases) + tuple(a for c in same for a in c.aliases)
        if iso == "GE":
            cand = ("Georgia",) + cand
        files[slugify(title)] = country_article(country, cities_by_country[iso], names, free_aliases(cand, title),
                                                extra, banned, city_state=bool(same))
    for key in sorted(by_city):
        city = CITIES[key]
        if _key(city.name) in taken_titles or _key(city.name) == _key(country_title(COUNTRIES[city.iso])):
            continue  # an existing article (or the country of the same name) covers it
        files[slugify(city.name)] = city_article(city, by_city[key], free_aliases(city.aliases, city.name))
    for city in rivals:
        if _key(city.name) in taken_titles:
            raise ValueError(f"rival city {city.name} already has an article outside the geo group, which would "
                             f"not state its conventions: pick another city in rival_cities.py")
        files[slugify(city.name)] = city_article(city, [], free_aliases(city.aliases, city.name))
    by_climate: dict[str, list[City]] = defaultdict(list)
    for city in [CITIES[key] for key in by_city] + rivals:
        by_climate[city.climate].append(city)
    for key, art in CLIMATE_ARTICLES.items():
        if _key(art.title) in taken_titles:
            raise ValueError(f"the climate article {art.title} already exists outside the geo group; rename it "
                             "in climates.py")
        files[slugify(art.title)] = climate_article(key, by_climate.get(key, []), free_aliases(art.aliases, art.title))
    for path in out_dir.glob("*.md"):
        if path.stem not in files:
            path.unlink()  # a location set that shrank leaves no stale articles behind
    for slug, text in sorted(files.items()):
        (out_dir / f"{slug}.md").write_text(text, encoding="utf-8")
        written += 1
    return written


TAKEN_HEADING = "## What the city looks like"


def taken_city_sections(articles_root: Path) -> dict[Path, str]:
    """The conventions block each article outside the geo group must end with when it already holds a
    location city's title (New York City, from the street world's wiki): write_articles skips such a
    city, and without the block its article would not state what the city's views show, so a hard
    location there could not be told from its rivals. Path -> the block, from TAKEN_HEADING on."""
    from ewa_mcp.websites.wiki.store import read_articles

    articles, _problems = read_articles(articles_root)
    by_key = {_key(a.title): a for a in articles if a.group != GROUP}
    by_city: dict[str, list[Location]] = defaultdict(list)
    for loc in LOCATIONS_LIST:
        by_city[loc.city_key].append(loc)
    blocks: dict[Path, str] = {}
    for key in sorted(by_city):
        article = by_key.get(_key(CITIES[key].name))
        if article is not None and article.path is not None:
            blocks[Path(article.path)] = "\n\n".join(_paragraphs(_city_sections(CITIES[key], by_city[key]))) + "\n"
    return blocks


def write_taken_sections(articles_root: Path) -> int:
    """Replace (or add) the conventions block at the end of each article taken_city_sections names."""
    blocks = taken_city_sections(articles_root)
    for path, block in blocks.items():
        text = path.read_text(encoding="utf-8")
        head = text.split("\n" + TAKEN_HEADING, 1)[0].rstrip("\n")
        path.write_text(head + "\n\n" + block, encoding="utf-8")
    return len(blocks)


if __name__ == "__main__":
    from ewa_mcp.websites.wiki.store import ARTICLES_DIR

    print(f"wrote {write_articles(ARTICLES_DIR / GROUP)} geolocation articles")
    print(f"wrote the conventions of {write_taken_sections(ARTICLES_DIR)} cities into articles outside the geo group")
