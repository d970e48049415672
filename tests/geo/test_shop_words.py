"""Shop signs speak the country's own words where one language's countries differ (Mexico's "Abarrotes" is
an Argentine "Almacén"), and the wiki can never name those words."""

from __future__ import annotations

from collections import defaultdict

from ewa_mcp.envs.geo.graph import build_graph
from ewa_mcp.envs.geo.languages import COUNTRY_WORDS, LANGUAGES, SHOP_KINDS, shop_words
from ewa_mcp.envs.geo.locations import LOCATIONS
from ewa_mcp.envs.geo.scene import compose_view
from ewa_mcp.envs.geo.vocabulary import sign_words, words
from ewa_mcp.geometry import FOUR_DIRECTIONS


def _shop_lines_by_country() -> dict[str, list[tuple[str, str, str]]]:
    """{country: [(location id, shop kind, the sign's first line)]} over every standpoint and facing of the
    locations whose country has words of its own."""
    out: dict[str, list[tuple[str, str, str]]] = defaultdict(list)
    for loc in LOCATIONS.values():
        iso = loc.country.iso
        if iso not in COUNTRY_WORDS or (loc.city.langs or loc.country.langs)[0] not in COUNTRY_WORDS[iso]:
            continue
        for sp in build_graph(loc):
            for heading in FOUR_DIRECTIONS:
                for sign in compose_view(loc, sp, heading).shops:
                    out[iso].append((loc.id, sign.kind, sign.lines[0].native))
    return out


def test_a_countrys_shop_signs_use_its_own_words_and_no_other_countrys():
    seen = _shop_lines_by_country()
    assert set(seen) == set(COUNTRY_WORDS), "every listed country has views that show shop signs"
    for iso, lines in seen.items():
        own = COUNTRY_WORDS[iso]["es-la"]
        for loc_id, kind, text in lines:
            allowed = {native for native, _ in shop_words(iso, "es-la", kind)}
            assert text in allowed, (iso, loc_id, kind, text, allowed)
            if kind in own:
                assert text in own[kind], (iso, loc_id, kind, text)
    argentine = {text for _, kind, text in seen["AR"] if kind == "grocery"}
    assert argentine and "Abarrotes" not in argentine and argentine <= {"Almacén", "Kiosco", "Despensa"}
    assert "Abarrotes" in {text for _, kind, text in seen["MX"] if kind == "grocery"}


def test_unlisted_kinds_keep_the_languages_word():
    for iso, by_language in COUNTRY_WORDS.items():
        for code, kinds in by_language.items():
            assert code in LANGUAGES and set(kinds) <= set(SHOP_KINDS), (iso, code)
            for kind in SHOP_KINDS:
                if kind not in kinds:
                    assert shop_words(iso, code, kind) == (LANGUAGES[code].words[kind],)
    assert shop_words("ES", "es", "grocery") == (("Supermercado", "Supermercado"),)


def test_the_wiki_may_name_no_countrys_own_shop_word():
    banned = sign_words()
    for by_language in COUNTRY_WORDS.values():
        for kinds in by_language.values():
            for own in kinds.values():
                for word in own:
                    assert words(word) <= banned, word
