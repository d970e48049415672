"""Call one MCP tool on a running ewa-mcp server and print what the tool returns — the way a play-tester
(a person, or an LLM agent with a shell) plays a task one call at a time, reading only the tools' answers.

    .venv/bin/ewa-mcp serve --transport http --port 8765 &
    .venv/bin/python examples/mcp_call.py list_tasks '{"domain": "navigation", "limit": 3}'
    .venv/bin/python examples/mcp_call.py start_episode '{"task_id": "navigation-boston-000"}'
    .venv/bin/python examples/mcp_call.py street_move '{"episode_id": "ep-…", "direction": "forward"}'
    .venv/bin/python examples/mcp_call.py --tools          # every tool with its description

Episodes live in the server, so each call may open a new session. Images in a result are written to
--images DIR (default ./mcp-images) and named in the output. Every image gets a name of its own, so a whole
play-through keeps all its images: NNNN-TOOL-K.png, where NNNN counts up across calls (one more than the highest
number already in DIR), TOOL is the tool called and K the image's place in that result
(0001-get_observation-1.png, 0002-browser_scroll-1.png, 0003-browser_scroll-1.png). Names sort in call order.
"""

from __future__ import annotations

import argparse
import base64
import json
import re
import sys
from pathlib import Path

import anyio
from mcp import Client


IMAGE_NAME = re.compile(r"^(\d+)-")


def save_images(folder: Path, tool: str, images: list[tuple[int, bytes]]) -> list[Path]:
    """Write one result's images (place in the result, PNG bytes) under names no earlier call used (see the
    module docstring): they share the next free number, so ``browser_scroll`` twice keeps both screenshots."""
    if not images:
        return []
    folder.mkdir(parents=True, exist_ok=True)
    taken = [int(m.group(1)) for p in folder.iterdir() if (m := IMAGE_NAME.match(p.name))]
    number = max(taken, default=0) + 1
    while True:  # exclusive creation: a call running at the same time never writes over these images
        first = folder / f"{number:04d}-{tool}-{images[0][0]}.png"
        try:
            with first.open("xb") as out:
                out.write(images[0][1])
            break
        except FileExistsError:
            number += 1
    paths = [first]
    for index, data in images[1:]:
        path = folder / f"{number:04d}-{tool}-{index}.png"
        path.write_bytes(data)
        paths.append(path)
    return paths


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
        images = [(n, base64.b64decode(item.data)) for n, item in enumerate(result.content) if item.type == "image"]
        paths = iter(save_images(Path(args.images), args.tool, images))
        for item in result.content:
            if item.type == "text":
                print(item.text)
            elif item.type == "image":
                print(f"[image: {next(paths)}]")
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
