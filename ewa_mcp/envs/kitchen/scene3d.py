"""What the first-person kitchen camera draws: AI2-THOR metadata in, coloured primitive parts out.

Pure Python and no GL, so it is tested on its own; camera3d.py draws the parts. Everything comes from the
metadata any backend reports (objects' boxes, positions, states, containment, the agent pose) plus the
reachable positions, which tell which side of a cabinet or fridge faces the room (its doors open there).

How states look:
* sliced food is its pieces (the simulator places them side by side where the food lay), each drawn as a
  slice of that food; cooked food and pieces are browned (most of the way to a toasted brown, whatever the
  food) and cooked slices carry dark sear stripes; a cracked egg is a white with a yolk;
* a closed Fridge, Cabinet, Drawer or Microwave is a solid box with its door, and nothing inside is drawn;
  open, it is a hollow box with its door swung out (a drawer slides out, carrying its contents), the fridge
  lit inside, and its contents on thin wire shelves that do not hide the shelf below;
* each burner has a coloured ring and the knob that lights it is the same colour (blue, yellow, violet,
  cyan, ... in the order of the burners' ids), so which knob drives which burner can be seen;
* a lit burner glows red-orange, a turned-on knob shows a red mark, a running microwave's window glows, a
  toaster's slots glow, a coffee machine shows a green light; a filled cup or mug shows coffee;
* the held object (with what it holds) floats at the bottom of the frame, drawn over everything.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from .vocabulary import PIECE_OF

Vec = tuple[float, float, float]
Colour = tuple[float, float, float]

EYE_ABOVE_AGENT = 0.675  # AI2-THOR's camera sits this far above the reported agent position (1.575 m)
WALL_CABINET_DEPTH = 0.32


@dataclass(frozen=True, slots=True)
class Part:
    """One primitive: ``mesh`` (box, cylinder, cup, sphere; meshes.py) scaled to ``size``, tilted ``tilt``
    degrees about its local z (90 lays a cylinder on its side along x), turned ``yaw`` degrees about +y the
    AI2-THOR way (0 faces +z, 90 faces +x) and centred at ``center``. ``glow`` (0–1) is emitted light."""

    mesh: str
    center: Vec
    size: Vec
    colour: Colour
    yaw: float = 0.0
    tilt: float = 0.0
    glow: float = 0.0


@dataclass(frozen=True, slots=True)
class CameraPose:
    eye: Vec
    yaw: float  # degrees, AI2-THOR's agent rotation y
    horizon: float  # degrees, positive looks down (AI2-THOR's cameraHorizon)

    def basis(self) -> tuple[Vec, Vec, Vec]:
        """(right, up, forward) unit vectors in world space."""
        a, p = math.radians(self.yaw), math.radians(self.horizon)
        forward = (math.sin(a) * math.cos(p), -math.sin(p), math.cos(a) * math.cos(p))
        right = (math.cos(a), 0.0, -math.sin(a))
        up = (math.sin(a) * math.sin(p), math.cos(p), math.cos(a) * math.sin(p))
        return right, up, forward


# ------------------------------------------------------------------ palette
WOOD = (0.58, 0.40, 0.25)
WOOD_PANEL = (0.66, 0.47, 0.30)
WOOD_INSIDE = (0.80, 0.68, 0.52)
STONE = (0.86, 0.84, 0.79)
STEEL = (0.66, 0.68, 0.71)
DARK_STEEL = (0.30, 0.31, 0.33)
BLACK = (0.08, 0.08, 0.09)
WHITE = (0.95, 0.95, 0.94)
FRIDGE = (0.86, 0.89, 0.92)
HANDLE = (0.80, 0.81, 0.83)
WALLS = [(0.90, 0.87, 0.80), (0.83, 0.87, 0.88), (0.90, 0.84, 0.80), (0.85, 0.88, 0.82)]  # north, east, south, west
FLOOR_TILES = ((0.74, 0.70, 0.64), (0.60, 0.56, 0.50))
CEILING = (0.93, 0.93, 0.92)
GLOW_RED = (1.0, 0.32, 0.08)

FOOD_COLOURS: dict[str, Colour] = {
    "Apple": (0.78, 0.07, 0.10), "Tomato": (0.95, 0.22, 0.10), "Egg": (0.96, 0.92, 0.80),
    "Bread": (0.76, 0.52, 0.26), "Lettuce": (0.38, 0.72, 0.25), "Potato": (0.62, 0.45, 0.25),
}


TOASTED = (0.36, 0.24, 0.10)
SEAR = (0.13, 0.07, 0.03)


def browned(colour: Colour) -> Colour:
    """Cooked: most of the way to a toasted brown, whatever the food, so that a cooked tomato is no longer red
    and a cooked slice of bread no longer pale (a darker shade of the raw colour was hard to tell at 300×300)."""
    return tuple(0.2 * c + 0.8 * t for c, t in zip(colour, TOASTED))  # type: ignore[return-value]


# The rings round the burners and the knobs that light them share a colour; none is red or orange (a lit
# burner's glow), black/grey (the stove) or a food's green.
BURNER_MARKS: tuple[Colour, ...] = ((0.15, 0.40, 0.95), (0.95, 0.85, 0.15), (0.65, 0.30, 0.90),
                                   (0.10, 0.80, 0.85), (0.97, 0.97, 0.97), (0.95, 0.55, 0.80))


def burner_marks(objects: Iterable[dict[str, Any]]) -> dict[str, Colour]:
    """The mark colour of every burner and of every knob (its burner's): burners of one stove take the colours in
    the order of their ids, so each stove's burners differ and the same kitchen always gets the same colours."""
    objects = list(objects)
    burners = sorted((o for o in objects if o["objectType"] == "StoveBurner"), key=lambda o: o["objectId"])
    stoves: list[list[dict[str, Any]]] = []
    for burner in burners:
        c, _ = _box_of(burner)
        for stove in stoves:
            sc, _ = _box_of(stove[0])
            if abs(sc[0] - c[0]) < 0.9 and abs(sc[2] - c[2]) < 0.9:
                stove.append(burner)
                break
        else:
            stoves.append([burner])
    marks = {b["objectId"]: BURNER_MARKS[i % len(BURNER_MARKS)] for stove in stoves for i, b in enumerate(stove)}
    for knob in objects:
        if knob["objectType"] == "StoveKnob":
            lit = [marks[b] for b in knob.get("controlledObjects") or [] if b in marks]
            if lit:
                marks[knob["objectId"]] = lit[0]
    return marks


# ------------------------------------------------------------------ helpers
def _box_of(obj: dict[str, Any]) -> tuple[Vec, Vec]:
    box = obj.get("axisAlignedBoundingBox") or {}
    c = box.get("center") or obj["position"]
    s = box.get("size") or {"x": 0.1, "y": 0.1, "z": 0.1}
    return (c["x"], c["y"], c["z"]), (s["x"], s["y"], s["z"])


def _slab(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, colour: Colour,
          glow: float = 0.0) -> Part:
    return Part("box", ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), (abs(x1 - x0), abs(y1 - y0), abs(z1 - z0)),
                colour, glow=glow)


