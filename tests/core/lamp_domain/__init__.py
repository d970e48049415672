"""A tiny extra domain, "lighting", declared in its own package as docs/extending.md describes ("Add a domain"):
an embodied environment (a lamp), one tool (lamp_switch), a task generator and a grader check for its goal kind
(lamp_lit). tests/core/test_extending.py registers it, generates its tasks, plays and grades episodes.

In a real plugin the registration is one line in ewa_mcp/registry.py: ``DOMAIN_PACKAGES.append(
"<package>:DOMAIN")``; the test calls ``registry.register_domain(DOMAIN)`` for its own process instead.
"""

from __future__ import annotations

from ewa_mcp.registry import Domain, EnvironmentSpec

LAMP = EnvironmentSpec(name="lamp", side="embodied", cls=f"{__name__}.env:LampEnvironment", tools=f"{__name__}.tools",
                       tool_hint="lamp_switch")

DOMAIN = Domain(
    name="lighting",
    environments=(LAMP,),
    generator=f"{__name__}.generate:generate",
    goal_kinds=("lamp_lit",),
    checks={"lamp_lit": f"{__name__}.checks:check_lamp_lit"},
    difficulties=("easy",),
)
