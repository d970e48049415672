"""Fork time: how long ``fork_episode`` takes to copy a running episode, per world, and a gym step for scale.

For each world (a street walk, a simulated kitchen, a geolocation walk; their suite tasks without the web part,
since episodes with a browser cannot be forked yet), starts an episode, plays half its oracle (so the state is
not the start state), then forks it ``--rounds`` times. Prints one JSON object: median and p95 milliseconds per
world, the issue's target (20 ms), and whether it holds. Each fork also copies the record so far (files).

    .venv/bin/python benchmarks/bench_fork.py [--rounds 50]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

import anyio

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from ewa_mcp.forking import fork_episode  # noqa: E402
from ewa_mcp.server import ServerConfig, build_server  # noqa: E402
from ewa_mcp.task_variants import embodied_only  # noqa: E402

TARGET_MS = 20.0


async def main(rounds: int) -> dict:
    run_dir = Path(tempfile.mkdtemp(prefix="ewa-bench-fork-"))
    full, episodes = build_server(ServerConfig(run_dir=run_dir))
    cook = next(t for t in sorted(episodes.tasks.all("cooking"), key=lambda t: t.id) if t.id.startswith("cooking-cook"))
    worlds = {"street": embodied_only(episodes.tasks.get("navigation-boston-000"), "bench-walk"),
              "kitchen": embodied_only(cook, "bench-kitchen"),
              "geo": embodied_only(episodes.tasks.get("geo-0079-embodied"), "bench-geo")}
    out: dict = {"rounds": rounds, "target_ms": TARGET_MS, "worlds": {}}
    try:
        for world, task in worlds.items():
            episodes.tasks.add(task)
            start = await full.call_tool("start_episode", {"task_id": task.id})
            episode_id = start.structured_content["episode_id"]
            oracle = task.oracle if world != "geo" else []  # geo's oracle only submits: walk a step instead
            for step in oracle[: len(oracle) // 2]:
                await full.call_tool(step.tool, {**step.args, "episode_id": episode_id})
            if world == "geo":
                await full.call_tool("geo_move", {"episode_id": episode_id, "direction": "north"})
            times = []
            for _ in range(rounds):
                t0 = time.perf_counter()
                fork = await fork_episode(episodes, episode_id)
                times.append((time.perf_counter() - t0) * 1000)
                await episodes.abort(fork.id, "benchmark")
            times.sort()
            out["worlds"][world] = {"median_ms": round(statistics.median(times), 2),
                                    "p95_ms": round(times[int(0.95 * (len(times) - 1))], 2),
                                    "meets_target": times[int(0.95 * (len(times) - 1))] <= TARGET_MS}
    finally:
        await episodes.aclose()
        await episodes.services.aclose()
    return out


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=50)
    args = parser.parse_args()
    print(json.dumps(anyio.run(main, args.rounds), indent=2))
