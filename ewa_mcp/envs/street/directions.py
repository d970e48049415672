"""Turn-by-turn walking directions along a path of the street graph, in the words a map gives
(depart, continue, slight/turn/sharp left/right, U-turn, arrive on your left/right), agreeing step by
step with the embodied street walk."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from ewa_mcp.geometry import angle_diff, cardinal_word

if TYPE_CHECKING:
    from .graph import CityGraph, Place


@dataclass
class DirectionStep:
    maneuver: str  # depart, continue, slight/turn/sharp left/right, u-turn (walking back), waypoint, arrive
    street: str
    distance_m: float
    instruction: str
    start_node: str = ""
    end_node: str = ""
    heading: float = 0.0  # compass bearing when starting this step


@dataclass
class Directions:
    city: str
    origin: str
    destination: str
    nodes: list[str]
    distance_m: float
    duration_s: float
    steps: list[DirectionStep]


@dataclass
class _Segment:
    """A run of consecutive edges on one street, walked without reversing."""

    street: int  # index into CityGraph.streets
    length: float
    start: int  # node index
    end: int
    heading: float  # compass bearing of the first edge
    last_heading: float  # compass bearing of the last edge
    reverses: bool  # starts by walking straight back along the edge just walked


def _maneuver(turn: float, reverses: bool = False) -> str:
    """The instruction for a change of heading. A U-turn is only ever walking back the way one came;
    a street leaving at a very sharp angle (a diagonal crossing a grid) is a sharp turn."""
    if reverses:
        return "u-turn"
    a = abs(turn)
    if a < 25:
        return "continue"
    side = "right" if turn > 0 else "left"
    if a < 60:
        return f"slight {side}"
    if a <= 135:
        return f"turn {side}"
    return f"sharp {side}"


def _round_m(d: float) -> int:
    return int(round(d / 10.0) * 10) if d >= 15 else int(round(d))


def walking_steps(g: CityGraph, path: list[int], dest: Place | None) -> list[DirectionStep]:
    if len(path) == 1:
        name = dest.name if dest else "your destination"
        return [DirectionStep("arrive", g.node_streets[path[0]][0] if g.node_streets[path[0]] else "",
                              0.0, f"You are already at {name}.", g.ids[path[0]], g.ids[path[0]], 0.0)]
    segments: list[_Segment] = []
    for k, (a, b) in enumerate(zip(path, path[1:])):
        length, s, h = g.edge(a, b)
        reverses = k > 0 and path[k - 1] == b  # walking straight back along the edge just walked
        if segments and segments[-1].street == s and not reverses:
            seg = segments[-1]
            seg.length += length
            seg.end = b
            seg.last_heading = h
        else:
            segments.append(_Segment(street=s, length=length, start=a, end=b, heading=h, last_heading=h,
                                     reverses=reverses))
    steps: list[DirectionStep] = []
    prev_heading: float | None = None  # None only before the first segment
    for seg in segments:
        street = g.streets[seg.street]
        dist = round(seg.length, 1)
        if prev_heading is None:
            maneuver = "depart"
            text = f"Head {cardinal_word(seg.heading)} on {street} for {_round_m(dist)} m."
        else:
            maneuver = _maneuver(angle_diff(seg.heading, prev_heading), seg.reverses)
            if maneuver == "continue":
                text = f"Continue onto {street} for {_round_m(dist)} m."
            elif maneuver == "u-turn":
                text = f"Make a U-turn and walk back along {street} for {_round_m(dist)} m."
            elif maneuver.startswith("sharp"):
                text = f"Turn {maneuver} onto {street} and walk {_round_m(dist)} m."
            else:
                text = f"{maneuver.capitalize()} onto {street} and walk {_round_m(dist)} m."
        steps.append(DirectionStep(maneuver, street, dist, text, g.ids[seg.start], g.ids[seg.end],
                                   round(seg.heading, 1)))
        prev_heading = seg.last_heading
    end = path[-1]
    where = dest.name if dest else "your destination"
    side = ""
    if dest is not None and dest.heading_from_node is not None and dest.offset_m > 5 and prev_heading is not None:
        rel = angle_diff(dest.heading_from_node, prev_heading)
        side = " on your right" if rel > 20 else " on your left" if rel < -20 else " ahead"
    steps.append(DirectionStep("arrive", g.streets[segments[-1].street], 0.0, f"Arrive at {where}{side}.",
                               g.ids[end], g.ids[end], round(prev_heading or 0.0, 1)))
    return steps
