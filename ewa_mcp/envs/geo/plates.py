"""Number-plate styles: colours, bands and the character pattern of each country's plates.

A pattern uses ``A`` for a letter, ``9`` for a digit and ``{r}`` for the region code of
the city (German district letters, Indian state codes, a US state caption, ...). Plates
with a region code are a city-level cue, so the scene shows them legibly only where the
location's difficulty lets city cues appear.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

LATIN_PLATE_LETTERS = "ABCDEFGHJKLMNPRSTUVWXYZ"


@dataclass(frozen=True)
class PlateStyle:
    pattern: str
    bg: str = "#f4f4f0"  # plate background (front, and rear unless rear_bg is set)
    fg: str = "#111111"
    band: str | None = None  # text of a blue band on the left (EU-style country code)
    band_bg: str = "#1d3f95"
    caption: str | None = None  # fixed text above the characters (a country name)
    region_caption: bool = False  # the region code is shown as a caption line instead of inline
    rear_bg: str | None = None  # e.g. yellow rear plates
    letters: str = LATIN_PLATE_LETTERS
    digits: str = "0123456789"

    @property
    def has_region(self) -> bool:
        return "{r}" in self.pattern or self.region_caption

    def text(self, rng: random.Random, region: str | None) -> str:
        """The plate's characters, drawn with ``rng`` (deterministic per scene)."""
        out: list[str] = []
        pattern = self.pattern.replace("{r}", "\x00")
        for ch in pattern:
            if ch == "A":
                out.append(rng.choice(self.letters))
            elif ch == "9":
                out.append(rng.choice(self.digits))
            elif ch == "\x00":
                out.append(_expand_region(region or "", rng, self.letters, self.digits))
            else:
                out.append(ch)
        return "".join(out).strip()

    def caption_text(self, region: str | None) -> str | None:
        if self.region_caption:
            return region
        return self.caption

    def describe_colours(self, rear: bool) -> str:
        bg = self.rear_bg if (rear and self.rear_bg) else self.bg
        words = f"{colour_name(bg)} plate with {colour_name(self.fg)} characters"
        if self.band:
            words += f" and a blue band on the left marked '{self.band}'"
        return words


def _expand_region(region: str, rng: random.Random, letters: str, digits: str) -> str:
    """Region codes are literal except ``#`` (a digit) and ``@`` (a letter): a South African
    Western Cape plate is "CA ###-###"."""
    return "".join(rng.choice(digits) if c == "#" else rng.choice(letters) if c == "@" else c for c in region)


_COLOUR_NAMES = {
    "#f4f4f0": "white",
    "#111111": "black",
    "#f2c200": "yellow",
    "#1d3f95": "blue",
    "#1f5fb0": "blue",
    "#0b6b2e": "green",
    "#b01818": "red",
    "#e9e4d0": "cream",
    "#2a2a2a": "black",
}


def colour_name(hex_colour: str) -> str:
    return _COLOUR_NAMES.get(hex_colour, "coloured")


YELLOW = "#f2c200"
BLACK = "#2a2a2a"
WHITE = "#f4f4f0"
BLUE = "#1f5fb0"
RED = "#b01818"
GREEN = "#0b6b2e"
