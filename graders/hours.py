"""Opening hours read as a schedule, so reworded hours name the same answer (docs/grading.md).

"daily 6:00-23:30", "Open every day from 6 am to 11:30 pm" and "6:00–23:30, 7 days a week" are one
schedule; "Mon-Fri 9:00-17:00" and "Monday to Friday, 9 am - 5 pm" another. A schedule is the set of
(weekday, opens, closes) triples, minutes after midnight (closing at midnight is 0, so "9:00-24:00" and
"9 am to midnight" agree). Text that is not hours (a year, a name) has no schedule: ``schedule`` returns
None and the answer is compared word by word as before.
"""

from __future__ import annotations

import re
import unicodedata

Schedule = frozenset[tuple[int, int, int]]

_DAYS = {"mon": 0, "monday": 0, "mondays": 0, "tue": 1, "tues": 1, "tuesday": 1, "tuesdays": 1, "wed": 2,
         "weds": 2, "wednesday": 2, "wednesdays": 2, "thu": 3, "thur": 3, "thurs": 3, "thursday": 3,
         "thursdays": 3, "fri": 4, "friday": 4, "fridays": 4, "sat": 5, "saturday": 5, "saturdays": 5,
         "sun": 6, "sunday": 6, "sundays": 6}
_DAY = "|".join(sorted(_DAYS, key=len, reverse=True))
_ALL_WEEK = r"daily|every\s*day|each\s*day|(?:7|seven)\s*days\s*(?:a|per|of\s*the)\s*week|all\s*week(?:\s*long)?"
_ALWAYS = r"always\s*open|open\s*24\s*(?:hours|h|hrs)(?:\s*a\s*day)?|24\s*/\s*7|24\s*hours(?:\s*a\s*day)?|round\s*the\s*clock|around\s*the\s*clock"
_TIME = r"(?:\d{1,2}(?::\d{2})?\s*(?:a\.?\s*m\.?|p\.?\s*m\.?)|\d{1,2}:\d{2}|noon|midday|midnight)"
_RANGE_SEP = r"\s*(?:-|–|—|to|until|till|til|through|thru)\s*"
_TOKEN = re.compile(
    rf"(?P<closed>closed\s*(?:on\s*)?(?:{_DAY})\b\.?(?:\s*(?:,|and|&|{_RANGE_SEP})\s*(?:{_DAY})\b\.?)*)"
    rf"|(?P<always>{_ALWAYS})"
    rf"|(?P<dayrange>\b(?:{_DAY})\b\.?{_RANGE_SEP}\b(?:{_DAY})\b\.?)"
    rf"|(?P<allweek>\b(?:{_ALL_WEEK})\b)"
    r"|(?P<weekdays>\bweekdays\b)|(?P<weekends>\bweekends?\b)"
    rf"|(?P<day>\b(?:{_DAY})\b\.?)"
    rf"|(?P<range>(?P<open>{_TIME}|\b\d{{1,2}}\b){_RANGE_SEP}(?P<close>{_TIME}|\b\d{{1,2}}\b))"
)
_CLOCK = re.compile(r"(\d{1,2})(?::(\d{2}))?\s*(a|p)?")


def _fold(text: str) -> str:
    decomposed = unicodedata.normalize("NFKD", text)
    return "".join(ch for ch in decomposed if not unicodedata.combining(ch)).casefold()


def _minutes(text: str, partner: str | None = None) -> int | None:
    """Minutes after midnight of one time ("6 pm", "18:00", "noon"); a bare hour ("9" in "9-5 pm") takes
    its partner's half of the day when that makes the range run forwards."""
    text = text.strip().replace(".", "").replace(" ", "")
    if text in ("noon", "midday"):
        return 12 * 60
    if text == "midnight":
        return 0
    m = _CLOCK.fullmatch(text.replace("am", "a").replace("pm", "p"))
    if m is None:
        return None
    hour, minute, half = int(m.group(1)), int(m.group(2) or 0), m.group(3)
    if half is None and m.group(2) is None:  # a bare hour: only inside a range with a clock time
        if partner is None:
            return None
        half = "a" if "a" in partner else "p" if "p" in partner else None
        if half is None:
            return None
    if hour > 24 or minute > 59 or (half and not 1 <= hour <= 12):
        return None
    if half == "a":
        hour %= 12
    elif half == "p":
        hour = hour % 12 + 12
    return (hour * 60 + minute) % (24 * 60)


