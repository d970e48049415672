"""Per-episode metrics and damaged run directories."""

from __future__ import annotations

import json
from pathlib import Path

from grading_builders import EpisodeBuilder, kitchen_state, kitchen_task, make_task, obj, recipe_step

from ewa_mcp.graders import grade_episode

PLATE = "Plate|+0.00|+0.90|-1.00"
GOALS = [
    {"kind": "object_state", "object_type": "Tomato", "prop": "isSliced"},
    {"kind": "object_in", "object_type": "Tomato", "receptacle_type": "Plate"},
    {"kind": "object_state", "object_type": "Bread", "prop": "isCooked"},
]
WEB = [{"kind": "recipe_completed", "recipe_id": "r-1"}]


def _cooking(tmp_path: Path, answer_check: dict | None = None) -> EpisodeBuilder:
    extra = {"answer": answer_check} if answer_check else {}
    ep = EpisodeBuilder(tmp_path, kitchen_task(embodied_goals=GOALS, web_goals=WEB, **extra))
    ep.call("start_episode", {"task_id": "cook-1"}, counted=False)
    ep.call("browser_click", {"ref": "e1"}).event(**recipe_step("r-1", 1, 2))
    ep.call("browser_click", {"ref": "e9"}).event(**recipe_step("r-1", 2, 2))
    ep.switch("embodied")
    ep.call("kitchen_slice", {"object": "Tomato"})
    ep.call("kitchen_put", {"receptacle": "Plate"})
    return ep


def test_episode_metrics(tmp_path: Path) -> None:
    objects = [obj("Plate"), obj("TomatoSliced", 0, parents=[PLATE], source="Tomato"), obj("Bread")]
    ep = _cooking(tmp_path).finish(embodied=kitchen_state(objects), wall_time_s=42.0)
    r = grade_episode(ep.directory)
    assert (r.web_success, r.embodied_success, r.overall_success) == (True, False, False)
    assert (r.conditions_met, r.conditions_total) == (3, 4)
    assert r.completion == 0.75
    assert (r.steps, r.calls, r.switches, r.wall_time_s) == (5, 6, 1, 42.0)
    assert r.status == "finished" and r.gradable and r.problems == []
    assert r.error is not None


def test_overall_needs_the_answer_too(tmp_path: Path) -> None:
    objects = [obj("Plate"), obj("TomatoSliced", 0, parents=[PLATE], source="Tomato"), obj("Bread", isCooked=True)]
    check = {"kind": "text", "must_include": ["toast"]}
    wrong = grade_episode(_cooking(tmp_path, check).finish(answer="soup", embodied=kitchen_state(objects)).directory)
    assert (wrong.web_success, wrong.embodied_success, wrong.answer_correct) == (True, True, False)
    assert wrong.overall_success is False and wrong.completion == 0.8
    assert wrong.error is not None and wrong.error.category == "wrong_answer"
    right = grade_episode(_cooking(tmp_path, check).finish(answer="Toast!", embodied=kitchen_state(objects)).directory)
    assert right.overall_success is True and right.completion == 1.0 and right.error is None


def test_truncated_trajectory_and_no_final_state_are_graded_as_far_as_possible(tmp_path: Path) -> None:
    ep = _cooking(tmp_path).close()  # crash: no final_state.json
    with open(ep.directory / "trajectory.jsonl", "a", encoding="utf-8") as fh:
        fh.write('{"step": 7, "tool": "kitchen_co')  # torn last line
    r = grade_episode(ep.directory)
    assert r.status == "incomplete"
    assert r.web_success is True  # web goals come from web_events.jsonl, written live
    assert r.embodied_success is None and r.overall_success is None and r.gradable is False
    assert all(c.met is None for c in r.conditions if c.side == "embodied")
    assert r.steps == 5 and r.switches == 1  # counted from the complete trajectory lines
    assert any("last line is not complete JSON" in p for p in r.problems)
    assert any("final_state.json missing" in p for p in r.problems)
    assert r.error is not None and r.error.category == "incomplete_record"


def test_a_known_failure_decides_even_when_other_data_is_missing(tmp_path: Path) -> None:
    ep = EpisodeBuilder(tmp_path, kitchen_task(embodied_goals=GOALS, web_goals=WEB)).close()
    r = grade_episode(ep.directory)  # no recipe step at all, no final state
    assert r.web_success is False and r.overall_success is False and r.gradable is True


def test_answer_is_recovered_from_the_trajectory_after_a_crash(tmp_path: Path) -> None:
    task = make_task("q-1", "traveling", answer={"kind": "text", "must_include": ["2008"]})
    ep = EpisodeBuilder(tmp_path, task).call("finish_episode", {"answer": "in 2008"}, counted=False).close()
    r = grade_episode(ep.directory)
    assert r.answer == "in 2008" and r.answer_correct is True and r.overall_success is True


def test_missing_task_json(tmp_path: Path) -> None:
    ep = EpisodeBuilder(tmp_path, None).call("browser_click").finish()
    r = grade_episode(ep.directory)
    assert r.gradable is False and r.overall_success is None and r.completion is None
    assert any("task.json missing" in p for p in r.problems)
    assert r.steps == 1


def test_task_from_a_newer_schema_is_graded_goal_by_goal(tmp_path: Path) -> None:
    task = kitchen_task(embodied_goals=GOALS[:1], web_goals=WEB)
    task["schema_version"] = 2
    task["embodied_goals"].append({"kind": "object_temperature", "object_type": "Bread", "value": "hot"})
    ep = EpisodeBuilder(tmp_path, task).event(**recipe_step("r-1", 3, 3))
    r = grade_episode(ep.finish(embodied=kitchen_state([obj("TomatoSliced", 0, source="Tomato")])).directory)
    assert r.web_success is True
    assert [c.met for c in r.conditions] == [True, True, None]  # web, readable goal, unreadable goal
    assert r.embodied_success is None and r.gradable is False
    assert any("does not match task schema" in p for p in r.problems)
    assert any("newer than this grader" in p for p in r.problems)


def test_garbage_files_never_raise(tmp_path: Path) -> None:
    for name, content in {"task.json": "{not json", "final_state.json": "[1, 2]",
                          "trajectory.jsonl": "\x00\x01garbage\n[]\n", "web_events.jsonl": "{\n"}.items():
        directory = tmp_path / "ep-garbage"
        directory.mkdir(exist_ok=True)
        (directory / name).write_text(content, encoding="utf-8")
    r = grade_episode(tmp_path / "ep-garbage")
    assert r.gradable is False and r.domain == "unknown"
    assert len(r.problems) >= 4


def test_embodied_environment_error_is_unknown_not_failure(tmp_path: Path) -> None:
    ep = EpisodeBuilder(tmp_path, kitchen_task(embodied_goals=GOALS[:1])).finish(
        embodied={"name": "kitchen", "error": "RuntimeError: boom"})
    r = grade_episode(ep.directory)
    assert r.embodied_success is None and "boom" in (r.conditions[0].note or "")


def test_final_state_is_what_the_core_writes(tmp_path: Path) -> None:
    """The builder writes with the core's recorder; this guards the file names and keys the grader reads."""
    ep = _cooking(tmp_path).finish(embodied=kitchen_state([]))
    assert sorted(p.name for p in ep.directory.iterdir()) == [
        "final_state.json", "task.json", "trajectory.jsonl", "web_events.jsonl"]
    line = json.loads((ep.directory / "trajectory.jsonl").read_text().splitlines()[1])
    assert {"step", "tool", "args", "ok", "error", "environment", "counted", "observation", "t"} <= set(line)
