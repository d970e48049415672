"""Fonts for sign text in any script (and the script of a text), with a deterministic Latin fallback.

The fonts ship with the package (``fonts/``: DejaVu Sans Bold under the Bitstream Vera licence, the Noto Sans
Bold faces under the SIL Open Font License, their licence texts beside them; scripts/make-fonts.py refreshes them),
and nothing is read from system paths or fontconfig: the same input renders the same pixels on every machine.
The Noto Sans CJK faces are cut to the characters the package's signs use. When no shipped font covers a script
the renderer draws the Latin transliteration instead. ``EWA_GEO_FONT_DIRS`` (os.pathsep-separated) names
directories searched first by file name: an explicit choice, which changes the pixels.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from PIL import ImageFont

FONT_DIR = Path(__file__).resolve().parent / "fonts"
_DEJAVU = str(FONT_DIR / "DejaVuSans-Bold.ttf")


def _noto(name: str) -> str:
    return str(FONT_DIR / f"NotoSans{name}-Bold.ttf")


# script -> candidate (file, index) pairs, best first. The CJK faces match the region's glyph shapes (JP, KR, SC,
# TC); each is a file of its own (the index is for a collection file named by EWA_GEO_FONT_DIRS).
_CANDIDATES: dict[str, tuple[tuple[str, int], ...]] = {
    "latin": ((_DEJAVU, 0),),
    "greek": ((_DEJAVU, 0),),
    "cyrillic": ((_DEJAVU, 0),),
    "armenian": ((_noto("Armenian"), 0), (_DEJAVU, 0)),
    "georgian": ((_noto("Georgian"), 0), (_DEJAVU, 0)),
    "hebrew": ((_noto("Hebrew"), 0), (_DEJAVU, 0)),
    "arabic": ((_noto("Arabic"), 0), (_DEJAVU, 0)),
    # Lines mixing Arabic or Hebrew with Latin letters (plates such as "مصر EGYPT") need one font
    # covering both; DejaVu Sans does.
    "arabic_latin": ((_DEJAVU, 0),),
    "hebrew_latin": ((_DEJAVU, 0),),
    "devanagari": ((_noto("Devanagari"), 0),),
    "bengali": ((_noto("Bengali"), 0),),
    "tamil": ((_noto("Tamil"), 0),),
    "kannada": ((_noto("Kannada"), 0),),
    "sinhala": ((_noto("Sinhala"), 0),),
    "thai": ((_noto("Thai"), 0),),
    "khmer": ((_noto("Khmer"), 0),),
    "ethiopic": ((_noto("Ethiopic"), 0),),
    "japanese": ((str(FONT_DIR / "NotoSansCJKjp-Bold-subset.otf"), 0),),
    "korean": ((str(FONT_DIR / "NotoSansCJKkr-Bold-subset.otf"), 0),),
    "han_simplified": ((str(FONT_DIR / "NotoSansCJKsc-Bold-subset.otf"), 0),),
    "han_traditional": ((str(FONT_DIR / "NotoSansCJKtc-Bold-subset.otf"), 0),),
}

# Unicode block ranges -> script (first match wins; Latin is the default).
_RANGES: tuple[tuple[int, int, str], ...] = (
    (0x0370, 0x03FF, "greek"), (0x0400, 0x052F, "cyrillic"), (0x0530, 0x058F, "armenian"),
    (0x0590, 0x05FF, "hebrew"), (0x0600, 0x06FF, "arabic"), (0x0750, 0x077F, "arabic"),
    (0xFB50, 0xFDFF, "arabic"), (0xFE70, 0xFEFF, "arabic"), (0x0900, 0x097F, "devanagari"),
    (0x0980, 0x09FF, "bengali"), (0x0B80, 0x0BFF, "tamil"), (0x0C80, 0x0CFF, "kannada"),
    (0x0D80, 0x0DFF, "sinhala"), (0x0E00, 0x0E7F, "thai"), (0x1780, 0x17FF, "khmer"),
    (0x10A0, 0x10FF, "georgian"), (0x1200, 0x139F, "ethiopic"), (0x3040, 0x30FF, "japanese"),
    (0xAC00, 0xD7AF, "korean"), (0x1100, 0x11FF, "korean"), (0x4E00, 0x9FFF, "han"), (0x3400, 0x4DBF, "han"),
)

# Characters that exist only in traditional Han decide the traditional face; any other Han text is simplified.
_TRADITIONAL_ONLY = set("藥麵廳書飯銀彌臺灣東區點樓館們號")


def script_of(text: str) -> str:
    scripts = []
    for ch in text:
        cp = ord(ch)
        for lo, hi, name in _RANGES:
            if lo <= cp <= hi:
                scripts.append(name)
                break
    if not scripts:
        return "latin"
    if "japanese" in scripts:
        return "japanese"  # kana present: Japanese, even when kanji appear too
    if "korean" in scripts:
        return "korean"
    first = scripts[0]
    if first in ("arabic", "hebrew") and any("a" <= ch.lower() <= "z" for ch in text):
        return f"{first}_latin"
    if first == "han":
        if any(ch in _TRADITIONAL_ONLY for ch in text):
            return "han_traditional"
        return "han_simplified"
    return first


def _extra_dirs() -> list[Path]:
    from ..settings import load_settings  # the geo_font_dirs setting (EWA_GEO_FONT_DIRS)

    return list(load_settings().geo_font_dirs)


@lru_cache(maxsize=64)
def font_file(script: str) -> tuple[str, int] | None:
    """The font (path, index) used for a script, or None when none is shipped (or named by EWA_GEO_FONT_DIRS)."""
    for path, index in _CANDIDATES.get(script, ()):
        for directory in _extra_dirs():
            candidate = directory / Path(path).name
            if candidate.exists():
                return str(candidate), index
        if Path(path).exists():
            return path, index
    return None


@lru_cache(maxsize=512)
def font(script: str, size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    found = font_file(script) or font_file("latin")
    if found is None:
        return ImageFont.load_default(size)
    path, index = found
    return ImageFont.truetype(path, size=size, index=index)


def has_font(script: str) -> bool:
    return font_file(script) is not None


def drawable(native: str, latin: str) -> tuple[str, str]:
    """(text, script) to draw: the native spelling when a font covers it, else the Latin one."""
    script = script_of(native)
    if has_font(script):
        return native, script
    return latin, "latin"


def installed_scripts() -> dict[str, bool]:
    """Which scripts render natively (reported by the benchmark and docs): all of them, from the shipped fonts."""
    return {script: has_font(script) for script in _CANDIDATES}
