"""ewa-grade: every format, --compare, --plots, --radius and the bad-input exits."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from grading_builders import (
    GOAL,
    EpisodeBuilder,
    kitchen_state,
    kitchen_task,
    obj,
    offset_north,
    recipe_step,
    street_state,
    street_task,
)

from ewa_mcp.graders.cli import main

DIRECTIONS = [{"kind": "directions_shown", "origin": "poi-a", "destination": "poi-b"}]


def build_run(root: Path, name: str, nav_distance_m: float, cook_success: bool) -> Path:
    run = root / name
    for n, distance in enumerate([nav_distance_m, 5.0]):
        ep = EpisodeBuilder(run, street_task(f"nav-{n}", web_goals=DIRECTIONS, metadata={"shortest_path_m": 80.0}))
        ep.call("browser_click").event(site="map", type="directions", origin="poi-a", destination="poi-b")
        ep.switch("embodied").call("street_move", {"direction": "forward"}).call("street_stop")
        ep.finish(embodied=street_state(*offset_north(GOAL["lat"], GOAL["lng"], distance), walked=100.0))
    goals = [{"kind": "object_state", "object_type": "Bread", "prop": "isSliced"}]
    ep = EpisodeBuilder(run, kitchen_task(embodied_goals=goals, web_goals=[{"kind": "recipe_completed",
                                                                              "recipe_id": "toast"}]))
    ep.call("browser_click").event(**recipe_step("toast", 3, 3)).switch("embodied").call("kitchen_slice")
    ep.finish(embodied=kitchen_state([obj("BreadSliced", 0, source="Bread")] if cook_success else [obj("Bread")]))
    return run


@pytest.fixture
def runs(tmp_path: Path) -> tuple[Path, Path]:
    return build_run(tmp_path, "model-a", 40.0, True), build_run(tmp_path, "model-b", 10.0, False)


def test_table_format(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0])]) == 0
    out = capsys.readouterr().out
    assert "Results by domain" in out and "model-a" in out
    assert out.index("navigation") < out.index("cooking")  # the paper's order: outdoor first
    nav_line = next(line for line in out.splitlines() if "Overall Accuracy" in line)
    assert "50.0 [" in nav_line  # 1 of 2 navigation episodes stopped within 25 m
    assert "Mean SPL" in out and "Error analysis" in out


def test_render_report_api_matches_the_cli(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    from ewa_mcp.graders import grade_run, render_report

    assert main([str(runs[0]), "--format", "markdown"]) == 0
    assert render_report(grade_run(runs[0]), fmt="markdown") == capsys.readouterr().out


def test_json_format(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0]), "--format", "json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["label"] == "model-a" and report["n_episodes"] == 3
    assert report["domains"]["cooking"]["overall_accuracy"]["value"] == 1.0
    nav = report["domains"]["navigation"]["navigation"]
    assert nav["success_within_radius"]["successes"] == 1
    assert nav["mean_spl"] == pytest.approx((0.8 + 0.0) / 2)
    assert {e["episode_id"] for e in report["episodes"]} == {p.name for p in runs[0].iterdir()}


def test_markdown_format(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0]), "--format", "markdown"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("## ewa-grade report")
    assert "| Domain | Metric | model-a |" in out
    assert "| navigation | Episodes | 2 |" in out


def test_compare_runs_side_by_side(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0]), "--compare", str(runs[1])]) == 0
    out = capsys.readouterr().out
    header = next(line for line in out.splitlines() if line.startswith("Domain"))
    assert header.split()[2:4] == ["model-a", "model-b"]  # then the difference column (test_grading_compare.py)
    cooking_rows = out.split("cooking", 1)[1].splitlines()
    overall = next(line for line in cooking_rows if "Overall Accuracy" in line)
    assert overall.split("Overall Accuracy")[1].split()[0] == "100.0"  # model-a
    assert "0.0 [" in overall  # model-b
    assert main([str(runs[0]), "--compare", str(runs[1]), "--format", "json"]) == 0
    both = json.loads(capsys.readouterr().out)
    assert [r["label"] for r in both["runs"]] == ["model-a", "model-b"]


def test_same_named_runs_get_distinct_labels(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    first = build_run(tmp_path / "x", "run", 5.0, True)
    second = build_run(tmp_path / "y", "run", 5.0, True)
    assert main([str(first), "--compare", str(second), "--format", "json"]) == 0
    assert [r["label"] for r in json.loads(capsys.readouterr().out)["runs"]] == ["x/run", "y/run"]


def test_radius_override(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0]), "--radius", "50", "--format", "json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["radius_m"] == 50.0
    assert report["domains"]["navigation"]["overall_accuracy"]["value"] == 1.0


def test_plots_are_written(runs: tuple[Path, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("matplotlib")
    out_dir = tmp_path / "plots"
    assert main([str(runs[0]), "--compare", str(runs[1]), "--plots", str(out_dir)]) == 0
    written = sorted(p.name for p in out_dir.iterdir())
    assert "metrics_by_domain.png" in written and "errors_all.png" in written
    for name in written:
        data = (out_dir / name).read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) > 5000
    assert "plots:" in capsys.readouterr().err


def test_damaged_episodes_are_listed_not_fatal(runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    victim = sorted(runs[0].iterdir())[0]
    (victim / "final_state.json").unlink()
    with open(victim / "trajectory.jsonl", "a", encoding="utf-8") as fh:
        fh.write('{"tool": "street_mo')
    assert main([str(runs[0])]) == 0
    out = capsys.readouterr().out
    assert "not gradable*" in out and "Problems" in out and victim.name in out


@pytest.mark.parametrize("case", ["missing", "empty", "file", "episode_dir", "runs_parent"])
def test_bad_run_dir_exits_2_with_a_clear_message(case: str, runs: tuple[Path, Path], tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    target = {
        "missing": tmp_path / "nope",
        "empty": tmp_path / "empty",
        "file": tmp_path / "file.txt",
        "episode_dir": next(runs[0].iterdir()),
        "runs_parent": tmp_path,
    }[case]
    (tmp_path / "empty").mkdir()
    (tmp_path / "file.txt").write_text("x")
    code = main([str(target)])
    err = capsys.readouterr().err
    if case == "runs_parent":
        # tmp_path holds run folders, not episodes: still an error pointing at the fix.
        assert code == 2 and "pass a run directory" in err
        return
    assert code == 2
    expected = {"missing": "does not exist", "empty": "holds no episodes", "file": "is a file",
                "episode_dir": "is an episode directory"}[case]
    assert expected in err and "Traceback" not in err


def test_bad_compare_dir_and_bad_radius(runs: tuple[Path, Path], tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(runs[0]), "--compare", str(tmp_path / "gone")]) == 2
    assert "does not exist" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        main([str(runs[0]), "--radius", "-3"])
    assert exc.value.code == 2
    assert "positive number of metres" in capsys.readouterr().err


def test_console_script(runs: tuple[Path, Path]) -> None:
    script = shutil.which("ewa-grade", path=str(Path(sys.executable).parent))
    if script is None:
        pytest.skip("ewa-grade console script not installed (pip install -e .)")
    done = subprocess.run([script, str(runs[1]), "--format", "json"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["domains"]["cooking"]["overall_accuracy"]["value"] == 0.0
    missing = subprocess.run([script, str(runs[1] / "nope")], capture_output=True, text=True, timeout=60)
    assert missing.returncode == 2 and missing.stderr.startswith("ewa-grade: ")
