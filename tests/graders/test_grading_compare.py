"""ewa-grade A --compare B: a difference column beside the runs, and a paired comparison over the tasks both runs
played with McNemar's exact test."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from grading_builders import EpisodeBuilder, make_task

from ewa_mcp.graders.cli import main
from ewa_mcp.graders.stats import mcnemar_exact


def test_mcnemar_exact_known_values() -> None:
    assert mcnemar_exact(0, 0) == 1.0  # no discordant task: nothing tells the runs apart
    assert mcnemar_exact(0, 5) == pytest.approx(2 / 32)  # five of five discordant tasks one way
    assert mcnemar_exact(1, 9) == pytest.approx(2 * (1 + 10) / 1024)
    assert mcnemar_exact(9, 1) == mcnemar_exact(1, 9)
    assert mcnemar_exact(3, 3) == 1.0
    # Against the binomial distribution summed by hand: P(X <= 4) for X ~ Bin(15, 1/2), doubled.
    assert mcnemar_exact(4, 11) == pytest.approx(2 * sum(math.comb(15, k) for k in range(5)) / 2 ** 15)
    with pytest.raises(ValueError):
        mcnemar_exact(-1, 2)


def answer_task(task_id: str, domain: str) -> dict:
    return make_task(task_id, domain, answer={"kind": "text", "must_include": ["yes"]})


def build(run: Path, passes: dict[str, bool], domain_of: dict[str, str]) -> Path:
    for task_id, ok in passes.items():
        EpisodeBuilder(run, answer_task(task_id, domain_of[task_id])).call("finish_episode").finish(
            answer="yes" if ok else "no")
    return run


@pytest.fixture
def two_runs(tmp_path: Path) -> tuple[Path, Path]:
    """Twelve traveling tasks: A passes 0-5, B passes 0-1 and 6-11; a geolocation task only A played, and one
    only B played. So on the 12 shared tasks: both 2, only A 4, only B 6, neither 0."""
    shared = {f"travel-{k:02d}": "traveling" for k in range(12)}
    domains = {**shared, "geo-a": "geolocation", "geo-b": "geolocation"}
    a = {t: int(t[-2:]) < 6 for t in shared} | {"geo-a": True}
    b = {t: int(t[-2:]) < 2 or int(t[-2:]) >= 6 for t in shared} | {"geo-b": False}
    return build(tmp_path / "model-a", a, domains), build(tmp_path / "model-b", b, domains)


def test_the_table_has_a_difference_column(two_runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(two_runs[0]), "--compare", str(two_runs[1])]) == 0
    out = capsys.readouterr().out
    header = next(line for line in out.splitlines() if line.startswith("Domain  "))
    assert header.split("  ")[0] == "Domain" and header.rstrip().endswith("Δ model-b − model-a")
    traveling = out.split("traveling", 1)[1]
    overall = next(line for line in traveling.splitlines() if "Overall Accuracy" in line)
    assert overall.split()[-1] == "+16.7"  # 8/12 - 6/12
    geo = out.split("geolocation", 1)[1]
    assert next(line for line in geo.splitlines() if "Overall Accuracy" in line).split()[-1] == "-100.0"


def test_the_paired_comparison_uses_shared_tasks_only(two_runs: tuple[Path, Path],
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(two_runs[0]), "--compare", str(two_runs[1])]) == 0
    out = capsys.readouterr().out
    paired = out.split("Paired comparison over shared tasks (McNemar's exact test)", 1)[1].split("\n\n", 1)[0]
    rows = {line.split()[0]: line.split() for line in paired.splitlines()
            if line.startswith(("all ", "traveling "))}
    p = mcnemar_exact(4, 6)
    assert rows["all"][-7:] == ["12", "2", "4", "6", "0", "+16.7", f"{p:.3f}"]
    assert rows["traveling"][-7:] == rows["all"][-7:]
    assert "geolocation  model-b vs model-a" not in paired  # no geolocation task was played by both

    assert main([str(two_runs[0]), "--compare", str(two_runs[1]), "--format", "json"]) == 0
    (everything, traveling) = json.loads(capsys.readouterr().out)["comparisons"]
    assert (everything["domain"], everything["shared_tasks"], everything["only_baseline"],
            everything["only_other"]) == ("all", 12, 4, 6)
    assert everything["p_value"] == pytest.approx(p) and everything["difference"] == pytest.approx(2 / 12)
    assert traveling["domain"] == "traveling"


def test_a_single_run_has_neither(two_runs: tuple[Path, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(two_runs[0])]) == 0
    out = capsys.readouterr().out
    assert "Δ" not in out and "Paired comparison" not in out
