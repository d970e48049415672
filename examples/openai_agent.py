"""Run ewa-mcp tasks with an OpenAI model (Chat Completions function calling) as the agent.

    export OPENAI_API_KEY=...
    .venv/bin/python examples/openai_agent.py --model gpt-4o --domain navigation --sample 3

Any server that speaks the Chat Completions wire format works with --base-url (vLLM, a proxy).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import Any

import openai

from ewa_mcp.evaluation.llm import (NUDGE, LLMAgent, ToolOutcome, ToolRequest, ToolSpec, example_parser,
                                    parse_arguments, run_example)


class OpenAIAdapter:
    def __init__(self, client: openai.AsyncOpenAI, model: str, max_tokens: int):
        self.client, self.model, self.max_tokens = client, model, max_tokens
        self.messages: list[dict[str, Any]] = []

    def begin(self, system: str, tools: list[ToolSpec], user: str) -> None:
        self.tools = [{"type": "function", "function": {"name": t.name, "description": t.description,
                                                        "parameters": t.parameters}} for t in tools]
        self.messages = [{"role": "system", "content": system}, {"role": "user", "content": user}]

    async def next_actions(self) -> list[ToolRequest]:
        response = await self.client.chat.completions.create(model=self.model, messages=self.messages,
                                                             tools=self.tools, max_tokens=self.max_tokens)
        message = response.choices[0].message
        calls = message.tool_calls or []
        entry: dict[str, Any] = {"role": "assistant", "content": message.content or ""}
        if calls:
            entry["tool_calls"] = [{"id": c.id, "type": "function",
                                    "function": {"name": c.function.name, "arguments": c.function.arguments}}
                                   for c in calls]
        self.messages.append(entry)
        return [ToolRequest(id=c.id, name=c.function.name, arguments=parse_arguments(c.function.arguments))
                for c in calls]

    async def aclose(self) -> None:
        await self.client.close()

    def add_results(self, outcomes: list[ToolOutcome]) -> None:
        if not outcomes:
            self.messages.append({"role": "user", "content": NUDGE})
            return
        images = []
        for o in outcomes:
            self.messages.append({"role": "tool", "tool_call_id": o.request.id,
                                  "content": ("ERROR: " if o.is_error else "") + (o.text or "(no output)")})
            images += o.images
        if images:  # tool messages carry text only; images follow as a user message
            self.messages.append({"role": "user", "content": [
                {"type": "text", "text": "Images from the last observation:"},
                *({"type": "image_url", "image_url": {"url": f"data:image/png;base64,{img}"}} for img in images)]})


@dataclass
class OpenAIAdapterFactory:
    """Makes one adapter (and SDK client) per episode, inside the episode's event loop. A plain picklable
    object, so the agent can go to worker processes (--workers) and Ray actors (--ray)."""

    model: str
    max_tokens: int
    base_url: str | None = None

    def __call__(self) -> OpenAIAdapter:
        client = openai.AsyncOpenAI(base_url=self.base_url) if self.base_url else openai.AsyncOpenAI()
        return OpenAIAdapter(client, self.model, self.max_tokens)


def main(argv: list[str] | None = None) -> int:
    args = example_parser("An OpenAI model plays ewa-mcp tasks over MCP.", "gpt-4o").parse_args(argv)
    agent = LLMAgent(OpenAIAdapterFactory(args.model, args.max_tokens, args.base_url), name=f"openai:{args.model}",
                     send_images=not args.no_images)
    return run_example(args, agent)


if __name__ == "__main__":
    sys.exit(main())
