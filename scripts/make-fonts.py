#!/usr/bin/env python3
"""Refresh the fonts shipped in ewa_mcp/street_drawing/fonts/ (a maintainer's tool; run at release time, never at
run time). The package reads only those files, so a street view draws the same pixels on every machine.

    apt-get install fonts-dejavu-core fonts-noto-core fonts-noto-cjk
    .venv/bin/python scripts/make-fonts.py

Copies DejaVu Sans Bold (Bitstream Vera licence) and the Noto Sans Bold face of each script the signs use (SIL
Open Font License 1.1) with their licence texts. Noto Sans CJK (20 MB, four faces) is cut to the characters the
package's sources and data hold (fontTools' subsetter: glyph shapes unchanged), one OpenType file per face. Run
it again whenever sign text in a CJK script is added; tests/geo/test_shipped_fonts.py fails until then.
"""

from __future__ import annotations

import re
import shutil
import sys
from pathlib import Path

from fontTools import subset
from fontTools.ttLib import TTFont

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "ewa_mcp" / "street_drawing" / "fonts"
NOTO = Path("/usr/share/fonts/truetype/noto")
COPY = {
    Path("/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"): "LICENSE-DejaVu.txt",
    **{NOTO / f"NotoSans{s}-Bold.ttf": "LICENSE-Noto.txt"
       for s in ("Armenian", "Georgian", "Hebrew", "Arabic", "Devanagari", "Bengali", "Tamil", "Kannada",
                 "Sinhala", "Thai", "Khmer", "Ethiopic")},
}
LICENCES = {"LICENSE-DejaVu.txt": Path("/usr/share/doc/fonts-dejavu-core/copyright"),
            "LICENSE-Noto.txt": Path("/usr/share/doc/fonts-noto-core/copyright"),
            "LICENSE-NotoCJK.txt": Path("/usr/share/doc/fonts-noto-cjk/copyright")}
CJK = Path("/usr/share/fonts/opentype/noto/NotoSansCJK-Bold.ttc")
# The collection's faces in order (fonts.py picks by region), and the file each becomes.
CJK_FACES = ("NotoSansCJKjp-Bold-subset.otf", "NotoSansCJKkr-Bold-subset.otf", "NotoSansCJKsc-Bold-subset.otf",
             "NotoSansCJKtc-Bold-subset.otf")
_CJK_CHARS = re.compile(r"[\u1100-\u11ff\u3000-\u30ff\u3130-\u318f\u3400-\u4dbf\u4e00-\u9fff\uac00-\ud7af\uff00-\uffef]")


def cjk_text() -> str:
    """Every CJK, kana and Hangul character in the package's sources and data, and the ASCII range (plates mix)."""
    chars = {chr(c) for c in range(0x20, 0x7F)}
    for path in (ROOT / "ewa_mcp").rglob("*"):
        if path.suffix in (".py", ".json", ".jsonl", ".txt") and path.is_file():
            chars.update(_CJK_CHARS.findall(path.read_text(encoding="utf-8", errors="ignore")))
    return "".join(sorted(chars))


def main() -> None:
    missing = [str(p) for p in [*COPY, CJK, *LICENCES.values()] if not p.exists()]
    if missing:
        sys.exit("missing: " + ", ".join(missing) + "\napt-get install fonts-dejavu-core fonts-noto-core fonts-noto-cjk")
    OUT.mkdir(exist_ok=True)
    for src in COPY:
        shutil.copyfile(src, OUT / src.name)
    for name, src in LICENCES.items():
        shutil.copyfile(src, OUT / name)
    text = cjk_text()
    options = subset.Options()
    options.name_IDs = ["*"]
    options.name_languages = ["*"]
    options.notdef_outline = True
    options.layout_features = ["*"]
    for index, name in enumerate(CJK_FACES):
        font = TTFont(CJK, fontNumber=index)
        subsetter = subset.Subsetter(options)
        subsetter.populate(text=text)
        subsetter.subset(font)
        font.save(OUT / name)
    print(f"{OUT}: {len(COPY)} fonts copied, {len(CJK_FACES)} CJK faces cut to {len(text)} characters")


if __name__ == "__main__":
    main()
