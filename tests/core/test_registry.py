"""The registry (ewa_mcp/core/registry.py) is the one list of domains and environments, and the committed task
suite keeps to what each domain declares."""

from __future__ import annotations

import importlib
import json
from pathlib import Path

import pytest

from ewa_mcp.core import registry
from ewa_mcp.core.environment import Environment
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.response import environment_for_tool
from ewa_mcp.taskgen import generated_domains
from ewa_mcp.core.taskmodel import Task, TaskStore, export_json_schema, has_web_environment

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def suite():
    store = TaskStore([tasks_dir()])
    assert not store.errors
    return store.all()


def test_every_task_keeps_to_its_domains_declaration(suite):
    problems = []
    for task in suite:
        domain = registry.domain(task.domain)
        assert domain is not None, task.id
        kinds = {g.kind for g in [*task.web_goals, *task.embodied_goals]}
        if not kinds <= set(domain.goal_kinds):
            problems.append(f"{task.id}: goal kinds {sorted(kinds - set(domain.goal_kinds))} not declared")
        envs = {spec.name for spec in domain.environments}
        if not set(task.environment_names().values()) <= envs:
            problems.append(f"{task.id}: environments {task.environment_names()} not all in {sorted(envs)}")
        if domain.difficulties and task.difficulty not in domain.difficulties:
            problems.append(f"{task.id}: difficulty {task.difficulty}")
    assert not problems, problems[:10]


def test_every_environment_loads_lazily_and_matches_its_declaration():
    for name, spec in registry.environments().items():
        cls = registry.load_object(spec.cls)
        assert issubclass(cls, Environment) and cls.name == name and cls.side == spec.side, name
        assert spec.tools is not None and callable(importlib.import_module(spec.tools).register), name
        assert environment_for_tool(f"{name}_anything") == name
    assert environment_for_tool("submit_location") is None and environment_for_tool("finish_episode") is None
    assert registry.tool_groups()[0] == registry.CORE_TOOLS


def test_the_domain_list_exists_once():
    # Read from the worlds' own declarations, in the order of their registration lines: no second copy here.
    from ewa_mcp import envs

    names = registry.domain_names()
    assert names == [d.name for path in envs.PACKAGES for d in registry.load_object(path)]
    assert set(names) == {folder.name for folder in tasks_dir().iterdir() if folder.is_dir()}
    assert set(generated_domains()) == {d.name for d in registry.domains() if d.generator or d.writer}
    from ewa_mcp.inspect_tasks import DOMAINS

    assert list(DOMAINS) == registry.domain_names(scored_only=True)
    committed = json.loads((ROOT / "docs" / "task.schema.json").read_text(encoding="utf-8"))
    assert committed == export_json_schema(), "regenerate: ewa-mcp tasks schema -o docs/task.schema.json"
    with pytest.raises(ValueError, match="unknown domain 'cookery'"):
        Task.model_validate({"id": "x", "domain": "cookery", "intent": "i"})


def test_the_web_environment_rule_is_one_function():
    task = Task.model_validate({"id": "x", "domain": "demo", "intent": "i",
                                "web_goals": [{"kind": "page_visited", "site": "wiki", "path_prefix": "/"}]})
    assert task.environment_names() == {"web": "browser"}
    assert has_web_environment(None, []) is False and has_web_environment({"start_url": "home:/"}, []) is True


def test_the_exported_schema_accepts_every_domains_tasks_and_keeps_kinds_exclusive(suite):
    jsonschema = pytest.importorskip("jsonschema")
    schema = export_json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    firsts = {}
    for task in suite:
        firsts.setdefault(task.domain, task)
    for task in firsts.values():
        errors = list(validator.iter_errors(task.model_dump(mode="json")))
        assert not errors, (task.id, errors[0].message[:200])
    # A built-in kind with bad fields must not slip through as a registered domain's open kind.
    bad = firsts["cooking"].model_dump(mode="json")
    bad["start"]["embodied"] = {"kind": "kitchen", "scene": 3}
    assert list(validator.iter_errors(bad))
