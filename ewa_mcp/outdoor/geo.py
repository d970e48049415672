"""Small geodesy helpers: distances, bearings, a local planar frame, affine fitting, opaque ids."""

from __future__ import annotations

import hashlib
import math
from collections.abc import Sequence

EARTH_RADIUS_M = 6_371_008.8
CARDINALS_16 = ["N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE", "S", "SSW", "SW", "WSW", "W", "WNW", "NW", "NNW"]
CARDINAL_WORDS = {
    "N": "north", "NE": "northeast", "E": "east", "SE": "southeast",
    "S": "south", "SW": "southwest", "W": "west", "NW": "northwest",
}


def haversine_m(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dp, dl = p2 - p1, math.radians(lng2 - lng1)
    a = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return 2 * EARTH_RADIUS_M * math.asin(min(1.0, math.sqrt(a)))


def bearing_deg(lat1: float, lng1: float, lat2: float, lng2: float) -> float:
    """Initial compass bearing from point 1 to point 2, 0 = north, clockwise, in [0, 360)."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dl = math.radians(lng2 - lng1)
    x = math.sin(dl) * math.cos(p2)
    y = math.cos(p1) * math.sin(p2) - math.sin(p1) * math.cos(p2) * math.cos(dl)
    return math.degrees(math.atan2(x, y)) % 360.0


def angle_diff(a: float, b: float) -> float:
    """Signed smallest difference a - b in (-180, 180]; positive = a is clockwise (to the right) of b."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def cardinal(heading: float, points: int = 8) -> str:
    if points == 16:
        return CARDINALS_16[int((heading % 360) / 22.5 + 0.5) % 16]
    return ["N", "NE", "E", "SE", "S", "SW", "W", "NW"][int((heading % 360) / 45 + 0.5) % 8]


def cardinal_word(heading: float) -> str:
    return CARDINAL_WORDS[cardinal(heading, 8)]


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
    def fit(cls, src: Sequence[tuple[float, float]], dst: Sequence[tuple[float, float]]) -> "Affine2D":
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


def opaque_id(prefix: str, lat: float, lng: float) -> str:
    """A stable id from a position rounded to ~1 m, hashed so that the id does not reveal where it is
    (the agent must not be able to decode coordinates from node ids)."""
    key = f"{lat:.5f},{lng:.5f}".encode()
    return f"{prefix}-{hashlib.sha1(key).hexdigest()[:10]}"