def _shift(part: Part, offset: Vec) -> Part:
    c = part.center
    return Part(part.mesh, (c[0] + offset[0], c[1] + offset[1], c[2] + offset[2]), part.size, part.colour,
                part.yaw, part.tilt, part.glow)


@dataclass(frozen=True, slots=True)
class Frame:
    """A furniture box seen from its front: ``front`` is the unit (x, z) direction its doors face."""

    center: Vec
    size: Vec
    front: tuple[float, float]

    @property
    def lo(self) -> Vec:
        return (self.center[0] - self.size[0] / 2, self.center[1] - self.size[1] / 2, self.center[2] - self.size[2] / 2)

    @property
    def hi(self) -> Vec:
        return (self.center[0] + self.size[0] / 2, self.center[1] + self.size[1] / 2, self.center[2] + self.size[2] / 2)

    def pushed_back(self, distance: float) -> Frame:
        """The same frame, ``distance`` shallower, its back where it was."""
        fx, fz = self.front
        c, s = self.center, self.size
        return Frame((c[0] - fx * distance, c[1], c[2] - fz * distance),
                     (s[0] - abs(fx) * 2 * distance, s[1], s[2] - abs(fz) * 2 * distance), self.front)

    def depth(self) -> float:
        return self.size[0] if self.front[0] else self.size[2]

    def width(self) -> float:
        return self.size[2] if self.front[0] else self.size[0]

    def local(self, across: float, y: float, out: float, w: float, h: float, d: float, colour: Colour,
              glow: float = 0.0, mesh: str = "box") -> Part:
        """A box placed in the frame's own axes: ``across`` from the centre along the face (to the front's
        right), ``out`` from the front face outwards (negative: inside), ``y`` absolute height."""
        fx, fz = self.front
        rx, rz = fz, -fx  # the face's right-hand direction, seen from the room
        face = self.depth() / 2
        cx = self.center[0] + rx * across + fx * (face + out)
        cz = self.center[2] + rz * across + fz * (face + out)
        sx = abs(rx) * w + abs(fx) * d
        sz = abs(rz) * w + abs(fz) * d
        return Part(mesh, (cx, y, cz), (sx, h, sz), colour, glow=glow)


def front_direction(center: Vec, size: Vec, reachable: Sequence[tuple[float, float]],
                    room_center: tuple[float, float]) -> tuple[float, float]:
    """The side of a furniture box that faces the most standing positions (ties: the room's middle)."""
    best: tuple[float, float, tuple[float, float]] | None = None
    for fx, fz in ((0.0, -1.0), (0.0, 1.0), (-1.0, 0.0), (1.0, 0.0)):
        half_depth = (size[0] if fx else size[2]) / 2
        half_width = (size[2] if fx else size[0]) / 2 + 0.1
        count = 0
        for px, pz in reachable:
            dx, dz = px - center[0], pz - center[2]
            ahead = dx * fx + dz * fz - half_depth
            lateral = abs(dx * fz - dz * fx)
            if 0.0 < ahead <= 1.0 and lateral <= half_width:
                count += 1
        towards = (room_center[0] - center[0]) * fx + (room_center[1] - center[2]) * fz
        key = (float(count), towards, (fx, fz))
        if best is None or key[:2] > best[:2]:
            best = key
    assert best is not None
    return best[2]


