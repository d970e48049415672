"""Kitchen speed: simulator steps, agent actions in process and over MCP, scene resets, the ai2thor stand-in.

Prints JSON (milliseconds). Targets: a kitchen action round trip in process p50 <= 1 ms — at least
45x faster than AI2-THOR's published 13–22 actions/s on a GPU desktop — and a scene reset <= 5 ms.
The same actions are also timed through the real ai2thor client driving the FIFO stand-in.

    .venv/bin/python benchmarks/bench_kitchen.py          # BENCH_N=300 rounds per figure
"""

from __future__ import annotations

import json
import os
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import anyio

from ewa_mcp.envs.kitchen.observe import build_observation
from ewa_mcp.envs.kitchen.planner import check_recipe_executable
from ewa_mcp.envs.kitchen.kitchen_map import png_bytes, render_topdown
from ewa_mcp.envs.kitchen.scenes import SCENE_NAMES, _generate
from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim

N = int(os.environ.get("BENCH_N", "300"))
SCENE = "FloorPlan12"
# A loop of actions that all succeed and leave the kitchen as it was (but for where the knife lies).
CYCLE = ["Teleport Fridge", "OpenObject Fridge", "CloseObject Fridge", "Teleport Knife", "PickupObject Knife",
         "Teleport CounterTop", "PutObject CounterTop", "RotateRight", "RotateLeft"]
AI2THOR_PUBLISHED_ACTIONS_PER_S = (13, 22)


def stats(times: list[float]) -> dict[str, float]:
    ordered = sorted(times)
    return {"p50_ms": round(statistics.median(ordered), 4),
            "p95_ms": round(ordered[min(len(ordered) - 1, int(0.95 * (len(ordered) - 1)))], 4), "n": len(ordered)}


def timed(fn: Callable[[int], Any], n: int, warmup: int = 20) -> dict[str, float]:
    for i in range(warmup):
        fn(i)
    times = []
    for i in range(warmup, warmup + n):  # the counter runs on, so action cycles stay in step
        t0 = time.perf_counter()
        fn(i)
        times.append((time.perf_counter() - t0) * 1000)
    return stats(times)


def session_for(controller: Any, backend: str) -> KitchenSession:
    session = KitchenSession(controller, backend, SCENE)
    session.reset()
    return session


def bench_sim_step() -> dict[str, float]:
    sim = KitchenSim(SCENE)
    return timed(lambda i: sim.step(action="RotateRight" if i % 2 else "RotateLeft"), N)


def bench_session_action() -> dict[str, float]:
    session = session_for(KitchenSim(None), "sim")

    def act(i: int) -> None:
        session.run(CYCLE[i % len(CYCLE)])
        build_observation(session, "text")

    return timed(act, N)


def bench_reset() -> dict[str, Any]:
    sim = KitchenSim(SCENE)
    warm = timed(lambda i: sim.reset(SCENE_NAMES[i % len(SCENE_NAMES)]), N)
    session = session_for(KitchenSim(None), "sim")
    session_reset = timed(lambda i: session.reset(), max(50, N // 4))
    t0 = time.perf_counter()
    for number in range(1, len(SCENE_NAMES) + 1):
        _generate(number, 0)
    generate = (time.perf_counter() - t0) * 1000 / len(SCENE_NAMES)
    return {"sim_reset": warm, "episode_reset_incl_reachable_positions": session_reset,
            "generate_scene_first_time_ms": round(generate, 3)}


def bench_render() -> dict[str, float]:
    session = session_for(KitchenSim(None), "sim")
    return timed(lambda i: png_bytes(render_topdown(session.meta, session.reachable, label=session.handle)),
                 max(30, N // 10), warmup=3)


def bench_planner() -> dict[str, float]:
    ops = [{"op": "slice", "object": "Potato"}, {"op": "cook", "object": "PotatoSliced", "method": "stove"},
           {"op": "put", "object": "PotatoSliced", "receptacle": "Plate"}]
    return timed(lambda i: check_recipe_executable(SCENE_NAMES[i % 30], ops, ("Potato",)), 60, warmup=2)


async def bench_mcp() -> dict[str, float]:
    from mcp import Client

    from ewa_mcp.server import ServerConfig, build_server

    tmp = Path(tempfile.mkdtemp(prefix="ewa-bench-kitchen-"))
    (tmp / "tasks").mkdir()
    (tmp / "tasks" / "k.json").write_text(json.dumps({
        "id": "bench-kitchen", "domain": "cooking", "intent": "benchmark", "step_limit": 10_000,
        "start": {"environment": "embodied", "embodied": {"kind": "kitchen", "scene": SCENE}}}))
    mcp, _ = build_server(ServerConfig(task_dirs=[tmp / "tasks"], run_dir=tmp / "runs"))
    async with Client(mcp) as client:
        r = await client.call_tool("start_episode", {"task_id": "bench-kitchen"})
        ep = r.structured_content["episode_id"]
        times = []
        for i in range(N + 20):
            t0 = time.perf_counter()
            r = await client.call_tool("kitchen_action", {"episode_id": ep, "action": CYCLE[i % len(CYCLE)]})
            if i >= 20:
                times.append((time.perf_counter() - t0) * 1000)
            assert not r.is_error, r.content
        await client.call_tool("finish_episode", {"episode_id": ep})
    return stats(times)


def bench_ai2thor() -> dict[str, Any]:
    try:
        from ewa_mcp.envs.kitchen.ai2thor_backend import Ai2ThorController
        from ewa_mcp.envs.kitchen.standin import standin_command
    except ImportError:
        return {"skipped": "ai2thor is not installed (pip install 'ewa-mcp[ai2thor]')"}
    out: dict[str, Any] = {}
    for label, frames in (("headless", False), ("with_300x300_frames", True)):
        t0 = time.perf_counter()
        controller = Ai2ThorController(standin_command(), SCENE, render_images=frames)
        started = (time.perf_counter() - t0) * 1000
        try:
            session = session_for(controller, "ai2thor")
            raw = timed(lambda i: controller.step(action="RotateRight" if i % 2 else "RotateLeft"),
                        N if not frames else N // 3)

            def act(i: int) -> None:
                session.run(CYCLE[i % len(CYCLE)])
                build_observation(session, "text")

            action = timed(act, N if not frames else N // 3)
        finally:
            controller.close()
        out[label] = {"controller_start_ms": round(started, 1), "client_step": raw, "kitchen_action": action}
    return out


def main() -> None:
    action = bench_session_action()
    mcp = anyio.run(bench_mcp)
    best = 1000.0 / AI2THOR_PUBLISHED_ACTIONS_PER_S[1]  # ms per action at AI2-THOR's best published rate
    results = {
        "scene": SCENE,
        "sim_step": bench_sim_step(),
        "kitchen_action_in_process": action,
        "kitchen_action_mcp_in_process": mcp,
        "x_faster_than_ai2thor_22_actions_per_s": {
            "in_process": round(best / action["p50_ms"], 1),
            "mcp_in_process": round(best / mcp["p50_ms"], 1),
        },
        "scene_reset": bench_reset(),
        "render_png": bench_render(),
        "planner_check_recipe": bench_planner(),
        "ai2thor_client_with_standin": bench_ai2thor(),
        "targets": {"kitchen_action_in_process_p50_ms": 1.0, "x_faster": 45, "scene_reset_ms": 5.0},
    }
    print(json.dumps(results, indent=2))


if __name__ == "__main__":
    main()
