"""How intents name places: as people write them, once, and in a form the map site finds."""

from __future__ import annotations

import json
import re

from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.envs.street.taskgen.navigation import corner_phrase


def test_a_corner_where_a_street_changes_from_east_to_west_is_said_once():
    assert corner_phrase("5th Avenue & East 44th Street & West 44th Street") == "5th Avenue and 44th Street"
    assert corner_phrase("Market Street & North 21st Street & South 21st Street") == "Market Street and 21st Street"
    assert corner_phrase("Milk Street & School Street & Washington Street") == (
        "Milk Street and School Street and Washington Street")
    assert corner_phrase("South 7th Street & South Street") == "South 7th Street and South Street"
    assert corner_phrase("East 34th Street & West 34th Street") == "East 34th Street and West 34th Street"


def test_no_intent_names_a_place_twice_or_a_street_by_both_its_halves():
    doubled, halves = [], []
    for path in sorted(tasks_dir().glob("*/*.json")):
        for task in json.loads(path.read_text(encoding="utf-8")):
            intent = task["intent"]
            if re.search(r"\(([^()]+) \(\1", intent) or re.search(r"([A-Z][\w .']+) \(\1 \(", intent):
                doubled.append(task["id"])
            if re.search(r"East (\d+\w\w \w+) and West \1", intent):
                halves.append(task["id"])
    assert not doubled and not halves, (doubled[:5], halves[:5])


def test_the_map_finds_every_corner_as_an_intent_says_it():
    from ewa_mcp.websites.map.places import WorldAdapter

    adapter = WorldAdapter()
    for phrase in ("5th Avenue and 44th Street", "Market Street and 21st Street"):
        assert adapter.resolve(phrase).place is not None, phrase
