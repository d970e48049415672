"""What a standing agent can see in one direction: the street ahead and its cross streets, the
buildings and shop signs on either side, tall landmarks on the skyline, street-name signs.

The same Scene feeds the image renderer (street_view.py) and the text description (describe), so
text-only and vision agents observe the same world.
"""

from __future__ import annotations

import functools
import hashlib
import math
import re
from dataclasses import dataclass, field

from ewa_mcp.geometry import angle_diff, bearing_deg, cardinal_word, haversine_m, offset_flat
from .world import CityGraph, Place, World

VIEW_HALF_ANGLE = 50.0  # degrees either side of the view heading that count as "in view"
NEAR_RANGE_M = 160.0  # buildings along the street that are described
SKYLINE_RANGE_M = 1500.0
SKYLINE_MIN_HEIGHT_M = 120.0
AHEAD_LOOK_M = 250.0
SIGN_KINDS = {"store", "restaurant", "shop", "station", "market"}  # kinds whose name is on a sign
FACADE_KINDS = {"landmark", "church", "museum", "library", "hotel", "theater", "market", "station"}
# A place is seen where its entrance is: on the street front of the node it is attached to, this far
# towards the building (at most). Building centroids can lie 80 m inside a large block; measuring to
# them made a landmark's distance stay put while the agent walked past it.
ENTRANCE_SETBACK_M = 10.0


@dataclass
class Frontage:
    side: str  # left, right or ahead
    distance_m: float  # distance along the view direction (the renderer's depth)
    lateral_m: float  # distance to the side of the view axis
    range_m: float  # straight-line distance from the agent to the entrance (what the text says)
    rel_angle: float  # degrees right of the view centre
    kind: str
    sign: str | None  # the shop sign's text; None for landmarks (their names are not painted)
    style: str  # architectural style or "" (drives the facade drawing)
    height_m: float | None
    hint: str  # a visual description without the name
    place_id: str
    # Its node lies on the street ahead and its entrance to one side of it: ``side`` is then the side of that
    # street as a walker there facing the same way is told it ("on your left"), not the side of the view's axis.
    on_street: bool = False


@dataclass
class Opening:
    side: str  # left, right or both
    distance_m: float
    street: str  # the street to the left (or the one side's street)
    right_street: str | None = None  # side "both": the street to the right when it is named otherwise


@dataclass
class SkylineItem:
    rel_angle: float  # degrees right of the view centre
    distance_m: float
    height_m: float
    style: str
    hint: str
    place_id: str


@dataclass
class Scene:
    city: str
    node: str
    heading: float
    label: str  # front / right / back / left or N / E / S / W
    road_ahead: bool
    ahead_street: str | None
    ahead_length_m: float
    openings: list[Opening] = field(default_factory=list)
    frontages: list[Frontage] = field(default_factory=list)
    skyline: list[SkylineItem] = field(default_factory=list)
    street_signs: list[str] = field(default_factory=list)
    open_space: str = ""  # a park's look where it lies across the sidewalk this way ("" for none)
    in_park: bool = False  # the node is on a path through a park: no building fronts line the street ahead
    seed: int = 0
    # The places at this very node whose entrance lies within HERE_HALF_ANGLE of this view: what the text
    # mode's "Right here:" line names, drawn close up facing the camera (describe never reads this).
    here: list[Frontage] = field(default_factory=list)
    # The wall colours the descriptions of the places near this node give (wall_colour_of): an ordinary
    # front is drawn in none of them, so no nameless building a step away passes for a described one.
    place_walls: list[tuple[int, int, int]] = field(default_factory=list)


def _style(p: Place) -> str:
    return str(p.facts.get("architectural_style", "")) if p.kind in FACADE_KINDS else ""


def entrance(world: World, p: Place) -> tuple[float, float]:
    """Where a place meets its street: a few metres from its node towards the building (cached)."""
    cache: dict[str, tuple[float, float]] = world.__dict__.setdefault("_entrances", {})
    if p.id not in cache:
        node = world.node(p.node)
        d = min(p.offset_m, ENTRANCE_SETBACK_M) if p.heading_from_node is not None else 0.0
        cache[p.id] = offset_flat(node.lat, node.lng, p.heading_from_node or 0.0, d)
    return cache[p.id]


