"""Every browser action against a real Chromium and the fixture site (one browser for the module)."""

from __future__ import annotations

import http.server
import io
import threading

import pytest
from PIL import Image

from ewa_mcp.core.environment import EnvError
from ewa_mcp.envs.browser.som import colour_of

from .helpers import element_id, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


async def test_first_observation_is_webarena_text(web_services):
    env = await open_env(web_services)
    obs = await env.observe()
    assert obs.text.startswith("Tab 0 (current): Fixture catalogue — fixture:/")
    assert "[" in obs.text and "] RootWebArea 'Fixture catalogue' focused: True" in obs.text
    link = element_id(obs, "link", "Tomato Bruschetta")
    assert f"[{link}] link 'Tomato Bruschetta' url: /item/1" in obs.text
    assert "checkbox 'Favourites only' checked: false" in obs.text
    assert "button 'Unavailable' disabled: True" in obs.text
    assert obs.data["site_url"] == "fixture:/" and obs.data["title"] == "Fixture catalogue"
    assert obs.data["tabs"] == [{"index": 0, "title": "Fixture catalogue", "url": obs.data["url"],
                                 "site_url": "fixture:/", "active": True}]
    assert obs.images == []  # text mode
    again = await env.observe()
    assert element_id(again, "link", "Tomato Bruschetta") == link  # ids stable while the page lives
    await env.close()


async def test_click_navigates_and_old_ids_become_stale(web_services):
    env = await open_env(web_services)
    first = await env.observe()
    soup = element_id(first, "link", "Lentil Soup")
    page = await env.click(f"[{soup}]")
    assert page.data["site_url"] == "fixture:/item/2" and page.data["title"] == "Lentil Soup"
    with pytest.raises(EnvError, match="earlier page of this tab"):
        await env.click(str(element_id(first, "link", "Apple Crumble")))
    assert env.tabs[0].page.url.endswith("/item/2")  # the refused action changed nothing
    nxt = await env.click("link 'Next item'")  # role+name resolves on the page as it is now
    assert nxt.data["site_url"] == "fixture:/item/3"
    back = await env.go_back()
    assert back.data["site_url"] == "fixture:/item/2"
    fwd = await env.go_forward()
    assert fwd.data["site_url"] == "fixture:/item/3"
    with pytest.raises(EnvError, match="no later page"):
        await env.go_forward()
    state = await env.final_state()
    assert state["site_history"] == ["fixture:/", "fixture:/item/2", "fixture:/item/3", "fixture:/item/2",
                                     "fixture:/item/3"]
    assert state["tabs"] == [{"url": env.tabs[0].page.url, "title": "Apple Crumble", "site_url": "fixture:/item/3"}]
    assert state["active_tab"] == 0
    await env.close()


async def test_go_back_never_leaves_the_start_page_for_the_blank_tab(web_services):
    env = await open_env(web_services)
    with pytest.raises(EnvError, match="cannot go back"):
        await env.go_back()
    assert env.tabs[0].page.url.endswith("/")
    await env.close()


async def test_unknown_and_removed_elements_are_refused(web_services):
    env = await open_env(web_services)
    obs = await env.observe()
    with pytest.raises(EnvError, match="there is no element \\[99999\\]"):
        await env.click("99999")
    with pytest.raises(EnvError, match="cannot read the element reference"):
        await env.click("the soup link")
    done = element_id(obs, "button", "Mark done")
    after = await env.click(str(done))  # the button renames itself: a new element identity
    assert "button 'Done'" in after.text
    with pytest.raises(EnvError, match="no longer on the page"):
        await env.click(str(done))
    with pytest.raises(EnvError, match="ambiguous|no button named"):
        await env.click("button 'Mark done'")
    with pytest.raises(EnvError, match="is disabled"):
        await env.click("button 'Unavailable'")
    await env.close()


async def test_type_press_enter_and_press(web_services):
    env = await open_env(web_services)
    results = await env.type("textbox 'Search items'", "soup", press_enter=True)
    assert results.data["site_url"] == "fixture:/search?q=soup"
    assert "link 'Lentil Soup'" in results.text and "1 found" in results.text
    await env.go_back()
    typed = await env.type("textbox 'Search items'", "rice")
    assert "textbox 'Search items' focused: True value: 'rice'" in typed.text
    assert typed.data["site_url"] == "fixture:/"
    typed = await env.type("textbox 'Search items'", "egg")  # replaces, not appends
    assert "value: 'egg'" in typed.text
    pressed = await env.press("Enter")
    assert pressed.data["site_url"] == "fixture:/search?q=egg"
    with pytest.raises(EnvError, match="unknown key"):
        await env.press("Hyper+Q")
    await env.close()


