"""The pinhole camera of every street view: 90° horizontal field of view, so the focal length in
pixels is half the image width; the eye stands ``eye_height`` world units above the ground.

World coordinates: x to the right, y up from the ground, z ahead (depth). Two forms of one
projection: ``project`` takes the depth z (the walked cities, in metres), ``project_u`` its inverse
u = 1/z (the geolocation views, in 10-metre units, whose ground and facades are laid out in u).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Camera:
    width: int
    height: int
    horizon: float  # the screen row of the horizon (the vanishing point's y)
    eye_height: float  # camera height above the ground, in world units
    cx: float = field(init=False)  # the vanishing point's x: the image centre
    focal: float = field(init=False)  # pixels per world unit at depth 1: half the width (90 degree field of view)

    def __post_init__(self) -> None:
        object.__setattr__(self, "cx", self.width / 2.0)
        object.__setattr__(self, "focal", self.width / 2.0)

    def project(self, x: float, y: float, z: float) -> tuple[float, float]:
        """World (x right, y up from the ground, z ahead) to pixels; depth clamped to 0.5."""
        z = max(z, 0.5)
        return self.cx + x * self.focal / z, self.horizon + (self.eye_height - y) * self.focal / z

    def project_u(self, x: float, y: float, u: float) -> tuple[float, float]:
        """The same projection given u = 1/depth (u = 0 is the horizon, larger u is nearer)."""
        return self.cx + self.focal * x * u, self.horizon + self.focal * (self.eye_height - y) * u

    def screen_x(self, rel_angle: float) -> float:
        """The screen column of a direction ``rel_angle`` degrees right of the view axis."""
        return self.width / 2 + math.tan(math.radians(rel_angle)) * self.focal