def what_is_seen(kind: str, sign: str | None, hint: str) -> str:
    """A place in words: a shop's sign, else (and also) its look; never a landmark's name."""
    what = f'a sign reading "{sign}" ({kind})' if sign else hint.rstrip(".").lower()
    if sign and hint:
        what += f" — {hint.rstrip('.').lower()}"
    return what


def places_here(world: World, graph: CityGraph, i: int, heading: float) -> list[str]:
    """Sentences for the places whose entrance is at this very node, with the side they are on."""
    out = []
    for p in sorted(world.places_near(graph.ids[i]), key=lambda p: p.id):
        if p.heading_from_node is None:
            side = "beside you"
        else:
            rel = angle_diff(p.heading_from_node, heading)
            side = ("ahead of you" if abs(rel) <= 30 else "behind you" if abs(rel) >= 150
                    else "on your right" if rel > 0 else "on your left")
        what = what_is_seen(p.kind, p.name if p.kind in SIGN_KINDS else None, p.description_hint)
        out.append(f"{side}, {what}.")
    return out


# Where no street continues, the fronts across the street stand within this depth (the renderer draws a
# place up to it straight ahead as the front across; street_view.render_cues): nothing farther is in sight.
CLOSED_VIEW_DEPTH_M = 40.0
HERE_HALF_ANGLE = 45.0  # four views 90° apart: each place at a node falls in (at least) one of them


def places_in_view_here(world: World, graph: CityGraph, i: int, heading: float) -> list[Frontage]:
    """The places whose entrance is at this node (those places_here words) and lies this way: the vision
    mode's counterpart of "Right here:", so a walker can confirm arrival from the picture alone."""
    out = []
    for p in sorted(world.places_near(graph.ids[i]), key=lambda p: p.id):
        towards = (p.heading_from_node if p.heading_from_node is not None
                   else bearing_deg(graph.lat[i], graph.lng[i], p.lat, p.lng))
        rel = angle_diff(towards, heading)
        if abs(rel) > HERE_HALF_ANGLE:
            continue
        height = p.facts.get("height_m")
        d = min(p.offset_m, ENTRANCE_SETBACK_M) if p.heading_from_node is not None else 0.0
        out.append(Frontage("right" if rel >= 0 else "left", round(d * math.cos(math.radians(rel)), 1),
                            round(abs(d * math.sin(math.radians(rel))), 1), round(d, 1), round(rel, 1), p.kind,
                            p.name if p.kind in SIGN_KINDS or is_alley(p.name) else None, _style(p),
                            float(height) if height else None, p.description_hint, p.id))
    return out


OPEN_SPACE_KINDS = {"park"}
OPEN_SPACE_HALF_ANGLE = 45.0
OPEN_SPACE_MIN_REACH_M = 120.0  # a small park is seen this far from its centre; a large one further:
OPEN_SPACE_MARGIN_M = 60.0  # its centre lies as far inside as from its street node, plus this


# A street named for a park with one of these words runs through it ("Point State Park Promenade"); one
# named for it otherwise may run along its edge ("Union Square East").
PARK_PATH_WORDS = ("promenade", "path", "walk", "trail", "esplanade", "mall")


def park_around(world: World, graph: CityGraph, i: int) -> Place | None:
    """The park a node lies inside: every street there is a path through that park."""
    streets = graph.node_streets[i]
    if not streets:
        return None
    cache: dict[str, list[Place]] = world.__dict__.setdefault("_parks", {})
    if graph.city not in cache:
        cache[graph.city] = sorted((p for p in world.places.values()
                                    if p.city == graph.city and p.kind in OPEN_SPACE_KINDS), key=lambda p: p.id)
    for p in cache[graph.city]:
        if all(p.name in s and any(w in s.lower().split() for w in PARK_PATH_WORDS) for s in streets):
            return p
    return None


