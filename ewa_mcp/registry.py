"""The one place that declares the benchmark's domains and the environments their episodes run in.

An ``EnvironmentSpec`` names one environment implementation ("kitchen"): its class and the module of its
MCP tools. A ``Domain`` ("cooking") names the environments its tasks use, its task generator, the goal kinds
its tasks carry (and, for kinds the core grader does not know, the checks that grade them), whether it has
a difficulty split, and whether it is scored. ``DOMAINS`` lists them in display order (report tables,
``list_tasks``' domain choices); every other list of domains (the task schema's check, ``list_tasks``, the
grader's tables, ``ewa-mcp tasks generate``, the Inspect AI tasks) is read from here.

Everything is named by import path ("module:attribute") and imported on first use, so that a server that
never touches the browser never imports Playwright and the graders never import the MCP server. This
module itself imports nothing of the project.

Adding a domain (docs/extending.md): write one package that declares ``DOMAIN = Domain(...)`` (with its own
environment, tools, generator and checks) and add its path to ``DOMAIN_PACKAGES`` below — one line. Tests
register a domain for their own process with ``register_domain``.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Any, Literal


@dataclass(frozen=True)
class EnvironmentSpec:
    """One environment implementation an episode can hold."""

    name: str  # the registry name; also the prefix of its tools (kitchen_*) and, embodied, start.embodied.kind
    side: Literal["web", "embodied"]  # the slot it fills in an episode (switch_environment's target)
    cls: str  # "module:Class"; the class takes (episode, services) (ewa_mcp/environment.py)
    tools: str | None = None  # module exposing register(mcp, episodes) with this environment's tools
    tool_hint: str = ""  # how a refusal names its tools ("kitchen_* tools")

    def hint(self) -> str:
        return self.tool_hint or f"{self.name}_* tools"


@dataclass(frozen=True)
class Domain:
    """One task domain: what its episodes run in, how its tasks are made, and how they are graded."""

    name: str  # the task's ``domain`` field and its folder under tasks/
    environments: tuple[EnvironmentSpec, ...]  # every environment its tasks may use
    generator: str | None = None  # "module:function" -> list[Task] (written in chunks by ewa_mcp.taskgen)
    writer: str | None = None  # or "module:function(out_dir) -> int" for a generator that writes its own files
    goal_kinds: tuple[str, ...] = ()  # the goal kinds its tasks may carry (web and embodied)
    # goal kind -> "module:function(goal, state) -> ConditionResult" for kinds the core grader does not know
    # (ewa_mcp/graders/episode.py grades the built-in kinds); ``state`` is the embodied final state.
    checks: dict[str, str] = field(default_factory=dict)
    difficulties: tuple[str, ...] = ("easy", "medium", "hard")  # its difficulty split (report tables)
    scored: bool = True  # False: listed and playable, but left out of the run's aggregates (demo)


# ---------------------------------------------------------------- environments
BROWSER = EnvironmentSpec("browser", "web", "ewa_mcp.web.env:BrowserEnvironment", "ewa_mcp.tools.browser",
                          "browser_* tools")
KITCHEN = EnvironmentSpec("kitchen", "embodied", "ewa_mcp.indoor.env:KitchenEnvironment", "ewa_mcp.tools.kitchen",
                          "kitchen_* tools")
STREET = EnvironmentSpec("street", "embodied", "ewa_mcp.outdoor.env:StreetEnvironment", "ewa_mcp.tools.street",
                         "street_* tools")
GEO = EnvironmentSpec("geo", "embodied", "ewa_mcp.geo.env:GeoEnvironment", "ewa_mcp.tools.geo",
                      "geo_look, geo_move and submit_location")

# The episode lifecycle tools (list_tasks, start_episode, ...): always registered, and first.
CORE_TOOLS = "ewa_mcp.tools.core"

_WEB_GOALS = ("recipe_completed", "order_placed", "directions_shown", "page_visited")
_STREET_GOALS = ("reached_place", "passed_place")

# ---------------------------------------------------------------- domains, in display order
DOMAINS: list[Domain] = [
    Domain("navigation", (BROWSER, STREET), generator="ewa_mcp.taskgen.navigation:generate",
           goal_kinds=(*_WEB_GOALS, *_STREET_GOALS)),
    Domain("shopping", (BROWSER, STREET), generator="ewa_mcp.taskgen.shopping:generate",
           goal_kinds=(*_WEB_GOALS, *_STREET_GOALS)),
    Domain("traveling", (BROWSER, STREET), generator="ewa_mcp.taskgen.traveling:generate",
           goal_kinds=(*_WEB_GOALS, *_STREET_GOALS)),
    Domain("cooking", (BROWSER, KITCHEN), generator="ewa_mcp.taskgen.cooking:generate",
           goal_kinds=(*_WEB_GOALS, "object_state", "object_in")),
    Domain("geolocation", (BROWSER, GEO), writer="ewa_mcp.geo.generate:generate_tasks"),
    Domain("demo", (BROWSER,), difficulties=(), scored=False),
]

# Domains declared in their own package: "package.module:DOMAIN", imported on first use. One line per domain.
DOMAIN_PACKAGES: list[str] = []

# Tool groups in the order they are listed: core first, then each environment's in the order first named
# above (street, browser, kitchen, geo: the order clients have always seen).
_TOOL_ORDER = (STREET, BROWSER, KITCHEN, GEO)

_registered: list[Domain] = []
_loaded = False


class RegistryError(ValueError):
    """A domain declaration that cannot be used (a name clash, an unknown import path)."""


def _packaged() -> list[Domain]:
    global _loaded
    if not _loaded:
        _loaded = True
        for path in DOMAIN_PACKAGES:
            _add(load_object(path))
    return _registered


def _add(domain: Domain) -> None:
    if not isinstance(domain, Domain):
        raise RegistryError(f"a domain declaration must be a registry.Domain, got {type(domain).__name__}")
    taken = {d.name for d in [*DOMAINS, *_registered]}
    if domain.name in taken:
        raise RegistryError(f"domain {domain.name!r} is already registered; choose another name")
    for env in domain.environments:
        known = environments().get(env.name)
        if known is not None and known != env:
            raise RegistryError(f"domain {domain.name!r} declares an environment named {env.name!r} that differs "
                                "from the one already registered; reuse that EnvironmentSpec or pick a new name")
    _registered.append(domain)


def register_domain(domain: Domain) -> Domain:
    """Add a domain for this process (a test, a plugin's entry point); ``unregister_domain`` takes it away."""
    _packaged()
    _add(domain)
    return domain


def unregister_domain(name: str) -> None:
    _registered[:] = [d for d in _registered if d.name != name]


def domains() -> list[Domain]:
    """Every domain, in display order: the built-in ones, then the packaged and registered ones."""
    return [*DOMAINS, *_packaged()]


def domain(name: str) -> Domain | None:
    return next((d for d in domains() if d.name == name), None)


def domain_names(*, scored_only: bool = False) -> list[str]:
    return [d.name for d in domains() if d.scored or not scored_only]


def environments() -> dict[str, EnvironmentSpec]:
    """name -> spec of every environment some domain uses."""
    out: dict[str, EnvironmentSpec] = {}
    for d in domains():
        for env in d.environments:
            out.setdefault(env.name, env)
    return out


def tool_groups() -> list[str]:
    """Modules exposing register(mcp, episodes), in listing order: core first, then each environment's."""
    specs = environments()
    ordered = [e for e in _TOOL_ORDER if e.name in specs] + [e for e in specs.values() if e not in _TOOL_ORDER]
    groups = [CORE_TOOLS]
    for env in ordered:
        if env.tools and env.tools not in groups:
            groups.append(env.tools)
    return groups


def goal_kinds() -> set[str]:
    return {kind for d in domains() for kind in d.goal_kinds}


def goal_check(kind: str) -> str | None:
    """The declared check of a goal kind ("module:function"), or None when the core grader owns it."""
    return next((d.checks[kind] for d in domains() if kind in d.checks), None)


def load_object(path: str) -> Any:
    module_name, _, attr = path.partition(":")
    if not module_name or not attr:
        raise RegistryError(f"{path!r} is not an import path; write 'package.module:name'")
    return getattr(importlib.import_module(module_name), attr)
