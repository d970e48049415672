"""The one geometry module: its results, its light imports, and that no copy of its maths is left."""

import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from ewa_mcp.geometry import (
    angle_diff,
    bearing_deg,
    cardinal,
    cardinal_word,
    destination,
    haversine_km,
    haversine_m,
    offset_flat,
)

ROOT = Path(__file__).resolve().parents[2]


def test_distances_agree_in_metres_and_kilometres():
    paris, london = (48.853, 2.3499), (51.508, -0.1281)
    assert 340 < haversine_km(*paris, *london) < 346
    assert haversine_m(*paris, *london) == pytest.approx(haversine_km(*paris, *london) * 1000, rel=1e-12)
    assert haversine_m(*paris, *paris) == 0.0


def test_bearing_destination_and_flat_offset_round_trip():
    lat, lng = destination(40.75, -73.99, 37.0, 2.5)
    assert haversine_km(40.75, -73.99, lat, lng) == pytest.approx(2.5, rel=1e-9)
    assert bearing_deg(40.75, -73.99, lat, lng) == pytest.approx(37.0, abs=1e-6)
    east = offset_flat(40.75, -73.99, 90.0, 10.0)
    assert haversine_m(40.75, -73.99, *east) == pytest.approx(10.0, rel=0.01)
    assert bearing_deg(40.75, -73.99, *east) == pytest.approx(90.0, abs=0.01)


@pytest.mark.parametrize(("a", "b", "expected"), [(10, 350, 20), (350, 10, -20), (0, 180, 180), (180, 0, 180),
                                                  (90, 90, 0)])
def test_angle_diff_is_signed_and_in_half_open_range(a, b, expected):
    assert angle_diff(a, b) == expected


def test_compass_points_and_words():
    assert cardinal(44.0) == "NE" and cardinal(22.0, 16) == "NNE" and cardinal(359.0) == "N"
    assert [cardinal_word(h) for h in (0, 45, 135, 225, 315)] == ["north", "northeast", "southeast", "southwest",
                                                                   "northwest"]


def test_importing_geometry_loads_no_world_and_no_pillow():
    code = ("import sys, ewa_mcp.geometry; heavy = [m for m in sys.modules if m.startswith(('PIL', 'mcp', "
            "'ewa_mcp.envs.street', 'ewa_mcp.envs.geo.', 'pydantic'))]; print(heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_no_copy_of_the_sphere_maths_outside_the_geometry_module():
    """Distance and bearing formulas live once; a second haversine or bearing elsewhere is a duplicate."""
    pattern = re.compile(r"def (haversine\w*|\w*bearing\w*|signed_angle|compass_name|destination)\(|6371|asin\(|111_?320")
    found = []
    for folder in ("ewa_mcp", "graders", "websites"):
        for path in (ROOT / folder).rglob("*.py"):
            if path.name == "geometry.py" and path.parent.name == "ewa_mcp":
                continue
            for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                if pattern.search(line):
                    found.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not found, "geometry duplicated outside ewa_mcp/geometry.py:\n" + "\n".join(found)


def test_geometry_matches_a_direct_formula():
    p1, p2, dl = math.radians(40.0), math.radians(41.0), math.radians(1.0)
    a = math.sin((p2 - p1) / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    assert haversine_m(40.0, -74.0, 41.0, -73.0) == 2 * 6_371_008.8 * math.asin(math.sqrt(a))
