"""Scenes, rendering and descriptions: determinism, font fallback, where cues appear, and
that no observation names the place outside quoted sign text."""

from __future__ import annotations

import hashlib
import io
import os
import re
import subprocess
import sys

import pytest
from PIL import Image

from ewa_mcp.street_drawing import fonts
from ewa_mcp.envs.geo.describe import describe_view
from ewa_mcp.envs.geo.taskgen.geolocation import build_tasks
from ewa_mcp.geometry import FOUR_DIRECTIONS
from ewa_mcp.envs.geo.hardness import is_hard, task_difficulty
from ewa_mcp.envs.geo.languages import language
from ewa_mcp.envs.geo.styles import TREE_WORDS, vehicle_look
from ewa_mcp.envs.geo.graph import build_graph
from ewa_mcp.envs.geo.locations import LOCATIONS, LOCATIONS_LIST
from ewa_mcp.envs.geo.view_images import render_png, render_view
from ewa_mcp.envs.geo.scene import compose_view, deciding_city_cues
from ewa_mcp.envs.geo.seeding import rng_for

STANDPOINTS = ("p0", "p1", "p2", "p3", "p4")
QUOTED = re.compile(r"'[^']*'|\"[^\"]*\"")


def all_views(loc):
    for sp in STANDPOINTS:
        for heading in FOUR_DIRECTIONS:
            yield sp, heading, compose_view(loc, sp, heading)


def test_rendering_is_deterministic_and_views_differ():
    loc = LOCATIONS["g076"]  # Thai script, skytrain, left-hand traffic
    spec = compose_view(loc, "p1", "east")
    a = render_view(spec).tobytes()
    b = render_view(compose_view.__wrapped__(loc, "p1", "east")).tobytes()  # a fresh spec, no caches
    assert a == b
    png = render_png(spec)
    assert png == render_png.__wrapped__(spec)
    image = Image.open(io.BytesIO(png))
    assert image.size == (600, 400) and image.mode == "RGB"
    others = {render_view(compose_view(loc, sp, h)).tobytes() for sp, h in (("p0", "east"), ("p1", "north"),
                                                                               ("p3", "east"))}
    assert a not in others and len(others) == 3


def test_scenes_are_identical_in_another_process_with_another_hash_seed():
    # Seeds come from sha256, never hash(): a view must not depend on PYTHONHASHSEED.
    code = ("from ewa_mcp.envs.geo.scene import compose_view; from ewa_mcp.envs.geo.locations import LOCATIONS; "
            "from ewa_mcp.envs.geo.view_images import render_png; import hashlib; "
            "s = compose_view(LOCATIONS['g044'], 'p2', 'west'); "
            "print(s.seed, hashlib.sha256(render_png(s)).hexdigest())")
    here = compose_view(LOCATIONS["g044"], "p2", "west")
    expected = f"{here.seed} {hashlib.sha256(render_png(here)).hexdigest()}"
    for hash_seed in ("1", "4242"):
        env = {**os.environ, "PYTHONHASHSEED": hash_seed}
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
        assert out.stdout.strip() == expected
    assert rng_for("a", 1).random() == rng_for("a", 1).random() != rng_for("a", 2).random()


def test_missing_fonts_fall_back_to_latin_deterministically(monkeypatch):
    loc = LOCATIONS["g070"]  # Chinese signs with a pinyin line
    spec = compose_view(loc, "p3", "north")
    with_fonts = render_view(spec).tobytes()
    real = fonts.font_file.__wrapped__

    def latin_only(script):
        return real(script) if script == "latin" else None

    monkeypatch.setattr(fonts, "font_file", latin_only)
    fonts.font.cache_clear()
    try:
        assert fonts.drawable("王府井大街", "Wangfujing Dajie") == ("Wangfujing Dajie", "latin")
        first = render_view(spec).tobytes()
        assert first == render_view(spec).tobytes()
        if real("han_simplified") is not None:  # on a machine with the CJK font the fallback differs
            assert first != with_fonts
    finally:
        fonts.font.cache_clear()


def test_script_detection():
    assert fonts.script_of("Невский проспект") == "cyrillic"
    assert fonts.script_of("表参道") == "han_simplified" and fonts.script_of("パン屋") == "japanese"
    assert fonts.script_of("忠孝東路") == "han_traditional" and fonts.script_of("세종대로") == "korean"
    assert fonts.script_of("شارع") == "arabic" and fonts.script_of("Rue Neuve") == "latin"


