"""Memory of open web episodes: PSS per idle episode at 1, 16 and 64 concurrent ones, and the warm pool's.

One in-process MCP server (``Client(server)``: real sites, real Chromium, the real tools), a task whose
start page is the recipes site's index (the start of 1,080 of the suite's tasks). For each count N it
opens N episodes (``start_episode``, at most ``--open-concurrency`` at a time), leaves them all open and
idle, and reads the proportional set size (PSS, from ``/proc/<pid>/smaps_rollup``) of every process of
the server: Python itself, Playwright's driver (node) and Chromium's processes (browser, zygotes,
utility, renderers). PSS shares a page between the processes that map it, so the sum is what the
server costs the machine. Per episode = (total with N open - total with none open, read just before) / N;
the renderers' mean PSS is printed too, split into anonymous, file-backed and shared memory (each context
gets its own renderer; its file-backed pages are Chromium's code, shared with the zygote and every other
renderer, so with one episode open they weigh on that renderer alone). At N = 1 the per-episode figure
is within the drift of the shared processes (Python, the driver, the browser: tens of MB between two
readings), so read it with the renderer's figure.

Then the N episodes are finished (the pool keeps up to ``max_idle`` warm contexts) and the pool's
resident memory is read right after the burst and again once the pool has been idle past its idle
period (``--idle-s``; by default the pool's own setting).

With ``--browse`` each episode first loads three recipe pages (a search, a click on a result, a step
page), as an agent would before pausing to think; without it they idle on their start page.

Open episodes are read twice: 3 s after the last one opened (``just_opened``) and after idling
``--idle-wait-s`` seconds (the main figures), which gives the idle collector (ewa_mcp/envs/browser/idlegc.py)
time to see every page quiet for a whole period.

    .venv/bin/python benchmarks/bench_memory.py [--counts 1,16,64] [--open-concurrency 8] [--idle-s S]
        [--idle-wait-s 25] [--idle-gc-s 0] [--browse]

Prints one JSON object; the load average is read at the start and the end of each count.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
import time
from pathlib import Path
from typing import Any

import anyio
from mcp import Client

from ewa_mcp.settings import load_settings
from ewa_mcp.server import ServerConfig, build_server

TASK = {"id": "bench-memory", "domain": "demo", "intent": "benchmark: an idle web episode", "step_limit": 10_000,
        "start": {"environment": "web", "web": {"start_url": "recipes:/"}}}


# ------------------------------------------------------------------ reading /proc
def _children() -> dict[int, list[int]]:
    from ewa_mcp.evaluation.lifeline import children_map  # the one reader of /proc's process tree

    return children_map()


def descendants(root: int) -> list[int]:
    tree, found, todo = _children(), [], [root]
    while todo:
        pid = todo.pop()
        found.append(pid)
        todo.extend(tree.get(pid, []))
    return found


def pss_kib(pid: int) -> dict[str, int] | None:
    """PSS of a process in KiB: ``Pss`` and its parts (``Pss_Anon``, ``Pss_File``, ``Pss_Shmem``)."""
    found: dict[str, int] = {}
    try:
        with open(f"/proc/{pid}/smaps_rollup", encoding="utf-8") as f:
            for line in f:
                name, _, rest = line.partition(":")
                if name.startswith("Pss"):
                    found[name] = int(rest.split()[0])
    except (OSError, ValueError):
        return None
    return found if "Pss" in found else None


def kind(pid: int) -> str:
    if pid == os.getpid():
        return "python"
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            # Chromium's child processes rewrite their title: one string, arguments separated by spaces.
            argv = f.read().replace(b"\0", b" ").decode(errors="replace").split()
    except OSError:
        return "gone"
    exe = os.path.basename(argv[0]) if argv else ""
    if exe == "node" or exe.startswith("node"):
        return "playwright-driver"
    if exe in ("sh", "bash", "dash"):
        return "launcher-shell"  # Debian's /usr/bin/chromium* are shell scripts that exec the binary
    for arg in argv:
        if arg.startswith("--type="):
            return arg[len("--type="):]  # renderer, zygote, utility, gpu-process
    return "browser" if "chrom" in exe else exe or "other"


def memory() -> dict[str, Any]:
    """PSS of this process and all its descendants, in MiB, by kind of process."""
    by_kind: dict[str, list[dict[str, int]]] = {}
    for pid in descendants(os.getpid()):
        pss = pss_kib(pid)
        if pss is not None:
            by_kind.setdefault(kind(pid), []).append(pss)

    def mib(values: list[dict[str, int]], part: str = "Pss") -> float:
        return round(sum(v.get(part, 0) for v in values) / 1024, 1)

    renderers = by_kind.get("renderer", [])
    every = [v for values in by_kind.values() for v in values]
    return {"total_mib": mib(every),
            "by_kind_mib": {k: mib(v) for k, v in sorted(by_kind.items())},
            "processes": {k: len(v) for k, v in sorted(by_kind.items())},
            "renderer_mean_mib": {part.removeprefix("Pss_").lower() if part != "Pss" else "pss":
                                  round(mib(renderers, part) / max(1, len(renderers)), 1)
                                  for part in ("Pss", "Pss_Anon", "Pss_File", "Pss_Shmem")}}


def loadavg() -> list[float]:
    return [round(x, 2) for x in os.getloadavg()]


# ------------------------------------------------------------------ episodes
# With --browse, what each episode does after its start, before idling (a cooking task's first steps).
BROWSE = (("browser_goto", {"url": "recipes:/?q=Egg+Bhurji+Toast&difficulty=simple"}),
          ("browser_click", {"element": "link 'Egg Bhurji Toast'"}),
          ("browser_goto", {"url": "recipes:/recipe/r115?step=5"}))


async def open_episodes(client: Client, n: int, concurrency: int,
                        browse: bool = False) -> tuple[list[str], list[str]]:
    ids: list[str] = []
    errors: list[str] = []
    limit = anyio.Semaphore(concurrency)

    async def one() -> None:
        async with limit:
            r = await client.call_tool("start_episode", {"task_id": TASK["id"]})
            if r.is_error:
                errors.append(str(r.content[0].text if r.content else r)[:200])
                return
            episode_id = r.structured_content["episode_id"]
            for tool, arguments in BROWSE if browse else ():
                r = await client.call_tool(tool, {"episode_id": episode_id, **arguments})
                if r.is_error:
                    errors.append(f"{tool}: " + str(r.content[0].text if r.content else r)[:200])
        ids.append(episode_id)

    async with anyio.create_task_group() as tg:
        for _ in range(n):
            tg.start_soon(one)
    return ids, errors


async def finish(client: Client, ids: list[str], concurrency: int) -> None:
    limit = anyio.Semaphore(concurrency)

    async def one(ep: str) -> None:
        async with limit:
            await client.call_tool("finish_episode", {"episode_id": ep})

    async with anyio.create_task_group() as tg:
        for ep in ids:
            tg.start_soon(one, ep)


async def still_responsive(client: Client, ids: list[str]) -> int:
    """How many of the open episodes answer an observation (an open episode that silently died is a failure)."""
    ok = 0
    for ep in ids:
        r = await client.call_tool("browser_snapshot", {"episode_id": ep, "max_chars": 500})
        ok += 0 if r.is_error else 1
    return ok


async def settle_memory(seconds: float = 3.0) -> dict[str, Any]:
    await anyio.sleep(seconds)  # let just-opened renderers finish their idle work before reading
    return memory()


def server_config(tmp: Path, browser: dict[str, Any]) -> ServerConfig:
    """The benchmark's server: its one task, a run directory under ``tmp``, these browser options."""
    return ServerConfig(task_dirs=[tmp / "tasks"], run_dir=tmp / "runs", settings=load_settings({"browser": browser}))


