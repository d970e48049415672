"""The one geometry module: distances, bearings, offsets, turns and compass words on a spherical
Earth, plus the small planar helpers (a local east/north frame, an affine fit) the city importers use.

Every part of the project that measures or names a direction imports it: the street world
(outdoor/), the geolocation world (geo/), the task generators and the graders. It imports only
``math`` so that the graders can use it without loading a world, Pillow or the MCP layer.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

EARTH_RADIUS_M = 6_371_008.8  # IUGG mean radius
EARTH_RADIUS_KM = 6371.0088  # the same radius in km (kept as its own literal: results are bit-identical)
METRES_PER_DEGREE_LAT = 111_320.0  # flat-Earth metres per degree: entrances beside a node, the map site's SVG

COMPASS_POINTS_16 = ("N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE",
                     "S", "SSW", "SW", "WSW", "W", "WNW", "NW", "NNW")
COMPASS_POINTS_8 = ("N", "NE", "E", "SE", "S", "SW", "W", "NW")
COMPASS_WORDS = {
    "N": "north", "NE": "northeast", "E": "east", "SE": "southeast",
    "S": "south", "SW": "southwest", "W": "west", "NW": "northwest",
}
FOUR_DIRECTIONS = ("north", "east", "south", "west")
DIRECTION_DEG = {"north": 0, "east": 90, "south": 180, "west": 270}


# ------------------------------------------------------------------------------ on the sphere
def _half_central_angle(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    """Half the central angle between two points (radians), by the haversine formula."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dp, dl = p2 - p1, math.radians(lng2 - lng1)
    a = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return math.asin(min(1.0, math.sqrt(a)))


def haversine_m(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    """Great-circle distance in metres."""
    return 2 * EARTH_RADIUS_M * _half_central_angle(lat1, lng1, lat2, lng2)


def haversine_km(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    """Great-circle distance in kilometres."""
    return 2 * EARTH_RADIUS_KM * _half_central_angle(lat1, lng1, lat2, lng2)


def bearing_deg(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    """Initial compass bearing from point 1 to point 2, 0 = north, clockwise, in [0, 360)."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dl = math.radians(lng2 - lng1)
    x = math.sin(dl) * math.cos(p2)
    y = math.cos(p1) * math.sin(p2) - math.sin(p1) * math.cos(p2) * math.cos(dl)
    return math.degrees(math.atan2(x, y)) % 360.0


def destination(lat: float, lng: float, bearing: float, distance_km: float) -> tuple[float, float]:
    """The point ``distance_km`` away from (lat, lng) along the initial ``bearing`` (degrees)."""
    d = distance_km / EARTH_RADIUS_KM
    b = math.radians(bearing)
    p1, l1 = math.radians(lat), math.radians(lng)
    p2 = math.asin(math.sin(p1) * math.cos(d) + math.cos(p1) * math.sin(d) * math.cos(b))
    l2 = l1 + math.atan2(math.sin(b) * math.sin(d) * math.cos(p1), math.cos(d) - math.sin(p1) * math.sin(p2))
    return math.degrees(p2), (math.degrees(l2) + 540) % 360 - 180


def offset_flat(lat: float, lng: float, heading: float, metres: float) -> tuple[float, float]:
    """A point a few metres from (lat, lng) towards ``heading``, on a flat Earth (exact enough for
    building entrances a few metres off a street node)."""
    h = math.radians(heading)
    return (lat + metres * math.cos(h) / METRES_PER_DEGREE_LAT,
            lng + metres * math.sin(h) / (METRES_PER_DEGREE_LAT * math.cos(math.radians(lat))))


# ------------------------------------------------------------------------------ headings and words
def angle_diff(a: float, b: float) -> float:
    """Signed smallest difference a - b in (-180, 180]; positive = a is clockwise (to the right) of b.
    The turn from heading ``h0`` to heading ``h1`` is ``angle_diff(h1, h0)``."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def cardinal(heading: float, points: int = 8) -> str:
    """The nearest compass point as an abbreviation: 8 points ("NE") or 16 ("NNE")."""
    if points == 16:
        return COMPASS_POINTS_16[int((heading % 360) / 22.5 + 0.5) % 16]
    return COMPASS_POINTS_8[int((heading % 360) / 45 + 0.5) % 8]


def cardinal_word(heading: float) -> str:
    """The nearest of the 8 compass points as a word ("north", "northeast", ...)."""
    return COMPASS_WORDS[cardinal(heading, 8)]


# ------------------------------------------------------------------------------ planar helpers
class LocalFrame:
    """Equirectangular east/north metres around an origin; exact enough over a few kilometres."""

    def __init__(self, lat0: float, lng0: float):
        self.lat0, self.lng0 = lat0, lng0
        self.m_per_deg_lat = math.pi * EARTH_RADIUS_M / 180.0
        self.m_per_deg_lng = self.m_per_deg_lat * math.cos(math.radians(lat0))

    def to_xy(self, lat: float, lng: float) -> tuple[float, float]:
        return (lng - self.lng0) * self.m_per_deg_lng, (lat - self.lat0) * self.m_per_deg_lat

    def to_latlng(self, x: float, y: float) -> tuple[float, float]:
        return self.lat0 + y / self.m_per_deg_lat, self.lng0 + x / self.m_per_deg_lng


def _solve3(m: list[list[float]], v: list[float]) -> list[float]:
    """Solve a 3x3 linear system by Cramer's rule (the normal equations of an affine fit)."""

    def det(a: list[list[float]]) -> float:
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))

    d = det(m)
    if abs(d) < 1e-12:
        raise ValueError("affine fit is degenerate: the fit points are collinear; add a point off the line")
    out = []
    for col in range(3):
        mc = [row[:] for row in m]
        for r in range(3):
            mc[r][col] = v[r]
        out.append(det(mc) / d)
    return out


class Affine2D:
    """x' = a*x + b*y + c ; y' = d*x + e*y + f, fitted by least squares."""

    def __init__(self, coeffs: Sequence[float]):
        self.a, self.b, self.c, self.d, self.e, self.f = coeffs

    def __call__(self, x: float, y: float) -> tuple[float, float]:
        return self.a * x + self.b * y + self.c, self.d * x + self.e * y + self.f

    @classmethod
    def fit(cls, src: Sequence[tuple[float, float]], dst: Sequence[tuple[float, float]]) -> Affine2D:
        if len(src) < 3 or len(src) != len(dst):
            raise ValueError("an affine fit needs at least three matching point pairs")
        sxx = sum(x * x for x, _ in src)
        sxy = sum(x * y for x, y in src)
        syy = sum(y * y for _, y in src)
        sx = sum(x for x, _ in src)
        sy = sum(y for _, y in src)
        n = float(len(src))
        normal = [[sxx, sxy, sx], [sxy, syy, sy], [sx, sy, n]]
        coeffs: list[float] = []
        for k in range(2):
            rhs = [sum(x * p[k] for (x, _), p in zip(src, dst)),
                   sum(y * p[k] for (_, y), p in zip(src, dst)),
                   sum(p[k] for p in dst)]
            coeffs += _solve3(normal, rhs)
        return cls(coeffs)
