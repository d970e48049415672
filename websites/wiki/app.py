"""The wiki site: main page, articles, FTS5 search, random article, categories.

Per-episode state is only the random-article counter: ``/random`` is deterministic per episode
(the n-th random article of episode E is ``sha256("E:n") mod N`` over the slug-sorted articles),
so replaying an episode's actions replays its pages; ``reset_episode`` restarts the sequence.
"""

from __future__ import annotations

import hashlib
import threading
from pathlib import Path
from typing import Any
from urllib.parse import quote

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import RedirectResponse, Response
from starlette.routing import Route

from ..common import SiteContext, SiteEvents, episode_of, exception_handlers, make_templates
from .markup import render_body, render_inline
from .search import MAX_QUERY_CHARS, QueryError, SearchIndex
from .store import ARTICLES_DIR, ArticleIndex, index, normalize_title, strip_accents

SITE_DIR = Path(__file__).resolve().parent
PAGE_SIZE = 20
MAX_SLUG_CHARS = 200
MAX_OFFSET = 10_000
# Representative pages for benchmarks/bench_websites.py.
BENCH_URLS = ("/", "/wiki/flatiron-building", "/wiki/new-york-city", "/search?q=gothic+church&fulltext=1",
              "/search?q=when+was+the+flatiron+built", "/search?q=Central+Park", "/category/landmarks-in-manhattan",
              "/random")
# Shown on the main page when present; any missing one is simply skipped.
FEATURED = ("flatiron-building", "central-park", "beaux-arts-architecture", "philadelphia", "new-york-city",
            "boston", "pittsburgh", "omelette")


def category_slug(name: str) -> str:
    return normalize_title(name).replace(" ", "-")


class RandomSequence:
    """Per-episode deterministic random article choice."""

    def __init__(self, slugs: list[str]):
        self._slugs = slugs
        self._counts: dict[str, int] = {}
        self._lock = threading.Lock()

    def next(self, episode_id: str) -> str:
        with self._lock:
            n = self._counts.get(episode_id, 0)
            self._counts[episode_id] = n + 1
        digest = hashlib.sha256(f"{episode_id}:{n}".encode()).digest()
        return self._slugs[int.from_bytes(digest[:8], "big") % len(self._slugs)]

    def reset_episode(self, episode_id: str) -> None:
        with self._lock:
            self._counts.pop(episode_id, None)


