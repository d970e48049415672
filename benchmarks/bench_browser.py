"""Browser tool latency: ewa-mcp's browser tools against Microsoft's playwright-mcp, side by side.

Both servers run as stdio MCP servers, drive the same Chromium build (/usr/bin/chromium or what
find_chromium() picks) headless, and act on the same local pages (the fixture site served by
ewa-mcp's SiteServer). Each round does, on each server in turn: navigate to the catalogue,
click a link (a navigation), go back, type into the search field, click a button that changes
the page in place, take a screenshot, and after each action a snapshot (the peer's actions
return only a link to a snapshot file, so an agent needs the snapshot call to see the page).

The peer is installed into benchmarks/peer/ with npm on first run (package.json pins it), and
runs twice: with its defaults, and with --timeout-settle 0 (it otherwise waits a fixed 500 ms
after every action). A third runner, the floor, does the same steps with the Playwright library
alone in this process (no MCP, no server: each action, then the AI-mode ARIA snapshot, elements
by ``aria-ref``), on the same Chromium: what no server built on Playwright can go below on this
machine. Prints one JSON object: median and p95 per action and runner, the observation size in
characters, and whether the targets hold.

    .venv/bin/python benchmarks/bench_browser.py [--rounds 15] [--warmup 2] [--no-peer-settle0]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import anyio
from mcp import Client, StdioServerParameters

ROOT = Path(__file__).resolve().parent.parent
PEER_DIR = Path(__file__).resolve().parent / "peer"
PEER_CLI = PEER_DIR / "node_modules" / "@playwright" / "mcp" / "cli.js"
ACTIONS = ("navigate", "click", "back", "type", "click_js", "screenshot", "snapshot")

# Runs our server over stdio, serving the homepage and the fixture site on the given ports.
OURS_LAUNCHER = """
import json, sys
from pathlib import Path
from ewa_mcp.websites import serve
cfg = json.loads(sys.argv[1])
sys.path.insert(0, cfg["tests_dir"])  # the fixture site lives with the tests (tests/web/testsite.py)
serve.SITES = {"home": serve.SITES["home"], "recipes": serve.SITES["recipes"], "fixture": "web.testsite:create_app"}
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.settings import load_settings
mcp, _ = build_server(ServerConfig(task_dirs=[Path(cfg["tasks"])], run_dir=Path(cfg["runs"]),
                                   settings=load_settings({"site_ports": cfg["ports"], "browser": cfg["browser"]})))
mcp.run("stdio")
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def ensure_peer() -> str:
    if not PEER_CLI.exists():
        npm = shutil.which("npm")
        if npm is None:
            sys.exit("npm is needed to install the peer (@playwright/mcp); install Node.js 18+")
        subprocess.run([npm, "install", "--no-audit", "--no-fund", "--loglevel=error"], cwd=PEER_DIR, check=True,
                       stdout=sys.stderr)
    version = json.loads((PEER_CLI.parent / "package.json").read_text())["version"]
    return version


def text_of(result: Any) -> str:
    return "\n".join(c.text for c in result.content if getattr(c, "type", "") == "text")


def stats(samples: list[float]) -> dict[str, Any]:
    if not samples:
        return {"n": 0}
    ordered = sorted(samples)
    p95 = ordered[min(len(ordered) - 1, int(round(0.95 * (len(ordered) - 1))))]
    return {"n": len(ordered), "median_ms": round(statistics.median(ordered), 1), "p95_ms": round(p95, 1)}


