"""The street environment: an agent standing on a node of a city graph with a heading.

It observes the neighbours (absolute and relative heading, distance, street, and a direction label
that is unique at this node) and four views, moves by a direction label or to a named neighbour,
and ends the walk with stop. The walk ends at the first stop, or else when the episode finishes;
where it ended is what is graded. Observations never contain goal coordinates or goal-derived
headings: the start heading is the task's StreetStart.heading, and the agent is never told where
the target is.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, Literal, TypedDict

from ewa_mcp.core.environment import Environment, EnvError, Observation
from ewa_mcp.geometry import angle_diff, cardinal, haversine_m
from .street_view import render_png
from .scene import compute_scene, describe, places_here
from .world import CityGraph, World, WorldError, get_world

Direction = Literal["forward", "forward-right", "right", "back-right", "back", "back-left", "left", "forward-left"]
SECTORS: dict[str, tuple[float, float]] = {  # relative heading ranges (degrees, right positive)
    "forward": (-45.0, 45.0), "right": (45.0, 135.0), "back": (135.0, 225.0), "left": (-135.0, -45.0),
}
# The eight direction labels, clockwise from straight ahead, 45 degrees apart. At every node each
# neighbour gets its own label (see direction_labels), so a label never names two streets.
LABELS = ["forward", "forward-right", "right", "back-right", "back", "back-left", "left", "forward-left"]
RELATIVE_VIEWS = [("front", 0.0), ("right", 90.0), ("back", 180.0), ("left", 270.0)]
ABSOLUTE_VIEWS = [("north", 0.0), ("east", 90.0), ("south", 180.0), ("west", 270.0)]


class ViewData(TypedDict):
    """One view of an observation's ``data["views"]``."""

    view: str  # front/right/back/left or north/east/south/west
    heading: float  # compass bearing, rounded to 0.1 degree
    description: str


def sector_of(rel: float) -> str:
    r = rel % 360.0
    if r <= 45.0 or r >= 315.0:
        return "forward"
    if r < 135.0:
        return "right"
    if r <= 225.0:
        return "back"
    return "left"


def direction_labels(relative_headings: list[float]) -> list[str | None]:
    """One distinct label of LABELS per neighbour (None when more than eight), keeping their clockwise
    order and staying as close as possible to each neighbour's relative heading.

    Two streets leaving within the same 90-degree sector (a diagonal avenue crossing a grid) get two
    labels, e.g. forward and forward-left, instead of both being "forward"."""
    n = len(relative_headings)
    if n == 0:
        return []
    if n > len(LABELS):
        return [None] * n
    order = sorted(range(n), key=lambda k: relative_headings[k] % 360.0)
    angles = [relative_headings[k] % 360.0 for k in order]

    def cost(angle: float, slot: int) -> float:
        return angle_diff(angle, (slot % 8) * 45.0) ** 2

    best: tuple[float, list[int]] | None = None
    for first in range(8):  # the slot of the first neighbour clockwise from straight ahead
        # table[i][j]: least cost placing neighbours 0..i with neighbour i on slot first + j
        table = [[float("inf")] * 8 for _ in range(n)]
        back = [[-1] * 8 for _ in range(n)]
        table[0][0] = cost(angles[0], first)
        for i in range(1, n):
            for j in range(i, 8):
                prev = min(range(i - 1, j), key=lambda q: table[i - 1][q])
                if table[i - 1][prev] < float("inf"):
                    table[i][j] = table[i - 1][prev] + cost(angles[i], first + j)
                    back[i][j] = prev
        j = min(range(8), key=lambda q: table[n - 1][q])
        if table[n - 1][j] == float("inf"):
            continue
        slots = [0] * n
        for i in range(n - 1, -1, -1):
            slots[i] = first + j
            j = back[i][j]
        total = table[n - 1][slots[-1] - first]
        if best is None or total < best[0] - 1e-9:
            best = (total, slots)
    assert best is not None
    labels: list[str | None] = [None] * n
    for pos, k in enumerate(order):
        labels[k] = LABELS[best[1][pos] % 8]
    return labels


@lru_cache(maxsize=4096)
def view_png(city: str, node: int, heading: int) -> bytes:
    """The rendered view from a node of the process-wide world, cached (whole-degree headings)."""
    world = get_world()
    return render_png(compute_scene(world, world.city(city), node, float(heading), ""))


def neighbour_lines(neighbours: list[dict[str, Any]], *, named: bool) -> list[str]:
    """The neighbour list of an observation: with each street's name (text), or without (vision: the signs in the
    images name the streets)."""
    rule = "each direction names one street" if named else "each direction leads along one street"
    lines = [f"Neighbours (street_move direction or neighbour id; {rule}):"]
    for n in neighbours:
        label = n["direction"] or "(by id only)"
        along = f" along {n['street']}" if named else ""
        lines.append(f"- {label}: {n['node']}{along}, heading {round(n['heading'])}° "
                     f"({n['relative_heading']:+.0f}° relative), {n['distance_m']:.0f} m")
    return lines


