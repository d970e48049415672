"""Records that break their format, or episodes that never ended, are failures of that episode with a
named category; they never crash the grading of the rest of the run."""

from __future__ import annotations

import json
from pathlib import Path

from grading_builders import EpisodeBuilder, kitchen_state, kitchen_task, make_task, obj, recipe_step

from ewa_mcp.graders import grade_episode, grade_run

GOALS = [{"kind": "object_state", "object_type": "Bread", "prop": "isCooked"}]
WEB = [{"kind": "recipe_completed", "recipe_id": "r-1"}]


def _good(run: Path) -> EpisodeBuilder:
    ep = EpisodeBuilder(run, kitchen_task(embodied_goals=GOALS, web_goals=WEB))
    ep.call("start_episode", counted=False).call("browser_click", {"ref": "e1"}).event(**recipe_step("r-1", 1, 1))
    ep.switch("embodied").call("kitchen_cook", {"object": "Bread"})
    return ep.finish(embodied=kitchen_state([obj("Bread", isCooked=True)]))


def _overwrite_final(ep: EpisodeBuilder, payload: object) -> None:
    (ep.directory / "final_state.json").write_text(json.dumps(payload), encoding="utf-8")


def test_a_malformed_final_state_fails_its_episode_and_the_run_is_graded(tmp_path: Path) -> None:
    good = _good(tmp_path)
    bad = _good(tmp_path)
    _overwrite_final(bad, {"status": 5, "environments": "x"})
    report = grade_run(tmp_path)  # no AttributeError for the whole run
    results = {e.episode_id: e for e in report.episodes}
    assert results[good.episode_id].overall_success is True
    broken = results[bad.episode_id]
    assert broken.overall_success is False and broken.error is not None
    assert broken.error.category == "invalid_record"
    assert any("final_state.json" in p and "status" in p for p in broken.problems)


def test_an_otherwise_successful_record_with_a_malformed_line_is_not_a_success(tmp_path: Path) -> None:
    ep = _good(tmp_path)
    with open(ep.directory / "trajectory.jsonl", "a", encoding="utf-8") as fh:
        fh.write(json.dumps({"step": "seven", "tool": 3, "ok": "yes"}) + "\n")
    result = grade_episode(ep.directory)
    assert result.overall_success is False and result.error is not None
    assert result.error.category == "invalid_record"
    assert any("trajectory.jsonl record" in p for p in result.problems)


def test_final_states_of_every_wrong_shape_never_crash_grading(tmp_path: Path) -> None:
    shapes = [
        [], "finished", None, 7,
        {"status": "finished", "environments": {"embodied": "kitchen"}},
        {"status": "finished", "environments": {"embodied": {"objects": [1, "two", None]}}},
        {"status": "finished", "environments": {"embodied": {"objects": {"Bread": 1}}}},
        {"status": "finished", "steps": -1, "environments": {}},
        {"status": "finished", "answer": ["a", "b"], "environments": {}},
        {"status": "finished", "submission": "here", "environments": {}},
    ]
    built = []
    for shape in shapes:
        ep = _good(tmp_path)
        _overwrite_final(ep, shape)
        built.append(ep.episode_id)
    report = grade_run(tmp_path)
    results = {e.episode_id: e for e in report.episodes}
    for episode_id, shape in zip(built, shapes, strict=True):
        r = results[episode_id]
        assert r.overall_success is not True, shape
        assert r.error is not None and r.error.category in ("invalid_record", "incomplete_record"), (shape, r.error)


def test_an_unfinished_geolocation_episode_is_an_incomplete_record(tmp_path: Path) -> None:
    task = make_task("geo-1", "geolocation",
                     start={"environment": "embodied", "embodied": {"kind": "geo", "location_id": "x", "setting": "embodied"}},
                     answer={"kind": "geolocation", "lat": 48.85, "lng": 2.35, "continent": "Europe",
                             "country": "France", "city": "Paris", "street": "Rue de Rivoli"})
    ep = EpisodeBuilder(tmp_path, task)
    ep.call("start_episode", counted=False).call("geo_look", {"direction": "all"}).close()  # server killed here
    result = grade_episode(ep.directory)
    assert result.overall_success is not True and result.status == "incomplete"
    assert result.error is not None and result.error.category == "incomplete_record"
