"""Bad task files are skipped and reported (path, reason, fix) while every good task is served; `tasks validate`
resolves every reference against the shipped data; EWA_TASKS_DIR=a:b is honoured by every command; import-ewa
says what is wrong and exits non-zero when nothing was imported."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from mcp import Client

from ewa_mcp.cli import main
from ewa_mcp.core.paths import REPO_ROOT
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.core.taskmodel import Task, TaskStore
from ewa_mcp.taskrefs import ReferenceChecker

from .fixtures import counter_task, write_tasks

DEMO = REPO_ROOT / "tasks" / "demo"


def _bad_files(directory: Path) -> dict[str, str]:
    """One of each kind of bad task file; file name -> a word its report must contain."""
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "latin1.json").write_bytes(json.dumps(counter_task("latin")).replace("count", "c\xf6unt")
                                             .encode("latin-1"))
    (directory / "deep.json").write_text("[" * 100_000 + "]" * 100_000)
    (directory / "folder.json").mkdir()
    (directory / "folder.json" / "inside.txt").write_text("not a task")
    (directory / "invalid.json").write_text(json.dumps({**counter_task("broken"), "step_limit": 0}))
    return {"latin1.json": "UTF-8", "deep.json": "nested too deeply", "folder.json": "directory",
            "invalid.json": "step_limit"}


def _good_and_bad(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    root = write_tasks(tmp_path / "tasks", [counter_task("good-one"), counter_task("good-two")])
    return root, _bad_files(root / "nested")


def test_the_store_serves_every_good_task_and_reports_each_bad_file(tmp_path):
    root, bad = _good_and_bad(tmp_path)
    told: list[str] = []
    store = TaskStore([root], on_error=told.append)
    assert sorted(t.id for t in store.all()) == ["good-one", "good-two"]
    assert len(store.errors) == len(bad) and told == store.errors
    for name, reason in bad.items():
        report = next(e for e in store.errors if name in e)
        assert str(root / "nested" / name) in report and reason in report
    # each report says what to do about it
    assert all(any(fix in e for fix in ("fix", "rename", "save", "see docs")) for e in store.errors)


def test_cli_list_and_validate_survive_bad_files(tmp_path, capsys):
    root, bad = _good_and_bad(tmp_path)
    assert main(["tasks", "list", "--tasks-dir", str(root)]) == 0
    out, err = capsys.readouterr()
    assert out.splitlines()[0].startswith("good-one") and "good-two" in out
    assert all(f"warning: skipped {root / 'nested' / name}" in err for name in bad)
    assert "Traceback" not in err

    assert main(["tasks", "validate", "--tasks-dir", str(root)]) == 1
    out, err = capsys.readouterr()
    summary = json.loads(out)
    assert summary["tasks"] == 2 and summary["bad_files"] == len(bad)
    assert all(str(root / "nested" / name) in err for name in bad)


def test_eval_runs_the_good_tasks_beside_bad_files(tmp_path, capsys):
    root = tmp_path / "tasks"
    (root / "demo").mkdir(parents=True)
    (root / "demo" / "demo.json").write_text((DEMO / "demo.json").read_text())
    _bad_files(root / "junk")
    status = main(["eval", "--agent", "oracle", "--tasks-dir", str(root), "--run-dir", str(tmp_path / "run"), "-q"])
    out, err = capsys.readouterr()
    assert status == 0, err
    assert "warning: skipped" in err and "deep.json" in err and "Traceback" not in err
    assert (tmp_path / "run").is_dir() and len(list((tmp_path / "run").glob("ep-*/final_state.json"))) == 1


@pytest.mark.anyio
async def test_the_server_serves_good_tasks_beside_bad_files(tmp_path):
    root = tmp_path / "tasks"
    (root / "demo").mkdir(parents=True)
    (root / "demo" / "demo.json").write_text((DEMO / "demo.json").read_text())
    _bad_files(root / "junk")
    mcp, episodes = build_server(ServerConfig(task_dirs=[root], run_dir=tmp_path / "run"))
    async with Client(mcp) as client:
        listed = await client.call_tool("list_tasks", {})
        assert not listed.is_error and [t["id"] for t in listed.structured_content["tasks"]] == ["demo-hello"]
        started = await client.call_tool("start_episode", {"task_id": "demo-hello"})
        assert not started.is_error, started.content
        done = await client.call_tool("finish_episode", {"episode_id": started.structured_content["episode_id"],
                                                         "answer": "hello"})
        assert done.structured_content["status"] == "finished"
    assert len(episodes.tasks.errors) == 4


def _real(domain: str) -> dict:
    path = sorted((REPO_ROOT / "tasks" / domain).glob("*.json"))[0]
    raw = json.loads(path.read_text())
    return raw[0] if isinstance(raw, list) else raw


def test_references_to_missing_data_are_named():
    checker = ReferenceChecker()
    shop, cook, geo, nav = _real("shopping"), _real("cooking"), _real("geolocation"), _real("navigation")
    for task in (shop, cook, geo, nav, _real("traveling")):
        assert checker.missing(Task.model_validate(task)) == [], task["id"]

    shop["start"]["embodied"]["city"] = "atlantis"
    shop["web_goals"][0].update(product_id="prod-unicorn", store_id="store-nowhere")
    shop["embodied_goals"][0]["node"] = "mn-0000000000"
    cook["start"]["embodied"]["scene"] = "FloorPlan99"
    cook["web_goals"][0]["recipe_id"] = "r999"
    geo["start"]["embodied"]["location_id"] = "g999"
    nav["start"]["embodied"]["node"] = "bo-0000000000"
    nav["web_goals"][0]["destination"] = "poi-nowhere"
    nav["start"]["web"]["start_url"] = "nosuchsite:/"
    found = {t["domain"]: checker.missing(Task.model_validate(t)) for t in (shop, cook, geo, nav)}
    assert [p.split(":")[0] for p in found["shopping"]] == [
        "start.embodied.city", "web_goals.0.product_id", "web_goals.0.store_id", "embodied_goals.0.node"]
    assert "'atlantis'" in found["shopping"][0] and "'prod-unicorn'" in found["shopping"][1]
    assert [p.split(":")[0] for p in found["cooking"]] == ["start.embodied.scene", "web_goals.0.recipe_id"]
    assert "FloorPlan99" in found["cooking"][0] and "'r999'" in found["cooking"][1]
    assert found["geolocation"] == [found["geolocation"][0]] and "'g999'" in found["geolocation"][0]
    assert [p.split(":")[0] for p in found["navigation"]] == [
        "start.web.start_url", "start.embodied.node", "web_goals.0.destination"]


def test_validate_fails_a_task_naming_missing_data(tmp_path, capsys):
    task = _real("cooking")
    task.update(id="cook-nowhere")
    task["start"]["embodied"]["scene"] = "FloorPlan31"
    path = tmp_path / "tasks" / "bad.json"
    path.parent.mkdir()
    path.write_text(json.dumps([task]))
    assert main(["tasks", "validate", "--tasks-dir", str(path.parent)]) == 1
    out, err = capsys.readouterr()
    assert json.loads(out)["missing_references"] == 1
    assert f"{path}: task cook-nowhere: start.embodied.scene: unknown kitchen scene 'FloorPlan31'" in err


def test_every_command_reads_every_directory_of_the_tasks_dir_setting(tmp_path, monkeypatch, capsys):
    first = write_tasks(tmp_path / "a", [counter_task("only-in-a")])
    second = tmp_path / "b"
    (second / "demo").mkdir(parents=True)
    (second / "demo" / "demo.json").write_text((DEMO / "demo.json").read_text())
    monkeypatch.setenv("EWA_TASKS_DIR", f"{first}{os.pathsep}{second}")

    assert main(["tasks", "list"]) == 0
    assert [line.split("\t")[0] for line in capsys.readouterr().out.splitlines()] == ["demo-hello", "only-in-a"]
    assert main(["tasks", "validate"]) == 0
    assert json.loads(capsys.readouterr().out)["tasks"] == 2
    # the task eval plays is in the second directory
    assert main(["eval", "--agent", "oracle", "--tasks", "demo-*", "--run-dir", str(tmp_path / "run"), "-q"]) == 0
    capsys.readouterr()
    assert len(list((tmp_path / "run").glob("ep-*/final_state.json"))) == 1

    pytest.importorskip("inspect_ai")
    from ewa_mcp.inspect_tasks import ewa_dataset

    assert sorted(s.id for s in ewa_dataset(None)) == ["demo-hello", "only-in-a"]


def test_import_ewa_errors(tmp_path, capsys):
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000 + "]" * 100_000)
    assert main(["tasks", "import-ewa", str(deep), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert f"{deep}: JSON nested too deeply" in err and "Traceback" not in err

    empty = tmp_path / "empty.json"
    empty.write_text("[]")
    assert main(["tasks", "import-ewa", str(empty), "-o", str(tmp_path / "out")]) != 0
    assert "nothing was written" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()

    a_file = tmp_path / "a-file"
    a_file.write_text("keep me")
    assert main(["tasks", "import-ewa", str(empty), "-o", str(a_file)]) == 2
    assert f"the output {a_file} is a file" in capsys.readouterr().err
    assert a_file.read_text() == "keep me"
