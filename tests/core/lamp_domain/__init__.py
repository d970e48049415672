"""A tiny world, "lamp", with one domain, "lighting", laid out as every world under ewa_mcp/envs/ is
(docs/extending.md, "Add a world"): an embodied environment (a lamp), an action table with one tool
(lamp_switch), its task models (its start and its goal kind, lamp_lit), a task generator and the grader's check
of its goal kind.

tests/core/test_extending.py registers it for its own process (``registry.register_domain``) and plays and grades
episodes; tests/core/test_new_world.py writes these same files into a copy of ewa_mcp/envs/ as a built-in world.
"""

from __future__ import annotations

from ewa_mcp.core.registry import Domain, EnvironmentSpec

LAMP = EnvironmentSpec(name="lamp", side="embodied", cls=f"{__name__}.env:LampEnvironment", tools=f"{__name__}.tools",
                       tool_hint="lamp_switch", start=f"{__name__}.goals:LampStart",
                       goals=(f"{__name__}.goals:LampLit",))

DOMAIN = Domain(
    name="lighting",
    environments=(LAMP,),
    generator=f"{__name__}.taskgen.lighting:generate",
    goal_kinds=("lamp_lit",),
    checks={"lamp_lit": f"{__name__}.checks:check_lamp_lit"},
    difficulties=("easy",),
)
DOMAINS = [DOMAIN]