@pytest.mark.parametrize("loc", LOCATIONS_LIST, ids=lambda loc: loc.id)
def test_descriptions_never_name_the_place_outside_quotes(loc):
    names = {loc.city.name, *loc.city.aliases, loc.country.name, *loc.country.aliases}
    words = [n for n in names if len(n) >= 4 and any(ch.isalpha() for ch in n)]
    pattern = re.compile(r"\b(" + "|".join(re.escape(w) for w in words) + r")\b", re.IGNORECASE)
    for sp, heading, spec in all_views(loc):
        text = QUOTED.sub("''", describe_view(spec))
        found = pattern.search(text)
        assert found is None, f"{loc.id} {sp} {heading} leaks {found.group(0)!r}: {text}"


def test_cue_placement_follows_difficulty():
    for loc in LOCATIONS_LIST:
        graph = build_graph(loc)
        sign_at = {(sp, h) for sp, h, spec in all_views(loc) if spec.street_sign is not None}
        steps = {graph[sp].steps_from_start for sp, _ in sign_at}
        if loc.difficulty == "easy":
            assert ("p0", "north") in sign_at, loc.id
        elif loc.difficulty == "city" and not is_hard(loc):
            assert steps == {1}, loc.id
            for heading in FOUR_DIRECTIONS:  # no city-level cue anywhere at the start
                spec = compose_view(loc, "p0", heading)
                assert not spec.city_cues
                area_coded = "{a}" in loc.country.phone
                assert not (area_coded and any(s.phone for s in spec.shops)), loc.id
                assert all(v.plate is None or v.plate.text is None or not v.plate.style.has_region
                           for v in spec.vehicles), loc.id
        else:
            assert steps == {2}, loc.id
            assert compose_view(loc, "p0", "north").city_cues


def test_country_cues_are_in_the_baseline_view():
    for loc in LOCATIONS_LIST[::7]:
        spec = compose_view(loc, "p0", "north")
        text = describe_view(spec)
        assert spec.shops and all(f"'{sign.lines[0].native}" in text for sign in spec.shops)
        if not spec.pedestrian:
            assert f"keeps to the {loc.country.drive}" in text or "traffic moves from your" in text


def test_landmark_views_describe_the_landmark():
    concorde = compose_view(LOCATIONS["g001"], "p0", "north")
    assert concorde.composition == "landmark" and "obelisk" in describe_view(concorde)
    signed = [spec for _sp, _h, spec in all_views(LOCATIONS["g003"]) if spec.street_sign is not None]
    assert signed and all("RUE DE LA RÉPUBLIQUE" in describe_view(spec) for spec in signed)


def _deciding_city_cues(loc, spec, text) -> list[str]:
    """The city-deciding cues a view shows (and its text quotes): an area-coded telephone number,
    a legible regional number plate."""
    # The scene's own list (what the baseline grades the city by), kept only where the text quotes it.
    def quoted(cue: str) -> str:
        kind, _, value = cue.partition(" ")  # "phone 0131 …" is quoted in the text, "plate …" is not
        return f"'{value}'" if kind == "phone" else value

    return [cue for cue in deciding_city_cues(loc, spec) if quoted(cue) in text]


def _transport_shown(spec, text) -> list[str]:
    return [v.kind for v in spec.vehicles if v.kind != "car"
            and vehicle_look(v.kind, v.colour_words) in text]


def test_every_baseline_view_carries_what_its_difficulty_promises():
    """ewa_mcp/envs/geo/README.md, "Difficulty": the one view a baseline task has (p0 north) carries
    the country cues always; the city cues for easy and street-level tasks (where the city has
    one the street can show); a landmark and the street sign for easy tasks; only shared city
    cues (buildings, trees, local transport) and never a deciding one for hard tasks."""
    tasks = build_tasks("baseline")
    assert len(tasks) == len(LOCATIONS_LIST)
    for task in tasks:
        loc = LOCATIONS[task.start.embodied.location_id]
        spec = compose_view(loc, "p0", "north")
        text = describe_view(spec)
        where = f"{task.id} ({task.difficulty}, {task.metadata['cue_level']})"
        # Country cues: a shop sign in a local language; on roads, the driving side.
        words = {language(c).words[k][0] for c in (loc.city.langs or loc.country.langs)
                 for k in language(c).words}
        assert any(s.lines[0].native in words and f"'{s.lines[0].native}" in text for s in spec.shops), where
        if not loc.pedestrian:
            assert f"keeps to the {loc.country.drive}" in text or "traffic moves from your" in text, where
        deciding = _deciding_city_cues(loc, spec, text)
        showable = "{a}" in loc.country.phone or (
            not loc.pedestrian and (loc.city.transport or (loc.city.plate_region and spec.composition == "along")))
        if task_difficulty(loc) == "hard":
            assert not deciding, f"{where} shows a deciding city cue: {deciding}"
            assert spec.street_sign is None, where
            assert f"Buildings: {spec.arch.description}" in text, where
            if spec.trees:
                assert TREE_WORDS[spec.trees[0][0]] in text, where
            if loc.city.transport and not loc.pedestrian:
                assert _transport_shown(spec, text), f"{where}: no local transport"
            continue
        if task.difficulty == "easy":
            assert spec.landmark is not None and spec.street_sign is not None, where
            assert spec.street_sign.lines[-1].native in text, where
        if task.metadata["cue_level"] in ("easy", "street") and showable:
            assert deciding or _transport_shown(spec, text), f"{where}: no city cue in the baseline view"
        if task.metadata["cue_level"] == "city":
            assert not deciding and spec.street_sign is None, where
        if task.metadata["cue_level"] == "street":
            assert spec.street_sign is None, where


