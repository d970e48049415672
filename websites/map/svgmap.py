"""Draw a small street map as SVG: nearby street segments, an optional highlighted route, markers.

Pure geometry on (lat, lng) pairs, so it works for any city graph. Equirectangular projection
around the map's centre is accurate to well under a pixel at the scale of a walk. The output is
bounded: the viewport is the route's bounding box plus a margin, and at most ``max_segments``
street segments are drawn (nearest the centre first) as one <path>, so a long route in a dense
city stays a few hundred kilobytes at most.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from xml.sax.saxutils import escape

from ewa_mcp.geometry import METRES_PER_DEGREE_LAT

LatLng = tuple[float, float]


@dataclass(frozen=True)
class Segment:
    a: LatLng
    b: LatLng
    street: str = ""
    # (south, north, west, east), computed once: maps filter a city's ~10,000 segments per page.
    box: tuple[float, float, float, float] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        box = (min(self.a[0], self.b[0]), max(self.a[0], self.b[0]), min(self.a[1], self.b[1]), max(self.a[1], self.b[1]))
        object.__setattr__(self, "box", box)


@dataclass(frozen=True)
class Marker:
    at: LatLng
    label: str  # one or two characters drawn in the marker, e.g. "A"
    name: str  # what the marker stands for, e.g. the place name
    color: str


@dataclass(frozen=True)
class Viewport:
    south: float
    west: float
    north: float
    east: float

    @classmethod
    def around(cls, points: list[LatLng], margin_m: float, min_span_m: float = 300.0,
               aspect: float | None = None) -> "Viewport":
        """The points' bounding box grown to ``min_span_m``, then (with ``aspect`` = width / height)
        widened or heightened so the map is never a thin strip, then padded by ``margin_m``."""
        lats = [p[0] for p in points]
        lngs = [p[1] for p in points]
        mid_lat = (min(lats) + max(lats)) / 2
        cos_lat = max(0.2, math.cos(math.radians(mid_lat)))
        # Grow small boxes to a minimum span so a 20 m walk still shows its block.
        lat_span = max((max(lats) - min(lats)) * METRES_PER_DEGREE_LAT, min_span_m) / METRES_PER_DEGREE_LAT
        m_per_deg_lng = METRES_PER_DEGREE_LAT * cos_lat
        lng_span = max((max(lngs) - min(lngs)) * m_per_deg_lng, min_span_m) / m_per_deg_lng
        if aspect is not None:
            width_m, height_m = lng_span * METRES_PER_DEGREE_LAT * cos_lat, lat_span * METRES_PER_DEGREE_LAT
            if width_m < height_m * aspect * 0.75:
                lng_span = height_m * aspect * 0.75 / (METRES_PER_DEGREE_LAT * cos_lat)
            elif width_m > height_m * aspect * 1.6:
                lat_span = width_m / (aspect * 1.6) / METRES_PER_DEGREE_LAT
        mid_lng = (min(lngs) + max(lngs)) / 2
        pad_lat = margin_m / METRES_PER_DEGREE_LAT
        pad_lng = margin_m / (METRES_PER_DEGREE_LAT * cos_lat)
        return cls(mid_lat - lat_span / 2 - pad_lat, mid_lng - lng_span / 2 - pad_lng,
                   mid_lat + lat_span / 2 + pad_lat, mid_lng + lng_span / 2 + pad_lng)

    def contains(self, p: LatLng) -> bool:
        return self.south <= p[0] <= self.north and self.west <= p[1] <= self.east

    @property
    def centre(self) -> LatLng:
        return ((self.south + self.north) / 2, (self.west + self.east) / 2)


class Projection:
    """(lat, lng) -> SVG pixels for a viewport drawn at most width x max_height pixels."""

    def __init__(self, view: Viewport, width: int, max_height: int):
        self.view = view
        self.cos_lat = math.cos(math.radians(view.centre[0]))
        width_m = (view.east - view.west) * METRES_PER_DEGREE_LAT * self.cos_lat
        height_m = (view.north - view.south) * METRES_PER_DEGREE_LAT
        self.scale = min(width / width_m, max_height / height_m)  # pixels per metre, same on both axes
        self.width = round(width_m * self.scale)
        self.height = round(height_m * self.scale)
        self.metres_across = width_m

    def __call__(self, p: LatLng) -> tuple[float, float]:
        x = (p[1] - self.view.west) * METRES_PER_DEGREE_LAT * self.cos_lat * self.scale
        y = (self.view.north - p[0]) * METRES_PER_DEGREE_LAT * self.scale
        return round(x, 1), round(y, 1)

    def many(self, points: list[LatLng]) -> list[tuple[float, float]]:
        """``[self(p) for p in points]`` without a call per point: a long route's map projects
        ~10,000 street ends, and the per-call overhead was most of the page's time."""
        west, north = self.view.west, self.view.north
        fx = METRES_PER_DEGREE_LAT * self.cos_lat * self.scale
        fy = METRES_PER_DEGREE_LAT * self.scale
        return [(round((lng - west) * fx, 1), round((north - lat) * fy, 1)) for lat, lng in points]