def create_app(ctx: SiteContext, articles_dir: Path = ARTICLES_DIR) -> Starlette:
    wiki: ArticleIndex = index(articles_dir)
    if not len(wiki):
        raise RuntimeError(f"no wiki articles found under {articles_dir}")
    search_index = SearchIndex(wiki.articles)
    randoms = RandomSequence([a.slug for a in wiki.articles])
    templates = make_templates(SITE_DIR, ctx, "wiki")
    templates.env.globals.update(category_slug=category_slug, max_query_chars=MAX_QUERY_CHARS)

    def resolve(target: str) -> tuple[str, bool]:
        article = wiki.find(target)
        if article is not None:
            return article.url_path, True
        return f"/search?q={quote(target)}", False

    events = SiteEvents(ctx, "wiki")

    def emit(request: Request, event: dict[str, Any]) -> None:
        events(request, **event)

    def page(request: Request, name: str, context: dict[str, Any], status: int = 200) -> Response:
        return templates.TemplateResponse(request, name, context, status_code=status)

    # ------------------------------------------------------------ pages
    async def main_page(request: Request) -> Response:
        emit(request, {"type": "page_view", "path": "/"})
        featured = [wiki.by_slug[s] for s in FEATURED if s in wiki.by_slug] or wiki.articles[:4]
        categories = sorted(wiki.categories.items(), key=lambda kv: kv[0].casefold())
        return page(request, "main.html", {"featured": featured[0], "more": featured[1:],
                                           "categories": categories, "count": len(wiki)})

    async def article_page(request: Request) -> Response:
        requested: str = request.path_params["slug"]
        if len(requested) > MAX_SLUG_CHARS:
            raise HTTPException(400, f"The article name is {len(requested)} characters long; "
                                     f"use at most {MAX_SLUG_CHARS} (or search for it instead).")
        article = wiki.by_slug.get(requested)
        if article is None:
            found = wiki.find(requested)
            if found is not None:  # a title, alias or differently-cased slug: go to the canonical URL
                return RedirectResponse(f"{found.url_path}?redirected_from={quote(requested)}", status_code=302)
            emit(request, {"type": "page_view", "path": request.url.path, "slug": None, "missing": requested})
            return page(request, "missing.html", {"requested": requested.replace("_", " ")}, status=404)
        emit(request, {"type": "page_view", "path": article.url_path, "slug": article.slug})
        body = render_body(article.body, resolve)
        infobox = [(key, _infobox_value(value, wiki, resolve)) for key, value in article.infobox.items()]
        redirected_from = request.query_params.get("redirected_from", "")[:MAX_SLUG_CHARS]
        return page(request, "article.html", {"article": article, "body": body, "infobox": infobox,
                                              "redirected_from": redirected_from.replace("_", " ")})

    async def search_page(request: Request) -> Response:
        query = request.query_params.get("q", "").strip()
        offset = _int_param(request, "offset", 0, MAX_OFFSET)
        if len(query) > MAX_QUERY_CHARS:
            raise HTTPException(400, f"The search query is {len(query)} characters long; "
                                     f"shorten it to at most {MAX_QUERY_CHARS} characters.")
        if not query:
            emit(request, {"type": "page_view", "path": "/search"})
            return page(request, "search.html", {"query": "", "hits": [], "total": 0, "all_words": True,
                                                 "offset": 0, "page_size": PAGE_SIZE})
        exact = wiki.find(query)
        if exact is not None and request.query_params.get("fulltext") != "1" and offset == 0:
            emit(request, {"type": "search", "query": query, "results": 1, "went_to": exact.slug})
            return RedirectResponse(exact.url_path, status_code=302)
        try:
            hits, total, all_words = search_index.search(query, PAGE_SIZE, offset)
        except QueryError as exc:
            raise HTTPException(400, f"{exc} Shorten the query.") from None
        emit(request, {"type": "search", "query": query, "results": total, "went_to": None,
                       "top": [h.slug for h in hits[:5]]})
        emit(request, {"type": "page_view", "path": "/search", "query": query})
        return page(request, "search.html", {"query": query, "hits": hits, "total": total, "all_words": all_words,
                                             "offset": offset, "page_size": PAGE_SIZE, "exact": exact})

    async def random_article(request: Request) -> Response:
        slug = randoms.next(episode_of(request))
        emit(request, {"type": "random", "slug": slug})
        return RedirectResponse(f"/wiki/{slug}", status_code=302)

    async def category_page(request: Request) -> Response:
        requested: str = request.path_params["name"]
        if len(requested) > MAX_SLUG_CHARS:
            raise HTTPException(400, f"The category name is too long; use at most {MAX_SLUG_CHARS} characters.")
        name = wiki.category_key(requested)
        if name is None:
            raise HTTPException(404, f"There is no category named '{requested}'. "
                                     "See the list of categories on the main page.")
        emit(request, {"type": "page_view", "path": f"/category/{category_slug(name)}", "category": name})
        return page(request, "category.html", {"name": name, "members": wiki.categories[name]})

    async def wiki_root(request: Request) -> Response:
        return RedirectResponse("/", status_code=302)

    async def categories_page(request: Request) -> Response:
        # The list of every category is on the main page; agents guess /categories for it.
        return RedirectResponse("/#categories-heading", status_code=302)

    app = Starlette(routes=[
        Route("/", main_page),
        Route("/wiki/", wiki_root),
        Route("/wiki/{slug}", article_page),
        Route("/search", search_page),
        Route("/random", random_article),
        Route("/category/{name}", category_page),
        Route("/categories", categories_page),
    ], exception_handlers=exception_handlers(ctx))
    app.state.wiki = wiki
    app.state.reset_episode = randoms.reset_episode
    return app


def _int_param(request: Request, name: str, default: int, maximum: int) -> int:
    raw = request.query_params.get(name)
    if raw is None or raw == "":
        return default
    if not raw.isdigit() or int(raw) > maximum:
        raise HTTPException(400, f"'{name}' must be a whole number from 0 to {maximum}; got {raw[:20]!r}.")
    return int(raw)


def _words_key(text: str) -> str:
    """Case and accents folded and spaces collapsed; punctuation kept."""
    return " ".join(strip_accents(text).casefold().split())


def _infobox_value(value: str, wiki: ArticleIndex, resolve: Any) -> str:
    """Infobox values stay exactly as written (graders compare them with POI facts); a value that is
    itself the title or an alias of an article (a style, an architect) becomes a link to it. The match is
    on the words as written, not on the lookup key alone: the key drops punctuation, so an internet domain
    ".jp" would otherwise link to the article whose alias is "JP"."""
    if "[[" not in value:
        target = wiki.find(value)
        if target is not None and _words_key(value) in {_words_key(n) for n in (target.title, *target.aliases)}:
            value = f"[[{target.title}|{value}]]"
    return render_inline(value, resolve)