def test_hard_split_is_at_least_15_percent_and_no_single_cue_decides():
    from collections import Counter

    from ewa_mcp.envs.geo.cue_sets import candidates, combination_gaps, country_rivals, street_cues

    # Hard is the embodied setting's: one baseline view and no wiki leave nothing to put together.
    assert {t.difficulty for t in build_tasks("baseline")} == {"easy", "medium"}
    tasks = build_tasks("embodied")
    counts = Counter(t.difficulty for t in tasks)
    assert set(counts) == {"easy", "medium", "hard"} and counts["hard"] >= 0.15 * len(tasks), counts
    pool = candidates(loc.city for loc in LOCATIONS_LIST)
    for loc in LOCATIONS_LIST:
        if not is_hard(loc):
            continue
        # Each cue, and each pair, is some rival's of the same country too; all together decide
        # (tests/geo/test_hard_cues.py checks the same against what the views show).
        rivals = country_rivals(loc.city_key, pool)
        assert rivals and combination_gaps(street_cues(loc.city, loc.pedestrian), rivals) == [], loc.id
        for sp in build_graph(loc):  # and no view anywhere shows a deciding cue
            for heading in FOUR_DIRECTIONS:
                spec = compose_view(loc, sp, heading)
                assert not _deciding_city_cues(loc, spec, describe_view(spec)), (loc.id, sp, heading)
                assert spec.street_sign is None or spec.street_sign.style == loc.country.sign


# What a building style's words name must be drawn (issue 16: images showed generic buildings
# where the text said "grey sandstone, soot-darkened, chimney stacks").
DRAWN_FEATURES = {
    r"\bchimney": lambda a: a.chimneys,
    r"\bsoot": lambda a: a.soot,
    r"\bdormers?\b": lambda a: a.dormers and a.roof == "mansard",
    r"\bshutters\b": lambda a: a.shutters is not None,
    r"\bsash windows|\bstucco window frames": lambda a: a.window_frame is not None,
    r"\bfire escapes": lambda a: a.fire_escapes,
    r"\bwater tanks": lambda a: a.water_tanks,
    r"\bcorrugated-iron roofs": lambda a: a.corrugated,
    r"\bbrick\b": lambda a: a.material == "brick" or bool(a.brick_colours),
    r"\b(sandstone|limestone|stone buildings|stone blocks|beige stone)\b": lambda a: a.material == "stone",
    r"\bwooden townhouses|\btimber\b": lambda a: a.material == "wood",
    r"\bconcrete\b": lambda a: a.material in ("concrete", "glass", "stone", "wood"),
    r"\bglazed blue-and-white tiles": lambda a: bool(a.tiled_colours),
    r"^glass and steel": lambda a: a.material == "glass",
}


def test_every_feature_a_building_description_names_is_drawn():
    from ewa_mcp.envs.geo.styles import ARCH

    for key, arch in ARCH.items():
        for pattern, drawn in DRAWN_FEATURES.items():
            if re.search(pattern, arch.description):
                assert drawn(arch), f"{key}: the text says {pattern!r} but the style does not draw it"


@pytest.mark.parametrize("feature", ["chimneys", "soot", "material", "water_tanks", "fire_escapes", "shutters"])
@pytest.mark.parametrize("composition", ["facade", "along"])
def test_drawn_features_change_the_picture(feature, composition):
    import dataclasses

    from ewa_mcp.envs.geo.styles import ARCH

    owner = {"chimneys": "stone_terrace", "soot": "stone_terrace", "material": "british",
             "water_tanks": "middle_eastern", "fire_escapes": "na_downtown", "shutters": "mediterranean"}[feature]
    if composition == "along" and feature in ("fire_escapes", "shutters"):
        pytest.skip("drawn on front-on facades only")
    spec = next(s for loc in LOCATIONS_LIST for _sp, _h, s in all_views(loc)
                if s.arch_key == owner and s.composition == composition)
    off = {"material": "plaster", "shutters": None}.get(feature, False)
    plain = dataclasses.replace(spec, arch=dataclasses.replace(ARCH[owner], **{feature: off}))
    with_it, without = render_view(spec), render_view(plain)
    assert with_it.tobytes() != without.tobytes(), f"{owner} {composition}: {feature} draws nothing"
