"""Answer checks that make an answer commit (docs/grading.md, "Answers that must commit").

A generator names the expected answer and every candidate it must be told apart from; these helpers
drop candidates that read the same as the expected answer, so a check never contradicts itself, and
phrase the sentence every short-answer intent ends with.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..graders.hours import schedule
from ..graders.textnorm import tokens
from ewa_mcp.core.taskmodel import AnswerNumbers, TextAnswer

# Longest answer that still counts as a short answer; the intent says so.
SHORT_ANSWER_CHARS = 200
YEARS = AnswerNumbers(low=1000, high=2100)
CALORIES = AnswerNumbers(units=["kcal", "cal", "cals", "calorie", "calories", "kilocalories"])
METRES = AnswerNumbers(units=["m", "metre", "metres", "meter", "meters"])


def answer_rule(form: str) -> str:
    """The closing sentence of a short-answer intent: the form of the answer and how it is read."""
    return (f"{form} Reply in at most {SHORT_ANSWER_CHARS} characters and name only your answer: "
            "naming another candidate, even to rule it out, or hedging counts as wrong.")


def _key(text: str) -> tuple[str, ...]:
    return tuple(tokens(text))


def committed_answer(expected: str, distractors: Iterable[str], *, aliases: Iterable[str] = (),
                     context: Iterable[str] = (), numbers: AnswerNumbers | None = None) -> TextAnswer:
    """A check passing a short answer that names ``expected`` (or an alias) and no distractor."""
    own = _key(expected)
    hours = schedule(expected)
    others: dict[tuple[str, ...], str] = {}
    for d in distractors:
        # Hours that state the same schedule read the same ("daily 9:00-17:00 (timed tickets)").
        if _key(d) and _key(d) != own and (hours is None or schedule(d) != hours):
            others.setdefault(_key(d), d)
    kept_aliases = list(dict.fromkeys(a for a in aliases if _key(a) and _key(a) != own and _key(a) not in others))
    kept_context = list(dict.fromkeys(c for c in context if _key(c) and _key(c) not in others
                                      and _key(c) != own))
    return TextAnswer(must_include=[expected], aliases={expected: kept_aliases} if kept_aliases else {},
                      distractors=sorted(others.values(), key=lambda d: (_key(d), d)), context=kept_context,
                      numbers=numbers, max_chars=SHORT_ANSWER_CHARS)
