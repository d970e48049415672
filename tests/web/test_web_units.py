"""Browser-free tests: snapshot parsing, rendering, element references, URL policy, discovery, marks."""

from __future__ import annotations

import os
import stat

import pytest

from ewa_mcp.settings import load_settings
from ewa_mcp.envs.browser import chromium
from ewa_mcp.envs.browser.aria import parse_snapshot
from ewa_mcp.envs.browser.elements import (ElementRefError, ElementRegistry, IdRef, RoleNameRef, parse_element,
                                  resolve_role_name)
from ewa_mcp.envs.browser.tree_text import render_tree
from ewa_mcp.envs.browser.safety import BlockedUrlError, UrlPolicy, normalize_origin

SNAPSHOT = """\
- generic [active] [ref=e1] [box=8,8,1264,2193]:
  - banner [ref=e2] [box=8,8,1264,18]:
    - link "Go to page two" [ref=e3] [cursor=pointer] [box=8,8,98,17]:
      - /url: /p2
  - main [ref=e5] [box=8,47,1264,2153]:
    - heading "Hello" [level=1] [ref=e6] [box=8,47,1264,37]
    - paragraph [ref=e7] [box=8,106,1264,18]: Some text here.
    - 'link "Say: \\"hi\\"" [ref=e20] [box=8,120,50,17]'
    - textbox "Search" [ref=e10] [box=56,140,177,21]:
      - /placeholder: find
    - textbox "Code" [ref=e11] [box=56,170,177,21]: "R-17: a"
    - combobox "Diet" [ref=e12] [box=8,163,86,19]:
      - option "Any" [selected] [box=0,0,0,0]
      - option "Vegetarian" [box=0,0,0,0]
    - checkbox "Check me" [checked] [ref=e13] [box=102,164,13,13]
    - text: "line\\x01two"
    - button "Next" [disabled] [ref=e14] [box=186,162,43,21]
    - button "Next" [ref=e15] [box=186,900,43,21]
    - link "Far link" [ref=e16] [cursor=pointer] [box=8,2183,50,17]:
      - /url: /far
"""


def _ids(roots):
    registry = ElementRegistry()
    ids = {n.ref: registry.id_for(1, 0, n) for root in roots for n in root.walk() if n.ref}
    return registry, ids


def test_parse_snapshot_reads_roles_names_refs_boxes_props_and_escapes():
    roots = parse_snapshot(SNAPSHOT)
    nodes = {n.ref: n for root in roots for n in root.walk() if n.ref}
    assert nodes["e3"].role == "link" and nodes["e3"].name == "Go to page two"
    assert nodes["e3"].props["url"] == "/p2" and nodes["e3"].attrs["cursor"] == "pointer"
    assert nodes["e3"].box == (8, 8, 98, 17)
    assert nodes["e6"].attrs["level"] == "1"
    assert nodes["e7"].text == "Some text here."
    assert nodes["e20"].name == 'Say: "hi"'  # single-quoted key holding a JSON name
    assert nodes["e10"].props["placeholder"] == "find"
    assert nodes["e11"].text == "R-17: a"  # a quoted value containing ": "
    assert nodes["e13"].attrs["checked"] == "true"
    assert "line\x01two" in nodes["e5"].children
    options = [c for c in nodes["e12"].children]
    assert [o.name for o in options] == ["Any", "Vegetarian"] and options[0].ref is None
    assert nodes["e6"].parent is nodes["e5"]


def test_render_folds_layout_keeps_ids_and_states():
    roots = parse_snapshot(SNAPSHOT)
    _, ids = _ids(roots)
    tree = render_tree(roots, lambda n: ids[n.ref], title="P1", viewport=(1280, 720))
    lines = tree.text.splitlines()
    assert lines[0] == f"[{ids['e1']}] RootWebArea 'P1' focused: True"
    assert f"\t\t[{ids['e3']}] link 'Go to page two' url: /p2" in lines
    # a nameless paragraph folds into a StaticText that keeps the paragraph's id
    assert f"\t\t[{ids['e7']}] StaticText 'Some text here.'" in lines
    assert f"\t\t[{ids['e11']}] textbox 'Code' value: 'R-17: a'" in lines
    assert f"\t\t[{ids['e10']}] textbox 'Search' placeholder: 'find'" in lines
    assert f"\t\t[{ids['e13']}] checkbox 'Check me' checked: true" in lines
    assert f"\t\t[{ids['e14']}] button 'Next' disabled: True" in lines
    assert "\t\t\toption 'Any' selected: True" in lines
    assert not tree.truncated and tree.lines == tree.total_lines
    # marks: interactive elements inside the 1280x720 viewport only
    marked = {m.id for m in tree.marks}
    assert ids["e3"] in marked and ids["e10"] in marked and ids["e14"] in marked
    assert ids["e15"] not in marked and ids["e16"] not in marked and ids["e7"] not in marked