async def test_type_refusals_leave_the_page_unchanged(web_services):
    env = await open_env(web_services)
    with pytest.raises(EnvError, match="does not accept text.*textbox 'Search items'"):
        await env.type("button 'Save'", "hello")
    with pytest.raises(EnvError, match="read-only"):
        await env.type("textbox 'Code'", "X-1")
    obs = await env.observe()
    assert "textbox 'Code' value: 'R-17'" in obs.text and obs.data["site_url"] == "fixture:/"


async def test_type_into_what_takes_no_text_is_refused_naming_it(web_services):
    # play-test: on the map's form a type into a label's id filled the field it labels, and one into a
    # button was reported as doing nothing. Every control that takes no text is refused by name, with
    # what to do instead, and the page is left as it was.
    env = await open_env(web_services, "fixture:/form")
    obs = await env.observe()
    typed = await env.type(str(element_id(obs, "StaticText", "Your name")), "Ada")
    assert "textbox 'Your name' focused: True value: 'Ada'" in typed.text  # a label's text types into its field
    fields = r"editable elements here: \[\d+\] textbox 'Your name', \[\d+\] spinbutton 'Quantity'"
    refused = {
        ("button", "Go ahead"): rf"button 'Go ahead' is a button and does not accept text; type into a text field "
                                rf"instead — {fields}; press a button with browser_click",
        ("StaticText", "Go ahead"): rf"StaticText 'Go ahead' is the label of a button 'Go ahead' and does not "
                                    rf"accept text; .*{fields}",
        ("button", "Send form"): r"button 'Send form' is a button and does not accept text",
        ("radio", "Small size"): r"radio 'Small size' is a radio button and does not accept text; choose it "
                                 r"with browser_click",
        ("StaticText", "I agree"): r"StaticText 'I agree' is the label of a checkbox 'I agree' and does not accept "
                                   r"text; tick or untick it with browser_click",
        ("checkbox", "I agree"): r"checkbox 'I agree' is a checkbox and does not accept text",
        ("spinbutton", "Quantity"): r"spinbutton 'Quantity' takes a number only, and 'two' is not one",
    }
    for (role, name), message in refused.items():
        ref = element_id(obs, role, name)
        with pytest.raises(EnvError, match=rf"^\[{ref}\] {message}"):
            await env.type(f"[{ref}]", "two", press_enter=True)
    assert "value: '3'" in (await env.type("spinbutton 'Quantity'", "3")).text
    after = await env.observe()
    assert after.data["site_url"] == "fixture:/form"
    assert "textbox 'Your name' value: 'Ada'" in after.text
    assert "radio 'Small size' checked: false" in after.text and "checkbox 'I agree' checked: false" in after.text
    await env.close()


async def test_type_chooses_drop_down_options(web_services):
    env = await open_env(web_services)
    chosen = await env.type("combobox 'Diet'", "vegan")
    assert "option 'Vegan' selected: True" in chosen.text
    with pytest.raises(EnvError, match="without an option 'Keto'.*'Vegetarian'"):
        await env.type("combobox 'Diet'", "Keto")
    checked = await env.click("checkbox 'Favourites only'")
    assert "checkbox 'Favourites only' focused: True checked: true" in checked.text
    await env.close()


async def test_observation_waits_for_fetch_results(web_services):
    env = await open_env(web_services)
    first = await env.click("button 'Count click'")  # the API answers after 50 ms
    assert "StaticText 'Clicked 1 times'" in first.text
    second = await env.click("button 'Count click'")
    assert "StaticText 'Clicked 2 times'" in second.text
    await env.close()


async def test_hover_opens_a_hover_menu(web_services):
    env = await open_env(web_services)
    assert "Hidden dessert" not in (await env.observe()).text
    hovered = await env.hover("button 'More'")
    assert "link 'Hidden dessert'" in hovered.text
    await env.close()


async def test_scroll_moves_the_viewport(web_services):
    env = await open_env(web_services, "fixture:/long")
    top = await env.snapshot(viewport_only=True)
    assert "Bottom link" not in top.text and "visible part" in top.text
    assert top.data["scroll"]["y"] == 0
    with_notice = await env.scroll("up")
    assert "already at the top" in with_notice.text
    for _ in range(4):
        obs = await env.scroll("down")
    assert obs.data["scroll"]["y"] > 1500
    bottom = await env.snapshot(viewport_only=True)
    assert "link 'Bottom link'" in bottom.text and "Top of the long page" not in bottom.text
    clicked = await env.click("link 'Bottom link'")
    assert clicked.data["site_url"] == "fixture:/item/5"
    await env.close()


