"""Run ewa-mcp tasks with Claude (Anthropic Messages API, tool use) as the agent.

    export ANTHROPIC_API_KEY=...
    .venv/bin/python examples/claude_agent.py --model claude-sonnet-4-5 --domain cooking --sample 3

The agent connects to the ewa-mcp server as an MCP client (stdio by default), sees its tools,
and plays each task; the run directory it leaves is graded with `ewa-grade RUN_DIR`.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import Any

import anthropic

from ewa_mcp.evaluation.llm import (NUDGE, LLMAgent, ToolOutcome, ToolRequest, ToolSpec, example_parser,
                                    parse_arguments, run_example)


class ClaudeAdapter:
    def __init__(self, client: anthropic.AsyncAnthropic, model: str, max_tokens: int):
        self.client, self.model, self.max_tokens = client, model, max_tokens
        self.messages: list[dict[str, Any]] = []

    def begin(self, system: str, tools: list[ToolSpec], user: str) -> None:
        self.system = system
        self.tools = [{"name": t.name, "description": t.description, "input_schema": t.parameters} for t in tools]
        self.messages = [{"role": "user", "content": user}]

    async def next_actions(self) -> list[ToolRequest]:
        response = await self.client.messages.create(model=self.model, max_tokens=self.max_tokens,
                                                     system=self.system, tools=self.tools, messages=self.messages)
        self.messages.append({"role": "assistant",
                              "content": [block.model_dump(exclude_none=True) for block in response.content]})
        return [ToolRequest(id=b.id, name=b.name, arguments=parse_arguments(b.input))
                for b in response.content if b.type == "tool_use"]

    async def aclose(self) -> None:
        await self.client.close()

    def add_results(self, outcomes: list[ToolOutcome]) -> None:
        if not outcomes:
            self.messages.append({"role": "user", "content": NUDGE})
            return
        blocks = []
        for o in outcomes:
            content: list[dict[str, Any]] = [{"type": "text", "text": o.text or "(no output)"}]
            content += [{"type": "image", "source": {"type": "base64", "media_type": "image/png", "data": img}}
                        for img in o.images]
            blocks.append({"type": "tool_result", "tool_use_id": o.request.id, "content": content,
                           "is_error": o.is_error})
        self.messages.append({"role": "user", "content": blocks})


@dataclass
class ClaudeAdapterFactory:
    """Makes one adapter (and SDK client) per episode, inside the episode's event loop. A plain picklable
    object, so the agent can go to worker processes (--workers) and Ray actors (--ray)."""

    model: str
    max_tokens: int
    base_url: str | None = None

    def __call__(self) -> ClaudeAdapter:
        client = anthropic.AsyncAnthropic(base_url=self.base_url) if self.base_url else anthropic.AsyncAnthropic()
        return ClaudeAdapter(client, self.model, self.max_tokens)


def main(argv: list[str] | None = None) -> int:
    args = example_parser("Claude plays ewa-mcp tasks over MCP.", "claude-sonnet-4-5").parse_args(argv)
    agent = LLMAgent(ClaudeAdapterFactory(args.model, args.max_tokens, args.base_url), name=f"claude:{args.model}",
                     send_images=not args.no_images)
    return run_example(args, agent)


if __name__ == "__main__":
    sys.exit(main())
