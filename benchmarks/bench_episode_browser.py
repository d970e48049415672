"""The browser's share of an episode: fresh vs warm contexts, full Chromium vs the headless shell.

One "episode" is what the cooking oracle does on the web, through BrowserEnvironment itself: start
on the recipes index, search with a filter, click the recipe, open its last step, end. Three
measurements, each printed in one JSON object:

* latency: episodes one after another, per Chromium build found (Debian's chromium-headless-shell,
  the full chromium), with the context pool on and off (off = a new context per episode, as
  before the pool): median and p95 ms per episode;
* endurance: two workers side by side for ``--long`` episodes with the pool on, with its upkeep
  (a renderer garbage collection every 10 hand-overs, retirement after 50) and without: ms per
  episode over the first and the last 20;
* the pool's counters.

    .venv/bin/python benchmarks/bench_episode_browser.py [--episodes 30] [--long 160]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import statistics
import time
from types import SimpleNamespace
from typing import Any

from ewa_mcp.core.services import Services
from ewa_mcp.settings import load_settings
from ewa_mcp.core.taskmodel import Task
from ewa_mcp.envs.browser import chromium
from ewa_mcp.envs.browser.env import BrowserEnvironment
from ewa_mcp.websites.serve import site_service

START = Task.model_validate({"id": "bench", "domain": "demo", "intent": "bench",
                             "start": {"environment": "web", "web": {"start_url": "recipes:/"}}})


async def one_episode(services: Services, episode_id: str) -> float:
    t0 = time.perf_counter()
    env = BrowserEnvironment(SimpleNamespace(id=episode_id, options={}), services)
    await env.reset(START, {})
    await env.goto("recipes:/?q=Egg+Bhurji+Toast&difficulty=simple")
    await env.click("link 'Egg Bhurji Toast'")
    await env.goto("recipes:/recipe/r115?step=5")
    await env.final_state()
    await env.close()
    return (time.perf_counter() - t0) * 1000


def builds() -> dict[str, str]:
    found = {}
    for name, candidates in (("headless-shell", chromium.HEADLESS_SHELL_CANDIDATES),
                             ("chromium", chromium.SYSTEM_CANDIDATES)):
        path = next((c for c in candidates if os.path.isfile(c) and os.access(c, os.X_OK)), None)
        if path:
            found[name] = path
    return found


async def services_for(path: str, sites: Any, *, pool: bool, gc_every: int = 10,
                       max_uses: int = 50) -> Services:
    services = Services(load_settings({"browser": {"executable_path": path}}))
    # The environment reads only the sites' URLs; a plain view keeps aclose() from stopping them.
    await services.get("websites", lambda _: SimpleNamespace(urls=sites.urls))
    service = await services.get("chromium", chromium.chromium_service)
    if not pool:
        service.pool.max_idle = 0  # every episode closes its context: a new one each time
    service.pool.gc_every = gc_every
    service.pool.max_uses = max_uses
    return services


async def latency(path: str, sites: Any, pool: bool, episodes: int, warmup: int = 3) -> dict[str, Any]:
    services = await services_for(path, sites, pool=pool)
    try:
        for i in range(warmup):
            await one_episode(services, f"ep-warm-{i}")
        times = [await one_episode(services, f"ep-{i}") for i in range(episodes)]
    finally:
        await services.aclose()
    times.sort()
    return {"median_ms": round(statistics.median(times), 1), "p95_ms": round(times[int(0.95 * (len(times) - 1))], 1)}


async def endurance(path: str, sites: Any, episodes: int, gc_every: int, max_uses: int) -> dict[str, Any]:
    services = await services_for(path, sites, pool=True, gc_every=gc_every, max_uses=max_uses)
    ends: list[float] = []
    counter = iter(range(episodes))

    async def worker() -> None:
        for i in counter:
            await one_episode(services, f"ep-long-{i}")
            ends.append(time.perf_counter())

    try:
        t0 = time.perf_counter()
        await asyncio.gather(worker(), worker())
        pool = services.peek("chromium").pool
        counters = {"reused": pool.reused, "closed": pool.closed}
    finally:
        await services.aclose()
    first = (ends[19] - t0) / 20 * 1000
    last = (ends[-1] - ends[-21]) / 20 * 1000
    return {"ms_per_episode_first_20": round(first, 1), "ms_per_episode_last_20": round(last, 1),
            "slowdown": round(last / first, 2), "pool": counters}


async def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--episodes", type=int, default=30)
    parser.add_argument("--long", type=int, default=160)
    args = parser.parse_args()
    sites = await Services().get("websites", site_service)
    found = builds()
    report: dict[str, Any] = {"benchmark": "browser share of a cooking episode", "builds": found, "latency": {}}
    for name, path in found.items():
        for pool in (False, True):
            key = f"{name}, {'warm context (pool)' if pool else 'new context per episode'}"
            report["latency"][key] = await latency(path, sites, pool, args.episodes)
    best = next(iter(found.values()))
    report["endurance_two_workers"] = {
        "pool defaults (gc every 10 hand-overs, retire after 50)": await endurance(best, sites, args.long, 10, 50),
        "no upkeep (no forced gc, never retired)": await endurance(best, sites, args.long, 0, 10**6)}
    sites.stop()
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    asyncio.run(main())