class Driver:
    """One MCP server under test; ``act`` returns (milliseconds, text of the result)."""

    def __init__(self, name: str, client: Client):
        self.name = name
        self.client = client
        self.times: dict[str, list[float]] = {a: [] for a in ACTIONS}
        self.observed: dict[str, list[float]] = {a: [] for a in ACTIONS}  # action + the snapshot after it
        self.chars: dict[str, list[int]] = {a: [] for a in ACTIONS}
        self.last = ""

    async def call(self, tool: str, args: dict[str, Any]) -> tuple[float, str, Any]:
        start = time.perf_counter()
        result = await self.client.call_tool(tool, args)
        elapsed = (time.perf_counter() - start) * 1000
        if result.is_error:
            raise RuntimeError(f"{self.name} {tool} {args}: {text_of(result)[:500]}")
        return elapsed, text_of(result), result

    def record(self, action: str, ms: float, text: str, snapshot_ms: float, record: bool) -> None:
        if record:
            self.times[action].append(ms)
            self.observed[action].append(ms + snapshot_ms)
            self.chars[action].append(len(text))


class Ours(Driver):
    def __init__(self, client: Client, episode: str):
        super().__init__("ewa-mcp", client)
        self.episode = episode

    def ref(self, role: str, name: str) -> str:
        match = re.search(rf"\[(\d+)\] {role} '{re.escape(name)}'", self.last)
        if not match:
            raise RuntimeError(f"ewa-mcp: no {role} '{name}' in the observation")
        return match.group(1)

    async def step(self, action: str, tool: str, args: dict[str, Any], record: bool) -> None:
        ms, text, _ = await self.call(tool, {"episode_id": self.episode, **args})
        snap_ms, snap, _ = await self.call("browser_snapshot", {"episode_id": self.episode})
        self.last = snap
        # Our actions already return the new observation; the snapshot is for the snapshot figures.
        self.record(action, ms, text, 0.0, record)
        self.record("snapshot", snap_ms, snap, 0.0, record)

    async def round(self, urls: dict[str, str], record: bool) -> None:
        await self.step("navigate", "browser_goto", {"url": "fixture:/"}, record)
        await self.step("click", "browser_click", {"element": self.ref("link", "Lentil Soup")}, record)
        await self.step("back", "browser_go_back", {}, record)
        await self.step("type", "browser_type", {"element": self.ref("textbox", "Search items"), "text": "soup"},
                        record)
        await self.step("click_js", "browser_click", {"element": self.ref("button", "Mark done")}, record)
        ms, text, result = await self.call("browser_screenshot", {"episode_id": self.episode})
        assert any(getattr(c, "type", "") == "image" for c in result.content)
        self.record("screenshot", ms, text, 0.0, record)


class Peer(Driver):
    def ref(self, role: str, name: str) -> str:
        match = re.search(rf'{role} "{re.escape(name)}"[^\n]*\[ref=([A-Za-z0-9]+)\]', self.last)
        if not match:
            raise RuntimeError(f"{self.name}: no {role} '{name}' in its snapshot:\n{self.last[:1500]}")
        return match.group(1)

    async def step(self, action: str, tool: str, args: dict[str, Any], record: bool) -> None:
        ms, text, _ = await self.call(tool, args)
        snap_ms, snap, _ = await self.call("browser_snapshot", {})
        self.last = snap
        self.record(action, ms, text, snap_ms, record)
        self.record("snapshot", snap_ms, snap, 0.0, record)

    async def round(self, urls: dict[str, str], record: bool) -> None:
        base = urls["fixture"]
        await self.step("navigate", "browser_navigate", {"url": base + "/"}, record)
        soup = self.ref("link", "Lentil Soup")
        await self.step("click", "browser_click", {"element": "Lentil Soup link", "target": soup}, record)
        await self.step("back", "browser_navigate_back", {}, record)
        search = self.ref("textbox", "Search items")
        await self.step("type", "browser_type", {"element": "search field", "target": search, "text": "soup"}, record)
        await self.step("click_js", "browser_click", {"element": "Mark done button",
                                                      "target": self.ref("button", "Mark done")}, record)
        ms, text, result = await self.call("browser_take_screenshot", {"type": "png"})
        assert any(getattr(c, "type", "") == "image" for c in result.content)
        self.record("screenshot", ms, text, 0.0, record)


