"""Render time and PNG size of the first-person kitchen camera (indoor/camera3d.py).

Prints ms per 300×300 frame (p50 over poses in several kitchens, scene building, GL and PNG encoding apart),
the PNG bytes per observation, the renderer EGL chose and the load average (the machine is shared).
Run: .venv/bin/python benchmarks/bench_camera.py [--size 300] [--frames 60]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

from ewa_mcp.envs.kitchen import camera3d
from ewa_mcp.envs.kitchen.kitchen_map import png_bytes
from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim

SCENES = ("FloorPlan1", "FloorPlan5", "FloorPlan12", "FloorPlan23")
TARGETS = ("Tomato", "Fridge", "StoveBurner", "Plate", "Sink")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, default=300)
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--samples", type=int, default=camera3d.SAMPLES, help="multisampling (0: none)")
    args = parser.parse_args()
    camera3d.SAMPLES = args.samples
    poses = []
    for scene in SCENES:
        session = KitchenSession(KitchenSim(None), "sim", scene, 0)
        session.reset()
        for target in TARGETS:
            try:
                session.teleport(target)
            except Exception:  # noqa: BLE001 - a kitchen without this object: skip the pose
                continue
            poses.append((session.meta, list(session.reachable)))
    start = time.perf_counter()
    renderer = camera3d.renderer_name()
    first = time.perf_counter() - start
    build, whole, encode, sizes = [], [], [], []
    inner = camera3d._get()
    for i in range(args.frames):
        meta, reachable = poses[i % len(poses)]
        t0 = time.perf_counter()
        inner.scene.build(meta, reachable)
        build.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        image = camera3d.render_frame(meta, reachable, width=args.size, height=args.size)
        t1 = time.perf_counter()
        data = png_bytes(image)
        t2 = time.perf_counter()
        whole.append(t2 - t0)
        encode.append(t2 - t1)
        sizes.append(len(data))

    def ms(values: list[float]) -> str:
        return f"p50 {statistics.median(values) * 1000:.1f} ms, min {min(values) * 1000:.1f} ms"

    print(f"renderer: {renderer} (context + shaders: {first * 1000:.0f} ms, once per process)")
    print(f"{args.size}x{args.size} frame + PNG, {args.samples}x multisampling: {ms(whole)}  ({len(poses)} poses, {args.frames} frames)")
    print(f"  scene building (Python): {ms(build)}; PNG encoding: {ms(encode)}")
    print(f"PNG bytes per observation: p50 {int(statistics.median(sizes))}, max {max(sizes)}")
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())} on {os.cpu_count()} CPUs")


if __name__ == "__main__":
    main()
