"""Philadelphia, Center City: Front Street to 23rd Street, Spring Garden Street to South Street.

Method: William Penn's grid in index coordinates (x: the numbered street, Front = 1, Broad = 14;
y: blocks north of Market Street, negative to the south, with measured fractional positions for
the half-blocks). An affine transform is fitted on the centres of four of Penn's squares and a
station at 2nd & Market whose grid positions are known by construction (FIT_POINTS). The
Benjamin Franklin Parkway is a diagonal from City Hall through Logan Circle.
"""

from __future__ import annotations

from .base import CitySpec, FitPoint, FittedGrid, Way, polyline

EAST_WEST = {  # name -> y (blocks north of Market)
    "Spring Garden Street": 5.3, "Callowhill Street": 4.0, "Vine Street": 3.0, "Race Street": 2.0,
    "Arch Street": 1.0, "Market Street": 0.0, "Chestnut Street": -1.0, "Sansom Street": -1.5,
    "Walnut Street": -2.0, "Locust Street": -2.8, "Spruce Street": -3.6, "Pine Street": -4.05,
    "Lombard Street": -4.5, "South Street": -5.05,
}
# South of Spruce the blocks are short: Pine, Lombard and South lie about half a block apart, not one.
# South Street passes Jim's (4th St) and the Magic Gardens (10th St) and Lombard-South station sits
# across Broad between the two; at whole-block spacing South Street stood ~300 m south of them.
JFK_Y = 0.5
NORTH, SOUTH = 5.3, -5.05


def _ordinal(n: int) -> str:
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _ns_name(x: int, north: bool) -> str:
    side = "North" if north else "South"
    if x == 1:
        return f"{side} Front Street"
    if x == 14:
        return f"{side} Broad Street"
    return f"{side} {_ordinal(x)} Street"


FIT_POINTS = [
    FitPoint("City Hall (Broad & Market)", (14.0, 0.0), 39.95250, -75.16361, "Philadelphia City Hall coordinates"),
    FitPoint("Rittenhouse Square centre", (18.5, -2.4), 39.94944, -75.17167, "Rittenhouse Square coordinates"),
    FitPoint("Franklin Square centre", (6.5, 2.5), 39.95556, -75.15028, "Franklin Square coordinates"),
    FitPoint("2nd St & Market St", (2.0, 0.0), 39.94995, -75.14380, "2nd Street station coordinates"),
]


def build() -> CitySpec:
    grid = FittedGrid((39.9525, -75.1636), FIT_POINTS)
    ways: list[Way] = []
    for name, y in EAST_WEST.items():
        x0 = 7.0 if name == "Sansom Street" else 1.0
        ways.append(Way(name, [grid.latlng(x0, y), grid.latlng(23.0, y)]))
    ways.append(Way("John F. Kennedy Boulevard", [grid.latlng(14.0, JFK_Y), grid.latlng(23.0, JFK_Y)]))
    for x in range(1, 24):
        ways.append(Way(_ns_name(x, True), polyline(lambda y: grid.latlng(x, y), 0.0, NORTH, 1.0)))
        ways.append(Way(_ns_name(x, False), polyline(lambda y: grid.latlng(x, y), 0.0, SOUTH, 1.0)))
    # The Parkway runs from City Hall's north-west corner to Logan Circle and on toward the museum.
    ways.append(Way("Benjamin Franklin Parkway",
                    [grid.latlng(15.0, 0.5), grid.latlng(16.0, 1.0), grid.latlng(19.0, 2.5), grid.latlng(23.0, 4.7)]))
    aliases = {"Broad Street": "South Broad Street", "JFK Boulevard": "John F. Kennedy Boulevard",
               "Kennedy Boulevard": "John F. Kennedy Boulevard", "Ben Franklin Parkway": "Benjamin Franklin Parkway",
               "Penn Square": "Market Street"}
    fit = grid.report("affine fit (block-index grid -> local metres), least squares on Penn's squares and a station")
    return CitySpec("philadelphia", "Philadelphia (Center City)", "ph", ways, aliases, fit)