class Floor(Driver):
    """The floor under any server: the Playwright library in this process, no MCP, no server. Each
    action is followed by the AI-mode ARIA snapshot (what every step of ours returns), elements are
    found by the snapshot's ``aria-ref`` (as ours are), and a click that loads a page waits for its
    ``load`` event. Its times are action + snapshot."""

    def __init__(self, page: Any):
        super().__init__("playwright library, no server (floor)", None)  # type: ignore[arg-type]
        self.page = page

    def ref(self, role: str, name: str) -> Any:
        match = re.search(rf'{role} "{re.escape(name)}"[^\n]*\[ref=([A-Za-z0-9]+)\]', self.last)
        if not match:
            raise RuntimeError(f"{self.name}: no {role} '{name}' in its snapshot:\n{self.last[:1500]}")
        return self.page.locator(f"aria-ref={match.group(1)}")

    async def step(self, action: str, act: Any, record: bool) -> None:
        start = time.perf_counter()
        await act()
        self.last = await self.page.aria_snapshot(mode="ai")
        ms = (time.perf_counter() - start) * 1000
        self.record(action, ms, self.last, 0.0, record)

    async def round(self, urls: dict[str, str], record: bool) -> None:
        page = self.page

        async def click_and_load() -> None:
            await self.ref("link", "Lentil Soup").click()
            await page.wait_for_load_state("load")

        await self.step("navigate", lambda: page.goto(urls["fixture"] + "/", wait_until="load"), record)
        await self.step("click", click_and_load, record)
        await self.step("back", lambda: page.go_back(wait_until="load"), record)
        await self.step("type", lambda: self.ref("textbox", "Search items").fill("soup"), record)
        await self.step("click_js", lambda: self.ref("button", "Mark done").click(), record)
        start = time.perf_counter()
        await page.screenshot()
        self.record("screenshot", (time.perf_counter() - start) * 1000, "", 0.0, record)


async def episodes(client: Client, count: int, warmup: int = 2) -> dict[str, Any]:
    """start_episode (first observation included) and finish_episode, one episode after another."""
    out: dict[str, Any] = {}
    for task in ("bench-web", "bench-recipes"):
        starts: list[float] = []
        finishes: list[float] = []
        for index in range(warmup + count):
            t0 = time.perf_counter()
            started = await client.call_tool("start_episode", {"task_id": task})
            t1 = time.perf_counter()
            if started.is_error:
                raise RuntimeError(text_of(started))
            done = await client.call_tool("finish_episode", {"episode_id": started.structured_content["episode_id"]})
            t2 = time.perf_counter()
            if done.is_error:
                raise RuntimeError(text_of(done))
            if index >= warmup:
                starts.append((t1 - t0) * 1000)
                finishes.append((t2 - t1) * 1000)
        out[task] = {"start_episode": stats(starts), "finish_episode": stats(finishes)}
    return out


def peer_params(chromium: str, workdir: Path, settle_ms: int | None) -> StdioServerParameters:
    args = [str(PEER_CLI), "--headless", "--isolated", "--executable-path", chromium, "--viewport-size", "1280x720",
            "--output-dir", str(workdir / "out")]
    if os.geteuid() == 0:
        args.append("--no-sandbox")
    if settle_ms is not None:
        args += ["--timeout-settle", str(settle_ms)]
    workdir.mkdir(parents=True, exist_ok=True)
    return StdioServerParameters(command=shutil.which("node") or "node", args=args, cwd=str(workdir))


