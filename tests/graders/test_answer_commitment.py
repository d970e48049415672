"""Answers that must commit (docs/grading.md): every text-answer task in tasks/, graded on real records.

An answer listing every candidate of its domain, or hedging between the expected answer and another
candidate, or adding a rival value of the asked kind, fails; a short committed answer in any wording,
and the oracle's answer, pass.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from ewa_mcp.graders import grade_episode
from ewa_mcp.graders.answers import check_text_answer
from ewa_mcp.core.taskmodel import AnswerNumbers, TextAnswer
from ewa_mcp.websites.shop import catalog

from grading_builders import EpisodeBuilder

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def text_tasks() -> dict[str, list[dict[str, Any]]]:
    by_domain: dict[str, list[dict[str, Any]]] = {}
    for path in sorted(TASKS_DIR.glob("*/*.json")):
        for task in json.loads(path.read_text(encoding="utf-8")):
            if (task.get("answer") or {}).get("kind") == "text":
                by_domain.setdefault(task["domain"], []).append(task)
    return by_domain


TASKS = text_tasks()
SHORT_ANSWER_DOMAINS = ("shopping", "traveling")


def graded(tmp_path: Path, task: dict[str, Any], answer: str) -> bool | None:
    return grade_episode(EpisodeBuilder(tmp_path, task).finish(answer=answer).directory).answer_correct


def expected(task: dict[str, Any]) -> str:
    return task["answer"]["must_include"][0]


def oracle_answer(task: dict[str, Any]) -> str:
    return next(c["args"]["answer"] for c in task["oracle"] if c["tool"] == "finish_episode")


def paraphrases(task: dict[str, Any]) -> list[str]:
    """Short, committed answers in other wordings than the oracle's."""
    value = expected(task)
    if task["domain"] == "shopping" and task["id"].startswith("shopping-calories"):
        product = catalog.get_product(task["metadata"]["product_id"])
        size = task["metadata"]["size"]
        return [f"The lower one is {product.name} ({size}), {value} kcal", f"{value} calories per serving.",
                f"{product.name.upper()}: {value} KCAL"]
    if task["domain"] == "shopping":
        return [f"Buy the {value} one.", f"{value.upper()}!", f"The smallest size that is enough is {value}."]
    question = task["metadata"]["question"]
    form = {"year_built": "It was built in {}.", "architect": "Its architect was {}.",
            "architectural_style": "It is {} in style.", "height_m": "It is {} m tall.",
            "opening_hours": "It is open {}."}[question]
    return [form.format(value), form.format(value).upper(), f"“{value}”"]


def rival_value(task: dict[str, Any]) -> str | None:
    """A value of the asked kind that is in no distractor list (another year, another calorie count)."""
    numbers = task["answer"].get("numbers")
    if not numbers:
        return None
    unit = (numbers["units"] or [""])[0]
    low = numbers.get("low") or 0
    value = int(low) + 7 if numbers.get("low") else 997
    while str(value) == expected(task) or str(value) in task["answer"]["distractors"]:
        value += 1
    return f"{value} {unit}".strip()


@pytest.mark.parametrize("domain", SHORT_ANSWER_DOMAINS)
def test_every_text_task_of_the_domain_has_distractors(domain: str) -> None:
    tasks = TASKS.get(domain, [])
    assert tasks, f"no {domain} task with a text answer under {TASKS_DIR}"
    for task in tasks:
        answer = TextAnswer.model_validate(task["answer"])
        assert answer.distractors and answer.max_chars, task["id"]


@pytest.mark.parametrize("domain", SHORT_ANSWER_DOMAINS)
def test_listing_every_candidate_of_the_domain_fails_every_task(tmp_path: Path, domain: str) -> None:
    tasks = TASKS[domain]
    candidates = sorted({p for t in tasks for p in [*t["answer"]["must_include"], *t["answer"]["distractors"]]})
    listing = "; ".join(candidates)
    passed = [t["id"] for t in tasks if graded(tmp_path, t, listing) is not False]
    assert passed == []
    # Not only the length limit: without it the listing still names other candidates.
    for task in tasks:
        check = TextAnswer.model_validate({**task["answer"], "max_chars": None})
        result = check_text_answer(check, listing)
        assert result.met is False and "other candidates" in (result.note or ""), task["id"]


