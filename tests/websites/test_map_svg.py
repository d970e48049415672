"""The SVG street map: valid, accessible, bounded, and geometrically right."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

from ewa_mcp.websites.map.svgmap import Marker, Segment, Viewport, render_map_svg

SVG = "{http://www.w3.org/2000/svg}"


def grid(rows: int, cols: int, lat0: float = 40.75, lng0: float = -73.99, step: float = 0.001) -> list[Segment]:
    """A Manhattan-like street grid: horizontal streets 'St r', vertical avenues 'Ave c'."""
    segs = []
    for r in range(rows):
        for c in range(cols):
            p = (lat0 + r * step, lng0 + c * step)
            if c + 1 < cols:
                segs.append(Segment(p, (p[0], p[1] + step), f"St {r}"))
            if r + 1 < rows:
                segs.append(Segment(p, (p[0] + step, p[1]), f"Ave {c}"))
    return segs


def test_route_map_is_valid_accessible_svg():
    streets = grid(6, 6)
    route = [(40.751, -73.989), (40.751, -73.987), (40.753, -73.987)]
    svg = render_map_svg(title="Route from <A> & co", description="Blue line from A to B.", streets=streets,
                         route=route, markers=[Marker(route[0], "A", "start", "#0a0"),
                                               Marker(route[-1], "B", "end", "#a00")])
    root = ET.fromstring(svg)  # well-formed XML, names escaped
    assert root.get("role") == "img" and root.get("aria-labelledby") == "map-title"
    assert root.get("aria-describedby") == "map-desc"
    assert root.find(f"{SVG}g").get("aria-hidden") == "true"
    assert root.find(f"{SVG}title").text == "Route from <A> & co"
    assert root.find(f"{SVG}desc").text == "Blue line from A to B."
    assert [t.text for t in root.iter(f"{SVG}text") if t.text in ("A", "B")] == ["A", "B"]
    labels = {t.text for t in root.iter(f"{SVG}text") if t.get("class") == "label"}
    assert labels and labels <= {f"St {i}" for i in range(6)} | {f"Ave {i}" for i in range(6)}


def test_route_goes_where_the_coordinates_say():
    route = [(40.751, -73.989), (40.751, -73.987), (40.753, -73.987)]  # east, then north
    svg = render_map_svg(title="t", description="d", streets=grid(6, 6), route=route)
    root = ET.fromstring(svg)
    d = next(p.get("d") for p in root.iter(f"{SVG}path") if p.get("class") == "route")
    (x0, y0), (x1, y1), (x2, y2) = [tuple(map(float, xy.split())) for xy in re.findall(r"[\d.]+ [\d.]+", d)]
    assert x1 > x0 and y1 == pytest.approx(y0)  # east is +x
    assert y2 < y1 and x2 == pytest.approx(x1)  # north is up (-y)
    # Same scale on both axes: 0.002 deg of longitude is cos(lat) times as long as 0.002 deg of latitude.
    assert (x1 - x0) / (y1 - y2) == pytest.approx(0.7581, abs=0.002)
    width, height = float(root.get("width")), float(root.get("height"))
    assert 0 < x0 < width and 0 < y2 < height


def test_size_and_segment_count_are_bounded():
    streets = grid(80, 80, step=0.0005)  # 12,640 segments, far more than the view needs
    route = [(40.75 + 0.0005 * i, -73.99 + 0.0005 * i) for i in range(80)]  # a long diagonal
    svg = render_map_svg(title="t", description="d", streets=streets, route=route, max_segments=1000,
                         width=640, max_height=520)
    root = ET.fromstring(svg)
    assert float(root.get("width")) <= 640 and float(root.get("height")) <= 520
    d = next(p.get("d") for p in root.iter(f"{SVG}path") if p.get("class") == "streets")
    assert d.count("M") == 1000
    assert len(svg) < 200_000


def test_only_nearby_streets_are_drawn():
    near = grid(3, 3)
    far = [Segment((40.80, -73.95), (40.801, -73.95), "Far St")]
    svg = render_map_svg(title="t", description="d", streets=near + far,
                         markers=[Marker((40.751, -73.989), "P", "place", "#a00")], margin_m=100)
    assert "Far St" not in svg
    d = next(p.get("d") for p in ET.fromstring(svg).iter(f"{SVG}path") if p.get("class") == "streets")
    assert d.count("M") == len(near)


def test_viewport_has_a_minimum_span_and_margin():
    view = Viewport.around([(40.75, -73.99)], margin_m=50, min_span_m=300)
    assert (view.north - view.south) * 111_320 == pytest.approx(400, rel=0.01)
    assert view.contains((40.75, -73.99)) and not view.contains((40.76, -73.99))


def test_nothing_to_frame_is_an_error():
    with pytest.raises(ValueError, match="needs a route, markers or focus"):
        render_map_svg(title="t", description="d", streets=grid(2, 2))