async def test_tabs_new_focus_close_and_popups(web_services):
    env = await open_env(web_services)
    opened = await env.new_tab("fixture:/item/1")
    assert [t["site_url"] for t in opened.data["tabs"]] == ["fixture:/", "fixture:/item/1"]
    assert opened.data["active_tab"] == 1 and "Tab 1 (current): Tomato Bruschetta" in opened.text
    first_tab_link = element_id(await env.tab_focus(0), "link", "Potato Salad")
    await env.tab_focus(1)
    with pytest.raises(EnvError, match="on tab \\[0\\].*browser_tab_focus\\(0\\)"):
        await env.click(str(first_tab_link))
    with pytest.raises(EnvError, match="no tab \\[5\\]; the open tabs are 0 to 1"):
        await env.tab_focus(5)
    closed = await env.close_tab()
    assert len(closed.data["tabs"]) == 1 and closed.data["active_tab"] == 0
    with pytest.raises(EnvError, match="only tab"):
        await env.close_tab()
    popup = await env.click("link 'Soup in a new tab'")  # target=_blank: the new tab is current at once
    assert popup.data["active_tab"] == 1 and popup.data["site_url"] == "fixture:/item/2"
    assert "opened a new tab" in popup.text
    await env.tab_focus(0)
    scripted = await env.click("button 'Open rice'")  # window.open
    assert scripted.data["active_tab"] == 2 and scripted.data["site_url"] == "fixture:/item/4"
    blank = await env.new_tab()
    assert blank.data["url"] == "about:blank" and len(blank.data["tabs"]) == 4
    with pytest.raises(EnvError, match="refused"):
        await env.new_tab("http://example.com/")
    assert len(env.tabs) == 4
    await env.close()


async def test_goto_forms_and_refusals(web_services, fixture_sites):
    env = await open_env(web_services)
    assert (await env.goto("fixture:/item/3")).data["title"] == "Apple Crumble"
    assert (await env.goto("/item/4")).data["site_url"] == "fixture:/item/4"
    home = await env.goto(fixture_sites.urls["home"] + "/")
    assert home.data["site_url"] == "home:/"
    for url, reason in [("file:///etc/passwd", "file: URLs are refused"), ("data:text/html,hi", "data: URLs"),
                        ("javascript:alert(1)", "javascript: URLs"),
                        ("https://example.com/", "not one of the embedded"),
                        ("http://169.254.169.254/latest/meta-data/", "link-local"), ("wiki2:/x", "unknown site")]:
        with pytest.raises(EnvError, match=reason):
            await env.goto(url)
        assert env.tabs[0].page.url == fixture_sites.urls["home"] + "/"
    await env.close()


async def test_links_and_redirects_off_site_are_refused_and_page_kept(web_services, fixture_sites):
    env = await open_env(web_services)
    start = env.tabs[0].page.url
    for link, target in [("External site", "http://example.com/"), ("Redirect out", "http://example.com/landing"),
                         ("Metadata", "http://169.254.169.254/latest/meta-data/")]:
        with pytest.raises(EnvError, match="refused.*the page is unchanged") as refused:
            await env.click(f"link '{link}'")
        assert target in str(refused.value)
        assert env.tabs[0].page.url == start
        assert len(env.tabs) == 1
    obs = await env.observe()
    assert obs.data["title"] == "Fixture catalogue"
    # Sub-resources from elsewhere are blocked and reported; the page itself loads.
    offsite = await env.goto("fixture:/offsite")
    assert offsite.data["title"] == "Off-site resources"
    assert "a request to http://example.com/tracker.png was blocked" in offsite.text
    assert "http://169.254.169.254/pixel.png was blocked" in offsite.text
    state = await env.final_state()
    assert {"http://example.com/tracker.png", "http://169.254.169.254/pixel.png", "http://example.com/",
            "http://example.com/landing", "http://169.254.169.254/latest/meta-data/"} <= set(state["blocked"])
    await env.close()


