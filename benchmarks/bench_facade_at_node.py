"""Whether each place's own front is drawn, in the look its description gives, where its walk stops.

For every place of every city, at its anchored node (where a street goal is graded and the text mode says
"Right here"), and for every way a walker can face there (along each street at the node, either way, with the
views front/right/back/left; and the four compass views): the view that faces the place must draw it close up
(its "here:" cue) and, where its description names what it is built of, in that colour (scene.wall_colour_of:
"rust-brown weathering steel" is rust-brown, not the grey of bare steel). Prints how many places are off, and
for those drawn in another colour, how far the drawn colour is from the stated one (RGB distance).
Run: .venv/bin/python benchmarks/bench_facade_at_node.py [--city pittsburgh] [--show 20]
"""

from __future__ import annotations

import argparse
import math

from ewa_mcp.geometry import angle_diff, bearing_deg


def facing_headings(graph, i: int, towards: float) -> list[float]:
    """The heading of the view facing ``towards`` for each way a walker can face at node i."""
    faces = {0.0, 90.0, 180.0, 270.0}  # compass views
    for _j, _len, _s, h in graph.adj[i]:
        faces |= {h % 360.0, (h + 180.0) % 360.0}  # walking on along the street, or having arrived by it
    out = set()
    for face in faces:
        views = [(face + k * 90.0) % 360.0 for k in range(4)]
        out.add(round(min(views, key=lambda v: abs(angle_diff(towards, v))), 1))
    return sorted(out)


def wall_pixels(img, colour: tuple[int, int, int]) -> int:
    return sum(n for n, c in img.getcolors(maxcolors=1 << 18) or [] if c == colour)


def dominant_front_colour(img) -> tuple[int, int, int]:
    """The most frequent colour above the horizon's lower band that is not sky (what a front is drawn in)."""
    from ewa_mcp.envs.street.facades import SKY, SKY_TOP

    band = img.crop((60, 20, img.width - 60, int(img.height * 0.42)))
    counts = sorted(band.getcolors(maxcolors=1 << 18) or [], reverse=True)
    sky = {SKY, SKY_TOP}
    return next((c for _, c in counts if c not in sky and not (c[2] > c[0] + 30 and c[2] > 190)), (0, 0, 0))


def check_place(world, p) -> tuple[list[str], float]:
    """(problems, RGB distance of the drawn front from the stated colour) for one place at its node."""
    from ewa_mcp.envs.street.scene import OPEN_SPACE_KINDS, compute_scene, wall_colour_of
    from ewa_mcp.envs.street.here_view import sidewalk_entrance
    from ewa_mcp.envs.street.street_view import render_cues

    graph, i = world.locate(p.node)
    towards = p.heading_from_node if p.heading_from_node is not None else bearing_deg(
        graph.lat[i], graph.lng[i], p.lat, p.lng)
    colour = wall_colour_of(p.description_hint) if p.kind not in OPEN_SPACE_KINDS else None
    problems, worst = [], 0.0
    for heading in facing_headings(graph, i, towards):
        scene = compute_scene(world, graph, i, heading, "view")
        img, cues = render_cues(scene)
        if f"here:{p.id}" not in cues:
            problems.append(f"not drawn facing {heading:.0f}°")
            continue
        here = next(f for f in scene.here if f.place_id == p.id)
        if colour is None or sidewalk_entrance(here):
            continue
        if wall_pixels(img, colour) < 0.02 * img.width * img.height:
            drawn = dominant_front_colour(img)
            worst = max(worst, math.dist(drawn, colour))
            problems.append(f"facing {heading:.0f}°: front drawn {drawn}, its description gives {colour}")
    return problems, worst


def main() -> None:
    from ewa_mcp.envs.street.world import get_world

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--city", help="one city only")
    ap.add_argument("--show", type=int, default=20, help="how many off places to list")
    args = ap.parse_args()
    world = get_world()
    places = sorted((p for p in world.places.values() if p.node and (args.city is None or p.city == args.city)),
                    key=lambda p: p.id)
    off = []
    for p in places:
        problems, dist = check_place(world, p)
        if problems:
            off.append((p.id, dist, problems))
    missing = sum(1 for _, _, pr in off if any(x.startswith("not drawn") for x in pr))
    print(f"places: {len(places)}; off at their node: {len(off)} "
          f"(not drawn in the view facing them: {missing}; drawn in another colour than described: "
          f"{len(off) - missing})")
    if off:
        dists = sorted(d for _, d, _ in off if d)
        if dists:
            print(f"RGB distance of the drawn front from the stated colour: median {dists[len(dists) // 2]:.0f}, "
                  f"max {dists[-1]:.0f}")
    for pid, dist, problems in off[:args.show]:
        more = f" (+{len(problems) - 1} more)" if len(problems) > 1 else ""
        print(f"  {pid}: {problems[0]}{more}" + (f"; RGB distance {dist:.0f}" if dist else ""))


if __name__ == "__main__":
    main()