def open_space_this_way(world: World, graph: CityGraph, i: int, heading: float) -> str:
    """The look of a park lying this way beside the street (its centre within reach and within 45° of
    the view): a view across it shows lawns and trees, not building fronts. The data has no park
    outlines, so a park's reach is judged from how far its centre lies from its street node. Inside a
    park (on its paths, park_around) it lies every way: its centre may be a few metres off, in any
    direction, and still the ground all around is the park's."""
    inside = park_around(world, graph, i)
    if inside is not None:
        return inside.description_hint or "an open park with lawns and trees"
    lat0, lng0 = graph.lat[i], graph.lng[i]
    best: tuple[float, str] | None = None
    for p in world.places.values():
        if p.city != graph.city or p.kind not in OPEN_SPACE_KINDS:
            continue
        d = haversine_m(lat0, lng0, p.lat, p.lng)
        reach = max(OPEN_SPACE_MIN_REACH_M, p.offset_m + OPEN_SPACE_MARGIN_M)
        if d > reach or abs(angle_diff(bearing_deg(lat0, lng0, p.lat, p.lng), heading)) > OPEN_SPACE_HALF_ANGLE:
            continue
        if best is None or d < best[0]:
            best = (d, p.description_hint or "an open park with lawns and trees")
    return best[1] if best else ""


def compute_scene(world: World, graph: CityGraph, i: int, heading: float, label: str) -> Scene:
    node_id = graph.ids[i]
    seed = int(hashlib.sha1(f"{node_id}:{round(heading) % 360}".encode()).hexdigest()[:8], 16)
    scene = Scene(graph.city, node_id, heading % 360.0, label, False, None, 0.0, seed=seed)
    # The street ahead: follow the straightest continuation while it stays within 20 degrees.
    ahead = [(j, length, s, h) for j, length, s, h in graph.adj[i] if abs(angle_diff(h, heading)) <= 30.0]
    # The nodes of the street ahead, each with the heading one walks it at there (its side of the street is
    # told against that heading: a street that bends carries its fronts off the view's straight axis).
    street_heading: dict[int, float] = {i: heading % 360.0}
    if ahead:
        j, length, s, h = min(ahead, key=lambda link: abs(angle_diff(link[3], heading)))
        scene.road_ahead = True
        scene.ahead_street = graph.streets[s]
        travelled, prev, cur, cur_h = length, i, j, h
        street_heading[j] = h
        while travelled < AHEAD_LOOK_M:
            for k, _, s2, h2 in graph.adj[cur]:
                rel = angle_diff(h2, cur_h)
                if k != prev and 45.0 <= abs(rel) <= 135.0 and graph.streets[s2] != scene.ahead_street:
                    side = "right" if rel > 0 else "left"
                    existing = next((o for o in scene.openings if abs(o.distance_m - travelled) < 5), None)
                    if existing and existing.side != side:
                        # one cross street may change its name here (North / South 11th Street): each
                        # side is named as the map's directions name the street one turns onto
                        left, right = ((existing.street, graph.streets[s2]) if side == "right"
                                       else (graph.streets[s2], existing.street))
                        existing.side, existing.street = "both", left
                        existing.right_street = right if right != left else None
                    elif existing is None:
                        scene.openings.append(Opening(side, round(travelled, 1), graph.streets[s2]))
            straight = [(k, ln, s2, h2) for k, ln, s2, h2 in graph.adj[cur]
                        if k != prev and abs(angle_diff(h2, cur_h)) <= 20.0]
            if not straight:
                break
            k, ln, _, h2 = min(straight, key=lambda link: abs(angle_diff(link[3], cur_h)))
            prev, cur, cur_h = cur, k, h2
            travelled += ln
            street_heading.setdefault(cur, cur_h)
        scene.ahead_length_m = round(min(travelled, AHEAD_LOOK_M), 1)
    lat0, lng0 = graph.lat[i], graph.lng[i]
    for p in world.places.values():
        if p.city != graph.city or abs(p.lat - lat0) > 0.015 or abs(p.lng - lng0) > 0.02:
            continue
        # Near places are measured to their entrance on the street, far ones (the skyline) to the building.
        elat, elng = entrance(world, p)
        d = haversine_m(lat0, lng0, elat, elng)
        far = d > NEAR_RANGE_M
        if far:
            elat, elng = p.lat, p.lng
            d = haversine_m(lat0, lng0, elat, elng)
        wall = None if far or p.kind in OPEN_SPACE_KINDS else wall_colour_of(p.description_hint)
        if wall is not None and wall not in scene.place_walls:
            scene.place_walls.append(wall)
        if d < 1.0:
            continue
        rel = angle_diff(bearing_deg(lat0, lng0, elat, elng), heading)
        if abs(rel) > VIEW_HALF_ANGLE:
            continue
        along = d * math.cos(math.radians(rel))
        lateral = d * math.sin(math.radians(rel))
        height = p.facts.get("height_m")
        if not far:
            side = "ahead" if abs(rel) < 8.0 else ("right" if rel > 0 else "left")
            on_street = scene.road_ahead and graph.index.get(p.node, -1) in street_heading
            street_side = _street_side(graph, p, street_heading) if on_street else None
            if street_side:
                side = street_side
            elif on_street:  # its node says "ahead of you" / "behind you": beside the street only near its axis
                # Measured against the street's own heading at the place's node, not the view's: a view
                # turned off the street's line (a cardinal view down a grid street at 29°) would put an
                # entrance on the street's far side when it stands on the near one.
                along_h = street_heading[graph.index[p.node]]
                street_lateral = d * math.sin(math.radians(angle_diff(bearing_deg(lat0, lng0, elat, elng), along_h)))
                on_street = side != "ahead" and abs(street_lateral) <= STREET_SIDE_M
                if on_street:
                    side = "right" if street_lateral > 0 else "left"
            scene.frontages.append(Frontage(side, round(max(along, 3.0), 1), round(abs(lateral), 1),
                                            round(d, 1), round(rel, 1), p.kind,
                                            p.name if p.kind in SIGN_KINDS else None, _style(p),
                                            float(height) if height else None, p.description_hint, p.id,
                                            on_street=on_street))
        elif (height and float(height) >= SKYLINE_MIN_HEIGHT_M and d <= SKYLINE_RANGE_M and abs(rel) <= 40.0
              and seen_over_roofs(rel, d, float(height))):
            scene.skyline.append(SkylineItem(round(rel, 1), round(d, 1), float(height), _style(p),
                                             p.description_hint, p.id))
    scene.open_space = open_space_this_way(world, graph, i, heading)
    scene.in_park = park_around(world, graph, i) is not None
    scene.here = places_in_view_here(world, graph, i, heading)
    scene.skyline = _unhidden(scene.skyline)
    if not scene.road_ahead and not scene.open_space:
        scene.skyline = []  # building fronts across the sidewalk, a few metres away, hide every far tower
        # and every place behind them: only those up to the fronts across the street are in sight
        scene.frontages = [f for f in scene.frontages if f.distance_m <= CLOSED_VIEW_DEPTH_M]
    scene.frontages.sort(key=lambda f: f.range_m)
    scene.skyline.sort(key=lambda s: -s.distance_m)
    streets = graph.node_streets[i]
    if len(streets) >= 2:
        scene.street_signs = list(streets)
    return scene


