"""The shape every city spec produces: named street polylines on real coordinates plus a fit report."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from ewa_mcp.geometry import Affine2D, LocalFrame, haversine_m

LatLng = tuple[float, float]


@dataclass
class Way:
    """One named, walkable street polyline. The generator splits ways where they cross."""

    name: str
    points: list[LatLng]


@dataclass
class FitPoint:
    """A surveyed position: grid coordinates of a known intersection and its published lat/lng."""

    label: str
    grid: tuple[float, float]
    lat: float
    lng: float
    source: str = ""


@dataclass
class CitySpec:
    city: str  # key: "manhattan"
    name: str  # display name
    code: str  # two-letter node id prefix
    ways: list[Way]
    aliases: dict[str, str] = field(default_factory=dict)  # alternative street name -> canonical name
    fit: dict = field(default_factory=dict)  # method + residuals, copied into the data file


class FittedGrid:
    """Maps grid coordinates (any planar units) to lat/lng with a least-squares affine transform
    fitted from surveyed intersections, so the positions between the fit points follow the
    city's actual block geometry instead of a guess per intersection."""

    def __init__(self, origin: LatLng, fit_points: Sequence[FitPoint]):
        self.frame = LocalFrame(*origin)
        self.fit_points = list(fit_points)
        src = [p.grid for p in fit_points]
        dst = [self.frame.to_xy(p.lat, p.lng) for p in fit_points]
        self.transform = Affine2D.fit(src, dst)

    def latlng(self, gx: float, gy: float) -> LatLng:
        x, y = self.transform(gx, gy)
        lat, lng = self.frame.to_latlng(x, y)
        return round(lat, 7), round(lng, 7)

    def report(self, method: str) -> dict:
        residuals = []
        for p in self.fit_points:
            lat, lng = self.latlng(*p.grid)
            residuals.append({"label": p.label, "source": p.source,
                              "residual_m": round(haversine_m(lat, lng, p.lat, p.lng), 1)})
        return {"method": method, "fit_points": residuals}


def polyline(fn: Callable[[float], LatLng], start: float, stop: float, step: float = 1.0) -> list[LatLng]:
    """Sample a parametric street from start to stop (inclusive) every ``step`` parameter units."""
    pts: list[LatLng] = []
    t = start
    direction = 1 if stop >= start else -1
    while (t - stop) * direction < 1e-9:
        pts.append(fn(t))
        t += step * direction
    if abs((t - step * direction) - stop) > 1e-9:
        pts.append(fn(stop))
    return pts
