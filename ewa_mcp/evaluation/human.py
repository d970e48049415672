"""``ewa-mcp play TASK_ID``: a person plays a task at a terminal prompt, through the same MCP tools an
agent uses, recorded and graded the same way (the paper's human baseline row)."""

from __future__ import annotations

import json
import shlex
import sys
from typing import Any, TextIO

import anyio

from .agents import Session

HELP = """\
Type a tool call as:  TOOL key=value key="a longer value"   (values are JSON when they parse: 3, true, "x")
  e.g.  kitchen_pickup object=Apple      browser_click element=12      street_move direction=forward
Commands:  tools (list tools)   help TOOL (its arguments)   quit (finish the episode without an answer)
Finish with:  finish_episode answer="..."
"""


def parse_command(line: str) -> tuple[str, dict[str, Any]]:
    """'tool a=1 b="x y"' -> ("tool", {"a": 1, "b": "x y"}); raises ValueError with the fix."""
    try:
        parts = shlex.split(line)
    except ValueError as exc:
        raise ValueError(f"could not parse the line ({exc}); check your quotes") from exc
    if not parts:
        raise ValueError("empty line")
    tool, args = parts[0], {}
    for part in parts[1:]:
        key, sep, value = part.partition("=")
        if not sep or not key:
            raise ValueError(f"argument {part!r} is not key=value")
        try:
            args[key] = json.loads(value)
        except json.JSONDecodeError:
            args[key] = value
    return tool, args


class HumanAgent:
    name = "human"

    def __init__(self, stdin: TextIO | None = None, stdout: TextIO | None = None):
        self.stdin = stdin or sys.stdin
        self.stdout = stdout or sys.stdout

    def _print(self, text: str = "") -> None:
        self.stdout.write(text + "\n")
        self.stdout.flush()

    async def _readline(self, prompt: str) -> str | None:
        self.stdout.write(prompt)
        self.stdout.flush()
        line = await anyio.to_thread.run_sync(self.stdin.readline)
        return None if line == "" else line.strip()

    async def play(self, s: Session) -> None:
        tools = {t.name: t for t in (await s.client.list_tools()).tools}
        _enable_completion(sorted(tools))
        self._print("\n".join(c.text for c in s.start.content if getattr(c, "type", "") == "text"))
        self._print("\n" + HELP)
        while not s.ended:
            line = await self._readline("ewa> ")
            if line is None or line in {"quit", "exit"}:
                return  # the runner finishes the episode
            if not line:
                continue
            if line == "tools":
                self._print("  ".join(sorted(n for n in tools if n not in {"list_tasks", "start_episode"})))
                continue
            if line.startswith("help"):
                name = line[4:].strip()
                if name in tools:
                    props = tools[name].input_schema.get("properties", {})
                    self._print(f"{name}: {tools[name].description}")
                    for key, spec in props.items():
                        if key != "episode_id":
                            self._print(f"  {key}: {spec.get('type', spec.get('anyOf', ''))} {spec.get('description', '')}")
                else:
                    self._print(HELP)
                continue
            try:
                tool, args = parse_command(line)
            except ValueError as exc:
                self._print(f"! {exc}")
                continue
            if tool not in tools:
                self._print(f"! unknown tool {tool!r}; type `tools` to list them")
                continue
            result = await s.call(tool, args)
            text = "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")
            images = sum(getattr(c, "type", "") == "image" for c in result.content)
            self._print(("! " if result.is_error else "") + text + (f"\n({images} image(s) recorded)" if images else ""))


def _enable_completion(words: list[str]) -> None:
    """Tab-completes tool names when a person is at a real terminal."""
    if not sys.stdin.isatty():
        return
    try:
        import readline
    except ImportError:
        return

    def complete(text: str, state: int) -> str | None:
        matches = [w for w in words if w.startswith(text)]
        return matches[state] if state < len(matches) else None

    readline.set_completer(complete)
    readline.parse_and_bind("tab: complete")
