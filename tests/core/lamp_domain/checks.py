"""The grader check of the lamp_lit goal: read from the lamp's final state only (final_state.json)."""

from __future__ import annotations

from typing import Any

from ewa_mcp.graders.models import CheckContext, ConditionResult


def check_lamp_lit(goal: Any, ctx: CheckContext) -> ConditionResult:
    if ctx.state is None:
        return ctx.unknown("embodied", goal, ctx.why_no_state)
    want = bool(getattr(goal, "lit", True))
    lit = ctx.state.get("lit")
    if not isinstance(lit, bool):
        return ConditionResult(side="embodied", kind="lamp_lit", description="lamp state", met=None,
                               note="the lamp's final state has no 'lit' flag")
    return ConditionResult(side="embodied", kind="lamp_lit", description=f"the lamp is {'on' if want else 'off'}",
                           met=lit == want, note=None if lit == want else f"the lamp ended {'on' if lit else 'off'}")
