"""The article collection: loading, title/alias resolution and consistency checks.

Public API for the task generator::

    from ewa_mcp.websites.wiki import store
    articles = store.load_articles()          # every article, sorted by slug
    store.find("Fuller Building")             # -> Article for flatiron-building (title, alias or slug)
    store.by_poi_id("poi-flatiron-building")  # -> the landmark article of a POI

Articles are read once per process (they ship with the package and never change at run time).
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from .articles_format import Article, ArticleFormatError, parse_article

__all__ = ["Article", "ArticleFormatError", "ArticleIndex", "ARTICLES_DIR", "load_articles", "find", "by_poi_id",
           "index", "normalize_title", "links_in", "plain_text", "check_articles"]

ARTICLES_DIR = Path(__file__).resolve().parent / "articles"
# [[Target]] or [[Target|shown text]]; targets never contain brackets or pipes.
LINK_RE = re.compile(r"\[\[([^\[\]|\n]+)(?:\|([^\[\]\n]+))?\]\]")


def strip_accents(text: str) -> str:
    """The text with its accents taken off ("Bogotá" -> "Bogota")."""
    decomposed = unicodedata.normalize("NFKD", text)
    return "".join(c for c in decomposed if not unicodedata.combining(c))


def normalize_title(text: str) -> str:
    """Lookup key for titles, aliases and slugs: case, accents, punctuation and '_'/'-' do not matter.

    So "St. Patrick's Cathedral", "st-patricks-cathedral" and "St Patricks Cathedral" all meet."""
    stripped = strip_accents(text).replace("'", "").replace("\u2019", "").replace(".", "")
    return " ".join(re.sub(r"[^0-9a-z]+", " ", stripped.casefold()).split())


def links_in(markup: str) -> list[tuple[str, str]]:
    """(target, shown text) for every [[link]] in body markup or an infobox value."""
    return [(m.group(1).strip(), (m.group(2) or m.group(1)).strip()) for m in LINK_RE.finditer(markup)]


def plain_text(markup: str) -> str:
    """Body markup as readable text (what search indexes and snippets show)."""
    text = LINK_RE.sub(lambda m: (m.group(2) or m.group(1)).strip(), markup)
    text = re.sub(r"\*\*(.+?)\*\*", r"\1", text)
    text = re.sub(r"(?<![*\w])\*(?!\s)(.+?)(?<!\s)\*(?![*\w])", r"\1", text)
    text = re.sub(r"^#{2,3}\s+", "", text, flags=re.MULTILINE)
    text = re.sub(r"^- ", "", text, flags=re.MULTILINE)
    return text


@dataclass(frozen=True)
class Problem:
    slug: str
    message: str

    def __str__(self) -> str:
        return f"{self.slug}: {self.message}"


class ArticleIndex:
    """All articles plus the lookup tables the site and the task generator need."""

    def __init__(self, articles: Iterable[Article]):
        self.articles: list[Article] = sorted(articles, key=lambda a: (a.slug, str(a.path)))
        self.by_slug: dict[str, Article] = {}
        self.problems: list[Problem] = []
        kept: list[Article] = []
        for article in self.articles:
            if article.slug in self.by_slug:
                # Reported, not fatal: several people write articles in parallel and one clash must
                # not take the whole site down. The first file in path order keeps the slug.
                other = self.by_slug[article.slug]
                self.problems.append(Problem(article.slug, f"{article.path} reuses the slug of {other.path}; "
                                                           "rename one file (slugs are unique across groups)"))
                continue
            self.by_slug[article.slug] = article
            kept.append(article)
        self.articles = kept

        # Titles win over aliases, aliases over slugs, so a link always lands where a reader expects.
        self._lookup: dict[str, str] = {}
        for article in self.articles:
            key = normalize_title(article.title)
            if key in self._lookup:
                other = self.by_slug[self._lookup[key]]
                self.problems.append(Problem(article.slug, f"title '{article.title}' is also the title of "
                                                           f"{other.path}; give one a more specific title, "
                                                           "e.g. 'Chinatown (Boston)'"))
                continue
            self._lookup[key] = article.slug
        for article in self.articles:
            for alias in article.aliases:
                key = normalize_title(alias)
                owner = self._lookup.get(key)
                if owner is None:
                    self._lookup[key] = article.slug
                elif owner != article.slug:
                    self.problems.append(Problem(article.slug, f"alias '{alias}' already names '{owner}'"))
        for article in self.articles:
            self._lookup.setdefault(normalize_title(article.slug), article.slug)

        self.by_poi: dict[str, Article] = {}
        for article in self.articles:
            if article.poi_id:
                if article.poi_id in self.by_poi:
                    self.problems.append(Problem(article.slug, f"poi_id '{article.poi_id}' is also claimed by "
                                                               f"'{self.by_poi[article.poi_id].slug}'"))
                else:
                    self.by_poi[article.poi_id] = article
        self.categories: dict[str, list[Article]] = {}
        for article in self.articles:
            self.categories.setdefault(article.category, []).append(article)
        for members in self.categories.values():
            members.sort(key=lambda a: a.title.casefold())
        for article in self.articles:
            for target, _ in links_in(article.body) + [l for v in article.infobox.values() for l in links_in(v)]:
                if self.find(target) is None:
                    self.problems.append(Problem(article.slug, f"link [[{target}]] names no article"))

    def find(self, title_or_slug: str) -> Article | None:
        slug = self._lookup.get(normalize_title(title_or_slug))
        return self.by_slug.get(slug) if slug else None

    def category_key(self, name: str) -> str | None:
        """The category whose name or slug form matches ``name`` (case-insensitive)."""
        wanted = normalize_title(name)
        return next((c for c in self.categories if normalize_title(c) == wanted), None)

    def __len__(self) -> int:
        return len(self.articles)


def read_articles(root: Path = ARTICLES_DIR) -> tuple[list[Article], list[Problem]]:
    """Parse every ``<group>/<slug>.md`` under root (articles directly under root get group '').

    A malformed file is skipped and reported, so one bad file never takes the site down; the
    content test fails on any reported problem."""
    articles, problems = [], []
    for path in sorted(root.rglob("*.md")):
        if path.name.upper() == "README.MD":
            continue
        group = path.parent.relative_to(root).as_posix() if path.parent != root else ""
        try:
            articles.append(parse_article(path.read_text(encoding="utf-8"), path, group))
        except (ArticleFormatError, UnicodeDecodeError) as exc:
            problems.append(Problem(path.stem, str(exc)))
    return articles, problems


@lru_cache(maxsize=4)
def index(root: Path = ARTICLES_DIR) -> ArticleIndex:
    articles, problems = read_articles(root)
    built = ArticleIndex(articles)
    built.problems[:0] = problems
    return built


def load_articles() -> list[Article]:
    """Every article, sorted by slug."""
    return list(index().articles)


def find(title_or_slug: str) -> Article | None:
    """The article with this title, alias or slug (case, accents and punctuation ignored), else None."""
    return index().find(title_or_slug)


def by_poi_id(poi_id: str) -> Article | None:
    return index().by_poi.get(poi_id)


def check_articles(root: Path = ARTICLES_DIR) -> list[Problem]:
    """Consistency problems that do not stop the site (dangling links, clashing aliases)."""
    return list(index(root).problems)
