"""The geolocation world: standpoints with four directional views, moves between them.

Settings (paper §geolocation): ``baseline`` shows one north-facing view and allows no
moves; ``embodied`` shows all four views and allows moves to adjacent standpoints (the
task also gives a browser on the wiki). The task's ``start.embodied.setting`` chooses, and
the episode option ``geolocation_setting`` overrides it.

Observations never contain coordinates, place names or the location id: only what the
views show (images and/or descriptions) and the neighbour list.
"""

from __future__ import annotations

from typing import Any

from ewa_mcp.core.environment import EnvError, Environment, Observation
from ewa_mcp.geometry import DIRECTION_DEG, FOUR_DIRECTIONS, angle_diff, cardinal_word
from ewa_mcp.envs.geo.goals import GeoStart
from .describe import describe_view
from .graph import START, Neighbour, Standpoint, build_graph
from .locations import LOCATIONS, Location
from .view_images import render_png
from .scene import compose_view

RELATIVE_TURNS = {"forward": 0, "ahead": 0, "straight": 0, "right": 90, "back": 180, "backward": 180,
                  "backwards": 180, "behind": 180, "left": -90}
DIRECTION_ALIASES = {"n": "north", "e": "east", "s": "south", "w": "west"}
MATCH_TOLERANCE_DEG = 45.0


def _relative_word(turn: float) -> str:
    a = abs(turn)
    if a <= 22.5:
        return "ahead"
    if a >= 157.5:
        return "behind"
    side = "right" if turn > 0 else "left"
    if a < 67.5:
        return f"ahead-{side}"
    if a <= 112.5:
        return side
    return f"behind-{side}"


