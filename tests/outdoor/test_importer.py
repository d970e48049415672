"""Importing the paper's released navigation environments, on small files written in its shapes."""

from __future__ import annotations

import gzip
import json

import pytest

from ewa_mcp.cli import main as cli_main
from ewa_mcp.envs.street.taskgen import release
from ewa_mcp.envs.street.importer import ImportFormatError
from ewa_mcp.envs.street.world import World
from ewa_mcp.core.taskmodel import Task
from ewa_mcp.websites.map.places import WorldAdapter

from . import release_fixtures as fx


def load_graph(result):
    with gzip.open(result.graph_path, "rt", encoding="utf-8") as fh:
        return json.load(fh)


def node_of(graph, original_key):
    return next(n for n, keys in graph["fit"]["node_aliases"].items() if original_key in keys)


def test_list_file_imports_each_environment_or_says_why(tmp_path):
    result = release.import_file(fx.write_release(tmp_path / "src"), tmp_path / "out")
    assert result.report.environments_read == 3
    assert [t["id"] for t in result.tasks] == ["nav-import-navi-env-test-000"]
    reasons = {s["environment"]: s["reason"] for s in result.report.skipped}
    assert set(reasons) == {"1", "2"}
    assert "same panorama" in reasons["1"] and "no walkable route" in reasons["2"]
    task = Task.model_validate(json.loads(result.task_paths[0].read_text(encoding="utf-8")))
    graph = load_graph(result)
    assert task.start.embodied.node == node_of(graph, fx.K1)
    assert task.embodied_goals[0].node == node_of(graph, fx.K5)
    # the link to a panorama outside the environment is dropped, the one-way link is walkable
    assert result.report.counts["links to panoramas outside their environment (dropped)"] == 1
    assert result.report.counts["one-way links (walkable both ways here)"] >= 1
    report = (tmp_path / "out" / "import-navi-env-test.import-report.txt").read_text(encoding="utf-8")
    assert "environment 1:" in report and "environment 2:" in report


def test_near_duplicate_panoramas_merge_and_keep_every_id(tmp_path):
    result = release.import_file(fx.write_release(tmp_path / "src"), tmp_path / "out")
    graph = load_graph(result)
    merged = node_of(graph, fx.K2)
    assert node_of(graph, fx.K2B) == merged
    assert set(graph["fit"]["node_aliases"][merged]) == {fx.K2, fx.K2B}
    assert set(graph["fit"]["pano_ids"][merged]) == {"pano-2", "pano-2b"}
    # five walk panoramas (six, less the duplicate; the second environment reuses two) + two more
    assert len(graph["nodes"]) == 5 + 2
    assert any(m["node"] == merged and 0 < m["spread_m"] < 1 for m in result.report.merged)


def test_street_names_come_from_link_text(tmp_path):
    result = release.import_file(fx.write_release(tmp_path / "src"), tmp_path / "out")
    graph = load_graph(result)
    assert {fx.SENORA, fx.BEACON} <= set(graph["streets"])
    world = World(data_dirs=[tmp_path / "out" / "streets"])
    links = world.neighbours(node_of(graph, fx.K3))
    assert sorted(link.street for link in links) == [fx.BEACON, fx.SENORA]
    steps = world.directions(node_of(graph, fx.K1), node_of(graph, fx.K5)).steps
    assert [s.street for s in steps[:2]] == [fx.SENORA, fx.BEACON] and steps[1].maneuver == "turn right"


def test_mapping_and_single_environment_files_and_older_field_names(tmp_path):
    legacy = fx.legacy_shape()
    (tmp_path / "one.json").write_text(json.dumps(legacy, ensure_ascii=False), encoding="utf-8")
    (tmp_path / "named.json").write_text(json.dumps({"walk": fx.WALK, "cut": fx.CUT}, ensure_ascii=False),
                                         encoding="utf-8")
    one = release.import_file(tmp_path / "one.json", tmp_path / "out")
    named = release.import_file(tmp_path / "named.json", tmp_path / "out")
    assert [t["id"] for t in one.tasks] == ["nav-import-one-one"]
    assert [t["id"] for t in named.tasks] == ["nav-import-named-walk"]
    assert [s["environment"] for s in named.report.skipped] == ["cut"]
    graph = load_graph(one)
    assert {fx.SENORA, fx.BEACON} <= set(graph["streets"])
    assert "pano-2b" in graph["fit"]["pano_ids"][node_of(graph, fx.K2)]


