"""Unit primitive meshes for the first-person kitchen camera: box, cylinder, open cup, sphere.

Each mesh fills the unit cube centred on the origin (x, y, z in [-0.5, 0.5], the cylinder's axis along y)
and is a flat list of triangles, six floats a vertex: position, then the outward normal. The camera
(camera3d.py) uploads each once and draws every object part as an instance of one of them, scaled, turned
and placed by the part's matrix (scene3d.py), so no geometry is built per frame.
"""

from __future__ import annotations

import math
from array import array

Vec = tuple[float, float, float]

SEGMENTS = 20  # around a cylinder or sphere: round enough at 300×300, cheap on the CPU renderer
RINGS = 10


def _tri(out: array, a: Vec, b: Vec, c: Vec, n: Vec | None = None, normals: tuple[Vec, Vec, Vec] | None = None) -> None:
    for i, p in enumerate((a, b, c)):
        out.extend(p)
        out.extend(normals[i] if normals is not None else n)  # type: ignore[arg-type]


def _quad(out: array, a: Vec, b: Vec, c: Vec, d: Vec, n: Vec) -> None:
    _tri(out, a, b, c, n)
    _tri(out, a, c, d, n)


def box() -> array:
    out = array("f")
    h = 0.5
    faces: list[tuple[Vec, list[Vec]]] = [
        ((1, 0, 0), [(h, -h, -h), (h, h, -h), (h, h, h), (h, -h, h)]),
        ((-1, 0, 0), [(-h, -h, h), (-h, h, h), (-h, h, -h), (-h, -h, -h)]),
        ((0, 1, 0), [(-h, h, -h), (-h, h, h), (h, h, h), (h, h, -h)]),
        ((0, -1, 0), [(-h, -h, h), (-h, -h, -h), (h, -h, -h), (h, -h, h)]),
        ((0, 0, 1), [(h, -h, h), (h, h, h), (-h, h, h), (-h, -h, h)]),
        ((0, 0, -1), [(-h, -h, -h), (-h, h, -h), (h, h, -h), (h, -h, -h)]),
    ]
    for normal, (a, b, c, d) in faces:
        _quad(out, a, b, c, d, normal)
    return out


def _ring(i: int) -> tuple[float, float]:
    angle = 2 * math.pi * (i % SEGMENTS) / SEGMENTS
    return math.cos(angle), math.sin(angle)


def cylinder(top: bool = True) -> array:
    """A closed cylinder; ``top=False`` leaves the top open (a pan, pot, bowl or mug one can see into)."""
    out = array("f")
    r, h = 0.5, 0.5
    for i in range(SEGMENTS):
        (c0, s0), (c1, s1) = _ring(i), _ring(i + 1)
        a, b = (r * c0, -h, r * s0), (r * c1, -h, r * s1)
        c, d = (r * c1, h, r * s1), (r * c0, h, r * s0)
        n0, n1 = (c0, 0.0, s0), (c1, 0.0, s1)
        _tri(out, a, b, c, normals=(n0, n1, n1))
        _tri(out, a, c, d, normals=(n0, n1, n0))
        _tri(out, (0.0, -h, 0.0), b, a, (0.0, -1.0, 0.0))
        if top:
            _tri(out, (0.0, h, 0.0), d, c, (0.0, 1.0, 0.0))
    return out


def sphere() -> array:
    out = array("f")

    def point(ring: int, seg: int) -> Vec:
        phi = math.pi * ring / RINGS
        c, s = _ring(seg)
        return (0.5 * math.sin(phi) * c, 0.5 * math.cos(phi), 0.5 * math.sin(phi) * s)

    def normal(p: Vec) -> Vec:
        return (p[0] * 2, p[1] * 2, p[2] * 2)

    for ring in range(RINGS):
        for seg in range(SEGMENTS):
            a, b = point(ring, seg), point(ring + 1, seg)
            c, d = point(ring + 1, seg + 1), point(ring, seg + 1)
            if ring > 0:
                _tri(out, a, b, d, normals=(normal(a), normal(b), normal(d)))
            if ring < RINGS - 1:
                _tri(out, b, c, d, normals=(normal(b), normal(c), normal(d)))
    return out


MESHES = {"box": box, "cylinder": cylinder, "cup": lambda: cylinder(top=False), "sphere": sphere}
FLOATS_PER_VERTEX = 6