STREET_SIDE_M = 20.0  # an entrance this close to the view's axis is beside the street ahead, not off it


def _street_side(graph: CityGraph, p: Place, street_heading: dict[int, float]) -> str | None:
    """The side of the street ahead a place's entrance is on, as places_here words it at the place's node for
    one walking the street there ("on your left"); None where its entrance lies along the street rather
    than to one side (there the node says "ahead of you" or "behind you")."""
    if p.heading_from_node is None:
        return None
    h = street_heading.get(graph.index.get(p.node, -1))
    if h is None:
        return None
    rel = angle_diff(p.heading_from_node, h)
    if abs(rel) <= 30 or abs(rel) >= 150:
        return None
    return "right" if rel > 0 else "left"


# The street's building fronts stand this far to either side (facades.FACADE_X_M), and the lowest
# building drawn in front of a far tower is one storey (street_view.MIN_ROOF_M) above a 1.7 m eye.
FRONTS_LATERAL_M = 11.0
ROOF_OVER_EYE_M = 4.0 - 1.7
SKYLINE_SHOWN = 0.4  # the share of a tower's height that must clear the roofs in front of it


def seen_over_roofs(rel_angle: float, distance_m: float, height_m: float) -> bool:
    """Whether a far tower this many degrees off the view axis shows over the street's nearer roofs: the
    front it is seen across stands at depth 11 m / tan(angle), and even a one-storey building there must
    leave the top SKYLINE_SHOWN of the tower in sight (what the picture draws: street_view caps the
    roofs in front of a named tower, down to one storey)."""
    angle = min(89.0, abs(rel_angle) + 2.0)  # the tower's own width, about 2 degrees either side
    depth = FRONTS_LATERAL_M / max(1e-6, math.tan(math.radians(angle)))
    return SKYLINE_SHOWN * height_m * depth / distance_m >= ROOF_OVER_EYE_M


