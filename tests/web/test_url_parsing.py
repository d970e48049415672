"""URLs are read the way Chromium reads them (WHATWG), not the way urllib does: the policy's
verdict, the URL the browser is given, and Chromium's own navigation must agree."""

from __future__ import annotations

from urllib.parse import urlsplit

import pytest

from ewa_mcp.core.environment import EnvError
from ewa_mcp.envs.browser.chromium import chromium_service
from ewa_mcp.envs.browser.safety import BlockedUrlError, UrlPolicy, parse_url

from .helpers import open_env

P = 8702
POLICY = UrlPolicy({"home": "http://127.0.0.1:8701", "recipes": f"http://127.0.0.1:{P}"})

# (written, what the browser loads, or None when refused, a word of the refusal)
ALLOWED = [
    (f"http://127.1:{P}/", f"http://127.0.0.1:{P}/"),  # IPv4 shorthand
    (f"http://2130706433:{P}/a", f"http://127.0.0.1:{P}/a"),  # one 32-bit number
    (f"http://0x7f.0.0.1:{P}/", f"http://127.0.0.1:{P}/"),  # hexadecimal part
    (f"http://127.0.0.1.:{P}/", f"http://127.0.0.1:{P}/"),  # trailing dot
    (f"HTTP://127.0.0.1:{P}/R", f"http://127.0.0.1:{P}/R"),  # case of the scheme
    (f"http://%31%32%37.0.0.1:{P}/", f"http://127.0.0.1:{P}/"),  # percent-encoded host
    (f"ht\ttp://127.0.0.1:{P}/", f"http://127.0.0.1:{P}/"),  # tab stripped
    (f"http://127.0.0.1:{P}/a\nb", f"http://127.0.0.1:{P}/ab"),  # newline stripped
    (f"http:\\\\127.0.0.1:{P}\\item", f"http://127.0.0.1:{P}/item"),  # backslashes are slashes
    (f"http://127.0.0.1:{P}\\@example.com/", f"http://127.0.0.1:{P}/@example.com/"),  # '@' after a path '\'
]
REFUSED = [
    (f"http://x\\@127.0.0.1:{P}/", "host 'x'"),  # urllib: host 127.0.0.1; a browser: host x, path /@127...
    (f"http://127.0.0.1:{P}@example.com/", "host 'example.com'"),
    (f"http://user:pw@127.0.0.1:{P}/", "user name or password"),
    ("http://0251.0376.0251.0376/", "link-local/cloud-metadata"),  # octal 169.254.169.254
    ("http://[::ffff:169.254.169.254]/", "link-local/cloud-metadata"),
    ("http://metadata.google.internal./", "link-local/cloud-metadata"),
    ("http://169.254.169.254.:80/", "link-local/cloud-metadata"),
    (f"http://127.0.0.1:{P}0000/", "not a valid URL"),  # port out of range
    ("http://exa mple.com/", "not a valid URL"),
]


@pytest.mark.parametrize(("url", "loads"), ALLOWED)
def test_forms_of_an_embedded_site_resolve_to_what_the_browser_loads(url, loads):
    assert POLICY.resolve(url) == loads


@pytest.mark.parametrize(("url", "reason"), REFUSED)
def test_forms_that_leave_the_sites_are_refused_with_the_reason(url, reason):
    with pytest.raises(BlockedUrlError) as refused:
        POLICY.resolve(url)
    assert reason in str(refused.value) and "recipes:/ (http://127.0.0.1:8702)" in str(refused.value)


def test_urllib_disagrees_on_these_forms():
    """Why a WHATWG parser: urllib reads the host of the cases above differently."""
    assert urlsplit(f"http://x\\@127.0.0.1:{P}/").hostname == "127.0.0.1"
    assert urlsplit(f"http://127.1:{P}/").hostname == "127.1"
    assert urlsplit(f"http://127.0.0.1:{P}\\@example.com/").hostname == "example.com"


def test_paths_resolve_against_the_current_page_as_a_browser_does():
    here = f"http://127.0.0.1:{P}/list"
    assert POLICY.resolve("/search?q=egg", here) == f"http://127.0.0.1:{P}/search?q=egg"
    for path in ("/\\example.com/x", "/\\/example.com/"):  # a browser reads both as //example.com
        with pytest.raises(BlockedUrlError, match="example.com"):
            POLICY.resolve(path, here)


def test_site_relative_names_use_the_same_parser():
    assert POLICY.site_relative(f"http://127.1:{P}/r?x=1#n") == "recipes:/r?x=1#n"
    assert POLICY.site_relative(f"http://x\\@127.0.0.1:{P}/") is None
    assert POLICY.site_relative(f"http://u@127.0.0.1:{P}/") is None


# ----------------------------------------------------------------------------- against Chromium
@pytest.mark.anyio
@pytest.mark.browser
async def test_chromium_navigates_where_the_policy_reads(web_services):
    """Chromium is asked to open each form in a context where every request is recorded and
    aborted: the URL it requests is the one the policy parsed, and its origin is allowed exactly
    when the policy allows the URL."""
    service = await web_services.get("chromium", chromium_service)
    context = await (await service.browser()).new_context()
    requested: list[str] = []

    async def record(route):
        requested.append(route.request.url)
        await route.abort()

    await context.route("**/*", record)
    page = await context.new_page()
    try:
        for url in [u for u, _ in ALLOWED] + [u for u, reason in REFUSED if "valid URL" not in reason]:
            requested.clear()
            try:
                await page.goto(url, timeout=5000)
            except Exception:
                pass  # every request is aborted
            assert requested, url
            assert requested[0] == parse_url(url).href, url
            chromium_origin = parse_url(requested[0])
            reaches_site = (f"{chromium_origin.protocol}//{chromium_origin.host}" in POLICY.allowed_origins
                            and not chromium_origin.username)
            assert reaches_site == POLICY.is_allowed(url), url
    finally:
        await context.close()


@pytest.mark.anyio
@pytest.mark.browser
async def test_refused_forms_open_no_tab_and_accepted_ones_open_the_site(web_services, fixture_sites):
    env = await open_env(web_services)
    port = urlsplit(fixture_sites.urls["fixture"]).port
    for url, reason in [(f"http://x\\@127.0.0.1:{port}/", "host 'x'"),
                        ("fixture:/redirect-out", "led to http://example.com/landing, which is refused")]:
        with pytest.raises(EnvError, match=reason):
            await env.new_tab(url)
        assert len(env.tabs) == 1 and env.active == 0  # no tab reports a page it did not open
        with pytest.raises(EnvError, match="refused"):
            await env.goto(url)
        assert env.tabs[0].page.url == fixture_sites.urls["fixture"] + "/"
    obs = await env.observe()
    assert "Tab 1" not in obs.text and "refused" not in obs.text  # the refusal is not repeated as a notice
    with pytest.raises(EnvError, match="example.com"):
        await env.goto("/\\example.com/")
    opened = await env.new_tab(f"http://127.1:{port}/item/1")
    assert opened.data["site_url"] == "fixture:/item/1" and opened.data["title"] == "Tomato Bruschetta"
    await env.close()
