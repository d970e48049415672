"""Outdoor world figures, printed as JSON: world load, move latency, routing + directions, view
rendering, and a street_move round trip through the in-process MCP client.

    .venv/bin/python benchmarks/bench_outdoor.py [--pairs 200] [--moves 2000]
Targets: move p50 <= 1 ms in-process; shortest path + directions p50 <= 5 ms; render <= 30 ms.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path


def pct(values: list[float], q: float) -> float:
    values = sorted(values)
    return round(values[min(len(values) - 1, int(q * len(values)))], 3)


def summary(ms: list[float]) -> dict[str, float]:
    return {"p50_ms": pct(ms, 0.5), "p95_ms": pct(ms, 0.95), "max_ms": round(max(ms), 3), "n": len(ms)}


async def bench_env(world, moves: int, mode: str) -> dict[str, object]:
    from ewa_mcp.envs.street.env import StreetEnvironment
    from ewa_mcp.core.services import Services
    from ewa_mcp.core.taskmodel import Task

    rng = random.Random(7)
    graph = world.city("manhattan")
    start = graph.ids[rng.randrange(len(graph.ids))]
    task = Task.model_validate({"id": "bench", "domain": "navigation", "intent": "bench",
                                "start": {"environment": "embodied",
                                          "embodied": {"kind": "street", "city": "manhattan", "node": start}}})
    env = StreetEnvironment(episode=None, services=Services())
    await env.reset(task, {"observation": mode})
    core, full = [], []
    for _ in range(moves):
        links = graph.adj[env.node]
        j, length, s, h = links[rng.randrange(len(links))]
        t = time.perf_counter()
        # the state transition alone (what a move changes)
        env.node, env.heading = j, h
        env.path.append(graph.ids[j])
        env.distance_walked_m += length
        core.append((time.perf_counter() - t) * 1000)
        nb = env._neighbours()
        target = nb[rng.randrange(len(nb))]["node"]
        t = time.perf_counter()
        env.move(neighbour=target)  # the full action: validate, move, build the observation
        full.append((time.perf_counter() - t) * 1000)
    return {"state_update": summary(core), "move_with_observation": summary(full)}


def bench_routes(world, pairs: int) -> dict[str, object]:
    rng = random.Random(11)
    out: dict[str, object] = {}
    for city in ("manhattan", "philadelphia"):
        places = sorted(p.id for p in world.places.values() if p.city == city)
        ms, km = [], []
        for _ in range(pairs):
            a, b = rng.sample(places, 2)
            t = time.perf_counter()
            d = world.directions(a, b)
            ms.append((time.perf_counter() - t) * 1000)
            km.append(d.distance_m / 1000)
        out[city] = {**summary(ms), "route_km_median": round(statistics.median(km), 2)}
    return out


def bench_render(world, n: int) -> dict[str, object]:
    from ewa_mcp.envs.street.street_view import render_png
    from ewa_mcp.envs.street.scene import compute_scene

    rng = random.Random(5)
    graph = world.city("manhattan")
    scene_ms, render_ms, sizes = [], [], []
    render_png(compute_scene(world, graph, 0, 0.0, "front"))  # font load
    for _ in range(n):
        i = rng.randrange(len(graph.ids))
        heading = float(rng.randrange(360))
        t = time.perf_counter()
        scene = compute_scene(world, graph, i, heading, "front")
        t1 = time.perf_counter()
        png = render_png(scene)
        t2 = time.perf_counter()
        scene_ms.append((t1 - t) * 1000)
        render_ms.append((t2 - t1) * 1000)
        sizes.append(len(png))
    return {"scene": summary(scene_ms), "render_png": summary(render_ms),
            "png_bytes_median": int(statistics.median(sizes))}


async def bench_mcp(world, n: int) -> dict[str, object]:
    from mcp import Client

    from ewa_mcp.core import registry
    from ewa_mcp.server import ServerConfig, build_server

    registry.tool_groups = lambda: ["ewa_mcp.core.lifecycle", "ewa_mcp.envs.street.tools"]
    with tempfile.TemporaryDirectory() as tmp:
        tasks = Path(tmp) / "tasks"
        tasks.mkdir()
        start = world.search("5th Ave & W 23rd St")[0].node
        (tasks / "t.json").write_text(json.dumps({
            "id": "bench", "domain": "navigation", "intent": "bench", "step_limit": 10000,
            "start": {"environment": "embodied", "embodied": {"kind": "street", "city": "manhattan", "node": start}}}))
        server, _ = build_server(ServerConfig(task_dirs=[tasks], run_dir=Path(tmp) / "run"))
        out = {}
        async with Client(server) as c:
            for mode in ("text", "both"):
                r = await c.call_tool("start_episode", {"task_id": "bench", "options": {"observation": mode}})
                ep = r.structured_content["episode_id"]
                ms = []
                for k in range(n):
                    t = time.perf_counter()
                    r = await c.call_tool("street_move", {"episode_id": ep, "direction": "forward" if k % 40 < 20 else "back"})
                    ms.append((time.perf_counter() - t) * 1000)
                    if r.is_error:
                        await c.call_tool("street_move", {"episode_id": ep, "direction": "back"})
                out[f"street_move_{mode}"] = summary(ms)
                await c.call_tool("finish_episode", {"episode_id": ep})
        return out


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--pairs", type=int, default=200)
    parser.add_argument("--moves", type=int, default=2000)
    parser.add_argument("--renders", type=int, default=100)
    parser.add_argument("--mcp-moves", type=int, default=200)
    args = parser.parse_args()
    t = time.perf_counter()
    from ewa_mcp.envs.street.world import get_world

    world = get_world()
    load_s = time.perf_counter() - t
    t = time.perf_counter()
    world.graph("manhattan")
    nx_s = time.perf_counter() - t
    result = {
        "benchmark": "outdoor",
        "python": sys.version.split()[0],
        "world_load_s": round(load_s, 3),
        "networkx_view_manhattan_s": round(nx_s, 3),
        "nodes": {c: len(world.city(c).ids) for c in world.cities},
        "pois": len(world.places),
        "move_text": asyncio.run(bench_env(world, args.moves, "text")),
        "directions": bench_routes(world, args.pairs),
        "views": bench_render(world, args.renders),
        "mcp_in_process": asyncio.run(bench_mcp(world, args.mcp_moves)),
        "targets": {"move_p50_ms": 1.0, "directions_p50_ms": 5.0, "render_ms": 30.0},
    }
    print(json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
