"""Parse one article file: a front-matter block between ``---`` lines, then the body.

The format is shared by everyone who writes articles (see websites/wiki/README.md), so every
error names the file, the line and how to fix it instead of failing somewhere downstream.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

SLUG_RE = re.compile(r"^[a-z0-9]+(?:-[a-z0-9]+)*$")
FIELD_RE = re.compile(r"^([a-z_]+):\s?(.*)$")
REQUIRED_FIELDS = ("title", "category")
KNOWN_FIELDS = ("title", "category", "aliases", "infobox", "coordinates", "poi_id")
MAX_TITLE_CHARS = 120


class ArticleFormatError(ValueError):
    """An article file does not follow the shared format; the message says where and how to fix it."""


@dataclass(frozen=True)
class Article:
    slug: str
    title: str
    category: str
    body: str
    aliases: tuple[str, ...] = ()
    infobox: dict[str, str] = field(default_factory=dict)
    poi_id: str | None = None
    coordinates: dict[str, float] | None = None
    group: str = ""  # the folder under articles/ (landmarks, geo, dishes, ...)
    path: Path | None = None

    @property
    def url_path(self) -> str:
        return f"/wiki/{self.slug}"


def _fail(path: Path, line: int | None, problem: str, fix: str) -> ArticleFormatError:
    where = f"{path}:{line}" if line else str(path)
    return ArticleFormatError(f"{where}: {problem}. Fix: {fix}")


def _json_value(path: Path, line: int, key: str, raw: str) -> Any:
    try:
        return json.loads(raw)
    except json.JSONDecodeError as exc:
        raise _fail(path, line, f"'{key}' is not valid one-line JSON ({exc.msg})",
                    f'write it as JSON on one line, e.g. {key}: {_EXAMPLES[key]}') from None


_EXAMPLES = {
    "aliases": '["Fuller Building"]',
    "infobox": '{"Architect": "Daniel Burnham", "Year built": "1902"}',
    "coordinates": '{"lat": 40.7411, "lng": -73.9897}',
}


def parse_article(text: str, path: Path, group: str = "") -> Article:
    """Parse the text of ``<group>/<slug>.md``; raises ArticleFormatError on any deviation."""
    slug = path.stem
    if not SLUG_RE.match(slug):
        raise _fail(path, None, f"file name '{path.name}' is not a valid slug",
                    "name the file with lowercase ASCII words joined by hyphens, e.g. flatiron-building.md")
    lines = text.replace("\r\n", "\n").split("\n")
    if not lines or lines[0].strip() != "---":
        raise _fail(path, 1, "the file does not start with a '---' front-matter line",
                    "begin with '---', then 'title: ...' and 'category: ...', then a closing '---'")
    try:
        end = next(i for i in range(1, len(lines)) if lines[i].strip() == "---")
    except StopIteration:
        raise _fail(path, 1, "the front matter is never closed",
                    "add a line with just '---' after the last front-matter field") from None

    fields: dict[str, Any] = {}
    for number in range(1, end):
        raw_line = lines[number]
        if not raw_line.strip():
            continue
        match = FIELD_RE.match(raw_line)
        if not match:
            raise _fail(path, number + 1, f"front-matter line {raw_line[:60]!r} is not 'key: value'",
                        f"use one of {', '.join(KNOWN_FIELDS)} followed by ': ' and the value")
        key, value = match.group(1), match.group(2).strip()
        if key not in KNOWN_FIELDS:
            raise _fail(path, number + 1, f"unknown front-matter field '{key}'",
                        f"use only {', '.join(KNOWN_FIELDS)}")
        if key in fields:
            raise _fail(path, number + 1, f"field '{key}' appears twice", "keep one of them")
        fields[key] = _json_value(path, number + 1, key, value) if key in _EXAMPLES else value

    for key in REQUIRED_FIELDS:
        if not fields.get(key):
            raise _fail(path, None, f"the front matter has no '{key}'", f"add a line '{key}: ...'")
    title = fields["title"]
    if len(title) > MAX_TITLE_CHARS or "[" in title or "|" in title or "]" in title:
        raise _fail(path, None, f"title {title[:40]!r} is too long or contains [ ] |",
                    f"use a plain title of at most {MAX_TITLE_CHARS} characters")

    aliases = fields.get("aliases", [])
    if not isinstance(aliases, list) or not all(isinstance(a, str) and a.strip() for a in aliases):
        raise _fail(path, None, "'aliases' must be a JSON list of non-empty strings",
                    f"aliases: {_EXAMPLES['aliases']}")
    infobox = fields.get("infobox", {})
    if not isinstance(infobox, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in infobox.items()):
        raise _fail(path, None, "'infobox' must be a JSON object whose keys and values are strings",
                    f"infobox: {_EXAMPLES['infobox']} (write numbers as strings, e.g. \"87 m\")")
    coordinates = fields.get("coordinates")
    if coordinates is not None:
        ok = (isinstance(coordinates, dict) and set(coordinates) == {"lat", "lng"}
              and all(isinstance(coordinates[k], (int, float)) for k in ("lat", "lng"))
              and -90 <= coordinates["lat"] <= 90 and -180 <= coordinates["lng"] <= 180)
        if not ok:
            raise _fail(path, None, "'coordinates' must be {\"lat\": number, \"lng\": number} in range",
                        f"coordinates: {_EXAMPLES['coordinates']}")
        coordinates = {"lat": float(coordinates["lat"]), "lng": float(coordinates["lng"])}

    body = "\n".join(lines[end + 1:]).strip()
    if not body:
        raise _fail(path, None, "the article has no body", "write at least one paragraph after the closing '---'")
    return Article(slug=slug, title=title, category=fields["category"], body=body,
                   aliases=tuple(a.strip() for a in aliases), infobox=dict(infobox),
                   poi_id=fields.get("poi_id") or None, coordinates=coordinates, group=group, path=path)
