"""Render the article Markdown subset to HTML: "## Heading", "- item" lists, **bold**, *italic*, [[links]].

Everything is escaped first and only our own tags are added afterwards, so article text can
never inject markup. Links are resolved through a callback (title or alias -> URL) so a link to
a missing article renders as a "new page" link to the search page, like a real wiki.
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from .store import LINK_RE

# (target) -> (href, exists)
Resolver = Callable[[str], tuple[str, bool]]
BOLD_RE = re.compile(r"\*\*(.+?)\*\*")
ITALIC_RE = re.compile(r"(?<![*\w])\*(?!\s)(.+?)(?<!\s)\*(?![*\w])")
HEADING_RE = re.compile(r"^(#{2,3})\s+(.+?)\s*#*$")


@dataclass
class Rendered:
    html: str
    # (level, text, anchor) for the table of contents
    headings: list[tuple[int, str, str]] = field(default_factory=list)


def render_inline(text: str, resolve: Resolver) -> str:
    links: list[str] = []

    def stash(match: re.Match[str]) -> str:
        target = match.group(1).strip()
        shown = (match.group(2) or match.group(1)).strip()
        href, exists = resolve(target)
        css = "" if exists else ' class="new"'
        title = target if exists else f"{target} (page does not exist)"
        links.append(f'<a href="{html.escape(href)}" title="{html.escape(title)}"{css}>{html.escape(shown)}</a>')
        return f"\x00{len(links) - 1}\x00"

    out = html.escape(LINK_RE.sub(stash, text), quote=False)
    out = BOLD_RE.sub(r"<b>\1</b>", out)
    out = ITALIC_RE.sub(r"<i>\1</i>", out)
    return re.sub(r"\x00(\d+)\x00", lambda m: links[int(m.group(1))], out)


def anchor_for(text: str, used: set[str]) -> str:
    base = re.sub(r"[^0-9a-z]+", "-", text.casefold()).strip("-") or "section"
    anchor, n = base, 2
    while anchor in used:
        anchor, n = f"{base}-{n}", n + 1
    used.add(anchor)
    return anchor


def render_body(markup: str, resolve: Resolver) -> Rendered:
    rendered = Rendered(html="")
    parts: list[str] = []
    used_anchors: set[str] = set()
    paragraph: list[str] = []
    items: list[str] = []

    def flush() -> None:
        if paragraph:
            parts.append(f"<p>{render_inline(' '.join(paragraph), resolve)}</p>")
            paragraph.clear()
        if items:
            parts.append("<ul>" + "".join(f"<li>{render_inline(i, resolve)}</li>" for i in items) + "</ul>")
            items.clear()

    for line in markup.split("\n"):
        stripped = line.strip()
        heading = HEADING_RE.match(stripped)
        if not stripped:
            flush()
        elif heading:
            flush()
            level = len(heading.group(1))
            text = heading.group(2)
            anchor = anchor_for(text, used_anchors)
            plain = BOLD_RE.sub(r"\1", LINK_RE.sub(lambda m: (m.group(2) or m.group(1)), text))
            rendered.headings.append((level, plain, anchor))
            parts.append(f'<h{level} id="{anchor}">{render_inline(text, resolve)}</h{level}>')
        elif stripped.startswith("- "):
            if paragraph:  # a list right after a paragraph line ends the paragraph
                parts.append(f"<p>{render_inline(' '.join(paragraph), resolve)}</p>")
                paragraph.clear()
            items.append(stripped[2:].strip())
        elif items and line.startswith("  "):
            items[-1] += " " + stripped  # continuation of a list item
        else:
            if items:
                flush()
            paragraph.append(stripped)
    flush()
    rendered.html = "\n".join(parts)
    return rendered
