"""Built-in agents. Each plays one episode through an MCP client session; none reads server internals."""

from __future__ import annotations

import json
import random
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ewa_mcp.core.taskmodel import Task, ToolCall


@dataclass
class Session:
    """One episode as an agent sees it: the client, the episode id and the start result."""

    client: Any
    task: Task
    episode_id: str
    start: Any
    log: list[dict[str, Any]] = field(default_factory=list)
    ended: bool = False
    record_problem: str | None = None  # the server could not write the episode's record (a full disk)

    async def call(self, tool: str, args: dict[str, Any] | None = None) -> Any:
        payload = {"episode_id": self.episode_id, **(args or {})}
        result = await self.client.call_tool(tool, payload)
        sc = result.structured_content or {}
        if isinstance(sc, dict) and sc.get("status") not in (None, "running"):
            self.ended = True
        self.log.append({"tool": tool, "ok": not result.is_error})
        if result.is_error and self.record_problem is None:
            from ..core.records import RECORD_WRITE_MARKER

            text = " ".join(getattr(c, "text", "") for c in result.content)
            if RECORD_WRITE_MARKER in text:
                self.record_problem = text[text.index(RECORD_WRITE_MARKER):][:600]
                self.ended = True
        return result


class OracleAgent:
    """Makes the task's oracle calls: what a perfect agent would do, through the real tools."""

    name = "oracle"

    async def play(self, s: Session) -> None:
        for call in s.task.oracle:
            if s.ended:
                break
            await s.call(call.tool, call.args)
        if not s.ended:
            await s.call("finish_episode", {})


class NoopAgent:
    """Finishes at once without acting: the floor every metric should sit on."""

    name = "noop"

    async def play(self, s: Session) -> None:
        await s.call("finish_episode", {})


# Tools a random agent may call with arguments it can invent without understanding the page.
_RANDOM_MOVES: dict[str, list[tuple[str, dict[str, Any]]]] = {
    "web": [("browser_scroll", {"direction": "down"}), ("browser_scroll", {"direction": "up"}),
            ("browser_go_back", {}), ("browser_go_forward", {}), ("browser_press", {"keys": "Tab"})],
    "embodied": [("kitchen_move", {"direction": d}) for d in ("ahead", "back", "left", "right")]
    + [("kitchen_rotate", {"direction": d}) for d in ("left", "right")]
    + [("street_move", {"direction": d}) for d in ("forward", "left", "right", "back")]
    + [("geo_move", {"direction": d}) for d in ("forward", "left", "right", "back")],
}


class RandomAgent:
    """Uniformly random legal-looking actions (seeded per task) until the step limit or a budget."""

    name = "random"

    def __init__(self, seed: int = 0, max_calls: int = 20):
        self.seed = seed
        self.max_calls = max_calls

    async def play(self, s: Session) -> None:
        rng = random.Random(f"{self.seed}:{s.task.id}")
        tools = {t.name for t in (await s.client.list_tools()).tools}
        active = (s.start.structured_content or {}).get("active_environment", "web")
        envs = list(((s.start.structured_content or {}).get("environments") or {}).keys())
        for _ in range(min(self.max_calls, s.task.step_limit - 1)):
            if s.ended:
                return
            if len(envs) > 1 and rng.random() < 0.15:
                active = "embodied" if active == "web" else "web"
                await s.call("switch_environment", {"target": active, "message": "random switch"})
                continue
            moves = [m for m in _RANDOM_MOVES.get(active, []) if m[0] in tools]
            if not moves:
                break
            tool, args = rng.choice(moves)
            await s.call(tool, args)
        if not s.ended:
            await s.call("finish_episode", {})


class ReplayError(ValueError):
    pass


def load_replay(path: Path) -> dict[str, list[ToolCall]]:
    """Tool calls per task id, from a JSONL replay file or a run directory's trajectories.

    JSONL lines: {"task_id": "...", "tool": "...", "args": {...}} (blank lines and lines starting with # skipped).
    A run directory: each episode's task.json + trajectory.jsonl (its start_episode line is skipped)."""
    if not path.exists():
        raise ReplayError(f"replay {path} does not exist; pass a .jsonl file or a run directory")
    calls: dict[str, list[ToolCall]] = {}
    if path.is_dir():
        for task_file in sorted(path.glob("*/task.json")):
            task_id = json.loads(task_file.read_text())["id"]
            trajectory = task_file.parent / "trajectory.jsonl"
            for line in trajectory.read_text().splitlines() if trajectory.exists() else []:
                try:
                    rec = json.loads(line)
                except json.JSONDecodeError:
                    break  # a crash left a half-written last line: replay what was complete
                if rec.get("tool") != "start_episode":
                    calls.setdefault(task_id, []).append(ToolCall(tool=rec["tool"], args=rec.get("args") or {}))
        if not calls:
            raise ReplayError(f"{path} holds no episodes (expected <episode>/task.json + trajectory.jsonl)")
        return calls
    for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            rec = json.loads(line)
        except json.JSONDecodeError as exc:
            raise ReplayError(f"{path}:{n}: not JSON ({exc.msg}); each line must be one JSON object") from exc
        if not isinstance(rec, dict) or not isinstance(rec.get("task_id"), str) or not isinstance(rec.get("tool"), str):
            raise ReplayError(f"{path}:{n}: each line needs string fields task_id and tool (and optional args)")
        args = rec.get("args", {})
        if not isinstance(args, dict):
            raise ReplayError(f"{path}:{n}: args must be a JSON object")
        args.pop("episode_id", None)  # filled in per episode
        calls.setdefault(rec["task_id"], []).append(ToolCall(tool=rec["tool"], args=args))
    if not calls:
        raise ReplayError(f"{path} holds no tool calls")
    return calls


class ReplayAgent:
    name = "replay"

    def __init__(self, calls: dict[str, list[ToolCall]]):
        self.calls = calls

    async def play(self, s: Session) -> None:
        for call in self.calls.get(s.task.id, []):
            if s.ended:
                break
            await s.call(call.tool, call.args)
        if not s.ended:
            await s.call("finish_episode", {})
