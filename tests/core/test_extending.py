"""docs/extending.md made true: a domain added as one package plus one registration, and a kitchen action
added through the action table only, both exercised end to end through a real MCP client."""

from __future__ import annotations

import dataclasses
import json

import pytest
from mcp import Client
from pydantic import BaseModel, Field

from ewa_mcp.core import registry
from ewa_mcp.graders import grade_run
from ewa_mcp.envs.kitchen.actions import TABLE, KitchenAction
from ewa_mcp.envs.kitchen.commands import parse_command
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.taskgen import generate_all
from ewa_mcp.core.taskmodel import Task, TaskStore, export_json_schema

from .lamp_domain import DOMAIN

pytestmark = pytest.mark.anyio


def text_of(result) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


@pytest.fixture
def lighting():
    registry.register_domain(DOMAIN)
    yield DOMAIN
    registry.unregister_domain(DOMAIN.name)


def lamp_task(**changes) -> dict:
    task = {"id": "lamp-x", "domain": "lighting", "intent": "lamp", "step_limit": 5,
            "start": {"environment": "embodied", "embodied": {"kind": "lamp", "lit": False}},
            "embodied_goals": [{"kind": "lamp_lit", "lit": True}]}
    return {**task, **changes}


def test_an_unregistered_domain_its_start_and_goal_kinds_are_refused():
    with pytest.raises(ValueError, match="unknown domain 'lighting'"):
        Task.model_validate(lamp_task())
    with pytest.raises(ValueError, match="unknown embodied environment 'lamp'"):
        Task.model_validate(lamp_task(domain="demo"))


def test_the_registration_line_loads_a_domain_package_on_first_use(monkeypatch):
    from . import lamp_domain

    monkeypatch.setattr(registry, "DOMAIN_PACKAGES",
                        [*registry.DOMAIN_PACKAGES, f"{lamp_domain.__name__}:DOMAIN"])  # the one line
    monkeypatch.setattr(registry, "_loaded", False)
    monkeypatch.setattr(registry, "_registered", [])
    assert registry.domain_names()[-1] == "lighting" and registry.goal_check("lamp_lit") is not None
    assert Task.model_validate(lamp_task()).environment_names() == {"embodied": "lamp"}
    assert "ewa_mcp.envs.browser.tools" in registry.tool_groups() and registry.tool_groups()[-1].endswith(".tools")


def test_a_registered_domain_validates_its_tasks_but_not_typos(lighting):
    Task.model_validate(lamp_task())
    with pytest.raises(ValueError, match="unknown embodied goal kind 'lamp_lt'"):
        Task.model_validate(lamp_task(embodied_goals=[{"kind": "lamp_lt"}]))
    with pytest.raises(ValueError, match="already registered"):
        registry.register_domain(DOMAIN)
    assert "lighting" in registry.domain_names() and registry.environments()["lamp"].side == "embodied"


def test_a_registered_worlds_task_models_are_read_as_a_built_in_worlds_are(lighting):
    from .lamp_domain.goals import LampLit, LampStart

    task = Task.model_validate(lamp_task())
    assert isinstance(task.start.embodied, LampStart) and task.start.embodied.lit is False
    assert isinstance(task.embodied_goals[0], LampLit)
    assert Task.model_validate(task.model_dump(mode="json")) == task
    # Typed: a wrong value or an unknown field is refused where it is, as a kitchen start's would be.
    with pytest.raises(ValueError, match=r"start\.embodied\.lamp\.lit"):
        Task.model_validate(lamp_task(start={"environment": "embodied", "embodied": {"kind": "lamp", "lit": "maybe"}}))
    with pytest.raises(ValueError, match=r"embodied_goals\.0\.lamp_lit\.glow"):
        Task.model_validate(lamp_task(embodied_goals=[{"kind": "lamp_lit", "glow": True}]))
    # The exported schema holds the models of the worlds registered now, and only those.
    assert {"LampStart", "LampLit"} <= set(export_json_schema()["$defs"])
    registry.unregister_domain(DOMAIN.name)
    try:
        defs = export_json_schema()["$defs"]
        assert not {"LampStart", "LampLit"} & set(defs) and "KitchenStart" in defs
    finally:
        registry.register_domain(DOMAIN)