class GeoEnvironment(Environment):
    side = "embodied"
    name = "geo"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.loc: Location | None = None
        self.setting = "embodied"
        self.mode = "text"
        self.graph: dict[str, Standpoint] = {}
        self.current = START
        self.facing_deg = 0.0
        self.visited: list[str] = []
        self.views_seen: list[str] = []
        self.moves = 0

    # ------------------------------------------------------------------ lifecycle
    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        start = task.start.embodied
        if not isinstance(start, GeoStart):
            raise EnvError(f"task {task.id} does not start in the geolocation world (its embodied start is "
                           f"{getattr(start, 'kind', None)!r}); geolocation tasks need start.embodied.kind='geo'")
        loc = LOCATIONS.get(start.location_id)
        if loc is None:
            raise EnvError(f"task {task.id} names unknown geolocation location {start.location_id!r}; valid ids are "
                           f"g001..g{len(LOCATIONS):03d} (regenerate the task files)")
        self.loc = loc
        self.setting = options.get("geolocation_setting") or start.setting
        self.mode = options.get("observation", "text")
        self.graph = build_graph(loc)
        self.current = START
        self.facing_deg = 0.0
        self.visited = [START]
        self.views_seen = []
        self.moves = 0

    async def final_state(self) -> dict[str, Any]:
        return {
            "location_id": self.loc.id if self.loc else None,
            "setting": self.setting,
            "standpoint": self.current,
            "visited": self.visited,
            "moves": self.moves,
            "views_seen": self.views_seen,
            "observation_mode": self.mode,
        }

    # ------------------------------------------------------------------ observation
    @property
    def allowed_views(self) -> tuple[str, ...]:
        return ("north",) if self.setting == "baseline" else FOUR_DIRECTIONS

    def _neighbours(self) -> list[dict[str, Any]]:
        if self.setting == "baseline":
            return []
        out = []
        for n in self.graph[self.current].neighbours:
            turn = angle_diff(n.bearing, self.facing_deg)
            out.append({
                "id": n.id,
                "heading_deg": round(n.bearing, 1),
                "compass": cardinal_word(n.bearing),
                "relative_deg": round(turn, 1),
                "relative": _relative_word(turn),
                "distance_m": n.distance_m,
            })
        return out

    def _views(self, headings: tuple[str, ...]) -> Observation:
        assert self.loc is not None
        want_text = self.mode in ("text", "both")
        want_images = self.mode in ("vision", "both")
        views: list[dict[str, Any]] = []
        images: list[bytes] = []
        lines: list[str] = []
        for heading in headings:
            spec = compose_view(self.loc, self.current, heading)
            view: dict[str, Any] = {"heading": heading}
            if want_text:
                view["description"] = describe_view(spec)
                lines.append(f"View {heading}: {view['description']}")
            if want_images:
                view["image_index"] = len(images)
                images.append(render_png(spec))
                if not want_text:
                    lines.append(f"View {heading}: image {len(images)}.")
            views.append(view)
            self.views_seen.append(f"{self.current}:{heading}")
        neighbours = self._neighbours()
        where = "the start" if self.current == START else f"{self.graph[self.current].steps_from_start} step(s) " \
                                                             "from the start"
        head = (f"Standpoint {self.current} ({where}); facing {cardinal_word(self.facing_deg)}. "
                f"Setting: {self.setting}.")
        if neighbours:
            near = "; ".join(
                f"{n['id']}: {n['distance_m']:.0f} m {n['compass']} ({n['relative']}, {n['relative_deg']:+.0f}°)"
                for n in neighbours
            )
            tail = f"Neighbours: {near}. Move with geo_move(neighbour=<id>) or geo_move(direction=...)."
        elif self.setting == "baseline":
            tail = "Baseline setting: only the north-facing view, no moves. Submit with submit_location."
        else:
            tail = "No neighbours."
        text = "\n".join([head, *lines, tail])
        data = {
            "setting": self.setting,
            "standpoint": self.current,
            "facing": cardinal_word(self.facing_deg),
            "views": views,
            "neighbours": neighbours,
            "can_move": self.setting != "baseline",
            "allowed_views": list(self.allowed_views),
        }
        return Observation(text=text, data=data, images=images)

    async def observe(self) -> Observation:
        return self._views(self.allowed_views)

    # ------------------------------------------------------------------ actions
    async def look(self, direction: str) -> Observation:
        direction = DIRECTION_ALIASES.get(direction.strip().lower(), direction.strip().lower())
        if direction == "all":
            return self._views(self.allowed_views)
        if direction not in FOUR_DIRECTIONS:
            raise EnvError(f"unknown direction {direction!r}; use 'all' or one of {', '.join(FOUR_DIRECTIONS)}")
        if direction not in self.allowed_views:
            raise EnvError(f"the {self.setting} setting shows only the {', '.join(self.allowed_views)}-facing view; "
                           "call geo_look(direction='north') or submit_location")
        self.facing_deg = float(DIRECTION_DEG[direction])
        return self._views((direction,))

    def _resolve_target(self, direction: str | None, neighbour: str | None) -> Neighbour:
        neighbours = self.graph[self.current].neighbours
        listing = ", ".join(f"{n.id} ({cardinal_word(n.bearing)})" for n in neighbours)
        if (direction is None) == (neighbour is None):
            raise EnvError(f"give exactly one of direction (forward/back/left/right or north/east/south/west) or "
                           f"neighbour (one of {listing})")
        if neighbour is not None:
            key = neighbour.strip()
            for n in neighbours:
                if n.id == key:
                    return n
            if key in self.graph:
                raise EnvError(f"{key} is not adjacent to {self.current}; its neighbours are {listing}")
            raise EnvError(f"unknown neighbour {neighbour!r}; the neighbours of {self.current} are {listing}")
        word = DIRECTION_ALIASES.get(direction.strip().lower(), direction.strip().lower())  # type: ignore[union-attr]
        if word in DIRECTION_DEG:
            target = float(DIRECTION_DEG[word])
        elif word in RELATIVE_TURNS:
            target = (self.facing_deg + RELATIVE_TURNS[word]) % 360
        else:
            raise EnvError(f"unknown direction {direction!r}; use forward/back/left/right or north/east/south/west, "
                           f"or a neighbour id ({listing})")
        best = min(neighbours, key=lambda n: abs(angle_diff(n.bearing, target)))
        if abs(angle_diff(best.bearing, target)) > MATCH_TOLERANCE_DEG:
            raise EnvError(f"there is no neighbour {word} of {self.current} (within {MATCH_TOLERANCE_DEG:.0f}°); "
                           f"its neighbours are {listing}")
        return best

    async def move(self, direction: str | None = None, neighbour: str | None = None) -> Observation:
        if self.setting == "baseline":
            raise EnvError("moves are not allowed in the baseline setting; look north with geo_look and submit "
                           "with submit_location")
        target = self._resolve_target(direction, neighbour)  # raises before any state changes
        self.current = target.id
        self.facing_deg = target.bearing
        self.moves += 1
        self.visited.append(target.id)
        return self._views(self.allowed_views)
