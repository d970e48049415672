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
class StatusField:
    """One field an environment adds to ``episode_status`` (a boolean, null where the episode has no such
    environment), with the words its text shows for true and false."""

    name: str
    description: str  # the field's description in the output schema
    phrase: str  # how episode_status's description names it
    when_true: str
    when_false: str


@dataclass(frozen=True)
class EnvironmentSpec:
    """One environment implementation an episode can hold."""

    name: str  # the registry name; also the prefix of its tools (kitchen_*) and, embodied, start.embodied.kind
    side: Literal["web", "embodied"]  # the slot it fills in an episode (switch_environment's target)
    cls: str  # "module:Class"; the class takes (episode, services) (ewa_mcp/core/environment.py)
    tools: str | None = None  # module exposing register(mcp, episodes) with this environment's tools
    tool_hint: str = ""  # how a refusal names its tools ("kitchen_* tools")
    tool_order: int = 100  # where its tools are listed (lower first; ties keep the order first declared)
    # What the kernel says about this environment without naming it: a line of the server's instructions, a
    # sentence of finish_episode's description, and the fields it adds to episode_status.
    instructions: str = ""
    finish_hint: str = ""
    status_fields: tuple[StatusField, ...] = ()
    # Its task models, by import path ("module:Model", pydantic models in its goals.py), from which the kernel
    # assembles the task schema (ewa_mcp/core/taskmodel.py): the start of its episodes (``start.web``, or
    # ``start.embodied`` whose ``kind`` is its name), the goal kinds it owns (``web_goals`` or
    # ``embodied_goals`` by its side) and the answer checks it owns (``answer``); each goal and answer model
    # names its kind by the default of its ``kind`` field. A goal kind a domain checks but no environment
    # declares a model for is read by the open model (``DomainGoal``), its fields the check's to read.
    start: str | None = None
    goals: tuple[str, ...] = ()
    answers: tuple[str, ...] = ()
    # "module:Model": the episode options it reads (start_episode's ``options``; ewa_mcp/core/options.py), each
    # named with its prefix (kitchen_view); the kernel's own options (observation, seed, structured) come first.
    options: str | None = None

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
    # goal kind -> "module:function(goal, ctx) -> ConditionResult": the check of every goal kind its tasks
    # carry, in the world that owns the kind (graders/models.py: CheckContext, what a check may read).
    checks: dict[str, str] = field(default_factory=dict)
    difficulties: tuple[str, ...] = ("easy", "medium", "hard")  # its difficulty split (report tables)
    scored: bool = True  # False: listed and playable, but left out of the run's aggregates (demo)


# Where the domains come from: "module:attribute" paths, each naming a Domain or a list of them, imported on
# first use. The built-in worlds declare theirs in their own packages and are listed, one line each, in
# ewa_mcp/envs/__init__.py; a plugin adds its own path here (or calls register_domain). The kernel itself
# names no world.
DOMAIN_PACKAGES: list[str] = ["ewa_mcp.envs:DOMAINS"]

# The episode lifecycle tools (list_tasks, start_episode, ...): always registered, and first.
CORE_TOOLS = "ewa_mcp.core.lifecycle"

_registered: list[Domain] = []
_loaded = False


class RegistryError(ValueError):
    """A domain declaration that cannot be used (a name clash, an unknown import path)."""


def _packaged() -> list[Domain]:
    global _loaded
    if not _loaded:
        _loaded = True
        for path in DOMAIN_PACKAGES:
            declared = load_object(path)
            for domain in declared if isinstance(declared, list | tuple) else [declared]:
                _add(domain)
    return _registered


def _add(domain: Domain) -> None:
    if not isinstance(domain, Domain):
        raise RegistryError(f"a domain declaration must be a registry.Domain, got {type(domain).__name__}")
    taken = {d.name for d in _registered}
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
    """Every domain, in display order: the packaged ones in the order declared, then those registered later."""
    return list(_packaged())


def use_only(*declared: Domain) -> tuple[list[Domain], bool]:
    """Replace every registered domain by ``declared`` (a kernel test with a throwaway domain); returns the
    domains it replaced, which ``restore`` puts back."""
    global _loaded
    before = (list(_registered), _loaded)
    _registered.clear()
    _loaded = True  # the packaged domains are not imported at all
    for domain in declared:
        _add(domain)
    return before


def restore(before: tuple[list[Domain], bool]) -> None:
    global _loaded
    _registered[:] = before[0]
    _loaded = before[1]


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
    groups = [CORE_TOOLS]
    for env in ordered_environments():
        if env.tools and env.tools not in groups:
            groups.append(env.tools)
    return groups


def ordered_environments() -> list[EnvironmentSpec]:
    """Every environment, in the order its tools are listed."""
    return sorted(environments().values(), key=lambda e: e.tool_order)


def status_fields() -> list[StatusField]:
    return [f for env in ordered_environments() for f in env.status_fields]


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
