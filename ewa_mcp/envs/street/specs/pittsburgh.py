"""Pittsburgh, Downtown (the Golden Triangle) between the two rivers, the Point and Grant Street.

Method: the lower grid (avenues parallel to the Monongahela, streets from the river up to Liberty
Avenue) is an affine grid fitted on three published positions (FIT_POINTS). Liberty Avenue, the
seam between the two grids, is a polyline through published positions; the upper grid (Penn
Avenue, Fort Duquesne Boulevard and the numbered streets toward the Allegheny) is laid out
perpendicular to it. Away from the fit points the positions are approximate (up to ~80 m).
"""

from __future__ import annotations

import math

from ewa_mcp.geometry import LocalFrame
from .base import CitySpec, FitPoint, FittedGrid, LatLng, Way

COLUMNS = {"Commonwealth Place": -0.7, "Stanwix Street": 0.0, "Market Street": 1.0, "Wood Street": 2.0,
           "Smithfield Street": 3.0, "William Penn Place": 3.55, "Grant Street": 4.0, "Ross Street": 5.0}
ROWS = {"Fort Pitt Boulevard": 0.0, "1st Avenue": 0.8, "Boulevard of the Allies": 1.8, "3rd Avenue": 2.6,
        "4th Avenue": 3.4, "Forbes Avenue": 4.2, "5th Avenue": 5.0, "Oliver Avenue": 5.8, "6th Avenue": 6.6,
        "7th Avenue": 7.4}
FIT_POINTS = [
    FitPoint("Market Square (Market St between Forbes & 5th)", (1.0, 4.6), 40.44060, -80.00220, "Market Square"),
    FitPoint("Grant St & Oliver Ave", (4.0, 6.2), 40.44110, -79.99660, "Steel Plaza station coordinates"),
    FitPoint("Wood St & Liberty Ave", (2.0, 6.9), 40.44290, -79.99891, "Wood Street station coordinates"),
    FitPoint("Smithfield St & Fort Pitt Blvd", (3.0, 0.0), 40.43600, -79.99940, "Smithfield Street Bridge north end"),
    FitPoint("Ross St & 1st Ave", (5.0, 0.8), 40.43530, -79.99580, "First Avenue station"),
]
LIBERTY = [(40.44140, -80.00850), (40.44290, -79.99891), (40.44470, -79.99250), (40.44560, -79.99050)]
POINT_FOUNTAIN = (40.44185, -80.01210)
BLOCK_HOUSE = (40.4411, -80.0103)  # the Fort Pitt Block House, on the lawn between the two promenades


def _at_lng(a: LatLng, b: LatLng, lng: float) -> LatLng:
    """The point of the straight line a-b at this longitude."""
    f = (lng - a[1]) / (b[1] - a[1])
    return round(a[0] + f * (b[0] - a[0]), 6), lng
UPPER_STREETS = {  # name -> metres along Liberty Avenue from its west end
    "Stanwix Street": None, "6th Street": None, "7th Street": 940.0, "8th Street": 1030.0,
    "9th Street": 1120.0, "10th Street": 1230.0, "11th Street": 1400.0,
}
PENN_OFFSET_M = 90.0
DUQUESNE_OFFSET_M = 190.0


def _intersect(p: tuple[float, float], r: tuple[float, float], q: tuple[float, float],
               s: tuple[float, float]) -> tuple[float, float] | None:
    """Intersection parameters (t, u) of p + t r and q + u s, or None when parallel."""
    cross = r[0] * s[1] - r[1] * s[0]
    if abs(cross) < 1e-9:
        return None
    qp = (q[0] - p[0], q[1] - p[1])
    return (qp[0] * s[1] - qp[1] * s[0]) / cross, (qp[0] * r[1] - qp[1] * r[0]) / cross