async def run(args: argparse.Namespace) -> dict[str, Any]:
    tmp = Path(tempfile.mkdtemp(prefix="ewa-bench-memory-"))
    (tmp / "tasks").mkdir()
    (tmp / "tasks" / "bench.json").write_text(json.dumps(TASK))
    browser = {} if args.idle_gc_s is None else {"idle_gc_s": args.idle_gc_s}
    mcp, episodes = build_server(server_config(tmp, browser))
    report: dict[str, Any] = {"benchmark": "memory of idle web episodes", "counts": {}}
    async with Client(mcp) as client:
        # Launch the browser (and the sites) with one episode, then empty the pool: the baseline is a
        # server with its browser up and no context open.
        ids, errors = await open_episodes(client, 1, 1)
        if errors:
            raise RuntimeError(errors[0])
        await finish(client, ids, 1)
        service = episodes.services.peek("chromium")
        pool = service.pool
        report["chromium"] = service.info.path
        report["launch_args"] = service.launch_args()
        if args.idle_s is not None:
            pool.idle_s = args.idle_s
        report["pool"] = {"max_idle": pool.max_idle, "keep_idle": pool.keep_idle, "idle_s": pool.idle_s}
        report["idle_gc_every_s"] = service.collector.every_s
        report["browse"] = [tool for tool, _ in BROWSE] if args.browse else []
        for index, n in enumerate(args.counts):
            # Before each count: no context open (the last count's pool closed), browser up.
            await pool.aclose()
            baseline = await settle_memory()
            load_before = loadavg()
            t0 = time.perf_counter()
            ids, errors = await open_episodes(client, n, args.open_concurrency, args.browse)
            opened_s = time.perf_counter() - t0
            just_opened = await settle_memory()
            load_open = loadavg()
            # Idle: long enough for the idle collector to see every page quiet for a whole period.
            collections = service.collector.collections
            await anyio.sleep(args.idle_wait_s)
            mem = memory()
            responsive = await still_responsive(client, ids)
            per = (mem["total_mib"] - baseline["total_mib"]) / max(1, len(ids))
            entry = {"opened": len(ids), "failed": len(errors), "errors": errors[:3], "answering": responsive,
                     "baseline_no_episode": baseline,
                     "open_s": round(opened_s, 1), "idle_s": args.idle_wait_s, "per_episode_mib": round(per, 1), **mem,
                     "idle_collections": service.collector.collections - collections,
                     "just_opened": {"per_episode_mib": round(
                         (just_opened["total_mib"] - baseline["total_mib"]) / max(1, len(ids)), 1), **just_opened},
                     "load_average": {"before": load_before, "open": load_open, "idle": loadavg()}}
            await finish(client, ids, args.open_concurrency)
            after_burst = await settle_memory(1.0)
            entry["pool_after_burst"] = {"idle_contexts": pool.idle(), **after_burst}
            await anyio.sleep(pool.idle_s + 1.5)
            await pool.shrink()  # what the pool's own timer does; called here so the reading does not race it
            entry["pool_after_idle"] = {"idle_contexts": pool.idle(), "after_s": pool.idle_s,
                                        **(await settle_memory(1.0))}
            entry["load_average"]["end"] = loadavg()
            report["counts"][str(n) if str(n) not in report["counts"] else f"{n} (run {index + 1})"] = entry
        await pool.aclose()
    report["target"] = {"per_episode_mib": 40, "met": all(
        e["per_episode_mib"] <= 40 and e["failed"] == 0 for e in report["counts"].values())}
    return report


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--counts", default="1,16,64", help="comma-separated episode counts (default 1,16,64)")
    parser.add_argument("--open-concurrency", type=int, default=8, help="start_episode calls in flight at once")
    parser.add_argument("--idle-s", type=float, default=None, help="the pool's idle period (default: its own)")
    parser.add_argument("--idle-gc-s", type=float, default=None,
                        help="the idle collector's period (default: the browser config's; 0 turns it off, as before)")
    parser.add_argument("--browse", action="store_true",
                        help="each episode loads three recipe pages (search, click, goto) before idling")
    parser.add_argument("--idle-wait-s", type=float, default=25.0,
                        help="how long the open episodes idle before the reading (default 25: two idle-GC periods)")
    args = parser.parse_args()
    try:
        args.counts = [int(c) for c in args.counts.split(",") if c.strip()]
    except ValueError:
        parser.error(f"--counts must be comma-separated integers, got {args.counts[:200]!r}")
    print(json.dumps(anyio.run(run, args), indent=2))


if __name__ == "__main__":
    main()