async def run(args: argparse.Namespace) -> dict[str, Any]:
    from ewa_mcp.envs.browser.chromium import find_chromium

    chromium = find_chromium().path
    peer_version = ensure_peer()
    tmp = Path(tempfile.mkdtemp(prefix="ewa-bench-browser-"))
    (tmp / "tasks").mkdir()
    (tmp / "tasks" / "bench.json").write_text(json.dumps(
        {"id": "bench-web", "domain": "demo", "intent": "benchmark", "step_limit": 10_000,
         "start": {"environment": "web", "web": {"start_url": "fixture:/"}}}))
    (tmp / "tasks" / "bench-recipes.json").write_text(json.dumps(
        {"id": "bench-recipes", "domain": "demo", "intent": "benchmark", "step_limit": 10_000,
         "start": {"environment": "web", "web": {"start_url": "recipes:/"}}}))
    ports = {"home": free_port(), "recipes": free_port(), "fixture": free_port()}
    urls = {name: f"http://127.0.0.1:{port}" for name, port in ports.items()}
    config = {"tasks": str(tmp / "tasks"), "runs": str(tmp / "runs"), "ports": ports,
              "browser": {"executable_path": chromium}, "tests_dir": str(ROOT / "tests")}
    ours_params = StdioServerParameters(command=sys.executable, args=["-c", OURS_LAUNCHER, json.dumps(config)],
                                        cwd=str(ROOT))
    peers = [("playwright-mcp", None)] + ([] if args.no_peer_settle0 else [("playwright-mcp --timeout-settle 0", 0)])

    from playwright.async_api import async_playwright

    from ewa_mcp.envs.browser.chromium import find_chromium as _find

    playwright = await async_playwright().start()
    floor_browser = await playwright.chromium.launch(executable_path=chromium, args=_find(chromium).launch_args())
    floor_page = await (await floor_browser.new_context(viewport={"width": 1280, "height": 720})).new_page()
    async with Client(ours_params) as ours_client:
        started = await ours_client.call_tool("start_episode", {"task_id": "bench-web"})
        if started.is_error:
            raise RuntimeError(text_of(started))
        drivers: list[Driver] = [Ours(ours_client, started.structured_content["episode_id"])]
        clients = []
        try:
            for i, (name, settle) in enumerate(peers):
                client = Client(peer_params(chromium, tmp / f"peer{i}", settle))
                await client.__aenter__()
                clients.append(client)
                drivers.append(Peer(name, client))
            drivers.append(Floor(floor_page))
            for index in range(args.warmup + args.rounds):
                # Alternate who goes first so neither gets a systematically warmer machine.
                order = drivers if index % 2 == 0 else list(reversed(drivers))
                for driver in order:
                    await driver.round(urls, record=index >= args.warmup)
        finally:
            for client in reversed(clients):
                await client.__aexit__(None, None, None)
        lifecycle = await episodes(ours_client, args.episodes)
    await floor_browser.close()
    await playwright.stop()
    shutil.rmtree(tmp, ignore_errors=True)

    ours = drivers[0]
    peer = drivers[1]
    result: dict[str, Any] = {
        "benchmark": "browser tool latency (ms per MCP tool call over stdio) and observation size (characters)",
        "chromium": chromium,
        "peer": f"@playwright/mcp {peer_version}",
        "rounds": args.rounds,
        "warmup_rounds": args.warmup,
        "load_average_1m": round(os.getloadavg()[0], 2),
        "cpu_count": os.cpu_count(),
        "actions": {},
        "observe_after_action": {},
        "observation_chars": {},
        "episodes": lifecycle,
    }
    for action in ACTIONS:
        result["actions"][action] = {d.name: stats(d.times[action]) for d in drivers}
        if action not in ("screenshot", "snapshot"):
            # What it takes to see the page after the action: ours returns it, the peer needs a snapshot.
            result["observe_after_action"][action] = {d.name: stats(d.observed[action]) for d in drivers}
        result["observation_chars"][action] = {
            d.name: int(statistics.median(d.chars[action])) if d.chars[action] else None for d in drivers}
    below = {a: result["actions"][a][ours.name]["median_ms"] <= result["actions"][a][peer.name]["median_ms"]
             for a in ACTIONS}
    result["targets"] = {
        "every_action_at_or_below_peer_median": all(below.values()),
        "per_action_at_or_below_peer_median": below,
        "click_to_observation_median_ms": result["actions"]["click"][ours.name]["median_ms"],
        # The same steps with the Playwright library alone (Floor): what no server can go below here.
        "floor_click_to_observation_median_ms": result["actions"]["click"][drivers[-1].name]["median_ms"],
        "floor_click_js_to_observation_median_ms": result["actions"]["click_js"][drivers[-1].name]["median_ms"],
        "click_js_to_observation_median_ms": result["actions"]["click_js"][ours.name]["median_ms"],
        "click_to_observation_le_60ms": result["actions"]["click"][ours.name]["median_ms"] <= 60
        and result["actions"]["click_js"][ours.name]["median_ms"] <= 60,
        "start_episode_median_ms": {task: lifecycle[task]["start_episode"]["median_ms"] for task in lifecycle},
        "start_episode_le_150ms": all(lifecycle[task]["start_episode"]["median_ms"] <= 150 for task in lifecycle),
    }
    return result


