"""Parse Playwright's AI-mode ARIA snapshot (``page.aria_snapshot(mode="ai", boxes=True)``) into nodes.

The snapshot is a YAML-like outline, one element per line::

    - link "Go to page two" [ref=e3] [cursor=pointer] [box=8,8,98,17]:
      - /url: /p2
    - paragraph [ref=e7] [box=8,106,1264,18]: Some text here.
    - text: Check me

A ``ref`` names an element for Playwright's ``aria-ref=`` selector; refs stay on an element
while it lives (and keeps its role and name), so they are the basis of stable element ids.
Parsing the text ourselves keeps us on Playwright's public API.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from dataclasses import dataclass, field

Box = tuple[int, int, int, int]  # x, y, width, height in CSS pixels, relative to the viewport

_ATTR = re.compile(r"\[([A-Za-z-]+)(?:=([^\]]*))?\]")
_ROLE = re.compile(r"[A-Za-z][\w-]*")
_ESCAPES = {"\\": "\\", '"': '"', "b": "\b", "f": "\f", "n": "\n", "r": "\r", "t": "\t", "/": "/"}


@dataclass
class AriaNode:
    role: str
    name: str = ""
    ref: str | None = None
    attrs: dict[str, str] = field(default_factory=dict)  # checked, disabled, active, level, cursor, ...
    box: Box | None = None
    props: dict[str, str] = field(default_factory=dict)  # url, placeholder
    text: str | None = None  # a single inline text (an input's value for textboxes)
    children: list[AriaNode | str] = field(default_factory=list)
    parent: AriaNode | None = field(default=None, repr=False, compare=False)

    def walk(self) -> Iterator[AriaNode]:
        yield self
        for child in self.children:
            if isinstance(child, AriaNode):
                yield from child.walk()


class SnapshotParseError(ValueError):
    pass


def _unquote_value(raw: str) -> str:
    """A YAML scalar as Playwright writes it: plain, or double-quoted with C-like escapes."""
    if not raw.startswith('"'):
        return raw
    if len(raw) < 2 or not raw.endswith('"'):
        raise SnapshotParseError(f"unterminated quoted value: {raw[:60]!r}")
    out: list[str] = []
    i, body = 0, raw[1:-1]
    while i < len(body):
        c = body[i]
        if c != "\\":
            out.append(c)
            i += 1
            continue
        nxt = body[i + 1 : i + 2]
        if nxt == "x":
            out.append(chr(int(body[i + 2 : i + 4], 16)))
            i += 4
        elif nxt == "u":
            out.append(chr(int(body[i + 2 : i + 6], 16)))
            i += 6
        else:
            out.append(_ESCAPES.get(nxt, nxt))
            i += 2
    return "".join(out)


def _split_key(content: str) -> tuple[str, str | None, bool]:
    """(key, inline value or None, has_children) of one outline entry."""
    if content.startswith("'"):
        # A single-quoted key: '' is an escaped quote.
        i, chars = 1, []
        while i < len(content):
            if content[i] == "'":
                if content[i + 1 : i + 2] == "'":
                    chars.append("'")
                    i += 2
                    continue
                break
            chars.append(content[i])
            i += 1
        rest = content[i + 1 :]
        key = "".join(chars)
    else:
        # An unquoted key never contains ": " or a trailing ":" (Playwright quotes those).
        cut = content.find(": ")
        if cut >= 0:
            return content[:cut], content[cut + 2 :], False
        if content.endswith(":"):
            return content[:-1], None, True
        return content, None, False
    if rest.startswith(": "):
        return key, rest[2:], False
    return key, None, rest == ":"


def _parse_key(key: str) -> AriaNode:
    match = _ROLE.match(key)
    if not match:
        raise SnapshotParseError(f"no role in snapshot entry {key[:60]!r}")
    node = AriaNode(role=match.group(0))
    rest = key[match.end() :].lstrip()
    if rest.startswith('"'):
        name, end = json.JSONDecoder().raw_decode(rest)
        node.name = str(name)
        rest = rest[end:]
    for attr in _ATTR.finditer(rest):
        name, value = attr.group(1), attr.group(2)
        if name == "ref":
            node.ref = value
        elif name == "box" and value:
            x, y, w, h = (int(float(v)) for v in value.split(","))
            node.box = (x, y, w, h)
        else:
            node.attrs[name] = value if value is not None else "true"
    return node


def parse_snapshot(text: str) -> list[AriaNode]:
    """The top-level nodes of a snapshot; text runs are plain strings among ``children``."""
    roots: list[AriaNode | str] = []
    stack: list[tuple[int, AriaNode]] = []  # (depth, node) of the open ancestors
    for lineno, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        stripped = line.lstrip(" ")
        depth = (len(line) - len(stripped)) // 2
        if not stripped.startswith("- "):
            raise SnapshotParseError(f"line {lineno}: expected '- ' entry, got {line[:60]!r}")
        content = stripped[2:]
        while stack and stack[-1][0] >= depth:
            stack.pop()
        parent = stack[-1][1] if stack else None
        siblings = parent.children if parent is not None else roots
        if content.startswith("text: ") or content == "text:":
            siblings.append(_unquote_value(content[6:]))
            continue
        if content.startswith("/"):
            prop, _, value = content[1:].partition(": ")
            if parent is not None:
                parent.props[prop.rstrip(":")] = _unquote_value(value)
            continue
        key, inline, _ = _split_key(content)
        node = _parse_key(key)
        node.parent = parent
        if inline is not None:
            node.text = _unquote_value(inline)
        siblings.append(node)
        stack.append((depth, node))
    return [n for n in roots if isinstance(n, AriaNode)] or [AriaNode(role="generic", children=list(roots))]