async def test_other_loopback_services_are_unreachable_from_the_pages(web_services):
    """Only the sites' own ports are reachable: a service listening on another loopback port (this
    server's HTTP port, anything local) gets no request from a page's script, image or link."""
    hits: list[str] = []

    class Counting(http.server.BaseHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802 - the stdlib's name
            hits.append(self.path)
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
            self.end_headers()
            self.wfile.write(b"<title>local service</title>")

        def log_message(self, *args: object) -> None:
            pass

    service = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Counting)
    threading.Thread(target=service.serve_forever, daemon=True).start()
    port = service.server_address[1]
    env = await open_env(web_services)
    try:
        start = env.tabs[0].page.url
        for url in (f"http://127.0.0.1:{port}/fetch", f"http://localhost:{port}/fetch"):
            reached = await env.tabs[0].page.evaluate(
                "url => fetch(url, {mode: 'no-cors'}).then(() => true, () => false)", url)
            assert reached is False, url
        await env.tabs[0].page.evaluate(
            """port => {
                const img = document.createElement('img'); img.src = `http://127.0.0.1:${port}/pixel.png`;
                const a = document.createElement('a'); a.href = `http://127.0.0.1:${port}/page`;
                a.textContent = 'Local service'; document.body.append(img, a);
            }""", port)
        with pytest.raises(EnvError, match="refused.*the page is unchanged"):
            await env.click("link 'Local service'")
        assert env.tabs[0].page.url == start and len(env.tabs) == 1
        assert hits == []
        state = await env.final_state()
        assert {f"http://127.0.0.1:{port}/fetch", f"http://127.0.0.1:{port}/pixel.png",
                f"http://127.0.0.1:{port}/page"} <= set(state["blocked"])
        assert state["history"] == [start]  # stepping back from the refused page is no new visit
        assert (await env.observe()).data["title"] == "Fixture catalogue"
    finally:
        await env.close()
        service.shutdown()


async def test_downloads_and_dialogs_are_handled_and_reported(web_services):
    env = await open_env(web_services)
    dl = await env.click("link 'Get the price list'")
    assert "download (prices.csv" in dl.text and "nothing was saved" in dl.text
    assert dl.data["site_url"] == "fixture:/"
    alert = await env.click("button 'Save'")
    assert "dialog (alert): 'Saved!'" in alert.text
    assert alert.data["notices"] and (await env.observe()).data["notices"] == []  # notices are shown once
    await env.close()


async def test_snapshot_budget_and_screenshot_marks(web_services):
    env = await open_env(web_services)
    small = await env.snapshot(max_chars=500)
    assert small.data["truncated"] and "[truncated:" in small.text and len(small.data["tree"]) <= 500
    shot = await env.screenshot()
    assert len(shot.images) == 1
    image = Image.open(io.BytesIO(shot.images[0]))
    assert image.format == "PNG" and image.size == (1280, 720)
    assert shot.data["marks"] >= 10
    # The mark of a link is a box in its colour around the link, just outside it (checked on its right
    # edge), so it hides nothing of the link itself.
    link = element_id(shot, "link", "Tomato Bruschetta")
    node = next(n for n in env.tabs[0].nodes if env.tabs[0].ref_ids.get(n.ref or "") == link)
    x, y, w, h = node.box
    colour = tuple(int(colour_of(link)[i:i + 2], 16) for i in (1, 3, 5))
    assert image.convert("RGB").getpixel((x + w + 2, y + h // 2)) == colour
    assert image.convert("RGB").getpixel((x + w - 1, y + h // 2)) != colour
    # The overlay existed only for the screenshot.
    assert await env.tabs[0].page.evaluate("document.querySelectorAll('ewa-marks').length") == 0
    await env.close()
    vision = await open_env(web_services, options={"observation": "vision"})
    obs = await vision.observe()
    assert len(obs.images) == 1 and "Marked elements" in obs.text and "RootWebArea" not in obs.text
    assert f"[{element_id(obs, 'link', 'Tomato Bruschetta')}] link 'Tomato Bruschetta'" in obs.text
    await vision.close()


async def test_episode_header_reaches_the_sites(web_services, fixture_sites):
    env = await open_env(web_services, "fixture:/counter", episode_id="ep-header-check")
    obs = await env.observe()
    assert "Episode ep-header-check visit 1" in obs.text
    assert ("ep-header-check", {"site": "fixture", "type": "page_view", "path": "/"}) not in fixture_sites.events
    await env.goto("fixture:/")
    assert ("ep-header-check", {"site": "fixture", "type": "page_view", "path": "/"}) in fixture_sites.events
    await env.close()