async def count_calls() -> dict[str, Any]:
    """Messages to Playwright per step of one episode on the fixture site (the third of three)."""
    import collections
    import re as _re
    from types import SimpleNamespace

    from playwright._impl import connection  # the one place every message goes out (a private module)

    from ewa_mcp.core.services import Services
    from ewa_mcp.core.taskmodel import Task
    from ewa_mcp.envs.browser.chromium import chromium_service
    from ewa_mcp.envs.browser.env import BrowserEnvironment

    sys.path.insert(0, str(ROOT / "tests"))  # the fixture site lives with the tests (tests/web/testsite.py)
    from web.testsite import start_fixture_sites

    sent: collections.Counter[str] = collections.Counter()
    original = connection.Connection.send_message_to_server

    def counting(self: Any, obj: Any, method: str, params: Any, options: Any) -> Any:
        if method != "__waitInfo__":
            sent[method if method != "send" else "cdp:" + str((params or {}).get("method"))] += 1
        return original(self, obj, method, params, options)

    connection.Connection.send_message_to_server = counting  # type: ignore[method-assign]
    sites = start_fixture_sites()
    services = Services()
    await services.get("websites", lambda _: sites)
    await services.get("chromium", chromium_service)
    task = Task.model_validate({"id": "calls", "domain": "demo", "intent": "count",
                                "start": {"environment": "web", "web": {"start_url": "fixture:/"}}})
    steps: dict[str, dict[str, int]] = {}

    async def step(name: str, work: Any) -> Any:
        sent.clear()
        result = await work
        steps[name] = dict(sorted(sent.items()))
        return result

    try:
        for index in range(3):
            env = BrowserEnvironment(SimpleNamespace(id=f"ep-calls-{index}", options={}), services)
            await step("start (reset)", env.reset(task, {}))
            seen = await step("first observation", env.observe())
            soup = _re.search(r"\[(\d+)\] link 'Lentil Soup'", seen.text).group(1)  # type: ignore[union-attr]
            await step("click by id (loads a page)", env.click(soup))
            await step("go_back", env.go_back())
            await step("click by role and name (same page)", env.click("button 'Mark done'"))
            await step("click by role and name (loads a page)", env.click("link 'Apple Crumble'"))
            await step("goto", env.goto("fixture:/"))
            await step("type", env.type("textbox 'Search items'", "soup"))
            await step("final_state", env.final_state())
            await step("close (finish_episode)", env.close())
            handovers = services.peek("web-handovers")
            if handovers is not None:
                await handovers.drain()
    finally:
        connection.Connection.send_message_to_server = original  # type: ignore[method-assign]
        await services.aclose()
        sites.stop()
    return {"benchmark": "messages to Playwright per step (not timed)",
            "steps": {name: {"total": sum(c.values()), "ariaSnapshot": c.get("ariaSnapshot", 0), "calls": c}
                      for name, c in steps.items()}}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--warmup", type=int, default=2)
    parser.add_argument("--episodes", type=int, default=20, help="start/finish episode pairs per task")
    parser.add_argument("--no-peer-settle0", action="store_true", help="skip the peer run with --timeout-settle 0")
    parser.add_argument("--calls", action="store_true", help="count messages to Playwright per step instead")
    args = parser.parse_args()
    if args.calls:
        print(json.dumps(anyio.run(count_calls), indent=2))
        return
    print(json.dumps(anyio.run(run, args), indent=2))


if __name__ == "__main__":
    main()