def test_task_models_that_do_not_fit_their_declaration_are_refused_naming_the_fix():
    from . import lamp_domain

    goals = f"{lamp_domain.__name__}.goals"
    lamp = DOMAIN.environments[0]
    task = lamp_task()
    for changes, message in (
        ({"start": f"{goals}:LampLit"}, r"must have kind: Literal\['lamp'\]"),
        ({"goals": ("ewa_mcp.core.taskmodel:ToolCall",)}, "has no 'kind' field with a default"),
        ({"goals": (f"{lamp_domain.__name__}.env:LampEnvironment",)}, "is not a pydantic model"),
    ):
        env = dataclasses.replace(lamp, **changes)
        before = registry.use_only(dataclasses.replace(DOMAIN, environments=(env,)))
        try:
            with pytest.raises(ValueError, match=message):  # a RegistryError, reported by the validation
                Task.model_validate(task)
        finally:
            registry.restore(before)
    # With no web environment registered, a web start is refused, saying so.
    before = registry.use_only(DOMAIN)
    try:
        Task.model_validate(task)
        with pytest.raises(ValueError, match="no registered web environment declares a start"):
            Task.model_validate(lamp_task(start={"environment": "embodied", "web": {"start_url": "home:/"},
                                                 "embodied": {"kind": "lamp"}}))
    finally:
        registry.restore(before)


async def test_a_domain_package_generates_plays_and_grades(lighting, tmp_path):
    assert generate_all(tmp_path / "tasks", ["lighting"]) == {"lighting": 2}
    store = TaskStore([tmp_path / "tasks"])
    assert not store.errors and [t.id for t in store.all("lighting")] == ["lighting-000", "lighting-001"]

    mcp, _ = build_server(ServerConfig(task_dirs=[tmp_path / "tasks"], run_dir=tmp_path / "run"))
    async with Client(mcp) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        assert tools["lamp_switch"].title == "Switch the lamp"
        listed = await client.call_tool("list_tasks", {"domain": "lighting"})
        assert listed.structured_content["total"] == 2

        # The oracle of the task that starts dark: switch on, finish -> success.
        started = await client.call_tool("start_episode", {"task_id": "lighting-000"})
        assert not started.is_error, text_of(started)
        assert started.structured_content["environments"] == {"embodied": "lamp"}
        good = started.structured_content["episode_id"]
        r = await client.call_tool("lamp_switch", {"episode_id": good, "state": "on"})
        assert not r.is_error and r.structured_content["observation"] == {"lit": True}
        # A kitchen tool on a lighting episode is refused, naming the episode's own tools.
        r = await client.call_tool("kitchen_move", {"episode_id": good, "direction": "ahead"})
        assert r.is_error and "lamp_switch" in text_of(r)
        await client.call_tool("finish_episode", {"episode_id": good})

        # Finishing in the dark fails the lamp_lit goal.
        started = await client.call_tool("start_episode", {"task_id": "lighting-000"})
        bad = started.structured_content["episode_id"]
        await client.call_tool("finish_episode", {"episode_id": bad})

    final = json.loads((tmp_path / "run" / good / "final_state.json").read_text())
    assert final["environments"]["embodied"] == {"name": "lamp", "lit": True, "presses": 1}
    report = grade_run(tmp_path / "run")
    results = {e.episode_id: e for e in report.episodes}
    assert results[good].overall_success is True
    assert [c.kind for c in results[good].conditions] == ["lamp_lit"]
    assert results[bad].overall_success is False and results[bad].conditions[0].note == "the lamp ended off"
    assert list(report.domains) == ["lighting"] and report.domains["lighting"].n == 2


class LampOptions(BaseModel):
    """The options of a lamp that declares some (the kernel's own come first)."""

    lamp_brightness: int | None = Field(None, ge=1, le=10, description="how bright the lamp shines")