# ------------------------------------------------------------------ the scene
class SceneBuilder:
    """Turns one metadata snapshot into parts. ``fronts`` caches furniture facings across frames (furniture
    never moves; the cache key is the scene and the objectId, which encodes the position)."""

    def __init__(self, fronts: dict[tuple[str, str], tuple[float, float]] | None = None):
        self.fronts = fronts if fronts is not None else {}

    def build(self, metadata: dict[str, Any], reachable: Sequence[tuple[float, float]]) -> tuple[list[Part], list[Part]]:
        """(world parts, held parts); the held parts are already placed in front of the camera."""
        objects: list[dict[str, Any]] = metadata.get("objects") or []
        by_id = {o["objectId"]: o for o in objects}
        bounds = metadata.get("sceneBounds") or {}
        bc = bounds.get("center") or {"x": 0.0, "z": 0.0}
        room_center = (bc["x"], bc["z"])
        scene = str(metadata.get("sceneName", ""))
        held_id = next((o["objectId"] for o in metadata.get("inventoryObjects") or []), None)

        parts: list[Part] = []
        parts.extend(room_parts(bounds))
        offsets: dict[str, Vec] = {}  # an open drawer slides out ...
        contents_shift: dict[str, Vec] = {}  # ... with its contents
        frames: dict[str, Frame] = {}
        for obj in objects:
            kind = obj["objectType"]
            if obj.get("pickupable") or kind == "Floor":
                continue
            center, size = _box_of(obj)
            frame = Frame(center, size, self._front(scene, obj, center, size, reachable, room_center))
            if kind == "Cabinet" and frame.lo[1] > 1.2 and frame.depth() > WALL_CABINET_DEPTH:
                # Wall cabinets are drawn as deep as real ones (the simulator's box is the counter's depth),
                # so they do not hang over the counter in front of the eye; their contents move back with them.
                back = (frame.depth() - WALL_CABINET_DEPTH) / 2
                frame = frame.pushed_back(back)
                contents_shift[obj["objectId"]] = (-frame.front[0] * back, 0.0, -frame.front[1] * back)
            frames[obj["objectId"]] = frame
            if kind == "Drawer" and obj.get("isOpen"):
                d = frame.depth() * 0.65
                offsets[obj["objectId"]] = (frame.front[0] * d, 0.0, frame.front[1] * d)
                contents_shift[obj["objectId"]] = offsets[obj["objectId"]]
        parts.extend(stove_bodies(objects))
        marks = burner_marks(objects)
        for obj in objects:
            kind = obj["objectType"]
            if obj.get("pickupable") or kind == "Floor":
                continue
            offset = offsets.get(obj["objectId"])
            made = furniture_parts(obj, frames[obj["objectId"]], frames, marks)
            parts.extend(_shift(p, offset) for p in made) if offset else parts.extend(made)
            if obj.get("openable") and obj.get("isOpen"):
                shelf = shelf_rails(obj, frames[obj["objectId"]], by_id)
                parts.extend(_shift(p, offset) for p in shelf) if offset else parts.extend(shelf)

        held_tree: list[dict[str, Any]] = []
        for obj in objects:
            if not obj.get("pickupable"):
                continue
            chain = obj.get("parentReceptacles") or []
            if obj["objectId"] == held_id or (held_id is not None and held_id in chain):
                held_tree.append(obj)
                continue
            if any(by_id.get(p, {}).get("openable") and not by_id.get(p, {}).get("isOpen") for p in chain):
                continue  # shut inside a closed fridge, cabinet, drawer or microwave: not seen
            parent = by_id.get(chain[0], {}) if chain else {}
            made = object_parts(obj, parent.get("objectType"))
            shift = next((contents_shift[p] for p in chain if p in contents_shift), None)
            parts.extend(_shift(p, shift) for p in made) if shift else parts.extend(made)
        held = held_parts(metadata, held_id, held_tree) if held_id else []
        return parts, held

    def _front(self, scene: str, obj: dict[str, Any], center: Vec, size: Vec,
               reachable: Sequence[tuple[float, float]], room_center: tuple[float, float]) -> tuple[float, float]:
        kind = obj["objectType"]
        if kind in ("Microwave", "Toaster", "CoffeeMachine"):  # counter appliances carry their facing
            yaw = math.radians(float((obj.get("rotation") or {}).get("y", 0.0)))
            return (round(math.sin(yaw)), round(math.cos(yaw)))
        key = (scene, obj["objectId"])
        front = self.fronts.get(key)
        if front is None:
            front = self.fronts[key] = front_direction(center, size, reachable, room_center)
        return front


def camera_pose(metadata: dict[str, Any]) -> CameraPose:
    agent = metadata.get("agent") or {}
    position = agent.get("position") or {"x": 0.0, "y": 0.9, "z": 0.0}
    camera = metadata.get("cameraPosition")
    eye = (camera["x"], camera["y"], camera["z"]) if camera else (
        position["x"], position["y"] + EYE_ABOVE_AGENT, position["z"])
    return CameraPose(eye, float((agent.get("rotation") or {}).get("y", 0.0)), float(agent.get("cameraHorizon") or 0.0))


