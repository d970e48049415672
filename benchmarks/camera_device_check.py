"""The first-person kitchen camera on whatever device EGL picks: which renderer, deterministic, first-person, and
the same picture as another renderer draws.

Renders a fixed set of kitchen states (several kitchens; facing a tomato, after MoveBack, after turning 180°,
with the fridge open and a burner lit) and prints:
- the OpenGL renderer EGL chose (a GPU where its driver is installed, Mesa's llvmpipe on the CPU);
- whether every state rendered twice gives the same bytes (determinism on one machine);
- the share of pixels that change when the agent turns 180° (a first-person view changes most of the frame);
- p50 ms per 300×300 frame (GL and readback, no PNG) and per 1024×1024 frame, with the load average;
- with ``--reference DIR``: for each state, the mean absolute difference per channel and the share of pixels that
  differ by more than 48 (sum over channels) from the frame another renderer wrote with ``--write DIR``. Two
  rasterisers never agree to the byte (rounding, multisampling patterns); they should agree on the picture.

Run on the CPU:  .venv/bin/python benchmarks/camera_device_check.py --write /tmp/cpu-frames
Then elsewhere: python benchmarks/camera_device_check.py --reference /tmp/cpu-frames [--write OUT]
"""

from __future__ import annotations

import argparse
import copy
import os
import statistics
import time
from pathlib import Path

from PIL import Image

from ewa_mcp.envs.kitchen import camera3d
from ewa_mcp.envs.kitchen.session import KitchenSession
from ewa_mcp.envs.kitchen.sim import KitchenSim

SCENES = ("FloorPlan1", "FloorPlan5", "FloorPlan12", "FloorPlan23")


def states() -> list[tuple[str, dict, list]]:
    """(name, metadata, reachable) for every state drawn; built by the simulator, so the same on every machine."""
    out: list[tuple[str, dict, list]] = []

    def keep(name: str, s: KitchenSession) -> None:
        out.append((name, copy.deepcopy(s.meta), list(s.reachable)))

    for scene in SCENES:
        s = KitchenSession(KitchenSim(None), "sim", scene, 0)
        s.reset()
        keep(f"{scene}-start", s)
        s.plain_action("RotateRight")
        s.plain_action("RotateRight")
        keep(f"{scene}-turned", s)
        for food in ("Tomato", "Apple", "Bread"):
            try:
                s.teleport(food)
            except Exception:  # noqa: BLE001 - not in this kitchen: the next food
                continue
            keep(f"{scene}-food", s)
            s.plain_action("MoveBack")
            keep(f"{scene}-back", s)
            break
        s.teleport("StoveBurner")
        burner = s.resolve("StoveBurner", "interact")[0]
        knob = next(i for i, o in s.objects.items() if burner in (o.get("controlledObjects") or []))
        s._step("ToggleObjectOn", knob)
        keep(f"{scene}-burner-lit", s)
        s.teleport("Fridge")
        s._step("OpenObject", s.by_handle["fridge_1"])
        keep(f"{scene}-fridge-open", s)
    return out


def changed_share(a: Image.Image, b: Image.Image, threshold: int = 48) -> float:
    pa, pb = a.get_flattened_data(), b.get_flattened_data()
    differ = sum(1 for x, y in zip(pa, pb) if sum(abs(i - j) for i, j in zip(x, y)) > threshold)
    return differ / (a.width * a.height)


def mean_abs(a: Image.Image, b: Image.Image) -> float:
    pa, pb = a.get_flattened_data(), b.get_flattened_data()
    return sum(abs(i - j) for x, y in zip(pa, pb) for i, j in zip(x, y)) / (3 * a.width * a.height)


def timed(meta: dict, reachable: list, size: int, frames: int) -> float:
    times = []
    for _ in range(frames):
        t0 = time.perf_counter()
        camera3d.render_frame(meta, reachable, width=size, height=size)
        times.append(time.perf_counter() - t0)
    return statistics.median(times) * 1000


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--reference", type=Path, help="folder of PNGs another renderer wrote with --write")
    parser.add_argument("--write", type=Path, help="write each state's 300×300 frame here as NAME.png")
    parser.add_argument("--frames", type=int, default=40)
    args = parser.parse_args()
    t0 = time.perf_counter()
    print(f"renderer: {camera3d.renderer_name()} (context: {(time.perf_counter() - t0) * 1000:.0f} ms)")
    drawn = states()
    same = 0
    frames: dict[str, Image.Image] = {}
    for name, meta, reachable in drawn:
        first = camera3d.render_png(meta, reachable)
        same += first == camera3d.render_png(meta, reachable)
        frames[name] = camera3d.render_frame(meta, reachable)
    print(f"deterministic: {same} of {len(drawn)} states gave the same bytes twice")
    for scene in SCENES:
        share = changed_share(frames[f"{scene}-start"], frames[f"{scene}-turned"])
        print(f"  {scene}: turning 180° changes {share:.0%} of the pixels")
    if args.write:
        args.write.mkdir(parents=True, exist_ok=True)
        for name, image in frames.items():
            image.save(args.write / f"{name}.png")
    if args.reference:
        diffs, shares = [], []
        for name, image in frames.items():
            path = args.reference / f"{name}.png"
            if not path.exists():
                continue
            other = Image.open(path).convert("RGB")
            diffs.append(mean_abs(image, other))
            shares.append(changed_share(image, other))
            print(f"  vs reference {name}: mean |diff| {diffs[-1]:.2f} per channel, {shares[-1]:.1%} pixels differ")
        if diffs:
            print(f"against the reference renderer: mean |diff| p50 {statistics.median(diffs):.2f}, max "
                  f"{max(diffs):.2f}; pixels differing p50 {statistics.median(shares):.1%}, max {max(shares):.1%}")
    name, meta, reachable = drawn[2]
    camera3d.render_frame(meta, reachable)  # warm
    print(f"frame time (GL + readback, no PNG): 300x300 p50 {timed(meta, reachable, 300, args.frames):.1f} ms, "
          f"1024x1024 p50 {timed(meta, reachable, 1024, max(5, args.frames // 4)):.1f} ms")
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())} on {os.cpu_count()} CPUs")


if __name__ == "__main__":
    main()
