"""The answer rule on every answer-bearing task in tasks/ (docs/grading.md, docs/verified.md).

Correct answers in the forms careful agents write (framing sentences, units and conversions, aliases, the
order number beside the calories, the address beside the year, reworded hours) fail at most 1 % of the
time; every other candidate, in every spelling any task accepts for it, fails.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import pytest

from ewa_mcp.graders.answers import check_text_answer
from ewa_mcp.graders.hours import schedule
from ewa_mcp.envs.geo.names import cities_match
from ewa_mcp.taskgen.answer_checks import CALORIES, METRES, YEARS
from ewa_mcp.taskgen.answer_forms import false_negatives, kind_of, natural_forms, reworded_hours
from ewa_mcp.envs.street.taskgen.traveling import names_of
from ewa_mcp.core.taskmodel import Task, TaskStore, TextAnswer

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"
TASKS = [t for t in sorted(TaskStore([TASKS_DIR]).all(), key=lambda t: t.id) if isinstance(t.answer, TextAnswer)]
SHORT = [t for t in TASKS if t.domain in ("shopping", "traveling")]


def check(task: Task) -> TextAnswer:
    assert isinstance(task.answer, TextAnswer)
    return task.answer


def test_natural_forms_of_correct_answers_fail_at_most_one_percent() -> None:
    graded, failed = false_negatives(TASKS)
    assert graded > 15 * len(SHORT)  # many forms per task, not a token sample
    assert len(failed) <= graded // 100, failed[:20]


def test_natural_forms_cover_every_kind_of_question() -> None:
    kinds = {kind_of(t) for t in SHORT}
    assert {"calories", "size", "year_built", "architect", "architectural_style", "opening_hours"} <= kinds
    for task in SHORT:
        assert len(natural_forms(task)) >= 10, task.id


def test_every_distractor_fails_alone_and_framed() -> None:
    for task in SHORT:
        for rival in check(task).distractors:
            for answer in (rival, f"The answer is {rival}."):
                assert check_text_answer(check(task), answer).met is False, (task.id, answer)


def _accepted_names(task: Task) -> list[str]:
    value = check(task).must_include[0]
    return [value, *check(task).aliases.get(value, [])]


def test_every_rival_answer_and_alias_fails() -> None:
    """What another task of the same question accepts, this task rejects (unless both expect the same)."""
    groups: dict[tuple[str, str], list[Task]] = defaultdict(list)
    for task in SHORT:
        kind = kind_of(task)
        groups[(kind, task.metadata.get("product_id", "") if kind == "size" else "")].append(task)
    checked = 0
    for group in groups.values():
        for task in group:
            own = check(task).must_include[0]
            for other in group:
                if check(other).must_include[0] == own:
                    continue
                for name in _accepted_names(other):
                    if name in _accepted_names(task):
                        continue
                    checked += 1
                    assert check_text_answer(check(task), name).met is False, (task.id, other.id, name)
    assert checked > 1000


def test_no_alias_is_shared_with_another_candidate_or_a_common_word() -> None:
    by_kind: dict[str, dict[str, set[str]]] = defaultdict(lambda: defaultdict(set))
    for task in SHORT:
        if task.domain != "traveling":
            continue
        value = check(task).must_include[0]
        for alias in check(task).aliases.get(value, []):
            by_kind[kind_of(task)][alias.casefold()].add(value)
            if kind_of(task) == "architect":
                assert alias[:1].isupper() and len(alias.split()) >= 2, (task.id, alias)
                assert not any(ch.isdigit() for ch in alias), (task.id, alias)
    for kind, aliases in by_kind.items():
        shared = {a: v for a, v in aliases.items() if len(v) > 1}
        assert not shared, (kind, shared)


@pytest.mark.parametrize(
    ("value", "aliases", "related"),
    [
        ("Theodate Pope Riddle (reconstruction)", ["Theodate Pope Riddle"], []),
        ("H. H. Richardson", ["Henry Hobson Richardson"], []),
        ("Ammi B. Young (1847); Peabody & Stearns (tower, 1915)",
         ["Ammi B. Young Peabody & Stearns", "Ammi B. Young and Peabody & Stearns"], []),
        ("Carrère and Hastings", [], ["Thomas Hastings", "John Merven Carrère"]),
    ],
)
def test_aliases_are_real_names_of_the_answer(value: str, aliases: list[str], related: list[str]) -> None:
    got_aliases, got_related = names_of("architect", value)
    assert got_aliases[:len(aliases)] == aliases and set(related) <= set(got_related)
    assert not {"reconstruction", "planting", "tower, 1915"} & set(got_aliases)


# ------------------------------------------------------------------ the rule, case by case
@pytest.mark.parametrize(
    ("answer", "met"),
    [("45 cal/serving", True), ("45 kcal. Ordered it for $1.40, order EWA-1140.", True),
     ("45 calories (order #1001, total $3.99)", True), ("45 kcal, order number 1002", True),
     ("45 kcal, 140 kcal", False), ("45 or 140 kcal", False), ("45/140 kcal", False), ("45 kcal, maybe 50", False)],
)
def test_prices_and_order_numbers_are_not_calorie_values(answer: str, met: bool) -> None:
    rule = TextAnswer(must_include=["45"], distractors=["140", "Almond Milk"], numbers=CALORIES, max_chars=200)
    assert check_text_answer(rule, answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("46 m (151 ft)", True), ("46 m / 151 ft", True), ("46 metres, or about 151 feet", True),
     ("46 ft", False), ("151 m", False), ("46 m or 151 m", False), ("46 m (151 m with the spire)", False)],
)
def test_a_height_with_its_conversion_to_feet(answer: str, met: bool) -> None:
    rule = TextAnswer(must_include=["46"], distractors=["151", "100"], numbers=METRES, max_chars=200)
    assert check_text_answer(rule, answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("Built in 1883 at 1401 Chestnut Street", True), ("1883 (206 Washington St)", True),
     ("1883, at 350 5th Ave", True), ("1883 on Market Street, opened 1885", False), ("1883 or 1401", False)],
)
def test_a_year_with_the_street_address(answer: str, met: bool) -> None:
    rule = TextAnswer(must_include=["1883"], distractors=["1401", "1713"], numbers=YEARS, max_chars=200)
    assert check_text_answer(rule, answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("Open every day from 6 am to 11:30 pm", True), ("6:00–23:30, 7 days a week", True),
     ("Daily, 6 AM - 11:30 PM", True), ("daily 6:00-23:00", False), ("6 am to 11 pm daily", False),
     ("always open", False), ("Mon-Fri 6:00-23:30", False)],
)
def test_reworded_opening_hours(answer: str, met: bool) -> None:
    rule = TextAnswer(must_include=["daily 6:00-23:30"], distractors=["daily 6:00-23:00", "always open"],
                      max_chars=200)
    assert check_text_answer(rule, answer).met is met


@pytest.mark.parametrize(
    ("a", "b", "same"),
    [("Mon-Sat 10:00-18:00, Sun 13:00-17:00", "10 am to 6 pm Monday to Saturday, 1 to 5 pm on Sunday", True),
     ("Wed-Mon 11:00-18:00", "Closed Tuesdays; Wednesday to Monday 11 am-6 pm", True),
     ("observation deck daily 9:00-24:00", "The observation deck is open daily from 9 a.m. to midnight", True),
     ("always open", "open 24 hours", True), ("Mon-Fri 9:00-17:00", "weekdays 9-5 pm", True),
     ("Mon-Fri 9:00-17:00", "Mon-Sat 9:00-17:00", False), ("daily 5:00-1:00", "daily 5:00-13:00", False)],
)
def test_hours_are_compared_as_schedules(a: str, b: str, same: bool) -> None:
    assert (schedule(a) == schedule(b)) is same
    assert schedule(a) is not None


def test_text_that_is_not_hours_has_no_schedule() -> None:
    for text in ("1713", "H. H. Richardson", "45 kcal", "29 oz", "9-5", "Rapp and Rapp"):
        assert schedule(text) is None, text


def test_reworded_hours_read_as_the_same_schedule() -> None:
    for value in ("Mon-Sat 10:00-18:00, Sun 13:00-17:00", "daily 5:15-2:00", "Wed-Sun 10:30-16:30"):
        for form in reworded_hours(value):
            assert schedule(form) == schedule(value), form


@pytest.mark.parametrize(
    ("answer", "met"),
    [("Paris", True), ("Paris, France", True), ("Paris, FR", True), ("Paris, Texas", False),
     ("Lyon, France", False), ("France", False)],
)
def test_city_country_in_the_city_field_is_the_city(answer: str, met: bool) -> None:
    assert cities_match(answer, "Paris", "France", 48.8566, 2.3522) is met