def _unhidden(items: list[SkylineItem]) -> list[SkylineItem]:
    """The skyline without the towers wholly behind a nearer one (narrower and lower in sight): drawn far
    to near, the nearer would cover them."""
    kept: list[SkylineItem] = []
    for item in sorted(items, key=lambda s: s.distance_m):
        half = math.degrees(math.atan(40.0 / item.distance_m))
        covered = any(abs(item.rel_angle - k.rel_angle) + half <= math.degrees(math.atan(40.0 / k.distance_m))
                      and item.height_m / item.distance_m <= k.height_m / k.distance_m for k in kept)
        if not covered:
            kept.append(item)
    return kept


def opening_words(o: Opening) -> str:
    at = f"at {int(round(o.distance_m))} m"
    if o.side != "both":
        return f"{o.street} opens to the {o.side} {at}"
    if o.right_street:
        return f"{o.street} opens to the left and {o.right_street} to the right {at}"
    return f"{o.street} opens to the left and right {at}"


def frontage_where(scene: Scene, f: Frontage) -> str:
    """Where a place is, in words that keep two meanings apart: the side of the street ahead (as the
    map's "on your left" means it: the side of the street one walks along), for a place whose node is on
    that street; else the direction of sight. An entrance near the view's axis is not enough for the
    first: one on a cross street at the corner, or across a bend, would be named on the wrong side."""
    if scene.road_ahead and f.on_street:
        return f"ahead on the {f.side}-hand side of {scene.ahead_street}"
    if f.side == "ahead":
        return "straight ahead"
    sight = f"{int(round(abs(f.rel_angle)))}° to the {f.side} of straight ahead"
    # where no street continues this way there is no street ahead to be off
    return f"off the street ahead, {sight}" if scene.road_ahead else sight


def describe(scene: Scene) -> str:
    """One paragraph for text-only agents; never names landmarks, only what a sign would show."""
    parts = [f"{scene.label} (facing {cardinal_word(scene.heading)}, {round(scene.heading)}°):"]
    if scene.road_ahead:
        parts.append(f"{scene.ahead_street} continues ahead for about {int(round(scene.ahead_length_m, -1))} m.")
        if scene.openings:
            crossings = "; ".join(opening_words(o) for o in scene.openings[:3])
            parts.append(f"Cross streets: {crossings}.")
    else:
        if scene.open_space:
            parts.append("No street continues this way: across the sidewalk lies open ground, "
                         f"{scene.open_space.rstrip('.').lower()}.")
        else:
            parts.append("No street continues this way: a row of building fronts across the sidewalk.")
    for f in scene.frontages[:5]:
        where = frontage_where(scene, f)  # capitalise its first letter only: street names keep theirs
        parts.append(f"{where[:1].upper()}{where[1:]}, {int(round(f.range_m))} m away: "
                     f"{what_is_seen(f.kind, f.sign, f.hint)}.")
    for s in sorted(scene.skyline, key=lambda s: s.distance_m)[:2]:
        side = "slightly right" if s.rel_angle > 10 else "slightly left" if s.rel_angle < -10 else "straight ahead"
        parts.append(f"On the skyline {side}, about {int(round(s.distance_m, -2))} m away: {s.hint.rstrip('.').lower()}.")
    if scene.street_signs:
        parts.append("Street signs here: " + " / ".join(scene.street_signs) + ".")
    return " ".join(parts)


# The words of a description -> the details a facade is drawn with (facades.draw_details): one table for the
# text's cues and the image's, so the two cannot drift apart.
DETAIL_WORDS = {
    "lions": ("lion",), "clock": ("clock",), "dome": ("dome",), "statue": ("statue", "figure"),
    "spire": ("spire", "steeple", "pointed"), "columns": ("column", "colonnade", "portico"),
    "arch": ("arched", "arches", "archway"), "steps": ("steps", "stairs", "stairway", "staircase"),
    "neon": ("neon",), "awning": ("awning", "canopy", "marquee"), "lamps": ("globe lamp", "lamps"),
    "trees": ("tree", "park", "garden", "lawn"), "twin": ("twin",), "flags": ("flag",),
    "cupola": ("cupola",), "fence": ("fence", "railing"), "gables": ("gable", "half-timber"),
    "stained": ("stained glass", "stained-glass"), "shutters": ("shutter",), "flowers": ("flower box", "window box"),
}

