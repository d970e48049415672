"""Boston: the Back Bay grid (Beacon to Boylston Street, Arlington Street to Massachusetts Avenue)
and the downtown core between the Common, Government Center and South Station.

Method: the Back Bay is a regular grid fitted by least squares on three station positions and a
Public Garden corner (FIT_POINTS). Downtown Boston has no grid; its junctions are hand-placed
from published coordinates of the landmarks and stations that stand on them (JUNCTIONS) and are
the least precise part of the outdoor world (about 50 m).
"""

from __future__ import annotations

from .base import CitySpec, FitPoint, FittedGrid, Way

COLUMNS = ["Arlington Street", "Berkeley Street", "Clarendon Street", "Dartmouth Street", "Exeter Street",
           "Fairfield Street", "Gloucester Street", "Hereford Street", "Massachusetts Avenue"]
ROWS = {"Beacon Street": 0.0, "Marlborough Street": 0.9, "Commonwealth Avenue": 2.0, "Newbury Street": 3.0,
        "Boylston Street": 4.0}

FIT_POINTS = [
    FitPoint("Arlington St & Boylston St", (0.0, 4.0), 42.35190, -71.07090, "Arlington station coordinates"),
    FitPoint("Boylston St at Copley Square", (3.4, 4.0), 42.34997, -71.07745, "Copley station coordinates"),
    FitPoint("Massachusetts Ave near Newbury St", (8.0, 3.5), 42.34789, -71.08790, "Hynes Convention Center station"),
    FitPoint("Arlington St & Beacon St", (0.0, 0.0), 42.35600, -71.07240, "Public Garden north-west corner"),
]

JUNCTIONS = {
    "charles_beacon": (42.35597, -71.07034),
    "joy_beacon": (42.35720, -71.06450),
    "park_beacon": (42.35775, -71.06300),
    "charles_boylston": (42.35232, -71.06855),
    "tremont_boylston": (42.35302, -71.06459),
    "washington_boylston": (42.35240, -71.06302),
    "tremont_park_winter": (42.35635, -71.06225),
    "tremont_school_beacon": (42.35785, -71.06055),
    "tremont_court": (42.35955, -71.05925),
    "washington_winter_summer": (42.35552, -71.06024),
    "washington_school_milk": (42.35735, -71.05895),
    "washington_state_court": (42.35866, -71.05797),
    "state_congress": (42.35879, -71.05680),
    "state_india": (42.35915, -71.05385),
    "state_atlantic": (42.35945, -71.05265),
    "milk_devonshire": (42.35712, -71.05755),
    "milk_congress": (42.35685, -71.05610),
    "milk_india": (42.35730, -71.05380),
    "congress_franklin": (42.35540, -71.05560),
    "congress_north": (42.36040, -71.05770),
    "summer_chauncy": (42.35480, -71.05880),
    "summer_federal": (42.35380, -71.05720),
    "summer_atlantic": (42.35262, -71.05585),
    "atlantic_rowes": (42.35640, -71.05100),
}

DOWNTOWN_WAYS = [
    ("Beacon Street", ["charles_beacon", "joy_beacon", "park_beacon", "tremont_school_beacon"]),
    ("Charles Street", ["charles_beacon", "charles_boylston"]),
    ("Boylston Street", ["charles_boylston", "tremont_boylston", "washington_boylston"]),
    ("Park Street", ["park_beacon", "tremont_park_winter"]),
    ("Tremont Street", ["tremont_boylston", "tremont_park_winter", "tremont_school_beacon", "tremont_court"]),
    ("Winter Street", ["tremont_park_winter", "washington_winter_summer"]),
    ("School Street", ["tremont_school_beacon", "washington_school_milk"]),
    ("Court Street", ["tremont_court", "washington_state_court"]),
    ("Washington Street", ["washington_boylston", "washington_winter_summer", "washington_school_milk",
                           "washington_state_court"]),
    ("State Street", ["washington_state_court", "state_congress", "state_india", "state_atlantic"]),
    ("Milk Street", ["washington_school_milk", "milk_devonshire", "milk_congress", "milk_india"]),
    ("Congress Street", ["congress_north", "state_congress", "milk_congress", "congress_franklin", "summer_federal"]),
    ("Summer Street", ["washington_winter_summer", "summer_chauncy", "summer_federal", "summer_atlantic"]),
    ("Atlantic Avenue", ["summer_atlantic", "atlantic_rowes", "state_atlantic"]),
]


def build() -> CitySpec:
    grid = FittedGrid((42.3520, -71.0700), FIT_POINTS)
    ways: list[Way] = []
    for name, y in ROWS.items():
        ways.append(Way(name, [grid.latlng(8.0, y), grid.latlng(0.0, y)]))
    for i, name in enumerate(COLUMNS):
        ways.append(Way(name, [grid.latlng(float(i), 0.0), grid.latlng(float(i), 4.0)]))
    # The grid's Beacon and Boylston Streets continue east along the Public Garden and Common.
    ways.append(Way("Beacon Street", [grid.latlng(0.0, 0.0), JUNCTIONS["charles_beacon"]]))
    ways.append(Way("Boylston Street", [grid.latlng(0.0, 4.0), JUNCTIONS["charles_boylston"]]))
    for name, keys in DOWNTOWN_WAYS:
        ways.append(Way(name, [JUNCTIONS[k] for k in keys]))
    aliases = {"Mass Ave": "Massachusetts Avenue", "Comm Ave": "Commonwealth Avenue"}
    fit = grid.report("Back Bay: affine grid fit on stations; downtown: hand-placed junctions")
    fit["hand_placed_junctions"] = len(JUNCTIONS)
    return CitySpec("boston", "Boston (Back Bay and Downtown)", "bo", ways, aliases, fit)