class StreetEnvironment(Environment):
    side = "embodied"
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
        links = sorted(self.graph.adj[self.node], key=lambda link: link[3])
        rels = [angle_diff(h, self.heading) for _, _, _, h in links]
        labels = direction_labels(rels)
        out = []
        for (j, length, s, h), rel, label in zip(links, rels, labels):
            out.append({"node": self.graph.ids[j], "heading": round(h, 1), "relative_heading": round(rel, 1),
                        "direction": label, "distance_m": round(length, 1), "street": self.graph.streets[s]})
        return out

    def where(self) -> str:
        """The agent's spot in words: the streets at the node (a corner reads "A and B")."""
        assert self.graph is not None
        streets = list(self.graph.node_streets[self.node])
        return f"the corner of {' and '.join(streets)}" if len(streets) > 1 else (streets[0] if streets else "a path")

    def views(self, frame: Literal["relative", "absolute"] = "relative") -> list[tuple[str, float]]:
        if frame == "absolute":
            return list(ABSOLUTE_VIEWS)
        return [(label, (self.heading + off) % 360.0) for label, off in RELATIVE_VIEWS]

    @property
    def vision_only(self) -> bool:
        """Observation "vision": the images, plus only what a camera cannot give and the action space needs
        (the neighbour list with headings and distances). No street names, place text or view descriptions."""
        return self.mode == "vision"

    def observation(self, frame: Literal["relative", "absolute"] = "relative", note: str = "") -> Observation:
        if self.vision_only:
            return self._vision_observation(frame, note)
        assert self.world is not None and self.graph is not None
        g = self.graph
        neighbours = self._neighbours()
        streets = list(g.node_streets[self.node])
        where = " and ".join(streets) if streets else "a path"
        lines = [note] if note else []
        lines.append(f"You are on {where} in {g.name}, facing {cardinal(self.heading, 16)} ({round(self.heading)}°).")
        if self.stopped:
            lines.append(self.stopped_sentence())
        lines += neighbour_lines(neighbours, named=True)
        here = places_here(self.world, g, self.node, self.heading)
        if here:
            # one place per line: "Right here: on your left, …" / "Also here: on your right, …"
            lines += [("Right here: " if i == 0 else "Also here: ") + item for i, item in enumerate(here)]
        view_data: list[ViewData] = []
        images: list[bytes] = []
        for label, heading in self.views(frame):
            scene = compute_scene(self.world, g, self.node, heading, label)
            text = describe(scene)
            view_data.append({"view": label, "heading": round(heading, 1), "description": text})
            lines.append(text)
            if self.mode == "both":
                images.append(view_png(g.city, self.node, int(round(heading)) % 360))
        if images:
            lines.append("Images: " + ", ".join(v["view"] for v in view_data) + " views, in that order.")
        lines.append(f"Walked {len(self.path) - 1} moves, {self.distance_walked_m:.0f} m.")
        data = {"city": g.city, "streets": streets, **self._walk_data(neighbours, view_data)}
        return Observation(text="\n".join(lines), data=data, images=images)

    def _walk_data(self, neighbours: list[dict[str, Any]],
                   views: list[ViewData] | list[dict[str, Any]]) -> dict[str, Any]:
        """What every observation's data holds, text or vision (text adds the city and the street names)."""
        assert self.graph is not None
        return {
            "node": self.graph.ids[self.node],
            "heading": round(self.heading, 1),
            "stopped": self.stopped,
            "walk_stopped": self.stopped,
            "neighbours": neighbours,
            "views": views,
            "moves": len(self.path) - 1,
            "distance_walked_m": round(self.distance_walked_m, 1),
        }

    def _vision_observation(self, frame: Literal["relative", "absolute"], note: str) -> Observation:
        assert self.graph is not None
        g = self.graph
        neighbours = [{k: v for k, v in n.items() if k != "street"} for n in self._neighbours()]
        lines = [note] if note else []
        lines.append(f"You are facing {cardinal(self.heading, 16)} ({round(self.heading)}°).")
        if self.stopped:
            lines.append(self.stopped_sentence())
        lines += neighbour_lines(neighbours, named=False)
        view_data: list[dict[str, Any]] = []
        images: list[bytes] = []
        for label, heading in self.views(frame):
            view_data.append({"view": label, "heading": round(heading, 1), "image_index": len(images)})
            images.append(view_png(g.city, self.node, int(round(heading)) % 360))
        lines.append("Images: " + ", ".join(f"{v['view']} ({round(v['heading'])}°)" for v in view_data)
                     + " views, in that order; a compass strip along each image's bottom edge shows its bearing.")
        lines.append(f"Walked {len(self.path) - 1} moves, {self.distance_walked_m:.0f} m.")
        return Observation(text="\n".join(lines), data=self._walk_data(neighbours, view_data), images=images)

    async def observe(self) -> Observation:
        return self.observation()

    # ------------------------------------------------------------ acting
    def stopped_sentence(self) -> str:
        where = "here" if self.vision_only else f"at {self.where()}"
        return f"Walk stopped {where}; call finish_episode to end the episode."

    def _street(self, n: dict[str, Any]) -> str:
        """A neighbour's street for messages: in vision-only mode its direction and id, never its name."""
        return f"{n['relative_heading']:+.0f}°" if self.vision_only else n["street"]

    def _choices(self) -> str:
        nb = self._neighbours()
        labelled = [f"{n['direction']} ({self._street(n)}, {n['node']})" for n in nb if n["direction"]]
        return (f"valid directions here: {', '.join(labelled) or 'none'}; "
                f"valid neighbour ids: {', '.join(n['node'] for n in nb) or 'none'}")

    def _refuse_after_stop(self) -> None:
        if self.stopped:
            where = "" if self.vision_only else f" at {self.where()}"
            raise EnvError(f"the walk is over: it stopped{where} (street_stop), and moves are refused. "
                           "Call finish_episode to end the episode.")

    def _pick(self, direction: str) -> tuple[int, float, int, float]:
        """The one neighbour a direction names: its label here, else the only street in that quarter
        (forward = within 45 degrees of the heading). Several candidates are refused, never guessed."""
        assert self.graph is not None
        nb = self._neighbours()
        links = {self.graph.ids[link[0]]: link for link in self.graph.adj[self.node]}
        exact = [n for n in nb if n["direction"] == direction]
        if len(exact) == 1:
            return links[exact[0]["node"]]
        if direction not in SECTORS:
            raise EnvError(f"there is no street to the {direction} here; {self._choices()}")
        in_sector = [n for n in nb if sector_of(n["relative_heading"]) == direction]
        if not in_sector:
            raise EnvError(f"there is no street to the {direction} here; {self._choices()}")
        if len(in_sector) > 1:
            options = "; ".join(f"direction={n['direction']!r} or neighbour={n['node']!r} ("
                                + ("" if self.vision_only else f"{n['street']}, ")
                                + f"{n['relative_heading']:+.0f}°)" for n in in_sector)
            raise EnvError(f"{direction!r} is ambiguous here: {len(in_sector)} streets lead that way. Choose one: "
                           f"{options}")
        return links[in_sector[0]["node"]]

    def move(self, direction: str | None = None, neighbour: str | None = None) -> Observation:
        assert self.graph is not None
        self._refuse_after_stop()
        if (direction is None) == (neighbour is None):
            raise EnvError("give exactly one of direction (forward, forward-right, right, ... as listed) or "
                           "neighbour (a node id); " + self._choices())
        links = self.graph.adj[self.node]
        if neighbour is not None:
            target = next((link for link in links if self.graph.ids[link[0]] == neighbour), None)
            if target is None:
                raise EnvError(f"{str(neighbour)[:80]!r} is not a neighbour of this node; {self._choices()}")
        else:
            if direction not in LABELS:
                raise EnvError(f"unknown direction {str(direction)[:80]!r}; use one of {', '.join(LABELS)}. "
                               + self._choices())
            target = self._pick(direction)
        j, length, s, h = target
        self.node = j
        self.heading = h
        self.path.append(self.graph.ids[j])
        self.distance_walked_m += length
        along = "" if self.vision_only else f" along {self.graph.streets[s]}"
        return self.observation(note=f"Moved {length:.0f} m{along}.")

    def stop(self) -> Observation:
        self._refuse_after_stop()
        self.stopped = True
        return self.observation(note="You ended the walk here (street_stop).")

    def status(self) -> dict[str, Any]:
        return {"walk_stopped": bool(self.stopped)}

    async def final_state(self) -> dict[str, Any]:
        assert self.graph is not None
        start = self.graph.index[self.path[0]]
        g = self.graph
        return {
            "city": g.city,
            "node": g.ids[self.node],
            "lat": g.lat[self.node],
            "lng": g.lng[self.node],
            "heading": round(self.heading, 1),
            "stopped": self.stopped,
            # The walk ends at the first street_stop, or else when the episode finishes (moves after a
            # stop are refused, so the two positions agree); graders read walk_end.
            "walk_stopped": self.stopped,
            "walk_end": {"node": g.ids[self.node], "lat": g.lat[self.node], "lng": g.lng[self.node],
                         "by": "street_stop" if self.stopped else "episode_end"},
            "path": list(self.path),
            "path_points": [[g.lat[g.index[n]], g.lng[g.index[n]]] for n in self.path],
            "distance_walked_m": round(self.distance_walked_m, 1),
            "straight_line_from_start_m": round(haversine_m(g.lat[start], g.lng[start],
                                                            g.lat[self.node], g.lng[self.node]), 1),
        }