# The words of a description naming what a front is built of -> the wall colour it is drawn in (where its
# style has no palette of its own): "colonial brick" reads as brick in the picture too.
MATERIAL_WORDS = {
    "brownstone": (112, 76, 60), "sandstone": (206, 182, 140), "limestone": (224, 216, 198),
    "marble": (238, 236, 230), "granite": (150, 146, 142), "terracotta": (196, 120, 84), "brick": (156, 74, 54),
    "glass": (124, 162, 190), "steel": (140, 150, 160), "concrete": (160, 158, 152), "stone": (186, 180, 168),
}
COLOUR_WORDS = {
    "red": (190, 28, 36), "blue": (28, 70, 160), "green": (20, 118, 64), "yellow": (226, 184, 20),
    "orange": (220, 110, 20), "purple": (110, 40, 120), "black": (28, 28, 28), "white": (244, 244, 240),
}
# Things a park's description names, drawn in its picture (lawns and trees always: a park is drawn as one).
PARK_WORDS = {"paths": ("path", "walk", "promenade"), "pond": ("pond", "lake", "lagoon", "reflecting pool"),
              "fountain": ("fountain",), "monument": ("monument", "statue", "obelisk", "memorial")}


@functools.lru_cache(maxsize=4096)
def material_of(hint: str) -> str:
    """The first building material a description names ("" for none)."""
    text = hint.lower()
    found = [(text.find(w), w) for w in MATERIAL_WORDS if w in text]
    return min(found)[1] if found else ""


# The colour words a description puts before the material a front is built of ("rust-brown weathering steel",
# "red-brick", "white marble", "pink-granite") -> the wall colour: the material's own tone alone drew the
# rust-brown steel of a tower in the grey of bare steel, so a walker at its node saw a front unlike the one
# the task describes.
WALL_COLOUR_WORDS = {
    "rust-brown": (140, 70, 40), "rust": (146, 74, 42), "blue-green": (70, 130, 140), "brown": (118, 78, 54),
    "red": (160, 56, 44), "white": (238, 236, 230), "pink": (204, 150, 140), "buff": (214, 190, 150),
    "orange": (200, 112, 62), "cream": (232, 220, 190), "tan": (200, 170, 130), "grey": (132, 134, 136),
    "gray": (132, 134, 136), "black": (44, 44, 48), "green": (84, 132, 112), "blue": (92, 132, 172),
    "bronze": (116, 88, 52), "copper": (176, 102, 62), "gold": (196, 160, 60), "golden": (196, 160, 60),
    "pale": (222, 216, 202), "dark": (70, 72, 78),
}
SHADE_WORDS = {"dark": 0.6, "pale": 1.35}  # before another colour word, they shade it
WALL_COLOUR_REACH = 3  # words before the material a colour word may stand ("rust-brown weathering steel")


@functools.lru_cache(maxsize=4096)
def wall_colour_of(hint: str) -> tuple[int, int, int] | None:
    """The colour a place's front is drawn in: the colour its description gives the material it is built of
    (the last colour word among the few words before it, shaded by a "dark" or "pale" before that), else
    that material's own tone; None where the description names no material (its style's palette, or a
    random tone, is drawn)."""
    material = material_of(hint)
    if not material:
        return None
    text = hint.lower()
    words = re.findall(r"[a-z]+(?:-[a-z]+)*", text[:text.find(material)])[-WALL_COLOUR_REACH:]
    named: list[str] = []
    for w in words:  # a compound ("rust-brown") as a whole where the table has it, else each of its parts
        named += [w] if w in WALL_COLOUR_WORDS else [q for q in w.split("-") if q in WALL_COLOUR_WORDS]
    hues = [w for w in named if w not in SHADE_WORDS]
    if not hues:
        return WALL_COLOUR_WORDS[named[-1]] if named else MATERIAL_WORDS[material]
    shade = next((SHADE_WORDS[w] for w in named if w in SHADE_WORDS), 1.0)
    r, g, b = (min(255, int(c * shade)) for c in WALL_COLOUR_WORDS[hues[-1]])
    return r, g, b