def room_parts(bounds: dict[str, Any]) -> list[Part]:
    c = bounds.get("center") or {"x": 0.0, "z": 0.0}
    s = bounds.get("size") or {"x": 6.0, "z": 6.0}
    x0, x1 = c["x"] - s["x"] / 2, c["x"] + s["x"] / 2
    z0, z1 = c["z"] - s["z"] / 2, c["z"] + s["z"] / 2
    height = 2.6
    parts = [
        _slab(x0, x1, 0.0, height, z1, z1 + 0.1, WALLS[0]),
        _slab(x1, x1 + 0.1, 0.0, height, z0, z1, WALLS[1]),
        _slab(x0, x1, 0.0, height, z0 - 0.1, z0, WALLS[2]),
        _slab(x0 - 0.1, x0, 0.0, height, z0, z1, WALLS[3]),
        _slab(x0 - 0.1, x1 + 0.1, height, height + 0.05, z0 - 0.1, z1 + 0.1, CEILING),
        # skirting boards: where the walls meet the floor
        _slab(x0, x1, 0.0, 0.08, z1 - 0.015, z1, WOOD), _slab(x1 - 0.015, x1, 0.0, 0.08, z0, z1, WOOD),
        _slab(x0, x1, 0.0, 0.08, z0, z0 + 0.015, WOOD), _slab(x0, x0 + 0.015, 0.0, 0.08, z0, z1, WOOD),
    ]
    # A checkered floor of 0.5 m tiles: it shows distance and movement.
    tile = 0.5
    nx, nz = max(1, math.ceil((x1 - x0) / tile)), max(1, math.ceil((z1 - z0) / tile))
    for i in range(nx):
        for k in range(nz):
            tx0, tz0 = x0 + i * tile, z0 + k * tile
            parts.append(_slab(tx0, min(x1, tx0 + tile), -0.02, 0.0, tz0, min(z1, tz0 + tile), FLOOR_TILES[(i + k) % 2]))
    return parts


def stove_bodies(objects: Iterable[dict[str, Any]]) -> list[Part]:
    """The stove under its burners and knobs (the body itself is no AI2-THOR object): steel, a black top."""
    burners = [o for o in objects if o["objectType"] in ("StoveBurner", "StoveKnob")]
    if not burners:
        return []
    # Group by the counter run they stand in: burners of one stove lie within half a metre of each other.
    groups: list[list[tuple[Vec, Vec]]] = []
    for obj in burners:
        c, s = _box_of(obj)
        for group in groups:
            gc = group[0][0]
            if abs(gc[0] - c[0]) < 0.9 and abs(gc[2] - c[2]) < 0.9:
                group.append((c, s))
                break
        else:
            groups.append([(c, s)])
    parts = []
    for group in groups:
        x0 = min(c[0] - s[0] / 2 for c, s in group) - 0.03
        x1 = max(c[0] + s[0] / 2 for c, s in group) + 0.03
        z0 = min(c[2] - s[2] / 2 for c, s in group) - 0.03
        z1 = max(c[2] + s[2] / 2 for c, s in group) + 0.03
        parts.append(_slab(x0 + 0.01, x1 - 0.01, 0.0, 0.9, z0 + 0.01, z1 - 0.01, STEEL))
        parts.append(_slab(x0, x1, 0.9, 0.925, z0, z1, BLACK))
    return parts