def build() -> CitySpec:
    grid = FittedGrid((40.4410, -80.0000), FIT_POINTS)
    frame = LocalFrame(40.4410, -80.0000)
    lib_xy = [frame.to_xy(*p) for p in LIBERTY]

    def liberty_hit(a: LatLng, b: LatLng) -> tuple[float, float] | None:
        """Where the line a->b first meets Liberty Avenue (t along a->b) in local metres."""
        pa, pb = frame.to_xy(*a), frame.to_xy(*b)
        r = (pb[0] - pa[0], pb[1] - pa[1])
        best = None
        for q0, q1 in zip(lib_xy, lib_xy[1:]):
            s = (q1[0] - q0[0], q1[1] - q0[1])
            hit = _intersect(pa, r, q0, s)
            if hit and 0.0 <= hit[1] <= 1.0 and hit[0] > 0 and (best is None or hit[0] < best[0]):
                best = hit
        return None if best is None else (pa[0] + best[0] * r[0], pa[1] + best[0] * r[1])

    def clipped(a: LatLng, b: LatLng) -> list[LatLng]:
        hit = liberty_hit(a, b)
        if hit is None:
            return [a, b]
        pa = frame.to_xy(*a)
        if (hit[0] - pa[0]) ** 2 + (hit[1] - pa[1]) ** 2 < 25.0:
            return []  # starts beyond Liberty
        return [a, frame.to_latlng(*hit)]

    ways: list[Way] = []
    for name, col in COLUMNS.items():
        pts = clipped(grid.latlng(col, 0.0), grid.latlng(col, 9.5))
        if len(pts) == 2:
            ways.append(Way(name, pts))
    for name, row in ROWS.items():
        west = COLUMNS["Commonwealth Place"] if row <= 1.8 else COLUMNS["Stanwix Street"]
        a, b = grid.latlng(COLUMNS["Ross Street"], row), grid.latlng(west, row)
        pts = clipped(a, b)
        if len(pts) == 2:
            ways.append(Way(name, pts))
    ways.append(Way("Liberty Avenue", list(LIBERTY)))

    # Upper grid: offsets perpendicular (toward the Allegheny, to the north-west) of Liberty.
    def along(dist: float) -> tuple[float, float, float]:
        acc = 0.0
        for q0, q1 in zip(lib_xy, lib_xy[1:]):
            seg = math.dist(q0, q1)
            if acc + seg >= dist or q1 == lib_xy[-1]:
                f = min(1.0, (dist - acc) / seg)
                heading = math.atan2(q1[1] - q0[1], q1[0] - q0[0])
                return q0[0] + f * (q1[0] - q0[0]), q0[1] + f * (q1[1] - q0[1]), heading
            acc += seg
        raise ValueError("distance beyond Liberty Avenue")

    def offset(dist: float, off: float) -> LatLng:
        x, y, h = along(dist)
        return frame.to_latlng(x - off * math.sin(h), y + off * math.cos(h))

    total = sum(math.dist(a, b) for a, b in zip(lib_xy, lib_xy[1:]))
    for name, off in (("Penn Avenue", PENN_OFFSET_M), ("Fort Duquesne Boulevard", DUQUESNE_OFFSET_M)):
        ways.append(Way(name, [offset(d, off) for d in range(120, int(total) + 1, 60)]))
    # Streets that cross Liberty continue as upper-grid streets: Stanwix keeps its name; Wood
    # Street's continuation toward the Roberto Clemente Bridge is 6th Street.
    for name, dist in UPPER_STREETS.items():
        if dist is None:
            src = "Stanwix Street" if name == "Stanwix Street" else "Wood Street"
            end = next(w.points[-1] for w in ways if w.name == src)
            ex, ey = frame.to_xy(*end)
            dist = min(range(0, int(total)), key=lambda d: math.dist(along(d)[:2], (ex, ey)))
        ways.append(Way(name, [offset(dist, 0.0), offset(dist, DUQUESNE_OFFSET_M)]))
    ways.append(Way("Point State Park Promenade", [LIBERTY[0], POINT_FOUNTAIN]))
    south_start = grid.latlng(COLUMNS["Commonwealth Place"], 0.0)
    ways.append(Way("Point State Park Promenade", [south_start, POINT_FOUNTAIN]))
    # A lawn path joins the two promenades past the Block House, so a walk to it need not round the tip.
    ways.append(Way("Point State Park Promenade", [_at_lng(LIBERTY[0], POINT_FOUNTAIN, BLOCK_HOUSE[1]),
                                                   _at_lng(south_start, POINT_FOUNTAIN, BLOCK_HOUSE[1])]))
    aliases = {"Fifth Avenue": "5th Avenue", "Sixth Avenue": "6th Avenue", "Seventh Avenue": "7th Avenue",
               "Sixth Street": "6th Street", "Seventh Street": "7th Street"}
    fit = grid.report("lower grid: affine fit on published positions; Liberty polyline; upper grid offset from Liberty")
    return CitySpec("pittsburgh", "Pittsburgh (Downtown)", "pg", ways, aliases, fit)
