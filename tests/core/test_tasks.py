"""The task schema and loader: valid files load, malformed ones give errors that name file and field."""

from __future__ import annotations

import json
import re

import pytest

from ewa_mcp.cli import main
from ewa_mcp.core.paths import REPO_ROOT
from ewa_mcp.core.taskmodel import Task, TaskFileError, TaskStore, export_json_schema, load_task_file

from .fixtures import counter_task


def test_round_trip_and_discriminated_goals(tmp_path):
    task = Task.model_validate({
        **counter_task(),
        "web_goals": [{"kind": "recipe_completed", "recipe_id": "r001"}],
        "embodied_goals": [{"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate",
                            "with_state": {"isSliced": True}}],
    })
    again = Task.model_validate_json(task.model_dump_json())
    assert again == task
    assert again.embodied_goals[0].receptacle_type == "Plate"


@pytest.mark.parametrize("payload, needle", [
    ("{not json", "not valid JSON"),
    (json.dumps({"id": "x", "intent": "no domain"}), "domain"),
    (json.dumps({**counter_task(), "step_limit": 0}), "step_limit"),
    (json.dumps({**counter_task(), "web_goals": [{"kind": "teleported"}]}), "web_goals"),
    (json.dumps({**counter_task(), "colour": "red"}), "colour"),
    (json.dumps({**counter_task(), "id": "Has Spaces"}), "id"),
])
def test_malformed_task_files_are_reported(tmp_path, payload, needle):
    path = tmp_path / "bad.json"
    path.write_text(payload)
    with pytest.raises(TaskFileError) as info:
        load_task_file(path)
    assert str(path) in str(info.value) and needle in str(info.value)


def test_store_skips_bad_files_and_duplicate_ids(tmp_path):
    (tmp_path / "a.json").write_text(json.dumps([counter_task("one"), counter_task("two")]))
    (tmp_path / "b.json").write_text(json.dumps(counter_task("one")))
    (tmp_path / "c.json").write_text("[")
    store = TaskStore([tmp_path])
    assert sorted(t.id for t in store.all()) == ["one", "two"]
    assert len(store.errors) == 2 and any("duplicate" in e for e in store.errors)


def test_committed_schema_is_current():
    committed = json.loads((REPO_ROOT / "docs" / "task.schema.json").read_text())
    assert committed == export_json_schema(), "run: ewa-mcp tasks schema -o docs/task.schema.json"


def test_committed_tasks_validate(capsys):
    assert main(["tasks", "validate"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["errors"] == 0 and summary["tasks"] >= 1


def test_validate_reports_bad_dir(tmp_path, capsys):
    (tmp_path / "bad.json").write_text("{}")
    assert main(["tasks", "validate", "--tasks", str(tmp_path)]) == 1
    assert "invalid task" in capsys.readouterr().err


def test_every_walking_intent_says_how_the_walk_ends():
    """Issue 15: navigation intents said "stop", shopping intents did not; one sentence now says it everywhere."""
    from ewa_mcp.core.paths import tasks_dir
    from ewa_mcp.taskgen.common import WALK_RULE
    from ewa_mcp.core.taskmodel import TaskStore

    walks = [t for t in TaskStore([tasks_dir()]).all()
             if t.start.embodied is not None and t.start.embodied.kind == "street"]
    assert {t.domain for t in walks} == {"navigation", "shopping", "traveling"}
    assert [t.id for t in walks if WALK_RULE not in t.intent] == []


# Metadata keys that name a task's answer or target (a page, a place, a product): an id carrying one hands
# the agent the URL or the answer (issue: /recipe/r071 from cooking-r071-cook-02).
TARGET_KEYS = ("recipe_id", "recipe_name", "product_id", "store_id", "destination_node", "poi_id", "article",
               "location_id", "answer_id")


def _forms(value: str) -> set[str]:
    """The value, its slug, and the slug without a type prefix ("prod-", "poi-", "bo-")."""
    slug = re.sub(r"[^a-z0-9]+", "-", value.lower()).strip("-")
    forms = {value.lower(), slug}
    if "-" in slug:
        forms.add(slug.split("-", 1)[1])
    return {f for f in forms if len(f) >= 4}


def test_no_task_id_names_its_target():
    from ewa_mcp.core.paths import tasks_dir
    from ewa_mcp.core.taskmodel import TaskStore

    checked = 0
    for task in TaskStore([tasks_dir()]).all():
        for key in TARGET_KEYS:
            value = (task.metadata or {}).get(key)
            if isinstance(value, str) and value:
                checked += 1
                for form in _forms(value):
                    assert form not in task.id.lower(), (task.id, key, value)
    assert checked > 1000
