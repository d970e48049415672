"""Geolocation figures, printed as JSON: view rendering and description cost, tool round trips
through the in-process MCP client, and the oracle over every generated task (expected 100 %
on every level).

    .venv/bin/python benchmarks/bench_geo.py [--views 300] [--real-web]

--real-web runs the embodied tasks with the registry's browser environment (needs Chromium);
by default a stand-in web environment is used, since the oracle never touches the web.
Targets: render + encode p50 <= 40 ms per 600x400 view; geo_move round trip p50 <= 60 ms in
text mode.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import random
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any


def summary(ms: list[float]) -> dict[str, float]:
    values = sorted(ms)
    pick = lambda q: round(values[min(len(values) - 1, int(q * len(values)))], 3)  # noqa: E731
    return {"p50_ms": pick(0.5), "p95_ms": pick(0.95), "max_ms": round(values[-1], 3), "n": len(values)}


def bench_views(n: int) -> dict[str, Any]:
    from ewa_mcp.envs.geo.describe import describe_view
    from ewa_mcp.envs.geo.locations import LOCATIONS_LIST
    from ewa_mcp.envs.geo.view_images import render_png
    from ewa_mcp.envs.geo.scene import compose_view

    rng = random.Random(3)
    compose, render, describe, sizes = [], [], [], []
    for _ in range(n):
        loc = rng.choice(LOCATIONS_LIST)
        sp, heading = rng.choice(["p0", "p1", "p2", "p3", "p4"]), rng.choice(["north", "east", "south", "west"])
        t = time.perf_counter()
        spec = compose_view.__wrapped__(loc, sp, heading)  # uncached: measure the real work
        compose.append((time.perf_counter() - t) * 1000)
        t = time.perf_counter()
        png = render_png.__wrapped__(spec)
        render.append((time.perf_counter() - t) * 1000)
        t = time.perf_counter()
        describe_view(spec)
        describe.append((time.perf_counter() - t) * 1000)
        sizes.append(len(png))
    return {"compose": summary(compose), "render_png": summary(render), "describe": summary(describe),
            "png_kib_mean": round(statistics.fmean(sizes) / 1024, 1)}


class WikiStandIn:
    side = "web"
    name = "browser"

    def __init__(self, episode: Any, services: Any):
        pass

    async def reset(self, task, options):
        return None

    async def observe(self):
        from ewa_mcp.core.environment import Observation

        return Observation(text="(wiki)")

    async def final_state(self):
        return {}

    async def close(self):
        return None


async def bench_episodes(real_web: bool) -> dict[str, Any]:
    from ewa_mcp.envs.geo.checks import aggregate_geolocation, grade_geolocation
    from mcp import Client

    from ewa_mcp.envs.geo.taskgen.geolocation import generate_tasks
    from ewa_mcp.server import ServerConfig, build_server

    tmp = Path(tempfile.mkdtemp(prefix="bench-geo-"))
    generate_tasks(tmp / "tasks")
    environments = None if real_web else {"browser": WikiStandIn}
    mcp, episodes = build_server(ServerConfig(task_dirs=[tmp / "tasks"], run_dir=tmp / "run",
                                              environments=environments))
    rows, start_ms, look_ms, move_ms, vision_move_ms = [], [], [], [], []
    t0 = time.perf_counter()
    async with Client(mcp) as client:
        for task in sorted(episodes.tasks.all("geolocation"), key=lambda t: t.id):
            t = time.perf_counter()
            r = await client.call_tool("start_episode", {"task_id": task.id})
            start_ms.append((time.perf_counter() - t) * 1000)
            episode_id = r.structured_content["episode_id"]
            for call in task.oracle:
                t = time.perf_counter()
                r = await client.call_tool(call.tool, {"episode_id": episode_id, **call.args})
                elapsed = (time.perf_counter() - t) * 1000
                assert not r.is_error, (task.id, call.tool, r.content)
                {"geo_look": look_ms, "geo_move": move_ms}.get(call.tool, []).append(elapsed)
            final = json.loads((tmp / "run" / episode_id / "final_state.json").read_text(encoding="utf-8"))
            rows.append({**grade_geolocation(task.answer, final["submission"]), "setting": task.metadata["setting"]})
        # Vision mode: four PNGs per move.
        for task_id in ("geo-0018-embodied", "geo-0042-embodied", "geo-0021-embodied"):
            r = await client.call_tool("start_episode", {"task_id": task_id, "options": {"observation": "vision"}})
            episode_id = r.structured_content["episode_id"]
            t = time.perf_counter()
            await client.call_tool("geo_move", {"episode_id": episode_id, "neighbour": "p1"})
            vision_move_ms.append((time.perf_counter() - t) * 1000)
    agg = aggregate_geolocation(rows)
    oracle = {setting: {level: s[level]["value"] for level in ("continent", "country", "city", "street", "all_levels")}
              for setting, s in agg["by_setting"].items()}
    return {
        "tasks": len(rows),
        "web": "registry browser" if real_web else "stand-in",
        "oracle_accuracy": oracle,
        "oracle_mean_score": {s: v["mean_score"] for s, v in agg["by_setting"].items()},
        "start_episode": summary(start_ms),
        "geo_look_text": summary(look_ms),
        "geo_move_text": summary(move_ms),
        "geo_move_vision": summary(vision_move_ms),
        "oracle_suite_s": round(time.perf_counter() - t0, 2),
    }


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--views", type=int, default=300)
    parser.add_argument("--real-web", action="store_true")
    args = parser.parse_args()

    from ewa_mcp.street_drawing.fonts import installed_scripts
    from ewa_mcp.envs.geo.locations import LOCATIONS_LIST

    out: dict[str, Any] = {"locations": len(LOCATIONS_LIST), "native_scripts": installed_scripts()}
    out["views"] = bench_views(args.views)
    out["episodes"] = asyncio.run(bench_episodes(args.real_web))
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
