"""Signs draw with the fonts shipped in the package, in every script the signs use, and no system font is read
(issue 29: the same observations on every machine)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import pytest
from fontTools.ttLib import TTFont
from PIL import Image, ImageDraw, ImageFont

from ewa_mcp.envs.geo.locations import LOCATIONS_LIST
from ewa_mcp.street_drawing import fonts
from ewa_mcp.street_drawing.text import fit_font


def _sign_lines() -> dict[str, list[str]]:
    by_script: dict[str, list[str]] = {}
    for loc in LOCATIONS_LIST:
        for line in loc.sign:
            by_script.setdefault(fonts.script_of(line), []).append(line)
    return by_script


@lru_cache(maxsize=None)
def _cmap(path: str) -> frozenset[int]:
    return frozenset(TTFont(path, fontNumber=0).getBestCmap())


@pytest.fixture
def opened(monkeypatch):
    """The paths Pillow is asked to open as fonts while the test runs (caches cleared before and after)."""
    paths: list[str] = []
    real = ImageFont.truetype

    def recording(font=None, *args, **kwargs):
        paths.append(str(font))
        return real(font, *args, **kwargs)

    monkeypatch.setattr(ImageFont, "truetype", recording)
    monkeypatch.delenv("EWA_GEO_FONT_DIRS", raising=False)
    fonts.font.cache_clear()
    fonts.font_file.cache_clear()
    yield paths
    fonts.font.cache_clear()
    fonts.font_file.cache_clear()


def test_the_signs_use_many_scripts_and_every_one_has_a_shipped_font():
    by_script = _sign_lines()
    assert {"latin", "cyrillic", "greek", "arabic", "hebrew", "devanagari", "thai", "japanese", "korean",
            "han_simplified", "han_traditional"} <= set(by_script)
    for script in by_script:
        found = fonts.font_file(script)
        assert found is not None, script
        assert fonts.FONT_DIR in Path(found[0]).parents, (script, found)
    licences = {p.name for p in fonts.FONT_DIR.glob("LICENSE-*.txt")}
    assert licences == {"LICENSE-DejaVu.txt", "LICENSE-Noto.txt", "LICENSE-NotoCJK.txt"}


def test_every_character_of_every_sign_has_a_glyph_in_the_font_its_script_uses():
    missing = []
    for script, lines in _sign_lines().items():
        path, _ = fonts.font_file(script)
        cmap = _cmap(path)
        for line in lines:
            missing += [f"{script}: {ch!r} in {line!r}" for ch in line if not ch.isspace() and ord(ch) not in cmap]
    # A new CJK sign needs its characters in the cut CJK faces: run scripts/make-fonts.py.
    assert not missing, missing[:10]


def test_a_sign_in_each_script_renders_with_the_shipped_font_and_no_system_font_is_opened(opened):
    for script, lines in sorted(_sign_lines().items()):
        text, drawn_script = fonts.drawable(lines[0], "Latin fallback")
        assert (text, drawn_script) == (lines[0], script)  # the native spelling, never the transliteration
        img = Image.new("L", (320, 60), 0)
        draw = ImageDraw.Draw(img)
        font, _ = fit_font(draw, text, script, 300, 40)
        assert isinstance(font, ImageFont.FreeTypeFont)
        assert fonts.FONT_DIR in Path(font.path).parents, (script, font.path)
        draw.text((4, 4), text, font=font, fill=255)
        assert img.getbbox() is not None, script  # ink on the sign
    assert opened, "no font was opened"
    outside = [p for p in opened if fonts.FONT_DIR not in Path(p).parents]
    assert not outside, outside