def test_render_viewport_only_and_budget():
    roots = parse_snapshot(SNAPSHOT)
    _, ids = _ids(roots)
    full = render_tree(roots, lambda n: ids[n.ref], title="P1", viewport=(1280, 720))
    seen = render_tree(roots, lambda n: ids[n.ref], title="P1", viewport=(1280, 720), viewport_only=True)
    assert "Far link" in full.text and "Far link" not in seen.text
    assert f"[{ids['e15']}]" not in seen.text and f"[{ids['e14']}]" in seen.text
    small = render_tree(roots, lambda n: ids[n.ref], title="P1", viewport=(1280, 720), max_chars=200)
    assert small.truncated and len(small.text) <= 200 and small.lines < small.total_lines
    assert full.text.startswith(small.text)


def test_parse_element_forms():
    assert parse_element("12") == IdRef(12)
    assert parse_element("[12]") == IdRef(12)
    assert parse_element(" [12] link 'Home'") == IdRef(12)
    assert parse_element("link 'Tomato Bruschetta'") == RoleNameRef("link", "Tomato Bruschetta")
    assert parse_element('button "Next"') == RoleNameRef("button", "Next")
    assert parse_element("link \"Mom's recipe\"") == RoleNameRef("link", "Mom's recipe")
    assert parse_element("button 'Next' #2") == RoleNameRef("button", "Next", 2)
    assert parse_element("combobox") == RoleNameRef("combobox", None)
    for bad in ("", "   ", "click the link", "link 'unterminated"):
        with pytest.raises(ElementRefError, match="12 or \\[12\\]"):
            parse_element(bad)


def test_resolve_role_name_exact_ambiguous_missing():
    roots = parse_snapshot(SNAPSHOT)
    _, ids = _ids(roots)
    nodes = [n for root in roots for n in root.walk()]
    assert resolve_role_name(RoleNameRef("link", "far LINK"), nodes, ids).ref == "e16"  # case-insensitive fallback
    with pytest.raises(ElementRefError) as ambiguous:
        resolve_role_name(RoleNameRef("button", "Next"), nodes, ids)
    assert "ambiguous" in str(ambiguous.value) and f"[{ids['e14']}]" in str(ambiguous.value)
    assert resolve_role_name(RoleNameRef("button", "Next", 2), nodes, ids).ref == "e15"
    with pytest.raises(ElementRefError, match="no link named 'Farm'.*Go to page two"):
        resolve_role_name(RoleNameRef("link", "Farm"), nodes, ids)
    with pytest.raises(ElementRefError, match="no slider on this page; roles present: .*button"):
        resolve_role_name(RoleNameRef("slider", "Volume"), nodes, ids)
    # options have no ref (not actionable), so they never match
    with pytest.raises(ElementRefError):
        resolve_role_name(RoleNameRef("option", "Any"), nodes, ids)


def test_registry_ids_are_never_reused_across_generations():
    roots = parse_snapshot(SNAPSHOT)
    registry = ElementRegistry()
    node = next(n for root in roots for n in root.walk() if n.ref == "e3")
    first = registry.id_for(1, 0, node)
    assert registry.id_for(1, 0, node) == first  # same page: stable
    later = registry.id_for(1, 1, node)  # same ref on the next document of the tab
    assert later != first
    assert registry.get(first).generation == 0 and registry.get(later).generation == 1


SITES = {"home": "http://127.0.0.1:8701", "recipes": "http://127.0.0.1:8702"}


def test_url_policy_resolves_site_forms():
    policy = UrlPolicy(SITES)
    assert policy.resolve("recipes:/recipe/r001") == "http://127.0.0.1:8702/recipe/r001"
    assert policy.resolve("home:") == "http://127.0.0.1:8701/"
    assert policy.resolve("http://127.0.0.1:8702/x?y=1") == "http://127.0.0.1:8702/x?y=1"
    assert policy.resolve("/search?q=egg", "http://127.0.0.1:8702/list") == "http://127.0.0.1:8702/search?q=egg"
    assert policy.resolve("about:blank") == "about:blank"
    assert policy.site_relative("http://127.0.0.1:8702/recipe/r1?x=1") == "recipes:/recipe/r1?x=1"
    assert policy.site_relative("http://127.0.0.1:9999/") is None


@pytest.mark.parametrize(
    ("url", "reason"),
    [
        ("file:///etc/passwd", "file: URLs are refused"),
        ("data:text/html,<h1>x</h1>", "data: URLs are refused"),
        ("javascript:alert(1)", "javascript: URLs are refused"),
        ("http://example.com/", "not one of the embedded sites"),
        ("http://127.0.0.1:9999/", "not one of the embedded sites"),
        ("http://localhost:8701/", "not one of the embedded sites"),
        ("http://169.254.169.254/latest/meta-data/", "link-local/cloud-metadata"),
        ("http://metadata.google.internal/", "link-local/cloud-metadata"),
        ("http://[fe80::1]/", "link-local/cloud-metadata"),
        ("shopping:/cart", "unknown site 'shopping'"),
        ("/search", "not on an embedded site"),
        ("example.com", "is not a URL"),
    ],
)
def test_url_policy_refuses_with_reason_and_lists_sites(url, reason):
    policy = UrlPolicy(SITES)
    with pytest.raises(BlockedUrlError) as refused:
        policy.resolve(url, "about:blank")
    assert reason in str(refused.value)
    assert "recipes:/ (http://127.0.0.1:8702)" in str(refused.value)


