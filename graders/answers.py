"""Answer checks: text answers here; geolocation answers by ewa_mcp/envs/geo/checks.py (the geolocation engineer's)."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from ewa_mcp.core.taskmodel import AnswerNumbers, TextAnswer

if TYPE_CHECKING:
    from ewa_mcp.envs.geo.goals import GeoAnswer

from .hours import schedule
from .models import ConditionResult
from .textnorm import HEDGES, KNOWN_UNITS, find_spans, is_number, non_value, normalize, number_value, tokens

GEO_MODULE = "ewa_mcp.envs.geo.checks"


def check_text_answer(check: TextAnswer, answer: str | None) -> ConditionResult:
    if check.exact is not None:
        description = f"answer equals {check.exact!r}"
    else:
        description = "answer names " + ", ".join(repr(p) for p in check.must_include)
        if check.distractors or check.numbers is not None:
            description += " and no other candidate"
    if not answer or not answer.strip():
        return ConditionResult(side="answer", kind=check.kind, description=description, met=False,
                               note="no answer was given")
    note = None
    if check.max_chars is not None and len(answer.strip()) > check.max_chars:
        note = f"the answer is {len(answer.strip())} characters; a short answer has at most {check.max_chars}"
    elif check.exact is not None:
        if normalize(answer) != normalize(check.exact):
            note = "not equal to the expected answer"
    else:
        note = commitment_problem(check, answer)
    return ConditionResult(side="answer", kind=check.kind, description=description, met=note is None,
                           detail={"answer": answer[:200]}, note=note)


def commitment_problem(check: TextAnswer, answer: str) -> str | None:
    """Why the answer does not commit to the expected answer, or None when it does (docs/grading.md).

    Each phrase (expected wording, distractor, context) is found as whole tokens; an occurrence lying
    inside a longer occurrence of another phrase is part of that phrase, not a mention of its own
    ("Modernism" inside "Late Modernism"). Where the check counts numbers, a phrase that is one number is
    found only where that number is a value of the asked kind ("151" in "46 m (151 ft)" is feet, "1401"
    in "1401 Chestnut Street" an address). Opening hours are also found by their schedule ("every day
    from 6 am to 11:30 pm" names "daily 6:00-23:30"). What the expected and context occurrences leave
    over must hold no hedge and no rival number."""
    toks = tokens(answer)
    found: list[tuple[int, int, str, str]] = []  # start, end, role, phrase
    for phrase in check.must_include:
        for wording in [phrase, *check.aliases.get(phrase, [])]:
            found += [(a, b, "expected", phrase) for a, b in _spans(toks, wording, check.numbers, expected=True)]
    for phrase in check.distractors:
        found += [(a, b, "distractor", phrase) for a, b in _spans(toks, phrase, check.numbers)]
    for phrase in check.context:
        found += [(a, b, "context", phrase) for a, b in find_spans(toks, tokens(phrase))]
    kept = [f for f in found
            if not any(g[0] <= f[0] and f[1] <= g[1] and g[1] - g[0] > f[1] - f[0] for g in found)]
    said = schedule(answer)
    missing = [p for p in check.must_include
               if tokens(p) and not any(f[2] == "expected" and f[3] == p for f in kept)
               and not (said is not None and said == schedule(p))]
    if missing:
        return "missing: " + ", ".join(repr(p) for p in missing)
    named = list(dict.fromkeys(f[3] for f in kept if f[2] == "distractor"))
    if named:
        shown = ", ".join(repr(p[:60]) for p in named[:3]) + (f" and {len(named) - 3} more" if len(named) > 3 else "")
        return f"names other candidates too: {shown} (an answer must name only the expected one)"
    covered = {i for f in kept if f[2] in ("expected", "context") for i in range(f[0], f[1])}
    rest = [i for i in range(len(toks)) if i not in covered]
    hedges = [toks[i] for i in rest if toks[i] in HEDGES and not _conversion(toks, i, check.numbers)]
    hedges += [toks[i - 1] + "'t" for i in rest if toks[i] == "t" and i > 0 and toks[i - 1].endswith("n")]
    if hedges:
        return f"hedges or denies ({', '.join(repr(h) for h in dict.fromkeys(hedges))}); state one answer"
    if check.numbers is not None:
        rivals = [toks[i] for i in rest if is_number(toks[i]) and is_rival(toks, i, check.numbers)]
        if rivals:
            return f"gives other values of the asked kind too: {', '.join(repr(r) for r in dict.fromkeys(rivals))}"
    return None


def _spans(toks: list[str], phrase: str, rule: AnswerNumbers | None, *,
           expected: bool = False) -> list[tuple[int, int]]:
    """Where the phrase is named; a one-number phrase only where the number is a value of the asked kind
    (in its unit; for a rival, also not a price, an identifier or an address)."""
    needle = tokens(phrase)
    spans = find_spans(toks, needle)
    if rule is not None and len(needle) == 1 and is_number(needle[0]):
        spans = [(a, b) for a, b in spans if is_rival(toks, a, rule, expected=expected)]
    return spans


def _conversion(toks: list[str], i: int, rule: AnswerNumbers | None) -> bool:
    """Whether the "or" at ``toks[i]`` introduces the same value in another unit ("46 m, or about 151 ft")."""
    if toks[i] != "or" or rule is None:
        return False
    ahead = toks[i + 1:i + 4]
    for j, tok in enumerate(ahead):
        if is_number(tok):
            unit = ahead[j + 1] if j + 1 < len(ahead) else (toks[i + 2 + j] if i + 2 + j < len(toks) else "")
            return unit in KNOWN_UNITS and not is_rival(toks, i + 1 + j, rule)
        if tok not in ("about", "approximately", "roughly", "around", "some", "nearly", "almost", "just", "over"):
            return False
    return False


def is_rival(toks: list[str], i: int, rule: AnswerNumbers, *, expected: bool = False) -> bool:
    """Whether the number at ``toks[i]`` is a value of the asked kind (its unit, its range; never a price,
    an identifier or an address, unless it is the expected value, which stands where the answer puts it)."""
    value = number_value(toks[i])
    if (rule.low is not None and value < rule.low) or (rule.high is not None and value > rule.high):
        return False
    if not expected and non_value(toks, i):
        return False
    after = toks[i + 1:]
    for unit in rule.units:
        unit_tokens = tokens(unit)
        if unit_tokens and after[:len(unit_tokens)] == unit_tokens:
            return True
    if after and after[0] in KNOWN_UNITS:
        return False
    return rule.bare


def geo_module() -> tuple[Any | None, str | None]:
    """The geolocation grader module, or why it is unavailable."""
    try:
        return importlib.import_module(GEO_MODULE), None
    except ModuleNotFoundError as exc:
        if exc.name in (GEO_MODULE, None):
            return None, "not gradable: geo grader missing (ewa_mcp/envs/geo/checks.py)"
        return None, f"not gradable: geo grader failed to import ({exc})"
    except Exception as exc:  # a broken geo module must not take the whole report down
        return None, f"not gradable: geo grader failed to import ({type(exc).__name__}: {exc})"


def check_geo_answer(check: GeoAnswer, submission: dict[str, Any] | None) -> tuple[ConditionResult, dict[str, Any] | None]:
    description = "location identified at every level (continent, country, city, street)"
    module, why = geo_module()
    if module is None:
        return ConditionResult(side="answer", kind=check.kind, description=description, met=None, note=why), None
    try:
        result = dict(module.grade_geolocation(check, submission))
    except Exception as exc:
        return ConditionResult(side="answer", kind=check.kind, description=description, met=None,
                               note=f"geo grader raised {type(exc).__name__}: {exc}"), None
    met = result.get("all_levels")
    if not isinstance(met, bool):
        met = all(result.get(level) is True for level in ("continent", "country", "city", "street"))
    graded = result.get("graded_levels") or ("continent", "country", "city", "street")
    wrong = [level for level in graded if result.get(level) is not True]
    # Name the levels that missed: a verdict that says only "not every level" leaves the player and the
    # researcher to dig the per-level detail out of the record.
    note = ("no location was submitted" if not submission
            else f"wrong at: {', '.join(wrong)}" if wrong and not met else None)
    return ConditionResult(side="answer", kind=check.kind, description=description, met=met,
                           detail={k: result.get(k) for k in ("continent", "country", "city", "street", "distance_km")},
                           note=note), result
