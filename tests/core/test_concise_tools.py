"""The agent plane's concise tool definitions and compact structured content (issue 29: fewer tokens)."""

from __future__ import annotations

import json

import pytest
from mcp import Client

from ewa_mcp.bound import BoundServer, concise_schema, first_sentence
from ewa_mcp.envs.browser.incremental import tree_changes
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio
TASK = "geo-0018-baseline"  # embodied only: no browser needed


def test_first_sentence_keeps_abbreviations_brackets_and_quotes_whole():
    assert first_sentence("Press a key, e.g. Enter or Tab. Keys are sent to the focused element.") == \
        "Press a key, e.g. Enter or Tab."
    assert first_sentence("Type (replacing it. Really) into a field. More here.") == "Type (replacing it. Really) into a field."
    assert first_sentence("Switch the environment; returns its observation.") == "Switch the environment."
    assert first_sentence("One sentence only") == "One sentence only"


def test_concise_schema_drops_titles_limits_and_null_options_but_keeps_types_enums_and_required():
    schema = {"title": "fArguments", "type": "object", "additionalProperties": False, "required": ["target"],
              "properties": {
                  "target": {"title": "Target", "enum": ["web", "embodied"], "type": "string"},
                  "answer": {"anyOf": [{"maxLength": 4000, "type": "string"}, {"type": "null"}], "default": None,
                             "title": "Answer", "description": "your answer, or a question's value; never a hedge"},
                  "count": {"type": "integer", "minimum": 0, "maximum": 9, "default": 1}}}
    assert concise_schema(schema) == {
        "type": "object", "required": ["target"],
        "properties": {"target": {"enum": ["web", "embodied"], "type": "string"},
                       "answer": {"type": "string", "description": "your answer"},
                       "count": {"type": "integer"}}}


def test_tree_changes_sends_only_what_changed_and_falls_back_to_the_whole_page():
    page = [f"[{i}] paragraph 'line number {i} of a long recipe page'" for i in range(40)]
    after = page[:20] + ["[99] paragraph 'Step 2: fold in the egg whites'"] + page[21:]
    changes = tree_changes(page, after)
    assert changes is not None
    assert "+ [99] paragraph 'Step 2: fold in the egg whites'" in changes
    assert f"@ after: {page[19]}" in changes and "- 1 line removed" in changes
    assert "line number 5 " not in changes  # the unchanged lines are not resent
    assert tree_changes(page, page) == "(no change since your last observation of this page)"
    assert tree_changes(None, after) is None  # nothing read before: the whole page
    assert tree_changes(page, [f"[{i}] link 'another site {i}'" for i in range(40)]) is None  # all changed


async def test_bound_tools_are_concise_and_the_full_descriptions_stay_available(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        catalogue = {t.name: t for t in await full.list_tools()}
        concise = BoundServer(full, task_id=TASK)
        await concise.start()
        verbose = BoundServer(full, task_id=TASK, descriptions="full")
        await verbose.start()
        short = {t.name: t for t in await concise.list_tools()}
        long = {t.name: t for t in await verbose.list_tools()}
        assert set(short) == set(long)  # same tools, same names
        assert "geo_move" in short and "kitchen_open" not in short
        size = len(json.dumps([{"d": t.description, "s": t.input_schema} for t in short.values()]))
        assert size < 0.6 * len(json.dumps([{"d": t.description, "s": t.input_schema} for t in long.values()]))
        assert long["finish_episode"].description == catalogue["finish_episode"].description
        assert short["finish_episode"].description == \
            "End the episode, with your answer when the task asks a question."
        for tool in short.values():
            assert "title" not in json.dumps(tool.input_schema), tool.name
            assert tool.output_schema == catalogue[tool.name].output_schema  # clients still validate results
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
    with pytest.raises(ValueError, match="'concise' or 'full'"):
        BoundServer(full, task_id=TASK, descriptions="short")  # type: ignore[arg-type]


async def test_structured_content_is_compact_for_bound_agents_and_full_when_asked(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        async with Client(BoundServer(full, task_id=TASK)) as client:
            result = await client.call_tool("geo_look", {"direction": "north"})
            text = result.content[0].text
            assert set(result.structured_content["observation"]) <= {"kind"}  # the text carries the observation
            assert result.structured_content["steps"] == 1
            assert len(json.dumps(result.structured_content)) <= len(text)
        async with Client(BoundServer(full, task_id=TASK, options={"structured": "full"})) as client:
            result = await client.call_tool("geo_look", {"direction": "north"})
            assert len(result.structured_content["observation"]) > 1
        # The control plane keeps its default: clients that read the observation's data still get it.
        started = await full.call_tool("start_episode", {"task_id": TASK})
        assert len(started.structured_content["observation"]) > 1
        compact = await full.call_tool("start_episode", {"task_id": TASK, "options": {"structured": "compact"}})
        assert set(compact.structured_content["observation"]) <= {"kind"}
        with pytest.raises(Exception, match="'full' or 'compact'"):
            await full.call_tool("start_episode", {"task_id": TASK, "options": {"structured": "tiny"}})
    finally:
        await episodes.aclose()
        await episodes.services.aclose()


def test_tree_changes_on_a_new_document_says_how_far_the_ids_of_unchanged_elements_moved():
    before = ["[10] heading 'Toast'", "[11] StaticText 'Step 1: slice the bread.'", "[12] link 'Next step'",
              "[13] link 'Shop'"] + [f"[{20 + i}] StaticText 'ingredient {i}'" for i in range(20)]
    after = ["[60] heading 'Toast'", "[61] StaticText 'Step 2: toast the bread.'", "[62] link 'Previous step'",
             "[63] link 'Next step'", "[64] link 'Shop'"] + [f"[{71 + i}] StaticText 'ingredient {i}'" for i in range(20)]
    changes = tree_changes(before, after)
    assert changes is not None
    assert changes.startswith("(a new document: the ids of the unchanged elements are 50 higher")
    assert "+ [62] link 'Previous step'" in changes
    assert "(ids of the unchanged elements below: 51 higher than before)" in changes
    scrambled = ["[60] heading 'Toast'", "[99] StaticText 'Step 1: slice the bread.'"] + after[2:]
    assert tree_changes(before[:2] + before[2:], scrambled[:2] + before[2:]) is None  # uneven: whole page
