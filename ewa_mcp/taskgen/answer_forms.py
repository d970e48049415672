"""Natural answer forms: how careful agents write a correct answer, for every answer-bearing task.

The answer rule (docs/grading.md) must accept them: framing sentences, units and their conversions,
accepted aliases, the price or order number beside a calorie count, the address beside a year, opening
hours in other words. ``false_negatives`` grades every form of every task and returns the ones that
fail; tests/graders/test_answer_forms.py holds the rate at 1 % or less, and

    python -m ewa_mcp.taskgen.answer_forms [TASKS_DIR]

prints the rate per kind of question and the failing forms.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Iterable
from pathlib import Path

from ..graders.answers import check_text_answer
from ..core.taskmodel import Task, TaskStore, TextAnswer

DAY_NAMES = {"Mon": "Monday", "Tue": "Tuesday", "Wed": "Wednesday", "Thu": "Thursday", "Fri": "Friday",
             "Sat": "Saturday", "Sun": "Sunday"}
# Framings any short answer may come in; {v} is the answer.
FRAMINGS = ("{v}", "{v}.", "Answer: {v}", "The answer is {v}.", "“{v}”", "**{v}**", "{v} (according to the wiki)")


def kind_of(task: Task) -> str:
    """The kind of question: the traveling question key, shopping-size, shopping-calories, or text."""
    if task.domain == "traveling":
        return str(task.metadata.get("question", "text"))
    if task.id.startswith("shopping-calories"):
        return "calories"
    if task.id.startswith("shopping-size"):
        return "size"
    return "text"


def _twelve_hour(match: re.Match[str]) -> str:
    hour, minute = int(match.group(1)), int(match.group(2))
    if hour in (0, 24) and minute == 0:
        return "midnight"
    if hour == 12 and minute == 0:
        return "noon"
    half = "am" if hour % 24 < 12 else "pm"
    shown = hour % 12 or 12
    return f"{shown}{':%02d' % minute if minute else ''} {half}"


def reworded_hours(value: str) -> list[str]:
    """The same hours in other words: 12-hour times, "to" for the dash, spelled-out days."""
    times = re.sub(r"(\d{1,2}):(\d{2})", _twelve_hour, value)
    times = re.sub(r"(?<=m|n|t)\s*-\s*(?=\d|noon|midnight)", " to ", times)
    spelled = re.sub(r"\b(Mon|Tue|Wed|Thu|Fri|Sat|Sun)\b", lambda m: DAY_NAMES[m.group(1)], times)
    spelled = re.sub(r"(day)-(?=[A-Z])", r"\1 to ", spelled)
    every = spelled.replace("daily", "every day")
    return list(dict.fromkeys([value.replace("-", "–"), f"Open {value}.", times, spelled, every,
                               f"It is open {every}."]))


def _address(task: Task) -> str | None:
    m = re.search(r"Walk to ([^:]+):", task.intent)
    return m.group(1).strip() if m else None


def natural_forms(task: Task) -> list[str]:
    """Correct answers to the task as careful agents write them (the expected value in many wordings)."""
    check = task.answer
    if not isinstance(check, TextAnswer) or not check.must_include:
        return []
    value = check.must_include[0]
    aliases = check.aliases.get(value, [])
    kind = kind_of(task)
    forms = [f.format(v=v) for v in [value, *aliases] for f in FRAMINGS]
    forms += [value.upper(), value.lower()]
    if kind == "year_built":
        forms += [f"It was built in {value}.", f"Built in {value}", f"Year built: {value}", f"It dates from {value}."]
        address = _address(task)
        if address:
            forms += [f"{value} (the building at {address})", f"Built in {value} at {address}."]
    elif kind == "architect":
        forms += [f"Its architect was {v}." for v in [value, *aliases]] + [f"Designed by {value}", f"Architect: {value}"]
    elif kind == "architectural_style":
        forms += [f"It is {value} in style.", f"{value} style", f"The style is {value}.", f"{value} architecture"]
    elif kind == "height_m":
        feet = round(float(value) * 3.28084)
        forms += [f"{value} m", f"{value} metres", f"It is {value} meters tall.", f"{value} m ({feet} ft)",
                  f"About {value} m ({feet} feet)", f"{value} m / {feet} ft", f"{value} metres, or about {feet} feet",
                  f"Height: {value} m"]
    elif kind == "opening_hours":
        forms += reworded_hours(value)
    elif kind == "size":
        forms += [f"The {v} size." for v in [value, *aliases]] + [f"Buy the {value} one.",
                                                                 f"The smallest size that is enough is {value}."]
        product = check.context[0] if check.context else ""
        if product:
            forms += [f"{product} ({value})", f"{product}, {value}"]
    elif kind == "calories":
        product = check.context[0] if check.context else "it"
        size = check.context[1] if len(check.context) > 1 else ""
        forms += [f"{value} kcal", f"{value} calories per serving", f"{value} cal/serving", f"{value} Calories.",
                  f"{product}: {value} kcal per serving",
                  f"{value} kcal. Ordered {product} ({size}) for $2.49, order EWA-1001.",
                  f"{value} calories (order #1002, total $3.99)"]
        if len(check.context) > 2:
            forms.append(f"{value} calories per serving ({check.context[-1]})")
    return list(dict.fromkeys(f for f in forms if f.strip()))


def false_negatives(tasks: Iterable[Task]) -> tuple[int, list[tuple[str, str, str]]]:
    """(forms graded, the failing ones as (task id, form, the grader's note))."""
    graded = 0
    failed: list[tuple[str, str, str]] = []
    for task in tasks:
        if not isinstance(task.answer, TextAnswer):
            continue
        for form in natural_forms(task):
            graded += 1
            result = check_text_answer(task.answer, form)
            if not result.met:
                failed.append((task.id, form, result.note or ""))
    return graded, failed


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    root = Path(args[0]) if args else Path(__file__).resolve().parents[2] / "tasks"
    tasks = sorted(TaskStore([root]).all(), key=lambda t: t.id)
    by_kind: dict[str, list[Task]] = {}
    for task in tasks:
        if isinstance(task.answer, TextAnswer):
            by_kind.setdefault(f"{task.domain}/{kind_of(task)}", []).append(task)
    total, all_failed = 0, []
    print(f"{'kind':32} {'tasks':>6} {'forms':>7} {'fail':>6} {'rate':>7}")
    for kind, group in sorted(by_kind.items()):
        graded, failed = false_negatives(group)
        total += graded
        all_failed += failed
        print(f"{kind:32} {len(group):6d} {graded:7d} {len(failed):6d} {100 * len(failed) / max(1, graded):6.2f}%")
    print(f"{'all':32} {sum(map(len, by_kind.values())):6d} {total:7d} {len(all_failed):6d} "
          f"{100 * len(all_failed) / max(1, total):6.2f}%")
    for task_id, form, note in all_failed[:40]:
        print(f"  {task_id}: {form!r} -> {note}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