def test_the_browser_guard_bypasses_exactly_the_allowed_origins():
    """Chromium's proxy guard (chromium.py) lets through only the allowed origins, each matched on
    scheme, host and port; everything else, other loopback ports included, goes to the dead proxy."""
    policy = UrlPolicy(SITES, ["http://10.0.0.5:9000", "https://example.org"])
    info = chromium.ChromiumInfo(path="/usr/bin/chromium", source="explicit")
    args = chromium.BrowserService(info, allowed_origins=policy.allowed_origins).launch_args()
    bypass = next(a for a in args if a.startswith("--proxy-bypass-list=")).split("=", 1)[1].split(";")
    assert bypass == ["<-loopback>", "http://127.0.0.1:8701", "http://127.0.0.1:8702", "http://10.0.0.5:9000",
                      "https://example.org:443"]
    assert any(a.startswith("--proxy-server=http://127.0.0.1:") for a in args)
    assert chromium.bypass_rule("http://example.org") == "http://example.org:80"
    assert chromium.bypass_rule("http://[::1]:8000") == "http://[::1]:8000"


def test_allowlist_validation():
    assert normalize_origin("HTTP://Example.org:80/path") == "http://example.org"
    with pytest.raises(ValueError, match="link-local"):
        normalize_origin("http://169.254.169.254")
    with pytest.raises(ValueError, match="http\\(s\\) origin"):
        normalize_origin("ftp://files.example.org")


def test_find_chromium_explicit_path_errors_name_the_fix(tmp_path, monkeypatch):
    monkeypatch.delenv("EWA_CHROMIUM", raising=False)
    with pytest.raises(chromium.ChromiumNotFoundError, match="apt-get install chromium"):
        chromium.find_chromium(str(tmp_path / "missing-chrome"))
    fake = tmp_path / "chrome"
    fake.write_text("#!/bin/sh\n")
    fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setenv("EWA_CHROMIUM", str(fake))
    info = chromium.find_chromium(load_settings().chromium_path())
    assert info.path == str(fake) and info.source == "explicit"
    assert "--disable-background-networking" in info.launch_args()
    assert ("--no-sandbox" in info.launch_args()) == (os.geteuid() == 0)


def test_find_chromium_without_any_browser_says_how_to_install(monkeypatch, tmp_path):
    monkeypatch.delenv("EWA_CHROMIUM", raising=False)
    monkeypatch.setenv("PLAYWRIGHT_BROWSERS_PATH", str(tmp_path))
    monkeypatch.setattr(chromium, "SYSTEM_CANDIDATES", (str(tmp_path / "none"),))
    monkeypatch.setattr(chromium, "HEADLESS_SHELL_CANDIDATES", (str(tmp_path / "no-shell"),))
    monkeypatch.setattr(chromium.shutil, "which", lambda name: None)
    with pytest.raises(chromium.ChromiumNotFoundError, match="apt-get install chromium"):
        chromium.find_chromium()


def test_find_chromium_prefers_the_headless_shell_only_when_headless(monkeypatch, tmp_path):
    monkeypatch.delenv("EWA_CHROMIUM", raising=False)
    monkeypatch.setenv("PLAYWRIGHT_BROWSERS_PATH", str(tmp_path))  # no bundled build there
    shell, full = tmp_path / "chromium-headless-shell", tmp_path / "chromium"
    for exe in (shell, full):
        exe.write_text("#!/bin/sh\n")
        exe.chmod(0o755)
    monkeypatch.setattr(chromium, "HEADLESS_SHELL_CANDIDATES", (str(shell),))
    monkeypatch.setattr(chromium, "SYSTEM_CANDIDATES", (str(full),))
    assert chromium.find_chromium(headless=True).path == str(shell)
    assert chromium.find_chromium(headless=False).path == str(full)  # the shell cannot open a window
    shell.unlink()
    assert chromium.find_chromium(headless=True).path == str(full)


def test_find_chromium_prefers_playwright_bundled_build(monkeypatch, tmp_path):
    monkeypatch.delenv("EWA_CHROMIUM", raising=False)
    monkeypatch.setenv("PLAYWRIGHT_BROWSERS_PATH", str(tmp_path))
    revision = chromium._expected_revision()
    assert revision is not None
    shell = tmp_path / f"chromium_headless_shell-{revision}" / "chrome-headless-shell-linux64" / "chrome-headless-shell"
    shell.parent.mkdir(parents=True)
    shell.write_text("#!/bin/sh\n")
    shell.chmod(0o755)
    monkeypatch.setattr(chromium.platform, "machine", lambda: "x86_64")
    info = chromium.find_chromium()
    assert info.source == "playwright" and info.path == str(shell)
