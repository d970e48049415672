"""Fonts for sign text in any script (and the script of a text), with a deterministic Latin fallback.

Fonts are looked up at fixed paths (Debian's fonts-dejavu-core, fonts-noto-core and
fonts-noto-cjk), never through fontconfig, so the choice does not depend on a user's font
configuration. When no listed font covers a script the renderer draws the Latin
transliteration instead; either way the same input renders the same pixels on the same
font set. Set ``EWA_GEO_FONT_DIRS`` (os.pathsep-separated) to add directories searched
first by file name.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from PIL import ImageFont

_DEJAVU = "/usr/share/fonts/truetype/dejavu/"
_NOTO = "/usr/share/fonts/truetype/noto/"
_CJK = "/usr/share/fonts/opentype/noto/"

# script -> candidate (file, collection index) pairs, best first. Index selects the CJK face
# whose glyph shapes match the region (JP, KR, SC, TC in Noto Sans CJK).
_CANDIDATES: dict[str, tuple[tuple[str, int], ...]] = {
    "latin": ((_DEJAVU + "DejaVuSans-Bold.ttf", 0), (_NOTO + "NotoSans-Bold.ttf", 0),
              ("/usr/share/fonts/truetype/liberation/LiberationSans-Bold.ttf", 0)),
    "greek": ((_DEJAVU + "DejaVuSans-Bold.ttf", 0), (_NOTO + "NotoSans-Bold.ttf", 0)),
    "cyrillic": ((_DEJAVU + "DejaVuSans-Bold.ttf", 0), (_NOTO + "NotoSans-Bold.ttf", 0)),
    "armenian": ((_NOTO + "NotoSansArmenian-Bold.ttf", 0), (_DEJAVU + "DejaVuSans-Bold.ttf", 0)),
    "georgian": ((_NOTO + "NotoSansGeorgian-Bold.ttf", 0), (_DEJAVU + "DejaVuSans-Bold.ttf", 0)),
    "hebrew": ((_NOTO + "NotoSansHebrew-Bold.ttf", 0), (_DEJAVU + "DejaVuSans-Bold.ttf", 0)),
    "arabic": ((_NOTO + "NotoSansArabic-Bold.ttf", 0), (_NOTO + "NotoNaskhArabic-Bold.ttf", 0),
               (_DEJAVU + "DejaVuSans-Bold.ttf", 0)),
    # Lines mixing Arabic or Hebrew with Latin letters (plates such as "مصر EGYPT") need one font
    # covering both; DejaVu Sans does.
    "arabic_latin": ((_DEJAVU + "DejaVuSans-Bold.ttf", 0),),
    "hebrew_latin": ((_DEJAVU + "DejaVuSans-Bold.ttf", 0),),
    "devanagari": ((_NOTO + "NotoSansDevanagari-Bold.ttf", 0),),
    "bengali": ((_NOTO + "NotoSansBengali-Bold.ttf", 0),),
    "tamil": ((_NOTO + "NotoSansTamil-Bold.ttf", 0),),
    "kannada": ((_NOTO + "NotoSansKannada-Bold.ttf", 0),),
    "sinhala": ((_NOTO + "NotoSansSinhala-Bold.ttf", 0),),
    "thai": ((_NOTO + "NotoSansThai-Bold.ttf", 0),),
    "khmer": ((_NOTO + "NotoSansKhmer-Bold.ttf", 0),),
    "ethiopic": ((_NOTO + "NotoSansEthiopic-Bold.ttf", 0),),
    "japanese": ((_CJK + "NotoSansCJK-Bold.ttc", 0),),
    "korean": ((_CJK + "NotoSansCJK-Bold.ttc", 1),),
    "han_simplified": ((_CJK + "NotoSansCJK-Bold.ttc", 2),),
    "han_traditional": ((_CJK + "NotoSansCJK-Bold.ttc", 3),),
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
    """The font (path, index) used for a script, or None when none is installed."""
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
    """Which scripts render natively on this machine (reported by the benchmark and docs)."""
    return {script: has_font(script) for script in _CANDIDATES}
