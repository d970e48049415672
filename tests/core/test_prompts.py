"""One MCP prompt per domain with the agent instructions, generated from the registry (issue 29)."""

from __future__ import annotations

import pytest
from mcp import Client

from ewa_mcp.core import registry
from ewa_mcp.core.prompts import agent_instructions
from ewa_mcp.server import ServerConfig, build_server

pytestmark = pytest.mark.anyio


async def test_every_domain_has_a_prompt_with_its_tools_and_rules(tmp_path):
    full, episodes = build_server(ServerConfig(run_dir=tmp_path))
    try:
        async with Client(full) as client:
            prompts = {p.name: p for p in (await client.list_prompts()).prompts}
            assert set(prompts) == set(registry.domain_names())
            for name, prompt in prompts.items():
                assert [(a.name, a.required) for a in prompt.arguments or []] == [("task_id", False)]
                domain = registry.domain(name)
                assert domain is not None
                text = (await client.get_prompt(name, {})).messages[0].content.text
                for spec in domain.environments:
                    assert spec.hint() in text, (name, spec.name)
                    assert spec.instructions in text, (name, spec.name)
                assert f'list_tasks(domain="{name}")' in text and "finish_episode" in text
                sides = {s.side for s in domain.environments}
                assert ("switch_environment" in text) == (sides == {"web", "embodied"}), name
            picked = (await client.get_prompt("cooking", {"task_id": "cooking-buy-0001"})).messages[0].content.text
            assert 'start_episode(task_id="cooking-buy-0001")' in picked and "list_tasks" not in picked
            assert "kitchen_* tools" in picked and "browser_* tools" in picked
    finally:
        await episodes.aclose()
        await episodes.services.aclose()


def test_a_new_world_gets_its_prompt_from_its_own_declaration():
    lamp = registry.EnvironmentSpec(name="lamp", side="embodied", cls="x:Lamp", tool_hint="lamp_* tools",
                                    instructions="A lamp episode ends when the lamp is lit.")
    text = agent_instructions(registry.Domain(name="lighting", environments=(lamp,)))
    assert "on a lighting task" in text and "lamp_* tools" in text and "ends when the lamp is lit" in text
    assert "switch_environment" not in text and "[id]" not in text  # no web side: no web advice
