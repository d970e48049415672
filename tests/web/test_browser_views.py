"""What each browser tool shows in each observation mode, and the tab header after navigating."""

from __future__ import annotations

import pytest

from .helpers import element_id, open_env

pytestmark = [pytest.mark.anyio, pytest.mark.browser]


def _shows_tree(obs) -> bool:
    # After an action on a page already read, the text holds the tree's changes (web_incremental, the default);
    # the structured data always holds the whole tree.
    shown = "Accessibility tree (" in obs.text or "Accessibility tree, changes since your last observation" in obs.text
    return shown and obs.data["tree"] is not None and "RootWebArea" in obs.data["tree"]


def _shows_marks(obs) -> bool:
    return "Marked elements (see the screenshot):" in obs.text and "link 'Tomato Bruschetta'" in obs.text


@pytest.mark.parametrize("mode", ["text", "vision", "both"])
async def test_each_view_shows_what_its_tool_says_in_every_mode(web_services, mode):
    env = await open_env(web_services, options={"observation": mode})
    # Actions and get_observation follow the mode.
    for obs in (await env.observe(), await env.scroll("down")):
        assert len(obs.images) == (0 if mode == "text" else 1)
        assert _shows_tree(obs) == (mode != "vision")
        assert _shows_marks(obs) == (mode == "vision")
        if mode == "vision":  # the mode shows no tree, not even in the structured data
            assert obs.data["tree"] is None and "RootWebArea" not in obs.text
    # browser_snapshot is the tree and never an image; browser_screenshot the image and never the tree.
    snap = await env.snapshot()
    assert snap.images == [] and _shows_tree(snap) and not _shows_marks(snap)
    assert "Accessibility tree (whole page)" in snap.text and snap.data["tree"] in snap.text  # always whole
    shot = await env.screenshot()
    assert len(shot.images) == 1 and _shows_marks(shot) and not _shows_tree(shot)
    assert shot.data["tree"] is None and "RootWebArea" not in shot.text
    await env.close()


@pytest.mark.parametrize("mode", ["text", "vision"])
async def test_tab_header_names_the_page_now_shown(web_services, mode):
    env = await open_env(web_services, options={"observation": mode})
    start = await env.observe()
    assert start.text.startswith("Tab 0 (current): Fixture catalogue — fixture:/\n")
    clicked = await env.click(str(element_id(start, "link", "Tomato Bruschetta")))
    assert clicked.text.startswith("Tab 0 (current): Tomato Bruschetta — fixture:/item/1\n")
    assert clicked.data["tabs"][0]["title"] == clicked.data["title"] == "Tomato Bruschetta"
    went = await env.goto("fixture:/item/3")
    assert went.text.startswith("Tab 0 (current): Apple Crumble — fixture:/item/3\n")
    back = await env.go_back()
    assert back.text.startswith("Tab 0 (current): Tomato Bruschetta — fixture:/item/1\n")
    opened = await env.new_tab("fixture:/item/2")
    assert "Tab 0: Tomato Bruschetta — fixture:/item/1\nTab 1 (current): Lentil Soup — fixture:/item/2\n" in opened.text
    await env.close()
