"""The map site's view of the outdoor world: resolve free text to a place, route, and draw streets.

``ewa_mcp.envs.street.world`` owns the street graphs, places and routing; this module only adapts
them for pages (an origin typed as text, a node id or a place id all become one ``Place``) and
caches the per-city street segments the SVG map draws.
"""

from __future__ import annotations

import re

import threading
from dataclasses import dataclass, field
from typing import Any

from .svgmap import LatLng, Segment

# Kinds whose search hit comes from parsing the query ("350 5th Ave", "5th Ave & W 34th St"),
# not from name similarity: one such hit is what the user meant.
STRUCTURED_KINDS = {"address", "intersection"}


@dataclass
class Resolution:
    place: Any = None  # ewa_mcp.envs.street.world.Place
    choices: list[Any] = field(default_factory=list)  # several plausible places: the user picks
    error: str = ""


_NAME_AND_ADDRESS = re.compile(r"\s*([^()]+?)\s*\(([^()]+)\)\s*")


def _load_world() -> Any:
    from ewa_mcp.envs.street.world import get_world  # imported late: the street graphs load on first use

    return get_world()


class WorldAdapter:
    def __init__(self, world: Any = None):
        self._world = world
        self._lock = threading.Lock()
        self._segments: dict[str, list[Segment]] = {}

    @property
    def world(self) -> Any:
        if self._world is None:
            with self._lock:
                if self._world is None:
                    self._world = _load_world()
        return self._world

    # ------------------------------------------------------------ cities and places
    def cities(self) -> list[str]:
        return list(self.world.cities)

    def city_name(self, city: str) -> str:
        return self.world.city(city).name

    def place(self, place_or_node_id: str) -> Any | None:
        """A place by place id or node id (a node reads as its intersection); None if unknown."""
        return self.world.place(place_or_node_id)

    def search(self, query: str, city: str | None, limit: int) -> list[Any]:
        return list(self.world.search(query, city=city, limit=limit))

    def resolve(self, text: str, city: str | None = None) -> Resolution:
        """Text -> one place: an exact place or node id, else the search's single clear match (in ``city``
        if given)."""
        place = self.place(text)
        if place is not None:
            return Resolution(place)
        results = self.search(text, city, 8)
        named = _NAME_AND_ADDRESS.fullmatch(text)
        if not results and named:
            # "Pennsylvania Station (New York City)", the way the wiki titles a place: the bracket names the
            # city to look in.
            hinted = {alias: key for key in self.cities() for alias in self._city_aliases(key)}
            if city is None and named.group(2).casefold() in hinted:
                found = self.resolve(named.group(1), hinted[named.group(2).casefold()])
                if found.place is not None or found.choices:
                    return found
            # "Old South Church (645 Boylston St)", the way task intents and place pages write a place: the name,
            # else the address in brackets, names it.
            by_name = self.resolve(named.group(1), city)
            at = [c for c in by_name.choices if c.address.casefold() == named.group(2).strip().casefold()]
            if len(at) == 1:  # "Point State Park (601 Commonwealth Pl)": of the places the name offers, the one there
                return Resolution(at[0])
            if by_name.place is not None:
                return by_name
            found = self.resolve(named.group(2), city)
            if found.place is not None:
                return found
        if not results:
            # "6th Ave between W 40th St & W 42nd St", "Broadway & 6th Ave at W 35th St": an address written the
            # way a place's own page writes it (a block or a corner with a cross street), which the street search
            # does not parse; the place that has it, when one does.
            owners = self.world.listed_at(text, city)
            if len(owners) == 1:
                return Resolution(owners[0])
        if not results and city is None:
            # "400 5th Ave, Pittsburgh" (or "..., Pittsburgh, PA"), the way the search lists a place and people
            # write one: the address in that city.
            parts = [part.strip() for part in text.split(",")]
            names = {alias: key for key in self.cities() for alias in self._city_aliases(key)}
            for i in range(len(parts) - 1, 0, -1):
                if parts[i].casefold() in names and all(parts[:i]):
                    found = self.resolve(", ".join(parts[:i]), names[parts[i].casefold()])
                    if found.place is not None or found.choices:
                        return found
        if not results:
            return Resolution(error=f"no place matches {text!r}. Try a place name, a street address such as "
                                    f"'350 5th Ave', or an intersection such as '5th Ave & W 34th St'.")
        exact = [p for p in results if p.name.casefold() == text.strip().casefold()]
        structured = [p for p in results if p.kind in STRUCTURED_KINDS]
        if len(exact) == 1 and exact[0].kind not in STRUCTURED_KINDS and not exact[0].id.startswith("address:"):
            # "Point State Park" names the park and is the Fort Pitt Block House's address (a building in the
            # park): both are offered, so the wiki's address of the one inside still finds it.
            inside = [p for p in self.world.listed_at(text, city) if p.id != exact[0].id and p not in results]
            if inside:
                return Resolution(choices=[exact[0], *inside])
        for candidates in (results, exact, structured):
            if len(candidates) == 1:
                return Resolution(candidates[0])
            same_spot = [p for p in candidates if p.name.casefold() == candidates[0].name.casefold()
                         and p.node == candidates[0].node]
            if candidates and len(same_spot) == len(candidates):
                # one spot under one name (a place whose name is its own address, and that address's
                # anonymous twin): the same answer either way; the place itself is the one to report
                return Resolution(next((p for p in candidates if not p.id.startswith("address:")), candidates[0]))
        return Resolution(choices=results)

    def _city_aliases(self, city: str) -> set[str]:
        """How people write a city after an address: its key, its name, the name before a comma or bracket
        ("Boston (Back Bay and Downtown)" -> boston), and New York's usual names for Manhattan."""
        name = self.city_name(city).casefold()
        aliases = {city.casefold(), name, re.split(r"[(,]", name)[0].strip()}
        if city == "manhattan":
            aliases |= {"new york", "new york city", "nyc", "ny"}
        return aliases

    # ------------------------------------------------------------ routing and drawing
    def directions(self, origin: Any, destination: Any, via: Any = None) -> Any:
        if via is not None:
            from ewa_mcp.envs.street.world import directions_via

            return directions_via(self.world, origin.id, via.id, destination.id)
        return self.world.directions(origin.id, destination.id)

    def route_coordinates(self, route: Any) -> list[LatLng]:
        graph = self.world.graph(route.city)
        return [(graph.nodes[n]["lat"], graph.nodes[n]["lng"]) for n in route.nodes]

    def segments(self, city: str) -> list[Segment]:
        """Every street segment of the city, cached (the graphs are static)."""
        if city not in self._segments:
            graph = self.world.graph(city)
            pos = {n: (d["lat"], d["lng"]) for n, d in graph.nodes(data=True)}
            segs = [Segment(pos[a], pos[b], data.get("street", "")) for a, b, data in graph.edges(data=True)]
            with self._lock:
                self._segments[city] = segs
        return self._segments[city]