def sign_colour_of(hint: str) -> tuple[int, int, int] | None:
    """The colour a description gives a shop's sign or logo ("a red sign", "a red bullseye logo")."""
    m = re.search(r"\b(" + "|".join(COLOUR_WORDS) + r")(?:[- ]\w+)?[- ](?:sign|logo|lettering|letters|canopy)",
                  hint.lower())
    return COLOUR_WORDS[m.group(1)] if m else None


def park_features(hint: str) -> set[str]:
    text = hint.lower()
    return {"lawn", "trees"} | {name for name, words in PARK_WORDS.items() if any(w in text for w in words)}


# Words by which a description makes a building low; one of unknown height is drawn this tall (two storeys)
# instead of as a tower block, so that "a tiny brick fort" is not drawn six storeys high.
LOW_WORDS = re.compile(r"\b(tiny|one-storey|single-storey|two-storey|low building|long,? low)\b")
LOW_HEIGHT_M = 8.0


def stated_low(f: Frontage) -> bool:
    return not f.height_m and bool(LOW_WORDS.search(f.hint.lower()))


def has_look(f: Frontage) -> bool:
    """Whether a place's front is drawn in its own look (a style, a named detail or a material)."""
    return bool(f.style or details_of(f.hint) or material_of(f.hint))


def is_alley(name: str) -> bool:
    """A small named street that is a place of its own (its street sign stands at its mouth)."""
    return bool(re.search(r"\b(alley|mews|lane)$", name.lower()))


def here_cues(scene: Scene) -> frozenset[str]:
    """The ids of what a view must draw for the places at its node that lie this way (scene.here), the
    picture's counterpart of the text's "Right here:" line: the place itself, close and facing the
    camera; a shop's sign; a park's lawns, trees and what its description adds; a building's material
    and the details its description names; a small street's own sign."""
    cues: set[str] = set()
    for f in scene.here:
        cues.add(f"here:{f.place_id}")
        if f.sign:
            cues.add(f"sign:{f.sign}")
        if f.kind in OPEN_SPACE_KINDS:
            cues |= {f"park:{f.place_id}:{x}" for x in park_features(f.hint)}
            continue
        cues.add(f"facade:{f.place_id}")
        cues |= {f"detail:{f.place_id}:{d}" for d in details_of(f.hint)}
        if material_of(f.hint):
            cues.add(f"material:{f.place_id}:{material_of(f.hint)}")
    return frozenset(cues)

# words match from their start: "pavilion" holds no lion and "street" no tree
_DETAIL_RES = {name: re.compile("|".join(r"\b" + re.escape(w) for w in words)) for name, words in DETAIL_WORDS.items()}


@functools.lru_cache(maxsize=4096)
def details_of(hint: str) -> frozenset[str]:
    """The details a description names (cached: every view of every place asks again)."""
    text = hint.lower()
    return frozenset(name for name, pattern in _DETAIL_RES.items() if pattern.search(text))


def text_cues(scene: Scene) -> frozenset[str]:
    """The ids of the visible things ``describe`` names (street_view.render_cues reports the ids it draws;
    a test checks these are a subset). Street names away from a corner's signs are map knowledge the
    text adds, not something a camera shows, so they have no id; the corner's signs do."""
    cues = {"road_ahead" if scene.road_ahead else "road_ends"}
    if scene.road_ahead:
        cues |= {f"opening:{o.side}:{round(o.distance_m)}" for o in scene.openings[:3]}
    elif scene.open_space:
        cues.add("open_space")
    here = {f.place_id for f in scene.here}  # drawn close up instead: here_cues names what they show
    for f in scene.frontages[:5]:
        if f.sign:
            cues.add(f"sign:{f.sign}")
        if has_look(f) and f.place_id not in here:
            cues.add(f"facade:{f.place_id}")
            cues |= {f"detail:{f.place_id}:{d}" for d in details_of(f.hint)}
    for item in sorted(scene.skyline, key=lambda s: s.distance_m)[:2]:
        cues.add(f"skyline:{item.place_id}")
    cues |= {f"street_sign:{name}" for name in scene.street_signs}
    return frozenset(cues) | here_cues(scene)
