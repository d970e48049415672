"""The importer for the paper's navigation environment format, on a small hand-written file."""

import json

import pytest

from ewa_mcp.outdoor import importer, world as world_module
from ewa_mcp.outdoor.env import StreetEnvironment
from ewa_mcp.outdoor.world import World
from ewa_mcp.services import Services
from ewa_mcp.taskmodel import Task

# Five panoramas along a short L-shaped walk near Madison Square (positions written for this test).
ENV = {
    "source": "40.74140-73.98940",
    "target": "40.74188-73.98862",
    "nodes": {
        "40.74140-73.98940": {"pano_id": "pA", "lat": 40.74140, "lng": -73.98940,
                              "links": {"40.74156-73.98929": 28.9}},
        "40.74156-73.98929": {"pano_id": "pB", "lat": 40.74156, "lng": -73.98929,
                              "links": {"40.74140-73.98940": 208.9, "40.74172-73.98918": 28.9}},
        "40.74172-73.98918": {"pano_id": "pC", "lat": 40.74172, "lng": -73.98918,
                              "links": {"40.74156-73.98929": 208.9, "40.74180-73.98890": 118.9,
                                        "40.80000-73.90000": 10.0}},
        "40.74180-73.98890": {"pano_id": "pD", "lat": 40.74180, "lng": -73.98890,
                              "links": {"40.74172-73.98918": 298.9, "40.74188-73.98862": 118.9}},
        "40.74188-73.98862": {"pano_id": "pE",
                              "links": {"40.74180-73.98890": 298.9}},
    },
}


def test_convert_builds_graph_and_task():
    graph, task = importer.convert(ENV, "Madison demo 1")
    assert graph["city"] == "import-madison-demo-1" and len(graph["nodes"]) == 5
    assert len(graph["edges"]) == 4  # symmetric links merged; the link leaving the file is dropped
    by_pano = {v: k for k, v in graph["fit"]["pano_ids"].items()}
    assert set(by_pano) == {"pA", "pB", "pC", "pD", "pE"}
    t = Task.model_validate(task)
    assert t.start.embodied.node == by_pano["pA"] and t.start.embodied.heading == 0.0
    # pE has no lat/lng fields: its position comes from the "lat-lng" key (western longitude).
    e = next(n for n in graph["nodes"] if n[0] == t.embodied_goals[0].node)
    assert e[1:] == [40.74188, -73.98862]


def test_bad_file_is_refused_with_a_reason():
    with pytest.raises(importer.ImportFormatError, match="source"):
        importer.convert({**ENV, "target": "nowhere"}, "x")
    with pytest.raises(importer.ImportFormatError, match="no nodes"):
        importer.convert({"source": "a", "target": "b"}, "x")


@pytest.mark.anyio
async def test_imported_environment_runs_in_the_street_environment(tmp_path, monkeypatch):
    src = tmp_path / "env.json"
    src.write_text(json.dumps({"madison": ENV}))
    assert importer.main([str(src), "--data-dir", str(tmp_path / "graphs"), "--task-dir", str(tmp_path / "tasks")]) == 0
    w = World(data_dirs=[tmp_path / "graphs"])
    monkeypatch.setattr(world_module, "_world", w)
    task = Task.model_validate(json.loads((tmp_path / "tasks" / "nav-import-madison.json").read_text()))
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": "text"})
    goal = task.embodied_goals[0].node
    for node in w.directions(task.start.embodied.node, goal).nodes[1:]:
        env.move(neighbour=node)
    env.stop()
    state = await env.final_state()
    assert state["node"] == goal and state["stopped"] and len(state["path"]) == 5
