"""Answer checks: text answers here; geolocation answers by graders/geo.py (the geolocation engineer's)."""

from __future__ import annotations

import importlib
from typing import Any

from ewa_mcp.taskmodel import GeoAnswer, TextAnswer

from .models import ConditionResult
from .textnorm import contains_phrase, normalize

GEO_MODULE = "ewa_mcp.graders.geo"


def check_text_answer(check: TextAnswer, answer: str | None) -> ConditionResult:
    if check.exact is not None:
        description = f"answer equals {check.exact!r}"
    else:
        description = "answer mentions " + ", ".join(repr(p) for p in check.must_include)
    if not answer or not answer.strip():
        return ConditionResult(side="answer", kind=check.kind, description=description, met=False,
                               note="no answer was given")
    missing = [p for p in check.must_include if not contains_phrase(answer, p)]
    exact_ok = check.exact is None or normalize(answer) == normalize(check.exact)
    note = None
    if missing:
        note = "missing: " + ", ".join(repr(p) for p in missing)
    elif not exact_ok:
        note = "not equal to the expected answer"
    return ConditionResult(side="answer", kind=check.kind, description=description,
                           met=not missing and exact_ok, detail={"answer": answer[:200]}, note=note)


def geo_module() -> tuple[Any | None, str | None]:
    """The geolocation grader module, or why it is unavailable."""
    try:
        return importlib.import_module(GEO_MODULE), None
    except ModuleNotFoundError as exc:
        if exc.name in (GEO_MODULE, None):
            return None, "not gradable: geo grader missing (graders/geo.py)"
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
    note = None if submission else "no location was submitted"
    return ConditionResult(side="answer", kind=check.kind, description=description, met=met,
                           detail={k: result.get(k) for k in ("continent", "country", "city", "street", "distance_km")},
                           note=note), result
