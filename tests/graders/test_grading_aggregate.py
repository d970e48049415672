"""Aggregates, intervals and error percentages: known values and properties (hypothesis)."""

from __future__ import annotations

from pathlib import Path

import pytest
from grading_builders import EpisodeBuilder, kitchen_state, kitchen_task, make_task, obj, recipe_step
from hypothesis import given, settings
from hypothesis import strategies as st

from ewa_mcp.graders import grade_run
from ewa_mcp.graders.aggregate import domain_aggregate, error_breakdown
from ewa_mcp.graders.models import EpisodeResult, ErrorClassification
from ewa_mcp.graders.stats import mean_t_interval, student_t_quantile, wilson_interval


# ------------------------------------------------------------------ intervals against published values
@pytest.mark.parametrize(("df", "table_value"), [(1, 12.706), (2, 4.303), (5, 2.571), (10, 2.228), (30, 2.042),
                                                 (120, 1.980)])
def test_t_quantile_matches_the_printed_t_table(df: int, table_value: float) -> None:
    assert student_t_quantile(0.975, df) == pytest.approx(table_value, abs=5e-4)


def test_wilson_matches_known_values() -> None:
    # Newcombe (1998), Table I: 1/29 -> 0.0061–0.1718 (Wilson, no continuity correction); 0/10 -> 0–0.2775.
    assert wilson_interval(1, 29) == pytest.approx((0.0061, 0.1718), abs=1e-4)
    assert wilson_interval(0, 10) == pytest.approx((0.0, 0.2775), abs=1e-4)
    with pytest.raises(ValueError, match="successes <= n"):
        wilson_interval(5, 3)


def test_t_interval_textbook_example() -> None:
    mean, low, high = mean_t_interval([0.2, 0.4, 0.6, 0.8], lower=-10, upper=10)
    # mean 0.5, s = 0.2582, s/sqrt(4) = 0.1291, t(3) = 3.182 -> ±0.4108
    assert (mean, low, high) == pytest.approx((0.5, 0.0892, 0.9108), abs=2e-4)
    assert mean_t_interval([0.7]) == (0.7, 0.0, 1.0)  # one value: spread unknown


# ------------------------------------------------------------------ a hand-built run with known aggregates
def test_domain_aggregates_and_error_percentages(tmp_path: Path) -> None:
    run = tmp_path / "run-a"
    goals = [{"kind": "object_state", "object_type": "Apple", "prop": "isSliced"}]
    web = [{"kind": "recipe_completed", "recipe_id": "r"}]
    sliced = kitchen_state([obj("AppleSliced", 0, source="Apple")])
    whole = kitchen_state([obj("Apple")])
    # 1 full success, 1 web-only success (stuck in web), 2 total failures (unclassified), 1 demo.
    EpisodeBuilder(run, kitchen_task(embodied_goals=goals, web_goals=web)).event(**recipe_step("r", 2, 2)).switch(
        "embodied").call("kitchen_slice").finish(embodied=sliced)
    EpisodeBuilder(run, kitchen_task(embodied_goals=goals, web_goals=web)).call("browser_click").event(
        **recipe_step("r", 2, 2)).finish(embodied=whole)
    for _ in range(2):
        EpisodeBuilder(run, kitchen_task(embodied_goals=goals, web_goals=web)).call("browser_click").switch(
            "embodied").call("kitchen_pickup").finish(embodied=whole)
    EpisodeBuilder(run, make_task("demo-1", "demo", answer={"kind": "text", "must_include": ["hello"]})).finish(
        answer="hello")
    report = grade_run(run)
    assert report.n_episodes == 5 and list(report.domains) == ["cooking"]
    cooking = report.domains["cooking"]
    assert (cooking.overall_accuracy.successes, cooking.overall_accuracy.n) == (1, 4)
    assert cooking.web_only_accuracy is not None and cooking.web_only_accuracy.value == 0.5
    assert cooking.embodied_only_accuracy is not None and cooking.embodied_only_accuracy.value == 0.25
    assert cooking.completion_rate.value == pytest.approx((1 + 0.5 + 0 + 0) / 4)
    assert cooking.answer_accuracy is None and cooking.navigation is None
    assert report.demo is not None and report.demo.overall_accuracy.value == 1.0
    errors = report.errors["cooking"]
    assert errors.failures == 3
    assert errors.by_category["stuck_in_web"] == 1 and errors.by_category["unclassified"] == 2
    assert errors.percent_by_group["cross_domain"] == pytest.approx(33.33, abs=0.01)
    assert report.errors["all"].failures == 3  # demo excluded


def test_web_only_is_na_for_a_domain_without_web_goals(tmp_path: Path) -> None:
    task = make_task("q", "traveling", answer={"kind": "text", "must_include": ["x"]})
    EpisodeBuilder(tmp_path / "run", task).finish(answer="x")
    agg = grade_run(tmp_path / "run").domains["traveling"]
    assert agg.web_only_accuracy is None and agg.embodied_only_accuracy is None
    assert agg.answer_accuracy is not None and agg.answer_accuracy.value == 1.0


# ------------------------------------------------------------------ properties
CATEGORY = st.sampled_from(["stuck_in_web", "stuck_in_embodied", "web_page_loop", "failed_to_reach_object",
                            "wrong_answer", "unclassified"])