def _scale_bar(proj: Projection) -> str:
    # A round length close to a fifth of the map width.
    target = proj.metres_across / 5
    length = max(10, min((n for n in (10, 20, 50, 100, 200, 250, 500, 1000, 2000, 5000) if n >= target * 0.5),
                         key=lambda n: abs(n - target)))
    px = round(length * proj.scale, 1)
    y = proj.height - 12
    label = f"{length} m" if length < 1000 else f"{length // 1000} km"
    return (f'<g class="scale"><path d="M10 {y} h{px}" stroke="#222" stroke-width="2"/>'
            f'<text x="10" y="{y - 4}" font-size="11">{label}</text></g>')


def render_map_svg(
    *,
    title: str,
    description: str,
    streets: list[Segment],
    route: list[LatLng] | None = None,
    markers: list[Marker] | None = None,
    focus: list[LatLng] | None = None,
    margin_m: float = 120.0,
    width: int = 640,
    max_height: int = 520,
    max_segments: int = 2500,
    max_labels: int = 14,
    label_first: list[str] | None = None,
) -> str:
    """An accessible SVG map. ``focus`` (default: the route and markers) decides the viewport."""
    route = route or []
    markers = markers or []
    points = focus or route + [m.at for m in markers]
    if not points:
        raise ValueError("render_map_svg needs a route, markers or focus points to frame the map")
    view = Viewport.around(points, margin_m, aspect=width / max_height)
    proj = Projection(view, width, max_height)
    centre = view.centre
    south, north, west, east = view.south, view.north, view.west, view.east
    # Segments whose box overlaps the view (an end inside, or a long avenue block crossing it);
    # inline comparisons, as this runs over every segment of the city.
    visible = [s for s in streets
               if not (s.box[1] < south or s.box[0] > north or s.box[3] < west or s.box[2] > east)]
    # Nearest the centre first (the order also decides where street labels go), at most max_segments.
    lat2, lng2 = 2 * centre[0], 2 * centre[1]
    keys = [abs(s.a[0] + s.b[0] - lat2) + abs(s.a[1] + s.b[1] - lng2) for s in visible]
    visible = [visible[i] for i in sorted(range(len(visible)), key=keys.__getitem__)[:max_segments]]
    ends = proj.many([p for s in visible for p in (s.a, s.b)])  # projected once, for the path and the labels
    projected = list(zip(ends[0::2], ends[1::2]))

    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" role="img" aria-labelledby="map-title" '
        f'aria-describedby="map-desc" '
        f'width="{proj.width}" height="{proj.height}" viewBox="0 0 {proj.width} {proj.height}" '
        f'font-family="system-ui, sans-serif">',
        f'<title id="map-title">{escape(title)}</title>',
        f'<desc id="map-desc">{escape(description)}</desc>',
        # The drawing itself is hidden from assistive technology: the title, the description and
        # the page's turn-by-turn list are the text alternative.
        '<g aria-hidden="true">',
        f'<rect width="{proj.width}" height="{proj.height}" fill="#f2efe9"/>',
    ]
    if visible:
        d = " ".join(f"M{a[0]} {a[1]}L{b[0]} {b[1]}" for a, b in projected)
        parts.append(f'<path class="streets" d="{d}" stroke="#ffffff" stroke-width="7" stroke-linecap="round" '
                     f'fill="none"/>')
    if len(route) >= 2:
        d = "M" + " L".join("{} {}".format(*proj(p)) for p in route)
        parts.append(f'<path class="route" d="{d}" stroke="#1a66d6" stroke-width="5" stroke-linejoin="round" '
                     f'stroke-linecap="round" fill="none" opacity="0.85"/>')
    # Labels over the route line (with a halo) so the route's own street names stay readable.
    parts.extend(_street_labels(visible, projected, view, max_labels, label_first or []))
    for marker in markers:
        x, y = proj(marker.at)
        parts.append(f'<g class="marker"><title>{escape(marker.name)}</title>'
                     f'<circle cx="{x}" cy="{y}" r="10" fill="{marker.color}" stroke="#fff" '
                     f'stroke-width="2"/><text x="{x}" y="{y + 4}" font-size="12" font-weight="700" fill="#fff" '
                     f'text-anchor="middle">{escape(marker.label)}</text></g>')
    parts.append(f'<text x="{proj.width - 8}" y="16" font-size="12" text-anchor="end">N &#8593;</text>')
    parts.append(_scale_bar(proj))
    parts.append("</g></svg>")
    return "".join(parts)


