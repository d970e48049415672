"""The street environment: an agent standing on a node of a city graph with a heading.

It observes the neighbours (absolute and relative heading, distance, street) and four views,
moves forward / left / right / back or to a named neighbour, and declares arrival with stop.
Observations never contain goal coordinates or goal-derived headings: the start heading is the
task's StreetStart.heading, and the agent is never told where the target is.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Literal

from ..environment import Environment, EnvError, Observation
from .geo import angle_diff, cardinal, haversine_m
from .render import render_png
from .scene import compute_scene, describe
from .world import CityGraph, World, WorldError, get_world

Direction = Literal["forward", "left", "right", "back"]
SECTORS: dict[str, tuple[float, float]] = {  # relative heading ranges (degrees, right positive)
    "forward": (-45.0, 45.0), "right": (45.0, 135.0), "back": (135.0, 225.0), "left": (-135.0, -45.0),
}
SECTOR_CENTRE = {"forward": 0.0, "right": 90.0, "back": 180.0, "left": -90.0}
RELATIVE_VIEWS = [("front", 0.0), ("right", 90.0), ("back", 180.0), ("left", 270.0)]
ABSOLUTE_VIEWS = [("north", 0.0), ("east", 90.0), ("south", 180.0), ("west", 270.0)]


def sector_of(rel: float) -> str:
    r = rel % 360.0
    if r <= 45.0 or r >= 315.0:
        return "forward"
    if r < 135.0:
        return "right"
    if r <= 225.0:
        return "back"
    return "left"


@lru_cache(maxsize=4096)
def view_png(city: str, node: int, heading: int) -> bytes:
    """The rendered view from a node of the process-wide world, cached (whole-degree headings)."""
    world = get_world()
    return render_png(compute_scene(world, world.city(city), node, float(heading), ""))


class StreetEnvironment(Environment):
    kind = "embodied"
    name = "street"

    def __init__(self, episode: Any, services: Any):
        self.episode = episode
        self.services = services
        self.world: World | None = None
        self.graph: CityGraph | None = None
        self.node = -1
        self.heading = 0.0
        self.stopped = False
        self.path: list[str] = []
        self.distance_walked_m = 0.0
        self.mode = "text"

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        start = task.start.embodied
        if start is None or getattr(start, "kind", None) != "street":
            raise EnvError(f"task {task.id} has no street start state; give start.embodied "
                           "{'kind': 'street', 'city': ..., 'node': ...}")
        self.world = await self.services.get("outdoor_world", lambda _s: get_world())
        try:
            self.graph = self.world.city(start.city)
            graph, index = self.world.locate(start.node)
        except WorldError as exc:
            raise EnvError(f"task {task.id}: {exc}") from None
        if graph is not self.graph:
            raise EnvError(f"task {task.id}: start node {start.node} is in {graph.city}, not in {start.city}; "
                           "fix start.embodied.city or start.embodied.node")
        self.node = index
        self.heading = float(start.heading) % 360.0
        self.stopped = False
        self.path = [start.node]
        self.distance_walked_m = 0.0
        self.mode = options.get("observation", "text")

    # ------------------------------------------------------------ observing
    def _neighbours(self) -> list[dict[str, Any]]:
        assert self.graph is not None
        out = []
        for j, length, s, h in sorted(self.graph.adj[self.node], key=lambda link: link[3]):
            rel = angle_diff(h, self.heading)
            out.append({"node": self.graph.ids[j], "heading": round(h, 1), "relative_heading": round(rel, 1),
                        "direction": sector_of(rel), "distance_m": round(length, 1), "street": self.graph.streets[s]})
        return out

    def views(self, frame: Literal["relative", "absolute"] = "relative") -> list[tuple[str, float]]:
        if frame == "absolute":
            return list(ABSOLUTE_VIEWS)
        return [(label, (self.heading + off) % 360.0) for label, off in RELATIVE_VIEWS]

    def observation(self, frame: Literal["relative", "absolute"] = "relative", note: str = "") -> Observation:
        assert self.world is not None and self.graph is not None
        g = self.graph
        neighbours = self._neighbours()
        streets = list(g.node_streets[self.node])
        where = " and ".join(streets) if streets else "a path"
        lines = [note] if note else []
        lines.append(f"You are on {where} in {g.name}, facing {cardinal(self.heading, 16)} ({round(self.heading)}°)."
                     + (" You have stopped here." if self.stopped else ""))
        lines.append("Neighbours (street_move direction or neighbour id):")
        for n in neighbours:
            lines.append(f"- {n['direction']}: {n['node']} along {n['street']}, heading {round(n['heading'])}° "
                         f"({n['relative_heading']:+.0f}° relative), {n['distance_m']:.0f} m")
        view_data = []
        images: list[bytes] = []
        for label, heading in self.views(frame):
            scene = compute_scene(self.world, g, self.node, heading, label)
            text = describe(scene)
            view_data.append({"view": label, "heading": round(heading, 1), "description": text})
            lines.append(text)
            if self.mode in ("vision", "both"):
                images.append(view_png(g.city, self.node, int(round(heading)) % 360))
        if images:
            lines.append("Images: " + ", ".join(v["view"] for v in view_data) + " views, in that order.")
        lines.append(f"Walked {len(self.path) - 1} moves, {self.distance_walked_m:.0f} m.")
        data = {
            "city": g.city,
            "node": g.ids[self.node],
            "streets": streets,
            "heading": round(self.heading, 1),
            "stopped": self.stopped,
            "neighbours": neighbours,
            "views": view_data,
            "moves": len(self.path) - 1,
            "distance_walked_m": round(self.distance_walked_m, 1),
        }
        return Observation(text="\n".join(lines), data=data, images=images)

    async def observe(self) -> Observation:
        return self.observation()

    # ------------------------------------------------------------ acting
    def _choices(self) -> str:
        nb = self._neighbours()
        directions = sorted({n["direction"] for n in nb}, key=list(SECTORS).index)
        return (f"valid directions here: {', '.join(directions) or 'none'}; "
                f"valid neighbour ids: {', '.join(n['node'] for n in nb) or 'none'}")

    def move(self, direction: str | None = None, neighbour: str | None = None) -> Observation:
        assert self.graph is not None
        if self.stopped:
            raise EnvError("you already stopped (street_stop); the walk is over and moves are refused. "
                           "Finish the episode with finish_episode, or switch to the web environment.")
        if (direction is None) == (neighbour is None):
            raise EnvError("give exactly one of direction (forward/left/right/back) or neighbour (a node id); "
                           + self._choices())
        links = self.graph.adj[self.node]
        if neighbour is not None:
            target = next((link for link in links if self.graph.ids[link[0]] == neighbour), None)
            if target is None:
                raise EnvError(f"{neighbour!r} is not a neighbour of this node; {self._choices()}")
        else:
            if direction not in SECTORS:
                raise EnvError(f"unknown direction {direction!r}; use forward, left, right or back. {self._choices()}")
            in_sector = [link for link in links if sector_of(angle_diff(link[3], self.heading)) == direction]
            if not in_sector:
                raise EnvError(f"there is no street to the {direction} here; {self._choices()}")
            centre = SECTOR_CENTRE[direction]
            target = min(in_sector, key=lambda link: abs(angle_diff(angle_diff(link[3], self.heading), centre)))
        j, length, s, h = target
        self.node = j
        self.heading = h
        self.path.append(self.graph.ids[j])
        self.distance_walked_m += length
        return self.observation(note=f"Moved {length:.0f} m along {self.graph.streets[s]}.")

    def stop(self) -> Observation:
        if self.stopped:
            raise EnvError("you already stopped here; the walk is over. Finish the episode with finish_episode.")
        self.stopped = True
        return self.observation(note="You declared that you have arrived; the walk is over.")

    async def final_state(self) -> dict[str, Any]:
        assert self.graph is not None
        start = self.graph.index[self.path[0]]
        return {
            "city": self.graph.city,
            "node": self.graph.ids[self.node],
            "lat": self.graph.lat[self.node],
            "lng": self.graph.lng[self.node],
            "heading": round(self.heading, 1),
            "stopped": self.stopped,
            "path": list(self.path),
            "distance_walked_m": round(self.distance_walked_m, 1),
            "straight_line_from_start_m": round(haversine_m(self.graph.lat[start], self.graph.lng[start],
                                                            self.graph.lat[self.node], self.graph.lng[self.node]), 1),
        }
