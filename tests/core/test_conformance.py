"""check_environment over every registered environment, on the first task of each domain that uses it (what
Gymnasium's check_env is for Gymnasium), and that it catches an environment that breaks the contract."""

from __future__ import annotations

from typing import Any

import pytest

from ewa_mcp.core import registry
from ewa_mcp.core.conformance import check_environment, check_spec
from ewa_mcp.core.environment import Environment, Observation
from ewa_mcp.core.paths import task_dirs
from ewa_mcp.core.services import Services
from ewa_mcp.core.taskmodel import TaskStore

from .lamp_domain import DOMAIN as LAMP_DOMAIN

pytestmark = pytest.mark.anyio


def first_tasks() -> list[tuple[str, str, Any]]:
    """(environment, domain, task) for each domain's first task (by id) and each environment it uses."""
    store = TaskStore(task_dirs())
    out = []
    for domain in registry.domains():
        tasks = sorted(store.all(domain.name), key=lambda t: t.id)
        if not tasks:
            continue
        for name in tasks[0].environment_names().values():
            out.append((name, domain.name, tasks[0]))
    return out


CASES = first_tasks()


def test_every_environment_is_covered():
    assert {name for name, _, _ in CASES} == set(registry.environments())


@pytest.mark.parametrize(("name", "domain", "task"), CASES, ids=[f"{n}-{d}" for n, d, _ in CASES])
async def test_environment_conforms(name, domain, task):
    if name == "browser":
        from ewa_mcp.envs.browser.chromium import find_chromium

        if find_chromium() is None:
            pytest.fail("no Chromium: `make test` installs one (scripts/ensure-chromium.sh)")
    services = Services()
    try:
        problems = await check_environment(registry.environments()[name], task, services)
    finally:
        await services.aclose()
    assert problems == []


class Wobbly(Environment):
    """Breaks the contract in three ways: wrong name, a non-JSON observation, a different first observation."""

    side = "embodied"
    name = "wobble"
    resets = 0

    def __init__(self, episode: Any, services: Any):
        pass

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        Wobbly.resets += 1

    async def observe(self) -> Observation:
        return Observation(text=f"reset {Wobbly.resets}", data={"when": object()})

    async def final_state(self) -> dict[str, Any]:
        return {"lit": True}


async def test_a_broken_environment_is_reported_with_fixes():
    lamp = LAMP_DOMAIN.environments[0]
    wrong = registry.EnvironmentSpec(lamp.name, "embodied", f"{__name__}:Wobbly", lamp.tools)
    assert any("Wobbly.name is 'wobble'" in p for p in check_spec(wrong))

    Wobbly.name = "lamp"
    registry.register_domain(LAMP_DOMAIN)
    try:
        from ewa_mcp.core.taskmodel import Task

        task = Task.model_validate({"id": "lamp-c", "domain": "lighting", "intent": "x", "step_limit": 5,
                                    "start": {"environment": "embodied", "embodied": {"kind": "lamp"}},
                                    "embodied_goals": [{"kind": "lamp_lit", "lit": True}]})
        spec = registry.EnvironmentSpec("lamp", "embodied", f"{__name__}:Wobbly", lamp.tools)
        from ewa_mcp.core import conformance

        problems = await conformance.check_environment(spec, task)
        assert any("not JSON-serializable" in p for p in problems), problems
        assert any("different first observations" in p for p in problems), problems
    finally:
        registry.unregister_domain(LAMP_DOMAIN.name)
        Wobbly.name = "wobble"