@pytest.mark.parametrize("domain", SHORT_ANSWER_DOMAINS)
def test_hedges_and_rival_values_fail_every_task(tmp_path: Path, domain: str) -> None:
    for task in TASKS[domain]:
        value, other = expected(task), task["answer"]["distractors"][0]
        for answer in (f"{value} or {other}", f"{other}, {value}", f"Not {other}: it is {value}.",
                       f"{value}, maybe {value}0 or so"):
            assert graded(tmp_path, task, answer) is False, (task["id"], answer)
        rival = rival_value(task)
        if rival is not None:
            assert graded(tmp_path, task, f"{value}; {rival}") is False, (task["id"], rival)


@pytest.mark.parametrize("domain", SHORT_ANSWER_DOMAINS)
def test_oracle_and_committed_paraphrases_pass_every_task(tmp_path: Path, domain: str) -> None:
    for task in TASKS[domain]:
        for answer in (oracle_answer(task), *paraphrases(task)):
            assert graded(tmp_path, task, answer) is True, (task["id"], answer)


# ------------------------------------------------------------------ the rule, case by case
STYLES = ["Modernism", "Late Modernism", "Gothic Revival", "Venetian Gothic", "Georgian", "Art Deco"]
YEARS = AnswerNumbers(low=1000, high=2100)


def style_check(value: str) -> TextAnswer:
    return TextAnswer(must_include=[value], distractors=[s for s in STYLES if s != value], max_chars=200)


@pytest.mark.parametrize(
    ("value", "answer", "met"),
    [
        ("Modernism", "Modernism", True),
        ("Modernism", "Late Modernism", False),           # a distractor containing the expected phrase
        ("Late Modernism", "late modernism.", True),      # the expected phrase containing a distractor
        ("Late Modernism", "Modernism", False),
        ("Georgian", "Not Gothic Revival, it is Georgian", False),  # a negation still names a candidate
        ("Georgian", "It's not Georgian", False),         # a denial
        ("Georgian", "GEORGIAN", True),
        ("Georgian", "Georgian/Federal", False),          # a hedge with a value outside the list
        ("Georgian", "Georgian, or perhaps Federal", False),
        ("Art Deco", "art-déco", True),                   # punctuation and diacritics
        ("Georgian", "Georgian " + "and very pretty " * 20, False),  # over 200 characters
    ],
)
def test_style_answers(value: str, answer: str, met: bool) -> None:
    assert check_text_answer(style_check(value), answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("It was built in 1713.", True), ("1713 or 1720", False), ("1713, opened in 1714", False),
     ("1,713", True), ("1713 (about 300 years ago)", True), ("built in 1713 and renovated in 1992", False)],
)
def test_year_answers(answer: str, met: bool) -> None:
    check = TextAnswer(must_include=["1713"], distractors=["1720"], numbers=YEARS, max_chars=200)
    assert check_text_answer(check, answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("The lower one is Oat Milk (1 L), 120 kcal", True), ("120.0 calories per 1 cup (240 ml)", True),
     ("120 kcal, Almond Milk has 140", False), ("120 kcal or 130 kcal", False), ("120 and 135 kcal", False),
     ("Oat Milk", False), ("Oat Milk (2 L): 120 kcal", True), ("12 kcal", False)],
)
def test_calorie_answers(answer: str, met: bool) -> None:
    check = TextAnswer(must_include=["120"], distractors=["140", "Almond Milk"],
                       context=["Oat Milk", "1 L", "2 L", "1 cup (240 ml)"],
                       numbers=AnswerNumbers(units=["kcal", "calories"]), max_chars=200)
    assert check_text_answer(check, answer).met is met


@pytest.mark.parametrize(
    ("answer", "met"),
    [("Oat Milk (1 L)", True), ("Oat Milk (2 L)", False), ("oat milk", False), ("Oat Milk & Oat Milk (2 L)", False)],
)
def test_a_distractor_that_extends_the_expected_phrase(answer: str, met: bool) -> None:
    check = TextAnswer(must_include=["Oat Milk (1 L)"], distractors=["Oat Milk (2 L)", "Oat Milk"], max_chars=200)
    assert check_text_answer(check, answer).met is met


def test_aliases_are_other_wordings_of_the_expected_answer() -> None:
    check = TextAnswer(must_include=["29 oz"], aliases={"29 oz": ["29 ounces"]}, distractors=["15.5 oz"],
                       numbers=AnswerNumbers(units=["oz", "ounces"], bare=False), max_chars=200)
    assert check_text_answer(check, "29 ounces").met is True
    assert check_text_answer(check, "29 oz, not 15.5 oz").met is False
    assert check_text_answer(check, "29 oz or 30 oz").met is False
    assert check_text_answer(check, "29 oz; 30 oz").met is False
