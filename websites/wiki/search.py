"""Full-text search over the articles with SQLite FTS5 (bm25 ranking, highlighted snippets).

The index lives in an in-memory database built once per site process (≈ 300 articles build in
tens of milliseconds). User queries never reach FTS5 syntax: they are reduced to word tokens,
each quoted, so operators, quotes and SQL meta-characters are plain text.
"""

from __future__ import annotations

import html
import re
import sqlite3
import threading
from dataclasses import dataclass

from .store import Article, plain_text

MAX_QUERY_CHARS = 200
MAX_TOKENS = 12
# bm25 column weights: a word in the title matters far more than one in the body.
WEIGHTS = (10.0, 6.0, 2.0, 1.0)  # title, aliases, infobox, body
_MARK_OPEN, _MARK_CLOSE = "\x02", "\x03"


class QueryError(ValueError):
    pass


@dataclass(frozen=True)
class Hit:
    slug: str
    title: str
    category: str
    snippet_html: str


def fts5_available() -> bool:
    try:
        sqlite3.connect(":memory:").execute("CREATE VIRTUAL TABLE t USING fts5(x)")
        return True
    except sqlite3.OperationalError:
        return False


def tokens_of(query: str) -> list[str]:
    if len(query) > MAX_QUERY_CHARS:
        raise QueryError(f"The search query is {len(query)} characters long; use at most {MAX_QUERY_CHARS}.")
    return re.findall(r"\w+", query)[:MAX_TOKENS]


class SearchIndex:
    def __init__(self, articles: list[Article]):
        if not fts5_available():
            raise RuntimeError("this Python's sqlite3 lacks FTS5; use a CPython build with SQLite FTS5 enabled")
        self._lock = threading.Lock()
        self._db = sqlite3.connect(":memory:", check_same_thread=False)
        self._db.execute(
            "CREATE VIRTUAL TABLE articles USING fts5(title, aliases, infobox, body, slug UNINDEXED, "
            "category UNINDEXED, tokenize = 'porter unicode61 remove_diacritics 2')")
        self._db.executemany(
            "INSERT INTO articles (title, aliases, infobox, body, slug, category) VALUES (?, ?, ?, ?, ?, ?)",
            [(a.title, " ; ".join(a.aliases),
              " ; ".join(f"{k}: {plain_text(v)}" for k, v in a.infobox.items()),
              plain_text(a.body), a.slug, a.category) for a in articles])
        self._db.commit()

    def search(self, query: str, limit: int = 20, offset: int = 0) -> tuple[list[Hit], int, bool]:
        """(hits, total, matched_all_words). All words must match; failing that, any word may."""
        tokens = tokens_of(query)
        if not tokens:
            return [], 0, True
        quoted = ['"' + t.replace('"', '""') + '"' for t in tokens]
        hits, total = self._run(" AND ".join(quoted), limit, offset)
        if total or len(tokens) == 1:
            return hits, total, True
        hits, total = self._run(" OR ".join(quoted), limit, offset)
        return hits, total, False

    def _run(self, match: str, limit: int, offset: int) -> tuple[list[Hit], int]:
        weights = ", ".join(str(w) for w in WEIGHTS)
        with self._lock:
            total = self._db.execute("SELECT count(*) FROM articles WHERE articles MATCH ?", (match,)).fetchone()[0]
            rows = self._db.execute(
                f"SELECT slug, title, category, snippet(articles, 3, ?, ?, '…', 24) FROM articles "
                f"WHERE articles MATCH ? ORDER BY bm25(articles, {weights}), slug LIMIT ? OFFSET ?",
                (_MARK_OPEN, _MARK_CLOSE, match, limit, offset)).fetchall()
        return [Hit(slug, title, category, _snippet_html(snippet)) for slug, title, category, snippet in rows], total


def _snippet_html(snippet: str) -> str:
    escaped = html.escape(snippet, quote=False)
    return escaped.replace(_MARK_OPEN, "<mark>").replace(_MARK_CLOSE, "</mark>")