def furniture_parts(obj: dict[str, Any], f: Frame, frames: dict[str, Frame],
                    marks: dict[str, Colour] | None = None) -> list[Part]:
    kind = obj["objectType"]
    mark = (marks or {}).get(obj["objectId"])
    (x0, y0, z0), (x1, y1, z1) = f.lo, f.hi
    open_ = bool(obj.get("isOpen"))
    on = bool(obj.get("isToggled"))
    w, h, d = f.width(), y1 - y0, f.depth()
    if kind == "CounterTop":
        return [_slab(x0, x1, y0, y1, z0, z1, STONE), _slab(x0 + 0.04, x1 - 0.04, 0.0, y0, z0 + 0.04, z1 - 0.04, WOOD)]
    if kind in ("Cabinet", "Drawer", "Fridge"):
        body = FRIDGE if kind == "Fridge" else WOOD
        panel = FRIDGE if kind == "Fridge" else WOOD_PANEL
        inside = (0.97, 0.98, 1.0) if kind == "Fridge" else WOOD_INSIDE
        if not open_:
            parts = [_slab(x0, x1, y0, y1, z0, z1, body),
                     f.local(0.0, (y0 + y1) / 2, 0.004, w - 0.04, h - 0.04, 0.01, panel)]
            if kind == "Fridge":
                parts.append(f.local(0.0, y0 + h * 0.62, 0.012, w - 0.02, 0.012, 0.006, DARK_STEEL))  # freezer line
                parts.append(f.local(w / 2 - 0.07, y0 + h * 0.45, 0.03, 0.025, 0.4, 0.025, HANDLE))
                parts.append(f.local(w / 2 - 0.07, y0 + h * 0.8, 0.03, 0.025, 0.2, 0.025, HANDLE))
            elif kind == "Drawer":
                parts.append(f.local(0.0, (y0 + y1) / 2, 0.02, min(0.18, w * 0.5), 0.02, 0.02, HANDLE))
            else:
                hy = y0 + h * (0.2 if y0 > 1.2 else 0.8)
                parts.append(f.local(w / 2 - 0.06, hy, 0.02, 0.02, min(0.14, h * 0.4), 0.02, HANDLE))
            return parts
        t = 0.02
        glow = 0.35 if kind == "Fridge" else 0.0  # the fridge's light is on while it is open
        parts = [
            f.local(0.0, (y0 + y1) / 2, -d + t / 2, w, h, t, inside, glow),  # back
            f.local(-w / 2 + t / 2, (y0 + y1) / 2, -d / 2, t, h, d, body),  # sides
            f.local(w / 2 - t / 2, (y0 + y1) / 2, -d / 2, t, h, d, body),
            f.local(0.0, y0 + t / 2, -d / 2, w, t, d, inside, glow),  # bottom
        ]
        if kind != "Drawer":
            parts.append(f.local(0.0, y1 - t / 2, -d / 2, w, t, d, body))  # top
        else:
            parts.append(f.local(0.0, (y0 + y1) / 2, -t / 2, w, h, t, panel))  # the drawer's front
            parts.append(f.local(0.0, (y0 + y1) / 2, 0.02, min(0.18, w * 0.5), 0.02, 0.02, HANDLE))
            return parts
        doors = 2 if kind == "Cabinet" and w > 0.5 else 1
        door_w = w / doors
        for i in range(doors):
            hinge = w / 2 if (doors == 1 or i == 1) else -w / 2  # a single door hinges on the right
            sign = 1.0 if hinge > 0 else -1.0
            parts.append(f.local(hinge + sign * 0.01, (y0 + y1) / 2, door_w / 2, 0.02, h - 0.02, door_w, panel))
        return parts
    if kind == "Microwave":
        parts = [_slab(x0, x1, y0, y1, z0, z1, DARK_STEEL),
                 f.local(w / 2 - w * 0.13, (y0 + y1) / 2, 0.004, w * 0.22, h * 0.8, 0.01, BLACK)]  # control panel
        if not open_:
            window = (1.0, 0.85, 0.4) if on else (0.12, 0.13, 0.15)
            parts.append(f.local(-w * 0.12, (y0 + y1) / 2, 0.006, w * 0.62, h * 0.7, 0.01, window, 0.9 if on else 0.0))
            return parts
        t = 0.015
        return [
            f.local(0.0, (y0 + y1) / 2, -d + t / 2, w, h, t, DARK_STEEL),
            f.local(-w / 2 + t / 2, (y0 + y1) / 2, -d / 2, t, h, d, DARK_STEEL),
            f.local(w * 0.25, (y0 + y1) / 2, -d / 2, w * 0.5, h, d, DARK_STEEL),  # the electronics behind the panel
            f.local(0.0, y0 + t / 2, -d / 2, w, t, d, (0.75, 0.75, 0.72)),
            f.local(0.0, y1 - t / 2, -d / 2, w, t, d, DARK_STEEL),
            f.local(w * 0.37, (y0 + y1) / 2, 0.004, w * 0.22, h * 0.8, 0.01, BLACK),
            f.local(-w / 2 - 0.01, (y0 + y1) / 2, w * 0.35, 0.02, h * 0.95, w * 0.7, (0.15, 0.15, 0.17)),  # door
        ]
    if kind == "StoveBurner":
        cx, _, cz = f.center
        r = min(f.size[0], f.size[2]) * 0.8
        parts = [Part("cylinder", (cx, y1 - 0.005, cz), (r, 0.02, r), (0.18, 0.18, 0.19))]
        if mark is not None:  # a coloured ring round the burner, the colour of the knob that lights it
            parts.append(Part("cylinder", (cx, y1 - 0.004, cz), (r * 1.3, 0.016, r * 1.3), mark))
        if on:
            parts.append(Part("cylinder", (cx, y1 + 0.007, cz), (r * 0.8, 0.006, r * 0.8), GLOW_RED, glow=1.0))
            parts.append(Part("cylinder", (cx, y1 + 0.009, cz), (r * 0.45, 0.006, r * 0.45), (0.2, 0.05, 0.02)))
        else:
            parts.append(Part("cylinder", (cx, y1 + 0.007, cz), (r * 0.8, 0.006, r * 0.8), (0.32, 0.32, 0.33)))
            parts.append(Part("cylinder", (cx, y1 + 0.009, cz), (r * 0.45, 0.006, r * 0.45), (0.12, 0.12, 0.13)))
        return parts
    if kind == "StoveKnob":
        # Simulator knobs are 2-3 cm, a pixel or two at 300×300: drawn at least 4.5 cm so their colour shows.
        kw, kh = max(w * 0.9, 0.045), max(h * 0.9, 0.045)
        parts = [f.local(0.0, (y0 + y1) / 2, 0.01, kw, kh, 0.03, BLACK)]
        if mark is not None:  # the knob's face in the colour of its burner's ring
            parts.append(f.local(0.0, (y0 + y1) / 2, 0.03, kw * 0.8, kh * 0.8, 0.012, mark))
        if on:
            parts.append(f.local(0.0, y1 + 0.008, 0.0, w * 0.6, 0.012, 0.02, GLOW_RED, 1.0))
        return parts
    if kind == "Sink":
        # a steel top with the basin's hole in it, over a cupboard
        rim = (0.78, 0.80, 0.83)
        parts = [_slab(x0, x1, 0.0, y0, z0, z1, WOOD)]
        basin = next((b for b in frames.values() if b is not f and _inside(b.center, f)
                      and b.size[1] < f.size[1]), None)
        if basin is None:
            return parts + [_slab(x0, x1, y1 - 0.02, y1, z0, z1, rim)]
        (bx0, _, bz0), (bx1, _, bz1) = basin.lo, basin.hi
        return parts + [_slab(x0, x1, y1 - 0.02, y1, z0, bz0, rim), _slab(x0, x1, y1 - 0.02, y1, bz1, z1, rim),
                        _slab(x0, bx0, y1 - 0.02, y1, bz0, bz1, rim), _slab(bx1, x1, y1 - 0.02, y1, bz0, bz1, rim),
                        f.local(0.0, y1 + 0.1, -d + 0.03, 0.03, 0.2, 0.03, HANDLE)]  # the tap
    if kind == "SinkBasin":
        grey = (0.45, 0.47, 0.50)
        return [_slab(x0, x1, y0, y0 + 0.01, z0, z1, grey), _slab(x0, x1, y0, y1 + 0.04, z0, z0 + 0.01, grey),
                _slab(x0, x1, y0, y1 + 0.04, z1 - 0.01, z1, grey), _slab(x0, x0 + 0.01, y0, y1 + 0.04, z0, z1, grey),
                _slab(x1 - 0.01, x1, y0, y1 + 0.04, z0, z1, grey)]
    if kind == "Toaster":
        top = y0 + h * 0.7
        slot = (1.0, 0.4, 0.1) if on else BLACK
        return [_slab(x0, x1, y0, top, z0, z1, (0.78, 0.78, 0.80)),
                f.local(0.0, top + 0.002, -d * 0.3, w * 0.7, 0.004, 0.02, slot, 1.0 if on else 0.0),
                f.local(0.0, top + 0.002, -d * 0.7, w * 0.7, 0.004, 0.02, slot, 1.0 if on else 0.0),
                f.local(w * 0.3, y0 + h * 0.3, 0.01, 0.03, 0.03, 0.02, BLACK)]
    if kind == "CoffeeMachine":
        colour = (0.16, 0.12, 0.10)
        parts = [f.local(0.0, (y0 + y1) / 2, -d * 0.85, w, h, d * 0.3, colour),  # the column at the back
                 f.local(0.0, y1 - h * 0.15, -d * 0.45, w, h * 0.3, d * 0.9, colour),  # the head over the cup
                 f.local(0.0, y0 + 0.01, -d * 0.45, w, 0.02, d * 0.9, (0.3, 0.3, 0.3)),  # drip tray
                 f.local(w * 0.3, y1 - h * 0.15, 0.002, 0.03, 0.03, 0.01, (0.2, 0.95, 0.3) if on else (0.25, 0.25, 0.25),
                         1.0 if on else 0.0)]
        return parts
    if kind == "GarbageCan":
        c = f.center
        return [Part("cylinder", c, (min(f.size[0], f.size[2]), h, min(f.size[0], f.size[2])), (0.32, 0.42, 0.34)),
                Part("cylinder", (c[0], y1 + 0.01, c[2]), (min(f.size[0], f.size[2]) * 1.05, 0.02,
                                                           min(f.size[0], f.size[2]) * 1.05), (0.25, 0.3, 0.26))]
    if kind == "DiningTable":
        table = (0.55, 0.36, 0.20)
        parts = [_slab(x0, x1, y1 - 0.05, y1, z0, z1, table)]
        for lx in (x0 + 0.06, x1 - 0.06):
            for lz in (z0 + 0.06, z1 - 0.06):
                parts.append(_slab(lx - 0.03, lx + 0.03, 0.0, y1 - 0.05, lz - 0.03, lz + 0.03, table))
        return parts
    if kind == "Shelf":
        board = (0.70, 0.56, 0.38)
        parts = [f.local(-w / 2 + 0.01, (y0 + y1) / 2, -d / 2, 0.02, h, d, board),
                 f.local(w / 2 - 0.01, (y0 + y1) / 2, -d / 2, 0.02, h, d, board),
                 f.local(0.0, (y0 + y1) / 2, -d + 0.01, w, h, 0.02, board)]
        for level in (0.05, 0.5, 0.9, 1.3, y1 - 0.01):
            parts.append(f.local(0.0, level - 0.01, -d / 2, w, 0.02, d, board))
        return parts
    return [_slab(x0, x1, y0, y1, z0, z1, (0.6, 0.6, 0.6))]


