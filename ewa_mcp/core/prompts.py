"""One MCP prompt per task domain: the agent instructions for playing that domain's tasks through the tools.

The instructions follow the agent prompt the paper's agents were given (an agent acting in an embodied web
environment through tools; only the active environment accepts actions; switch_environment says what it will
do; finish with the answer; limited steps), written from the registry: each domain's environments name their own
tools and add their own rules (EnvironmentSpec.instructions), so the kernel names no world. A client shows them
as slash commands or prompt templates (``/mcp__ewa-mcp__cooking`` in Claude Code); ``task_id`` picks a task,
otherwise the agent lists the domain's tasks and picks one.
"""

from __future__ import annotations

from typing import Any

from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.prompts.base import Prompt, UserMessage

from . import registry


def agent_instructions(domain: registry.Domain, task_id: str | None = None) -> str:
    """The instructions for an agent playing a task of ``domain`` on the control-plane server."""
    specs = domain.environments
    web = [s for s in specs if s.side == "web"]
    embodied = [s for s in specs if s.side == "embodied"]
    parts = []
    if web:
        parts.append("a web environment (" + " or ".join(s.hint() for s in web) + ")")
    if embodied:
        parts.append("an embodied one (" + " or ".join(s.hint() for s in embodied) + ")")
    lines = [
        f"You are an agent acting in an embodied web environment through the ewa-mcp tools, on a {domain.name} task.",
        f"Its episodes have {' and/or '.join(parts)}.",
    ]
    if web and embodied:
        lines.append("Only the ACTIVE environment accepts actions. To act in the other one, call "
                     "switch_environment(target, message) and say in message what you will do there.")
    if web:
        lines.append("Read observations carefully; element ids in the web page are shown as [id].")
    lines.append("When the task is done, call finish_episode, with your answer if the task asks a question.")
    lines += [s.instructions for s in specs if s.instructions]  # after the general rule: they refine it
    lines.append("Every call uses one step, failed calls included, and steps are limited: do not repeat failing "
                 "actions.")
    if task_id:
        lines.append(f"Start with start_episode(task_id=\"{task_id}\") and pass the episode_id it returns to every "
                     "tool.")
    else:
        lines.append(f"Start by choosing a task: list_tasks(domain=\"{domain.name}\"), then start_episode(task_id); "
                     "pass the episode_id it returns to every tool.")
    return "\n".join(lines)


def _prompt_for(domain: registry.Domain) -> Prompt:
    def render(task_id: str | None = None) -> list[Any]:
        return [UserMessage(agent_instructions(domain, task_id))]

    levels = f" ({', '.join(domain.difficulties)})" if domain.difficulties else ""
    return Prompt.from_function(
        render, name=domain.name, title=f"Play a {domain.name} task",
        description=f"Agent instructions for a {domain.name} task{levels}; task_id picks one, otherwise the agent "
                    "lists them.")


def register_prompts(mcp: MCPServer) -> None:
    """One prompt per registered domain, named after it."""
    for domain in registry.domains():
        mcp.add_prompt(_prompt_for(domain))