def _street_labels(segments: list[Segment], projected: list[tuple[tuple[float, float], tuple[float, float]]],
                   view: Viewport, limit: int, first: list[str]) -> list[str]:
    """Label each street once, at the middle of its visible stretch; the streets in ``first``
    (the route's) before the others, then the longest. Blocks are short, so a label may run
    past its own segment along the street."""
    by_street: dict[str, list[tuple[tuple[float, float], tuple[float, float]]]] = {}
    for seg, ends in zip(segments, projected):
        if seg.street and view.contains(seg.a) and view.contains(seg.b):
            by_street.setdefault(seg.street, []).append(ends)
    lengths = {street: sum(math.dist(a, b) for a, b in segs) for street, segs in by_street.items()}
    order = [s for s in dict.fromkeys(first) if s in by_street]
    order += sorted((s for s in by_street if s not in order), key=lambda s: -lengths[s])
    labels: list[str] = []
    for street in order:
        if len(labels) >= limit:
            break
        if lengths[street] < 60:  # too little of it in view to carry a readable label
            continue
        segs = by_street[street]
        (ax, ay), (bx, by) = max(segs, key=lambda ab: math.dist(*ab))
        ux, uy = (bx - ax), (by - ay)
        middle = sorted(segs, key=lambda ab: (ab[0][0] + ab[1][0]) * ux + (ab[0][1] + ab[1][1]) * uy)[len(segs) // 2]
        (x1, y1), (x2, y2) = middle
        angle = math.degrees(math.atan2(y2 - y1, x2 - x1))
        if angle > 90 or angle < -90:  # keep text upright
            angle += 180
        if angle > 90:
            angle -= 360
        cx, cy = round((x1 + x2) / 2, 1), round((y1 + y2) / 2, 1)
        labels.append(f'<text class="label" x="{cx}" y="{cy}" font-size="10" fill="#444" stroke="#f2efe9" '
                      f'stroke-width="3" paint-order="stroke" text-anchor="middle" dominant-baseline="middle" '
                      f'transform="rotate({angle:.0f} {cx} {cy})">{escape(street)}</text>')
    return labels
