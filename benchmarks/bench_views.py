"""Render time and image bytes of the street and geolocation views (the vision-mode observations).

Prints, for each world: ms per view (drawing, and drawing + PNG encoding; p50/p95 over a sample of views,
caches bypassed), PNG bytes per view, and image bytes per observation (four views; one for the geolocation
baseline setting). Also the load average, since the machine may be shared.
Run: .venv/bin/python benchmarks/bench_views.py [--views 120]
"""

from __future__ import annotations

import argparse
import os
import random
import statistics
import time

from ewa_mcp.geometry import FOUR_DIRECTIONS


def stats(values: list[float], unit: str = "ms") -> str:
    v = sorted(values)
    p95 = v[min(len(v) - 1, int(0.95 * len(v)))]
    if unit == "ms":
        return f"p50 {statistics.median(v) * 1000:.1f} ms, p95 {p95 * 1000:.1f} ms"
    return f"p50 {int(statistics.median(v))} B, p95 {int(p95)} B, max {int(v[-1])} B"


def bench_street(n: int, rng: random.Random, at_places: bool = False) -> None:
    from ewa_mcp.envs.street.scene import compute_scene
    from ewa_mcp.envs.street.street_view import render
    from ewa_mcp.street_drawing.png import encode_png
    from ewa_mcp.envs.street.world import get_world

    world = get_world()
    views = []
    for city in sorted(world.cities_by_name):
        g = world.city(city)
        # --at-places: the nodes places stand at, whose views draw the place close up (vision "Right here")
        pool = sorted({p.node for p in world.places.values() if p.city == g.city}) if at_places else g.ids
        for node in rng.sample(pool, min(len(pool), max(1, n // (4 * len(world.cities_by_name))))):
            views.append((g, g.index[node]))
    draw_t, whole_t, sizes, obs = [], [], [], []
    for g, i in views:
        per_obs = 0
        for heading in (0.0, 90.0, 180.0, 270.0):
            scene = compute_scene(world, g, i, heading, "front")
            t0 = time.perf_counter()
            img = render(scene)
            t1 = time.perf_counter()
            png = encode_png(img, colours=128)
            t2 = time.perf_counter()
            draw_t.append(t1 - t0)
            whole_t.append(t2 - t0)
            sizes.append(len(png))
            per_obs += len(png)
        obs.append(per_obs)
    where = "at place nodes" if at_places else "at random nodes"
    print(f"street view 480x330 ({len(sizes)} views {where} in {len(world.cities_by_name)} cities)")
    print(f"  drawing: {stats(draw_t)}; drawing + PNG: {stats(whole_t)}")
    print(f"  PNG bytes per view: {stats(sizes, 'B')}")
    print(f"  image bytes per observation (4 views): {stats(obs, 'B')}")


def bench_geo(n: int, rng: random.Random) -> None:
    from ewa_mcp.envs.geo.graph import build_graph
    from ewa_mcp.envs.geo.locations import LOCATIONS_LIST
    from ewa_mcp.envs.geo.scene import compose_view
    from ewa_mcp.envs.geo.view_images import render_view
    from ewa_mcp.street_drawing.png import encode_png

    locs = rng.sample(LOCATIONS_LIST, min(len(LOCATIONS_LIST), max(1, n // 4)))
    draw_t, whole_t, sizes, obs = [], [], [], []
    for loc in locs:
        sp = rng.choice(sorted(build_graph(loc)))
        per_obs = 0
        for heading in FOUR_DIRECTIONS:
            spec = compose_view(loc, sp, heading)
            t0 = time.perf_counter()
            img = render_view(spec)
            t1 = time.perf_counter()
            png = encode_png(img)
            t2 = time.perf_counter()
            draw_t.append(t1 - t0)
            whole_t.append(t2 - t0)
            sizes.append(len(png))
            per_obs += len(png)
        obs.append(per_obs)
    print(f"geolocation view 600x400 ({len(sizes)} views at {len(locs)} locations)")
    print(f"  drawing: {stats(draw_t)}; drawing + PNG: {stats(whole_t)}")
    print(f"  PNG bytes per view: {stats(sizes, 'B')}")
    print(f"  image bytes per observation (embodied setting, 4 views): {stats(obs, 'B')}")
    print("  (the baseline setting sends one view: the PNG bytes per view above)")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--views", type=int, default=120, help="about how many views per world")
    parser.add_argument("--at-places", action="store_true", help="street views only, at the nodes places stand at")
    args = parser.parse_args()
    rng = random.Random(0)
    bench_street(args.views, rng, args.at_places)
    if not args.at_places:
        bench_geo(args.views, rng)
    print(f"load average: {' '.join(f'{v:.2f}' for v in os.getloadavg())} on {os.cpu_count()} CPUs")


if __name__ == "__main__":
    main()