def _inside(point: Vec, f: Frame) -> bool:
    (x0, _, z0), (x1, _, z1) = f.lo, f.hi
    return x0 <= point[0] <= x1 and z0 <= point[2] <= z1


def shelf_rails(obj: dict[str, Any], f: Frame, by_id: dict[str, dict[str, Any]]) -> list[Part]:
    """Thin wire shelves under what an open fridge or cabinet holds, one per height its contents rest at:
    unlike solid boards they do not hide the shelf below from an eye above them."""
    y0 = f.lo[1]
    levels: set[float] = set()
    for child in obj.get("receptacleObjectIds") or []:
        item = by_id.get(child)
        if item is None or (item.get("parentReceptacles") or [None])[0] != obj["objectId"]:
            continue
        c, s = _box_of(item)
        level = round(c[1] - s[1] / 2, 2)
        if level > y0 + 0.05:
            levels.add(level)
    w, d = f.width(), f.depth()
    parts = []
    for level in sorted(levels):
        for out in (-0.03, -d / 2, -d + 0.03):
            parts.append(f.local(0.0, level - 0.005, out, w - 0.04, 0.008, 0.012, (0.85, 0.86, 0.88)))
    return parts


def object_parts(obj: dict[str, Any], parent_type: str | None = None) -> list[Part]:
    """A pickupable object where the metadata puts it, turned by its own rotation."""
    (cx, cy, cz), (sx, sy, sz) = _box_of(obj)
    yaw = float((obj.get("rotation") or {}).get("y", 0.0))
    return shape_parts(obj, (cx, cy, cz), (sx, sy, sz), yaw, upright=parent_type == "Toaster")


