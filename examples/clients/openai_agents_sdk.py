"""The OpenAI Agents SDK playing one ewa-mcp task, with the server run by uvx from PyPI (no checkout needed).

    pip install openai-agents && OPENAI_API_KEY=... python openai_agents_sdk.py
"""

import asyncio

from agents import Agent, Runner
from agents.mcp import MCPServerStdio


async def main() -> None:
    # One server for the whole run: the episodes live in it. The first start of a cold uvx environment can take
    # longer than the SDK's default 5 s session timeout, hence 30.
    async with MCPServerStdio(params={"command": "uvx", "args": ["ewa-mcp", "serve"]},
                              client_session_timeout_seconds=30, cache_tools_list=True) as ewa:
        # The server's prompt for the domain holds the agent instructions (the paper's agent prompt).
        prompt = await ewa.get_prompt("cooking", {"task_id": "cooking-cook-0001"})
        instructions = "\n".join(m.content.text for m in prompt.messages)
        agent = Agent(name="ewa", model="gpt-4o", mcp_servers=[ewa],
                      mcp_config={"convert_schemas_to_strict": True}, instructions=instructions)
        print((await Runner.run(agent, "Play the task.", max_turns=80)).final_output)


if __name__ == "__main__":
    asyncio.run(main())