def test_bad_files_are_refused_with_the_reason(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"hello": 1}))
    with pytest.raises(ImportFormatError, match="not a navigation environment file"):
        release.import_file(bad, tmp_path / "out")
    bad.write_text("version https://git-lfs.github.com/spec/v1\n")
    with pytest.raises(ImportFormatError, match="LFS"):
        release.import_file(bad, tmp_path / "out")
    missing = tmp_path / "partial.json"
    missing.write_text(json.dumps([{"source": "a", "target": "b", "graph": {}}, fx.WALK], ensure_ascii=False))
    result = release.import_file(missing, tmp_path / "out")
    assert "no panoramas" in result.report.skipped[0]["reason"] and len(result.tasks) == 1


def test_without_annotations_places_are_named_after_the_route(tmp_path):
    result = release.import_file(fx.write_release(tmp_path / "src"), tmp_path / "out")
    task = result.tasks[0]
    assert task["intent"].startswith('Starting at "Start of route 0 on Calle Señora", get walking directions')
    assert '"End of route 0 on Beacon Row"' in task["intent"]
    assert task["web_goals"] == [{"kind": "directions_shown", "origin": "place-import-navi-env-test-0000",
                                  "destination": "place-import-navi-env-test-0001"}]
    # the start is never closer than the goal's radius
    goal = task["embodied_goals"][0]
    assert 0 < goal["radius_m"] < task["metadata"]["start_goal_distance_m"]


def test_annotations_name_the_places_and_set_the_direction(tmp_path):
    result = release.import_file(fx.write_release(tmp_path / "src", annotations=True), tmp_path / "out")
    assert result.annotations.name == "navi_anno_test.json"  # found beside the environments
    task = result.tasks[0]
    assert task["intent"] == ('Starting at "40 Beacon Row, New York, NY", get walking directions on the map site to '
                              '"12 Harbor Lane, New York, NY", then walk there and stop when you arrive.')
    graph = load_graph(result)
    # the annotated start is the environment's target: the task walks target -> source
    assert task["start"]["embodied"]["node"] == node_of(graph, fx.K5)
    assert task["embodied_goals"][0]["node"] == node_of(graph, fx.K1)
    assert task["metadata"]["reversed_to_match_annotation"] is True
    # the map site resolves what the intent says to exactly the goal's places
    resolver = WorldAdapter(World(data_dirs=[tmp_path / "out" / "streets"]))
    assert resolver.resolve("40 Beacon Row, New York, NY").place.id == task["web_goals"][0]["origin"]
    assert resolver.resolve("12 Harbor Lane, New York, NY").place.id == task["web_goals"][0]["destination"]
    assert "from=40+Beacon+Row" in task["oracle"][0]["args"]["url"]


def test_cli_imports_and_prints_counts(tmp_path, capsys):
    src = fx.write_release(tmp_path / "src")
    assert cli_main(["tasks", "import-ewa", str(src), "--out", str(tmp_path / "out"), "--annotations", "none"]) == 0
    out = capsys.readouterr().out
    counts = json.loads(next(line for line in out.splitlines() if line.startswith("{")))
    assert counts["environments"] == 3 and counts["tasks"] == 1 and counts["skipped"] == 2
    assert f"ewa-mcp eval --tasks-dir {tmp_path / 'out'}" in out
    assert cli_main(["tasks", "validate", "--tasks-dir", str(tmp_path / "out")]) == 0
    assert cli_main(["tasks", "import-ewa", str(tmp_path / "nope.json"), "--out", str(tmp_path / "out")]) == 2


def test_a_name_another_imported_file_uses_gets_the_file_name(tmp_path):
    ann = tmp_path / "ann.json"
    ann.write_text(json.dumps({"walk": fx.ANNOTATIONS[0]}))
    for name in ("first", "second"):
        (tmp_path / f"{name}.json").write_text(json.dumps({"walk": fx.WALK}, ensure_ascii=False), encoding="utf-8")
    first = release.import_file(tmp_path / "first.json", tmp_path / "out", ann)
    second = release.import_file(tmp_path / "second.json", tmp_path / "out", ann)
    assert '"40 Beacon Row, New York, NY"' in first.tasks[0]["intent"]
    assert '"40 Beacon Row, New York, NY (second)"' in second.tasks[0]["intent"]
    resolver = WorldAdapter(World(data_dirs=[tmp_path / "out" / "streets"]))
    for result in (first, second):
        task = result.tasks[0]
        start_name = task["intent"].split('"')[1]
        assert resolver.resolve(start_name).place.id == task["web_goals"][0]["origin"]
        assert task["web_goals"][0]["origin"].startswith(f"place-{result.city}-")
