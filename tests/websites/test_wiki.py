"""Route tests for the wiki site (Starlette TestClient): every page, search, random, categories,
events, per-episode reset and hostile input — against the shipped articles, plus a few
hand-made article folders for the parser and the renderer."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from starlette.testclient import TestClient

from ewa_mcp.websites.common import EPISODE_HEADER, SiteContext
from ewa_mcp.websites.wiki import store
from ewa_mcp.websites.wiki.app import create_app
from ewa_mcp.websites.wiki.articles_format import ArticleFormatError, parse_article
from ewa_mcp.websites.wiki.search import MAX_QUERY_CHARS


class Events:
    def __init__(self) -> None:
        self.items: list[tuple[str, dict]] = []

    def emit(self, episode: str, event: dict) -> None:
        self.items.append((episode, event))

    def of(self, episode: str, type: str) -> list[dict]:
        return [e for ep, e in self.items if ep == episode and e["type"] == type]


@pytest.fixture(scope="module")
def events() -> Events:
    return Events()


@pytest.fixture(scope="module")
def app(events: Events):
    return create_app(SiteContext(urls={"wiki": "http://wiki.test"}, emit=events.emit))


@pytest.fixture(scope="module")
def client(app) -> TestClient:
    return TestClient(app)


def get(client: TestClient, path: str, episode: str = "ep-a", **kwargs):
    return client.get(path, headers={EPISODE_HEADER: episode}, follow_redirects=False, **kwargs)


def hrefs(html: str) -> list[str]:
    return re.findall(r'href="(/[^"#]*)"', html)


# ------------------------------------------------------------------ main page
def test_main_page_has_search_random_featured_and_categories(client):
    r = get(client, "/")
    assert r.status_code == 200
    assert 'role="search"' in r.text and '<label for="wiki-search-input">' in r.text
    assert 'href="/random"' in r.text
    assert 'href="/wiki/flatiron-building"' in r.text  # featured
    for name in ("Landmarks in Manhattan", "Architectural styles", "Dishes", "Ingredients"):
        assert f'href="/category/{name.lower().replace(" ", "-")}"' in r.text


# ------------------------------------------------------------------ articles
def test_article_page_renders_infobox_body_links_and_category(client):
    r = get(client, "/wiki/flatiron-building")
    assert r.status_code == 200
    html = r.text
    assert '<h1 id="article-title">Flatiron Building</h1>' in html
    # The infobox is a table whose labels are row headers, values exactly as in the POI file.
    assert '<th scope="row">Year built</th><td>1902</td>' in html
    assert '<th scope="row">Height</th><td>87 m</td>' in html
    # A value naming another article becomes a link to it; body [[links]] resolve to /wiki/ URLs.
    assert '<a href="/wiki/beaux-arts-architecture" title="Beaux-Arts architecture">Beaux-Arts</a>' in html
    assert '<a href="/wiki/daniel-burnham"' in html
    assert '<h2 id="architecture">Architecture</h2>' in html
    assert 'href="/category/landmarks-in-manhattan"' in html
    assert "[[" not in html and "**" not in html


def test_categories_leads_to_the_main_pages_list_of_every_category(client):
    r = client.get("/categories", headers={EPISODE_HEADER: "ep-a"}, follow_redirects=True)
    assert r.status_code == 200
    assert 'id="categories-heading"' in r.text and 'href="/category/climates"' in r.text


def test_an_infobox_value_links_only_to_an_article_it_names_as_written(client):
    html = get(client, "/wiki/japan").text
    # The capital is an article's title; the internet domain ".jp" only shares a lookup key with an
    # alias ("JP", Jamaica Plain) once punctuation is dropped, and must stay plain text.
    assert '<a href="/wiki/tokyo"' in html
    assert '<th scope="row">Internet domain</th><td>.jp</td>' in html
    assert "/wiki/jamaica-plain" not in html
    # Accents still fold: "Bogota" as written links to the article titled "Bogotá".
    assert '<a href="/wiki/bogota"' in get(client, "/wiki/colombia").text


def test_every_internal_link_on_a_rich_page_leads_somewhere(client):
    html = get(client, "/wiki/new-york-city").text
    targets = {h for h in hrefs(html) if h.startswith(("/wiki/", "/category/"))}
    assert len(targets) > 15
    for target in sorted(targets):
        assert get(client, target).status_code == 200, target


@pytest.mark.parametrize("requested", ["Fuller_Building", "FLATIRON-BUILDING", "fuller building", "Flatiron"])
def test_titles_aliases_and_other_spellings_redirect_to_the_canonical_slug(client, requested):
    r = get(client, f"/wiki/{requested}")
    assert r.status_code == 302
    assert r.headers["location"].startswith("/wiki/flatiron-building?redirected_from=")
    page = get(client, r.headers["location"])
    assert "redirected from" in page.text


def test_missing_article_is_a_404_page_with_a_search_link(client, events):
    r = get(client, "/wiki/no-such-place-at-all", episode="ep-missing")
    assert r.status_code == 404
    assert 'href="/search?q=no-such-place-at-all&amp;fulltext=1"' in r.text
    [view] = events.of("ep-missing", "page_view")
    assert view["slug"] is None and view["missing"] == "no-such-place-at-all"


def test_article_page_view_event_names_the_slug(client, events):
    get(client, "/wiki/central-park", episode="ep-views")
    assert events.of("ep-views", "page_view") == [
        {"site": "wiki", "type": "page_view", "path": "/wiki/central-park", "slug": "central-park"}]


# ------------------------------------------------------------------ search
def test_exact_title_search_goes_straight_to_the_article(client, events):
    r = get(client, "/search", params={"q": "St. Patrick's Cathedral"}, episode="ep-go")
    assert r.status_code == 302 and r.headers["location"] == "/wiki/st-patricks-cathedral"
    [search] = events.of("ep-go", "search")
    assert search["went_to"] == "st-patricks-cathedral"


def test_full_text_search_ranks_and_highlights(client, events):
    r = get(client, "/search", params={"q": "triangular Burnham", "fulltext": "1"}, episode="ep-s")
    assert r.status_code == 200
    slugs = re.findall(r'<li><a href="/wiki/([^"]+)"', r.text)
    assert slugs[0] == "flatiron-building"
    assert "<mark>" in r.text
    [search] = events.of("ep-s", "search")
    assert search["query"] == "triangular Burnham" and search["results"] == len(slugs)
    assert search["top"][0] == "flatiron-building"


def test_title_words_outrank_passing_mentions(client):
    r = get(client, "/search", params={"q": "cheesesteak", "fulltext": "1"})
    slugs = re.findall(r'<li><a href="/wiki/([^"]+)"', r.text)
    assert slugs[0] == "philadelphia-cheesesteak" and len(slugs) > 2


def test_search_falls_back_to_any_word_when_no_article_has_all(client):
    r = get(client, "/search", params={"q": "omelette zzzqqq"})
    assert r.status_code == 200
    assert "showing articles with any of them" in r.text
    assert 'href="/wiki/omelette"' in r.text


def test_search_pages_through_results(client):
    first = get(client, "/search", params={"q": "street", "fulltext": "1"}).text
    second = get(client, "/search", params={"q": "street", "fulltext": "1", "offset": "20"}).text
    a = re.findall(r'<li><a href="/wiki/([^"]+)"', first)
    b = re.findall(r'<li><a href="/wiki/([^"]+)"', second)
    assert len(a) == 20 and b and not set(a) & set(b)
    assert "Next 20" in first and "Previous 20" in second


def test_empty_search_shows_the_form(client):
    r = get(client, "/search")
    assert r.status_code == 200 and 'name="q"' in r.text and "<ol" not in r.text


@pytest.mark.parametrize("query", [
    "'; DROP TABLE articles; --", "<script>alert(1)</script>", 'title:"x" OR body:* NEAR(a b)', "\"unbalanced",
    "NOT", "%00%27", "ünïcödé façade"])
def test_hostile_queries_are_plain_text(client, query):
    r = get(client, "/search", params={"q": query, "fulltext": "1"})
    assert r.status_code == 200
    assert "<script>alert" not in r.text
    # The index still works afterwards.
    assert 'href="/wiki/omelette"' in get(client, "/search", params={"q": "omelette folded", "fulltext": "1"}).text


def test_over_long_query_and_bad_offset_are_400_pages(client):
    r = get(client, "/search", params={"q": "a" * (MAX_QUERY_CHARS + 1)})
    assert r.status_code == 400 and "at most 200" in r.text
    for offset in ("-1", "abc", "99999999"):
        r = get(client, "/search", params={"q": "park", "offset": offset})
        assert r.status_code == 400 and "offset" in r.text


def test_over_long_article_name_is_a_400(client):
    assert get(client, "/wiki/" + "x" * 300).status_code == 400


def test_post_is_refused_without_a_traceback(client):
    r = client.post("/search", data={"q": "x"})
    assert r.status_code == 405 and "Traceback" not in r.text


# ------------------------------------------------------------------ random and reset
def test_random_is_deterministic_per_episode_and_restarts_after_reset(app, client):
    def walk(episode: str) -> list[str]:
        return [get(client, "/random", episode=episode).headers["location"] for _ in range(5)]

    first = walk("ep-rand-1")
    assert all(loc.startswith("/wiki/") for loc in first)
    assert len(set(first)) > 1
    assert walk("ep-rand-2") != first  # another episode, another sequence
    app.state.reset_episode("ep-rand-1")
    assert walk("ep-rand-1") == first
    assert get(client, first[0]).status_code == 200


# ------------------------------------------------------------------ categories
def test_category_page_lists_its_members(client):
    r = get(client, "/category/architectural-styles")
    assert r.status_code == 200
    assert 'href="/wiki/art-deco"' in r.text and 'href="/wiki/omelette"' not in r.text
    assert get(client, "/category/Architectural%20styles").status_code == 200
    missing = get(client, "/category/nothing-here")
    assert missing.status_code == 404 and "no category" in missing.text


# ------------------------------------------------------------------ markup safety and parser
def write(root: Path, rel: str, text: str) -> Path:
    path = root / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_article_text_cannot_inject_markup_and_dangling_links_go_to_search(tmp_path):
    write(tmp_path, "a/first-page.md", "---\ntitle: First Page\ncategory: Tests\n"
          'infobox: {"Note": "<b>bold?</b>"}\n---\nHello <script>x()</script> [[Second Page|next]] and [[Nowhere]].\n')
    write(tmp_path, "b/second-page.md", "---\ntitle: Second Page\ncategory: Tests\n---\n## Part\n- one\n- **two**\n")
    store.index.cache_clear()
    client = TestClient(create_app(SiteContext(), articles_dir=tmp_path))
    html = client.get("/wiki/first-page").text
    assert "<script>x()" not in html and "&lt;script&gt;" in html
    assert "<b>bold?</b>" not in html
    assert '<a href="/wiki/second-page" title="Second Page">next</a>' in html
    assert 'href="/search?q=Nowhere" title="Nowhere (page does not exist)" class="new"' in html
    assert "<li><b>two</b></li>" in client.get("/wiki/second-page").text
    assert [str(p) for p in store.check_articles(tmp_path)] == ["first-page: link [[Nowhere]] names no article"]


def test_clashing_slugs_titles_and_aliases_are_reported_not_fatal(tmp_path):
    write(tmp_path, "a/same.md", "---\ntitle: One\ncategory: T\naliases: [\"Shared\"]\n---\nx\n")
    write(tmp_path, "b/same.md", "---\ntitle: Two\ncategory: T\n---\nx\n")
    write(tmp_path, "b/other.md", "---\ntitle: One\ncategory: T\n---\nx\n")
    write(tmp_path, "b/third.md", "---\ntitle: Three\ncategory: T\naliases: [\"Shared\"]\n---\nx\n")
    store.index.cache_clear()
    problems = " | ".join(str(p) for p in store.check_articles(tmp_path))
    assert "reuses the slug" in problems
    assert "is also the title of" in problems
    assert "alias 'Shared' already names 'same'" in problems
    assert store.index(tmp_path).find("Shared").slug == "same"


@pytest.mark.parametrize("text, expected", [
    ("title: X\n---\nbody", "does not start with a '---'"),
    ("---\ntitle: X\ncategory: Y\nbody", "never closed"),
    ("---\ntitle: X\n---\nbody", "no 'category'"),
    ("---\ntitle: X\ncategory: Y\ncolour: red\n---\nbody", "unknown front-matter field 'colour'"),
    ("---\ntitle: X\ncategory: Y\ninfobox: {'a': 1}\n---\nbody", "'infobox' is not valid one-line JSON"),
    ("---\ntitle: X\ncategory: Y\ninfobox: {\"Height\": 87}\n---\nbody", "keys and values are strings"),
    ("---\ntitle: X\ncategory: Y\ncoordinates: {\"lat\": 95, \"lng\": 0}\n---\nbody", "'coordinates' must be"),
    ("---\ntitle: X\ncategory: Y\n---\n\n", "has no body"),
])
def test_format_errors_name_the_file_the_problem_and_the_fix(text, expected):
    with pytest.raises(ArticleFormatError) as info:
        parse_article(text, Path("articles/group/some-page.md"))
    message = str(info.value)
    assert "some-page.md" in message and expected in message and "Fix:" in message


def test_bad_file_names_are_refused():
    with pytest.raises(ArticleFormatError, match="not a valid slug"):
        parse_article("---\ntitle: X\ncategory: Y\n---\nbody", Path("Bad Name.md"))


def test_a_malformed_file_is_skipped_and_reported(tmp_path):
    write(tmp_path, "a/good.md", "---\ntitle: Good\ncategory: T\n---\nfine\n")
    write(tmp_path, "a/broken.md", "no front matter\n")
    store.index.cache_clear()
    built = store.index(tmp_path)
    assert [a.slug for a in built.articles] == ["good"]
    assert any("broken.md" in str(p) for p in built.problems)
