"""Generates the geolocation tasks: a baseline and an embodied variant per location.

``generate_tasks(out_dir)`` writes ``geolocation-baseline.json`` and
``geolocation-embodied.json`` (task lists) and returns how many tasks it wrote. Output is
deterministic: rerunning it over an unchanged location set reproduces the files byte for
byte (a test checks that the committed files are current).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

from ewa_mcp.core.taskmodel import StartState, Task, ToolCall
from ewa_mcp.envs.browser.goals import WebStart
from ewa_mcp.envs.geo.goals import GeoAnswer, GeoStart
from .. import gazetteer
from ..graph import START, build_graph
from ..hardness import task_difficulty
from ..locations import LOCATIONS_LIST, Location
from ..scene import compose_view, deciding_city_cues, street_sign_visible

SETTINGS = ("baseline", "embodied")
# Every call is a step (looks and wiki reading too), so the baseline has room to look once and read the wiki.
STEP_LIMITS = {"baseline": 10, "embodied": 40}
FILE_NAMES = {setting: f"geolocation-{setting}.json" for setting in SETTINGS}

INTENTS = {
    "baseline": (
        "Where in the world are you? You see a single north-facing street view and cannot move. Study it "
        "(geo_look) and call submit_location with your best estimate of the latitude and longitude and of the "
        "continent, country, city and street."
    ),
    "embodied": (
        "Where in the world are you? Look around (geo_look), walk to nearby standpoints (geo_move) and research "
        "what you see in the wiki (switch_environment to the web), then call submit_location with the latitude "
        "and longitude and the continent, country, city and street."
    ),
}


def _task_numbers() -> dict[str, int]:
    """Each location's task number: its rank in a seeded shuffle, never its place in the location list.
    The list runs continent by continent, so numbering by it made the id (which the agent sees, and the
    order of list_tasks) tell the continent (issue 26, principle 3). Ranking by a hash of the location id
    is a shuffle that reproduces byte for byte."""
    def key(loc: Location) -> bytes:
        return hashlib.sha256(f"geo-task-number|{loc.id}".encode()).digest()

    return {loc.id: rank for rank, loc in enumerate(sorted(LOCATIONS_LIST, key=key), start=1)}


TASK_NUMBERS = _task_numbers()


def task_id(loc: Location, setting: str) -> str:
    return f"geo-{TASK_NUMBERS[loc.id]:04d}-{setting}"


def baseline_levels(loc: Location) -> list[str]:
    """The levels a baseline task's one north view can decide, with no wiki to read: the continent and
    country always; the city where the view shows what names it (a landmark, or a deciding cue: an
    area-coded number, a regional plate); the street where it shows the street's sign. A hard location
    shows only shared cues, which name the city only against the wiki's articles, and a city-level location
    shows its city's cues only after a move: there the city could only be guessed."""
    start = build_graph(loc)[START]
    view = compose_view(loc, START, "north")
    levels = ["continent", "country"]
    if view.landmark is not None or deciding_city_cues(loc, view):
        levels.append("city")
    if street_sign_visible(loc, start, "north"):
        levels.append("street")
    return levels


def answer_for(loc: Location, setting: str = "embodied") -> GeoAnswer:
    """The location's answer; in the baseline setting success asks only for the levels its one view can
    decide (``baseline_levels``); every level is still graded and reported."""
    levels = baseline_levels(loc) if setting == "baseline" else None
    return GeoAnswer(
        graded_levels=None if levels is None or len(levels) == 4 else levels,
        lat=loc.lat,
        lng=loc.lng,
        continent=loc.continent or gazetteer.country_continent(loc.city.iso),
        country=loc.country.name,
        city=loc.city.name,
        street=loc.street,
    )


def difficulty_for(loc: Location, setting: str) -> str:
    """The embodied task's difficulty is the location's (hardness.py). A baseline task is easy where its view
    shows a landmark and medium otherwise: with one view and no wiki there is nothing to put together, so
    nothing is hard by composition (the cues a hard location needs combined are read against articles)."""
    if setting == "embodied":
        return task_difficulty(loc)
    return "easy" if loc.difficulty == "easy" else "medium"


def _oracle(loc: Location, setting: str, answer: GeoAnswer) -> list[ToolCall]:
    submit = ToolCall(tool="submit_location", args={
        "lat": answer.lat, "lng": answer.lng, "continent": answer.continent, "country": answer.country,
        "city": answer.city, "street": answer.street,
    })
    if setting == "baseline":
        return [ToolCall(tool="geo_look", args={"direction": "north"}), submit]
    # Walk one step along the street (p1 is always adjacent to the start, see graph.py).
    return [ToolCall(tool="geo_look", args={"direction": "all"}), ToolCall(tool="geo_move", args={"neighbour": "p1"}),
            submit]


def build_task(loc: Location, setting: str) -> Task:
    answer = answer_for(loc, setting)
    start = StartState(
        environment="embodied",
        web=WebStart(start_url="wiki:/") if setting == "embodied" else None,
        embodied=GeoStart(location_id=loc.id, setting=setting),
    )
    metadata: dict[str, Any] = {
        "setting": setting,
        "cue_level": loc.difficulty,  # which level the cue placement makes hard (locations.py)
        "location_id": loc.id,
        "country_code": loc.city.iso,
        "continent": answer.continent,
        "generator": "ewa_mcp.envs.geo.taskgen.geolocation",
    }
    return Task(
        id=task_id(loc, setting),
        domain="geolocation",
        difficulty=difficulty_for(loc, setting),
        intent=INTENTS[setting],
        start=start,
        answer=answer,
        step_limit=STEP_LIMITS[setting],
        oracle=_oracle(loc, setting, answer),
        metadata=metadata,
    )


def build_tasks(setting: str) -> list[Task]:
    """The setting's tasks in id order (the shuffled numbering), so the file's order tells nothing either."""
    return sorted((build_task(loc, setting) for loc in LOCATIONS_LIST), key=lambda t: t.id)


def generate_tasks(out_dir: Path) -> int:
    out_dir.mkdir(parents=True, exist_ok=True)
    count = 0
    for setting in SETTINGS:
        tasks = build_tasks(setting)
        payload = [t.model_dump(mode="json", exclude_defaults=False) for t in tasks]
        text = json.dumps(payload, ensure_ascii=False, indent=1) + "\n"
        (out_dir / FILE_NAMES[setting]).write_text(text, encoding="utf-8")
        count += len(tasks)
    return count


if __name__ == "__main__":  # python -m ewa_mcp.envs.geo.taskgen.geolocation [out_dir]
    import sys

    from ewa_mcp.core.paths import tasks_dir

    target = Path(sys.argv[1]) if len(sys.argv) > 1 else tasks_dir() / "geolocation"
    print(f"wrote {generate_tasks(target)} geolocation tasks to {target}")