def _range(open_text: str, close_text: str) -> tuple[int, int] | None:
    bare = re.compile(r"\d{1,2}")
    if bare.fullmatch(open_text.strip()) and bare.fullmatch(close_text.strip()):
        return None  # "9-5" alone is two numbers, not hours
    close = _minutes(close_text, open_text.replace("m", ""))
    start = _minutes(open_text, close_text.replace("m", ""))
    if start is not None and close is not None and bare.fullmatch(open_text.strip()) and start > close:
        start = (start + 12 * 60) % (24 * 60)  # "9-5 pm": 9 is in the morning
    if start is None or close is None:
        return None
    return start, close


def _days_between(first: str, last: str) -> set[int]:
    a, b = _DAYS[first.rstrip(".")], _DAYS[last.rstrip(".")]
    return {(a + i) % 7 for i in range((b - a) % 7 + 1)}


def schedule(text: str) -> Schedule | None:
    """The schedule the text states, or None when it states no opening hours.

    Days bind to the time ranges that follow them ("Mon-Sat 10:00-18:00, Sun 13:00-17:00") or, when the
    text starts with a time range, to the ranges before them ("10 am to 6 pm Monday to Saturday"). Ranges
    without any day are every day."""
    items: list[tuple[str, object]] = []
    for m in _TOKEN.finditer(_fold(text)):
        kind = m.lastgroup if m.lastgroup not in ("open", "close") else "range"
        if m.group("range"):
            kind = "range"
        if kind == "closed":
            continue  # "closed Tuesdays" says when it is not open; the open days say the rest
        if kind == "always":
            items.append(("days", set(range(7))))
            items.append(("range", (0, 0)))
        elif kind == "dayrange":
            first, last = re.split(_RANGE_SEP, m.group(0).strip(), maxsplit=1)
            items.append(("days", _days_between(first.strip(), last.strip())))
        elif kind == "allweek":
            items.append(("days", set(range(7))))
        elif kind == "weekdays":
            items.append(("days", set(range(5))))
        elif kind == "weekends":
            items.append(("days", {5, 6}))
        elif kind == "day":
            items.append(("days", {_DAYS[m.group(0).rstrip(".")]}))
        else:
            span = _range(m.group("open"), m.group("close"))
            if span is not None:
                items.append(("range", span))
    if not any(kind == "range" for kind, _ in items):
        return None
    # Neighbouring day items form one group ("Mon, Wed, Fri 8:00-18:00").
    groups: list[tuple[str, object]] = []
    for kind, value in items:
        if kind == "days" and groups and groups[-1][0] == "days":
            groups[-1] = ("days", set(groups[-1][1]) | set(value))  # type: ignore[call-overload]
        else:
            groups.append((kind, value))
    out: set[tuple[int, int, int]] = set()
    days_first = groups[0][0] == "days"
    current: set[int] | None = None
    pending: list[tuple[int, int]] = []
    for kind, value in groups:
        if kind == "days":
            if days_first:
                current = set(value)  # type: ignore[call-overload]
            else:
                out |= {(d, o, c) for d in value for o, c in pending}  # type: ignore[attr-defined]
                pending = []
        elif days_first and current is not None:
            out |= {(d, *value) for d in current}  # type: ignore[misc]
        else:
            pending.append(value)  # type: ignore[arg-type]
    out |= {(d, o, c) for d in range(7) for o, c in pending}  # ranges no day claimed: every day
    return frozenset(out) if out else None
