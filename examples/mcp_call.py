"""Call one MCP tool on a running ewa-mcp server and print what the tool returns — the way a play-tester
(a person, or an LLM agent with a shell) plays a task one call at a time, reading only the tools' answers.

    .venv/bin/ewa-mcp serve --transport http --port 8765 &
    .venv/bin/python examples/mcp_call.py list_tasks '{"domain": "navigation", "limit": 3}'
    .venv/bin/python examples/mcp_call.py start_episode '{"task_id": "navigation-boston-000"}'
    .venv/bin/python examples/mcp_call.py street_move '{"episode_id": "ep-…", "direction": "forward"}'
    .venv/bin/python examples/mcp_call.py --tools          # every tool with its description

Episodes live in the server, so each call may open a new session. Images in a result are written to
--images DIR (default ./mcp-images) and named in the output.
"""

from __future__ import annotations

import argparse
import base64
import json
import sys
from pathlib import Path

import anyio
from mcp import Client


async def main(args: argparse.Namespace) -> int:
    async with Client(args.url) as client:
        if args.tools:
            for tool in (await client.list_tools()).tools:
                params = ", ".join(tool.input_schema.get("properties", {}))
                print(f"- {tool.name}({params}): {tool.description}")
            return 0
        try:
            arguments = json.loads(args.arguments or "{}")
        except json.JSONDecodeError as exc:
            print(f"arguments must be a JSON object: {exc}", file=sys.stderr)
            return 2
        result = await client.call_tool(args.tool, arguments)
        images = Path(args.images)
        for n, item in enumerate(result.content):
            if item.type == "text":
                print(item.text)
            elif item.type == "image":
                images.mkdir(parents=True, exist_ok=True)
                path = images / f"{args.tool}-{n}.png"
                path.write_bytes(base64.b64decode(item.data))
                print(f"[image: {path}]")
        if result.is_error:
            print("(the tool reported an error)")
        return 1 if result.is_error else 0


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tool", nargs="?")
    parser.add_argument("arguments", nargs="?", help="the tool's arguments as one JSON object")
    parser.add_argument("--url", default="http://127.0.0.1:8765/mcp")
    parser.add_argument("--tools", action="store_true", help="list the tools and their descriptions")
    parser.add_argument("--images", default="mcp-images", help="folder for images in results")
    ns = parser.parse_args()
    if not ns.tools and not ns.tool:
        parser.error("name a tool, or pass --tools")
    from ewa_mcp.pipes import quiet_on_closed_pipe  # `mcp_call.py ... | head` ends quietly, like ewa-mcp

    sys.exit(quiet_on_closed_pipe(lambda: anyio.run(main, ns))())