GROUP = {"stuck_in_web": "cross_domain", "stuck_in_embodied": "cross_domain", "web_page_loop": "web_only",
         "failed_to_reach_object": "embodied_only", "wrong_answer": "other", "unclassified": "other"}


@st.composite
def episodes(draw: st.DrawFn) -> EpisodeResult:
    has_web, has_embodied, has_answer = draw(st.booleans()), draw(st.booleans()), draw(st.booleans())
    n_web = draw(st.integers(1, 3)) if has_web else 0
    n_emb = draw(st.integers(1, 4)) if has_embodied else 0
    web_met = draw(st.integers(0, n_web))
    emb_met = draw(st.integers(0, n_emb))
    answer = draw(st.booleans()) if has_answer else None
    known = draw(st.booleans()) or not (has_web or has_embodied)  # sometimes the embodied state is missing
    web_ok = web_met == n_web
    emb_ok: bool | None = emb_met == n_emb if known or emb_met < n_emb else None
    parts = [web_ok, emb_ok] + ([answer] if has_answer else [])
    overall = False if False in parts else (None if None in parts else True)
    total = n_web + n_emb + int(has_answer)
    met = web_met + emb_met + int(answer is True)
    category = draw(CATEGORY)
    return EpisodeResult(
        episode_id=f"ep-{draw(st.integers(0, 10**9))}", task_id="t", domain="cooking", status="finished",
        gradable=overall is not None, has_web_goals=has_web, has_embodied_goals=has_embodied,
        answer_checked=has_answer, web_success=web_ok, embodied_success=emb_ok, answer_correct=answer,
        overall_success=overall, completion=met / total if total else None, conditions_met=met,
        conditions_total=total, conditions=[], steps=draw(st.integers(0, 60)), calls=0,
        switches=draw(st.integers(0, 10)), wall_time_s=None,
        error=None if overall is True else ErrorClassification(category=category, group=GROUP[category],
                                                               matched=[category]),
    )


@settings(max_examples=150, deadline=None)
@given(st.lists(episodes(), min_size=1, max_size=40))
def test_aggregate_properties(eps: list[EpisodeResult]) -> None:
    agg = domain_aggregate("cooking", eps)
    proportions = [p for p in (agg.overall_accuracy, agg.web_only_accuracy, agg.embodied_only_accuracy,
                               agg.answer_accuracy) if p is not None]
    for p in [*proportions, agg.completion_rate]:
        assert p.value is not None and 0.0 <= p.value <= 1.0
        assert 0.0 <= p.ci_low <= p.value <= p.ci_high <= 1.0
    for side in (agg.web_only_accuracy, agg.embodied_only_accuracy):
        if side is not None:
            assert agg.overall_accuracy.value <= side.value
    assert agg.n == len(eps) and agg.n_ungradable == sum(not e.gradable for e in eps)

    breakdown = error_breakdown(eps)
    assert breakdown.failures == sum(e.overall_success is not True for e in eps)
    if breakdown.failures:
        assert sum(breakdown.percent_by_category.values()) == pytest.approx(100.0, abs=0.05)
        assert sum(breakdown.percent_by_group.values()) == pytest.approx(100.0, abs=0.05)
        assert sum(breakdown.by_group.values()) == breakdown.failures


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 500).flatmap(lambda n: st.tuples(st.integers(0, n), st.just(n))))
def test_wilson_contains_the_estimate(pair: tuple[int, int]) -> None:
    successes, n = pair
    low, high = wilson_interval(successes, n)
    assert 0.0 <= low <= high <= 1.0
    if n:
        assert low <= successes / n <= high


@settings(max_examples=100, deadline=None)
@given(st.lists(st.floats(0, 1), min_size=2, max_size=60))
def test_t_interval_contains_the_mean_and_narrows_with_more_data(values: list[float]) -> None:
    mean, low, high = mean_t_interval(values)
    assert 0.0 <= low <= mean <= high <= 1.0
    _, low4, high4 = mean_t_interval(values * 4)  # same spread, four times the data
    assert high4 - low4 <= high - low + 1e-12


def test_results_break_down_by_difficulty(tmp_path: Path) -> None:
    from grading_builders import EpisodeBuilder, kitchen_state, kitchen_task, obj

    from ewa_mcp.graders import grade_run, render_report

    goals = [{"kind": "object_state", "object_type": "Bread", "prop": "isCooked"}]
    for n, (level, cooked) in enumerate([("easy", True), ("easy", False), ("hard", False)]):
        task = kitchen_task(f"cook-{n}", embodied_goals=goals, difficulty=level)
        ep = EpisodeBuilder(tmp_path, task).call("start_episode", counted=False)
        ep.finish(embodied=kitchen_state([obj("Bread", isCooked=cooked)]))
    report = grade_run(tmp_path)
    levels = report.by_difficulty["cooking"]
    assert set(levels) == {"easy", "hard"}
    assert (levels["easy"].n, levels["easy"].overall_accuracy.successes) == (2, 1)
    assert (levels["hard"].n, levels["hard"].overall_accuracy.successes) == (1, 0)
    assert {e.difficulty for e in report.episodes} == {"easy", "hard"}
    text = render_report(report)
    assert "By difficulty" in text and "50.0" in text