async def test_a_registered_worlds_episode_options_are_start_episodes_own(tmp_path):
    from ewa_mcp.core.options import episode_options

    lamp = dataclasses.replace(DOMAIN.environments[0], options=f"{__name__}:LampOptions")
    before = registry.use_only(dataclasses.replace(DOMAIN, environments=(lamp,)))
    try:
        assert list(episode_options().model_fields) == ["observation", "seed", "structured", "lamp_brightness"]
        mcp, episodes = build_server(ServerConfig(task_dirs=[], run_dir=tmp_path / "run"))
        episodes.tasks.add(Task.model_validate(lamp_task()))
        async with Client(mcp) as client:
            tools = {t.name: t for t in (await client.list_tools()).tools}
            offered = tools["start_episode"].input_schema["properties"]["options"]["anyOf"][0]["properties"]
            assert list(offered) == ["observation", "seed", "structured", "lamp_brightness"]
            r = await client.call_tool("start_episode", {"task_id": "lamp-x", "options": {"lamp_brightness": 11}})
            assert r.is_error and "lamp_brightness" in text_of(r)
            r = await client.call_tool("start_episode", {"task_id": "lamp-x", "options": {"kitchen_view": "map"}})
            assert r.is_error and "kitchen_view" in text_of(r)  # no kitchen registered: not an option here
            r = await client.call_tool("start_episode", {"task_id": "lamp-x", "options": {"lamp_brightness": 3}})
            assert not r.is_error, text_of(r)
            assert episodes.get(r.structured_content["episode_id"]).options == {"observation": "text",
                                                                                  "lamp_brightness": 3}
        # An option may be declared once: a world that takes the kernel's name is refused, naming the fix.
        clash = dataclasses.replace(lamp, options="ewa_mcp.core.options:EpisodeOptions")
        registry.restore(before)
        before = registry.use_only(dataclasses.replace(DOMAIN, environments=(clash,)))
        with pytest.raises(registry.RegistryError, match="'observation' of 'lamp' is already declared by the kernel"):
            episode_options()
    finally:
        registry.restore(before)


def test_a_graded_domain_goal_without_its_domain_is_unreadable_not_guessed(lighting, tmp_path):
    from ewa_mcp.graders.rundir import task_view

    raw = lamp_task()
    registry.unregister_domain("lighting")
    problems: list[str] = []
    view = task_view(raw, problems)
    assert view.embodied_goals == [] and view.unreadable and "lamp_lit" in view.unreadable[0].reason
    registry.register_domain(DOMAIN)


# ---------------------------------------------------------------- a kitchen action through the table only
@pytest.fixture
def wait_action():
    # AI2-THOR's Pass: the built-in simulator already answers it, so the table entry is all it takes.
    action = KitchenAction("wait", "Wait a moment", "Pass: wait without moving (the kitchen goes on heating).",
                           lambda s: s.plain_action("Pass"), {"Pass": {}}, aliases={"wait": "Pass"})
    TABLE.add(action)
    yield action
    TABLE.remove("wait")


def test_an_action_table_entry_is_parsed_by_name_and_alias(wait_action):
    assert parse_command("Pass").kitchen_action is wait_action
    assert parse_command("wait").action == "Pass"
    with pytest.raises(ValueError, match="takes no object"):
        parse_command("Pass Apple")


async def test_a_kitchen_action_added_to_the_table_is_a_tool(wait_action, tmp_path):
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "t.json").write_text(json.dumps({
        "id": "k-wait", "domain": "demo", "intent": "wait", "step_limit": 10,
        "start": {"environment": "embodied", "embodied": {"kind": "kitchen", "scene": "FloorPlan1"}}}))
    mcp, _ = build_server(ServerConfig(task_dirs=[tasks], run_dir=tmp_path / "run"))
    async with Client(mcp) as client:
        tools = {t.name: t for t in (await client.list_tools()).tools}
        assert tools["kitchen_wait"].title == "Kitchen: wait a moment"
        assert tools["kitchen_wait"].description == wait_action.description
        assert tools["kitchen_wait"].annotations.read_only_hint is False
        episode = (await client.call_tool("start_episode", {"task_id": "k-wait"})).structured_content["episode_id"]
        r = await client.call_tool("kitchen_wait", {"episode_id": episode})
        assert not r.is_error and "Done: Pass." in text_of(r)
        r = await client.call_tool("kitchen_action", {"episode_id": episode, "action": "wait"})
        assert not r.is_error and r.structured_content["steps"] == 2
    lines = (tmp_path / "run" / episode / "trajectory.jsonl").read_text().splitlines()
    assert [json.loads(line)["tool"] for line in lines[1:]] == ["kitchen_wait", "kitchen_action"]