# Slices lie flat where the simulator stands them on edge side by side: seen from above they overlap like a
# sliced tomato on a board, instead of showing only their edges.
_FLAT_SLICES = {"TomatoSliced", "PotatoSliced", "BreadSliced", "AppleSliced", "LettuceSliced"}
SLICE_THICKNESS = 0.016


def shape_parts(obj: dict[str, Any], c: Vec, s: Vec, yaw: float, upright: bool = False) -> list[Part]:
    kind = obj["objectType"]
    cooked = bool(obj.get("isCooked"))
    source = PIECE_OF.get(kind, kind)
    base = FOOD_COLOURS.get(source)
    if base is not None and cooked:
        base = browned(base)
    cx, cy, cz = c
    sx, sy, sz = s
    if kind in _FLAT_SLICES and not upright:
        width = max(sy, sz)
        cy, sx, sy, sz = cy - sy / 2 + SLICE_THICKNESS / 2, width, SLICE_THICKNESS, width
        c = (cx, cy, cz)
        s = (sx, sy, sz)
    a = math.radians(yaw)

    def at(u: float, v: float, w: float = 0.0) -> Vec:
        """A point ``u`` along the object's length (its local x) and ``w`` across, ``v`` up, turned by yaw."""
        return (cx + u * math.cos(a) + w * math.sin(a), cy + v, cz - u * math.sin(a) + w * math.cos(a))

    def part(mesh: str, centre: Vec, size: Vec, colour: Colour, tilt: float = 0.0, glow: float = 0.0) -> Part:
        return Part(mesh, centre, size, colour, yaw, tilt, glow)

    if kind == "Apple":
        assert base is not None
        return [part("sphere", c, s, base), part("cylinder", at(0, sy * 0.55), (0.008, 0.025, 0.008), (0.35, 0.22, 0.1))]
    if kind == "Tomato":
        assert base is not None
        return [part("sphere", c, s, base), part("cylinder", at(0, sy * 0.47), (sx * 0.45, 0.01, sz * 0.45),
                                                 (0.2, 0.55, 0.15))]
    if kind == "Egg":
        assert base is not None
        return [part("sphere", c, s, base)]
    if kind == "Potato":
        assert base is not None
        return [part("sphere", c, s, base)]
    if kind == "Lettuce":
        assert base is not None
        light = (min(1.0, base[0] + 0.2), min(1.0, base[1] + 0.15), min(1.0, base[2] + 0.1))
        return [part("sphere", c, s, base), part("sphere", at(sx * 0.1, sy * 0.15), (sx * 0.7, sy * 0.7, sz * 0.7), light)]
    if kind == "Bread":
        assert base is not None
        return [part("box", at(0, -sy * 0.15), (sx, sy * 0.7, sz), base),
                part("cylinder", at(0, sy * 0.15), (sy * 0.7, sx * 0.98, sz * 0.98), base, tilt=90.0)]
    if kind in _FLAT_SLICES:
        thin = min(range(3), key=lambda i: s[i])
        inner_size = tuple(v * (1.15 if i == thin else 0.8) for i, v in enumerate(s))
        flesh = {"BreadSliced": (0.95, 0.87, 0.66), "TomatoSliced": (0.98, 0.50, 0.40),
                 "PotatoSliced": (0.94, 0.86, 0.56), "AppleSliced": (0.96, 0.92, 0.72),
                 "LettuceSliced": (0.62, 0.86, 0.45)}[kind]
        if cooked:
            flesh = browned(flesh)
        # the skin or crust round the edge, the flesh or crumb on the faces
        mesh = "box" if kind in ("BreadSliced", "LettuceSliced", "AppleSliced") or upright else "cylinder"
        parts = [part(mesh, c, s, base or flesh), part(mesh, c, inner_size, flesh)]  # type: ignore[arg-type]
        if cooked and not upright:  # dark sear stripes across the top face: a cooked slice at a glance
            top = inner_size[1] / 2 + 0.001
            parts.extend(part("box", at(0.0, top, w), (sx * 0.7, 0.002, max(0.008, sz * 0.12)), SEAR)
                         for w in (-sz * 0.25, 0.0, sz * 0.25))
        return parts
    if kind == "EggCracked":
        white = browned(WHITE) if cooked else WHITE
        yolk = (0.85, 0.5, 0.05) if cooked else (1.0, 0.75, 0.1)
        return [part("cylinder", c, (sx, sy * 0.5, sz), white),
                part("sphere", at(0, sy * 0.3), (sx * 0.4, sy * 0.9, sz * 0.4), yolk)]
    if kind == "Pan":
        body = min(sx * 0.62, sz)
        return [part("cup", at(-sx / 2 + body / 2, 0), (body, sy, body), (0.16, 0.16, 0.18)),
                part("box", at(sx / 2 - (sx - body) / 2, sy * 0.3), (sx - body, 0.02, 0.03), BLACK)]
    if kind == "Pot":
        return [part("cup", c, (sx * 0.85, sy, sz * 0.85), STEEL),
                part("box", at(0, sy * 0.35), (sx, 0.02, 0.04), DARK_STEEL)]
    if kind == "Kettle":
        blue = (0.25, 0.42, 0.72)
        return [part("cylinder", c, (sx * 0.8, sy * 0.75, sz * 0.8), blue),
                part("sphere", at(0, sy * 0.38), (sx * 0.5, sy * 0.2, sz * 0.5), blue),
                part("box", at(sx * 0.45, sy * 0.1), (sx * 0.35, 0.025, 0.025), blue, tilt=35.0),
                part("box", at(0, sy * 0.47), (sx * 0.5, 0.02, 0.02), BLACK)]
    if kind == "Bowl":
        return [part("cup", c, s, (0.55, 0.70, 0.90))]
    if kind == "Plate":
        return [part("cylinder", c, s, WHITE), part("cylinder", at(0, sy * 0.2), (sx * 0.7, sy, sz * 0.7), (0.88, 0.88, 0.87))]
    if kind == "Cup":
        full = obj.get("isFilledWithLiquid")
        parts = [part("cup", c, s, (0.72, 0.86, 0.92))]
        if full:
            parts.append(part("cylinder", at(0, sy * 0.35), (sx * 0.95, 0.01, sz * 0.95), (0.3, 0.16, 0.07)))
        return parts
    if kind == "Mug":
        parts = [part("cup", c, (sx * 0.8, sy, sz * 0.8), (0.95, 0.72, 0.18)),
                 part("box", at(sx * 0.45, 0), (0.02, sy * 0.55, 0.015), (0.95, 0.72, 0.18))]
        if obj.get("isFilledWithLiquid"):
            parts.append(part("cylinder", at(0, sy * 0.35), (sx * 0.76, 0.01, sz * 0.76), (0.3, 0.16, 0.07)))
        return parts
    if kind == "Knife":
        return [part("box", at(sx * 0.2, 0), (sx * 0.6, 0.006, sz), (0.85, 0.87, 0.9)),
                part("box", at(-sx * 0.3, 0), (sx * 0.4, sy, sz * 0.8), BLACK)]
    if kind == "ButterKnife":
        return [part("box", at(sx * 0.2, 0), (sx * 0.6, 0.006, sz), (0.78, 0.8, 0.83)),
                part("box", at(-sx * 0.3, 0), (sx * 0.4, sy * 0.7, sz * 0.8), (0.9, 0.88, 0.8))]
    if kind == "Fork":
        parts = [part("box", at(-sx * 0.15, 0), (sx * 0.7, 0.006, 0.012), STEEL)]
        for k in (-1.5, -0.5, 0.5, 1.5):
            parts.append(part("box", at(sx * 0.35, 0, k * sz * 0.22), (sx * 0.3, 0.006, 0.004), STEEL))
        return parts
    if kind == "Spoon":
        return [part("box", at(-sx * 0.15, 0), (sx * 0.7, 0.006, 0.012), STEEL),
                part("sphere", at(sx * 0.35, 0), (sx * 0.3, 0.012, sz), STEEL)]
    if kind == "Spatula":
        return [part("box", at(-sx * 0.2, 0), (sx * 0.6, 0.012, 0.02), BLACK),
                part("box", at(sx * 0.3, 0), (sx * 0.4, 0.006, sz), (0.85, 0.25, 0.2))]
    if kind == "Ladle":
        return [part("box", at(-sx * 0.15, sy * 0.3), (sx * 0.7, 0.01, 0.015), STEEL),
                part("cup", at(sx * 0.35, -sy * 0.1), (sx * 0.3, sy * 0.6, sz), STEEL)]
    if kind in ("SaltShaker", "PepperShaker"):
        colour = WHITE if kind == "SaltShaker" else (0.15, 0.12, 0.1)
        return [part("cylinder", at(0, -sy * 0.1), (sx, sy * 0.8, sz), colour),
                part("sphere", at(0, sy * 0.3), (sx, sy * 0.4, sz), STEEL)]
    return [part("box", c, s, base or (0.5, 0.5, 0.6))]


def held_parts(metadata: dict[str, Any], held_id: str, tree: list[dict[str, Any]]) -> list[Part]:
    """The held object and its contents, moved to the bottom of the frame (a hand's place), turned with the agent."""
    pose = camera_pose(metadata)
    right, up, forward = pose.basis()
    held = next((o for o in tree if o["objectId"] == held_id), None)
    if held is None:
        return []
    (hx, hy, hz), size = _box_of(held)
    reach = 0.32 + 0.45 * max(size)
    side, drop = 0.06, -0.5 * reach
    target = tuple(pose.eye[i] + right[i] * side + up[i] * drop + forward[i] * reach for i in range(3))
    parts: list[Part] = []
    for obj in tree:
        (cx, cy, cz), s = _box_of(obj)
        c = (target[0] + cx - hx, target[1] + cy - hy, target[2] + cz - hz)
        parts.extend(shape_parts(obj, c, s, pose.yaw))
    return parts
