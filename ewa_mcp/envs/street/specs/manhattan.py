"""Manhattan, 14th to 59th Street, from the Hudson-side avenues to First Avenue, with Broadway.

Method: the Commissioners' grid is laid out in a grid frame (x: feet across the avenues from Fifth
Avenue, east positive; y: feet along the avenues from the centre line of 14th Street). Street
positions follow the plan's block depth (200 ft 10 in) and street widths (60 ft, 100 ft for the wide
crosstown streets). Avenue positions are a table in feet, calibrated on 14th and 23rd Street station
coordinates (see CALIBRATION). An affine transform from the grid frame to a local metric frame is
fitted by least squares on four surveyed intersections (FIT_POINTS); its residuals are written into
the data file. Test anchors (tests/outdoor/anchors.py) are different points.
"""

from __future__ import annotations

from .base import CitySpec, FitPoint, FittedGrid, Way, polyline

WIDE_STREETS = {14, 23, 34, 42, 57, 59}
BLOCK_FT = 200.83

# Centre lines across the grid, feet from Fifth Avenue (east positive). Calibrated on published
# station coordinates at 14th St (8th, 6th, 3rd, 1st Ave) and 23rd St (6th Ave, Park Ave South).
AVENUE_X = {
    "12th Avenue": -6311.0,
    "11th Avenue": -5511.0,
    "10th Avenue": -4611.0,
    "9th Avenue": -3711.0,
    "8th Avenue": -2811.0,
    "7th Avenue": -1941.0,
    "6th Avenue": -1024.0,
    "5th Avenue": 0.0,
    "Madison Avenue": 500.0,
    "Park Avenue": 1024.0,
    "Lexington Avenue": 1434.0,
    "3rd Avenue": 2054.0,
    "2nd Avenue": 2785.0,
    "1st Avenue": 3516.0,
}
CALIBRATION = [
    ("8th Ave & W 14th St", 40.739779, -74.002533),
    ("6th Ave & W 14th St", 40.737372, -73.996911),
    ("3rd Ave & E 14th St", 40.733243, -73.987212),
    ("1st Ave & E 14th St", 40.731324, -73.982577),
    ("6th Ave & W 23rd St", 40.742933, -73.992877),
    ("Park Ave S & E 23rd St", 40.740169, -73.986440),
]
UNION_SQUARE_WEST_X = 600.0  # Broadway along the west side of Union Square
VANDERBILT_X = 680.0
ROCKEFELLER_PLAZA_X = -500.0


def street_y(n: float) -> float:
    """Feet along the avenues from the centre of 14th Street to the centre of street ``n``."""
    whole = int(n)
    y = 0.0
    for k in range(14, whole):
        w1 = 100.0 if k in WIDE_STREETS else 60.0
        w2 = 100.0 if (k + 1) in WIDE_STREETS else 60.0
        y += BLOCK_FT + (w1 + w2) / 2
    frac = n - whole
    if frac:
        w1 = 100.0 if whole in WIDE_STREETS else 60.0
        w2 = 100.0 if (whole + 1) in WIDE_STREETS else 60.0
        y += frac * (BLOCK_FT + (w1 + w2) / 2)
    return y


FIT_POINTS = [
    FitPoint("8th Ave & W 14th St", (AVENUE_X["8th Avenue"], street_y(14)), 40.739779, -74.002533,
             "14th Street/Eighth Avenue station coordinates"),
    FitPoint("1st Ave & E 14th St", (AVENUE_X["1st Avenue"], street_y(14)), 40.731324, -73.982577,
             "First Avenue (Canarsie Line) station coordinates"),
    FitPoint("8th Ave & W 34th St", (AVENUE_X["8th Avenue"], street_y(34)), 40.752166, -73.993521,
             "34th Street-Penn Station (Eighth Avenue Line) station coordinates"),
    FitPoint("Columbus Circle (8th Ave & W 59th St)", (AVENUE_X["8th Avenue"], street_y(59)), 40.767997, -73.981934,
             "59th Street-Columbus Circle station coordinates"),
]

# Broadway's crossing of the grid, as (street number, x in feet); piecewise linear between.
BROADWAY = [(14.0, UNION_SQUARE_WEST_X), (17.0, UNION_SQUARE_WEST_X), (23.8, 0.0),
            (34.0, AVENUE_X["6th Avenue"]), (45.0, AVENUE_X["7th Avenue"]), (59.0, AVENUE_X["8th Avenue"])]

# (street number, x_from, x_to): blocks a cross street does not pass (parks, stations, rail yards).
GAPS = [
    (15, UNION_SQUARE_WEST_X, AVENUE_X["Park Avenue"]), (16, UNION_SQUARE_WEST_X, AVENUE_X["Park Avenue"]),  # Union Square
    (24, 0.0, AVENUE_X["Madison Avenue"]), (25, 0.0, AVENUE_X["Madison Avenue"]),  # Madison Square Park
    (31, AVENUE_X["12th Avenue"], AVENUE_X["10th Avenue"]), (32, AVENUE_X["12th Avenue"], AVENUE_X["10th Avenue"]),  # rail yards
    (32, AVENUE_X["9th Avenue"], AVENUE_X["8th Avenue"]),  # Farley Post Office
    (32, AVENUE_X["8th Avenue"], AVENUE_X["7th Avenue"]),  # Penn Station / Madison Square Garden
    (35, AVENUE_X["12th Avenue"], AVENUE_X["11th Avenue"]), (36, AVENUE_X["12th Avenue"], AVENUE_X["11th Avenue"]),
    (37, AVENUE_X["12th Avenue"], AVENUE_X["11th Avenue"]), (38, AVENUE_X["12th Avenue"], AVENUE_X["11th Avenue"]),
    (39, AVENUE_X["12th Avenue"], AVENUE_X["11th Avenue"]),  # Javits Center
    (41, AVENUE_X["6th Avenue"], 0.0),  # Bryant Park and the library
    (43, VANDERBILT_X, AVENUE_X["Lexington Avenue"]), (44, VANDERBILT_X, AVENUE_X["Lexington Avenue"]),  # Grand Central
]


def _ordinal(n: int) -> str:
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _west_end(n: int) -> float:
    if n >= 34:
        return AVENUE_X["12th Avenue"]
    return AVENUE_X["11th Avenue"]


def _cut(x0: float, x1: float, gaps: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Split the span [x0, x1] around the gap intervals."""
    spans = [(x0, x1)]
    for g0, g1 in gaps:
        lo, hi = min(g0, g1), max(g0, g1)
        nxt = []
        for a, b in spans:
            if hi <= a or lo >= b:
                nxt.append((a, b))
                continue
            if lo > a:
                nxt.append((a, lo))
            if hi < b:
                nxt.append((hi, b))
        spans = nxt
    return [s for s in spans if s[1] - s[0] > 1.0]


def broadway_x(n: float) -> float:
    for (n0, x0), (n1, x1) in zip(BROADWAY, BROADWAY[1:]):
        if n0 <= n <= n1:
            return x0 + (x1 - x0) * (n - n0) / (n1 - n0)
    raise ValueError(f"street {n} is outside Broadway's modelled stretch")


def build() -> CitySpec:
    grid = FittedGrid((40.7527, -73.9850), FIT_POINTS)

    def at(x: float, n: float) -> tuple[float, float]:
        return grid.latlng(x, street_y(n))

    ways: list[Way] = []
    # Cross streets: split at Fifth Avenue into West/East names (the city's own convention).
    for n in range(14, 60):
        west_end, east_end = _west_end(n), AVENUE_X["1st Avenue"]
        gaps = [(a, b) for (s, a, b) in GAPS if s == n]
        for x0, x1 in _cut(west_end, east_end, gaps):
            for side_lo, side_hi, prefix in ((x0, min(x1, 0.0), "West"), (max(x0, 0.0), x1, "East")):
                if side_hi - side_lo < 1.0:
                    continue
                if n == 59 and prefix == "West":
                    # Central Park South between Fifth and Eighth Avenues.
                    split = AVENUE_X["8th Avenue"]
                    if side_lo < split:
                        ways.append(Way("West 59th Street", [at(side_lo, n), at(min(side_hi, split), n)]))
                    if side_hi > split:
                        ways.append(Way("Central Park South", [at(max(side_lo, split), n), at(side_hi, n)]))
                    continue
                ways.append(Way(f"{prefix} {_ordinal(n)} Street", [at(side_lo, n), at(side_hi, n)]))

    def avenue(name: str, x_key: str, n0: float, n1: float) -> None:
        x = AVENUE_X[x_key]
        ways.append(Way(name, polyline(lambda n: at(x, n), n0, n1, 1.0)))

    for name in ["10th Avenue", "9th Avenue", "8th Avenue", "7th Avenue", "6th Avenue", "5th Avenue",
                 "3rd Avenue", "2nd Avenue", "1st Avenue"]:
        avenue(name, name, 14, 59)
    avenue("West Street", "11th Avenue", 14, 22)
    avenue("11th Avenue", "11th Avenue", 22, 59)
    avenue("12th Avenue", "12th Avenue", 34, 59)
    avenue("Madison Avenue", "Madison Avenue", 23, 59)
    avenue("Union Square East", "Park Avenue", 14, 17)
    avenue("Park Avenue South", "Park Avenue", 17, 32)
    avenue("Park Avenue", "Park Avenue", 32, 42)
    avenue("Park Avenue", "Park Avenue", 46, 59)
    avenue("Irving Place", "Lexington Avenue", 14, 20)
    avenue("Lexington Avenue", "Lexington Avenue", 21, 59)
    ways.append(Way("Vanderbilt Avenue", polyline(lambda n: at(VANDERBILT_X, n), 42, 47, 1.0)))
    ways.append(Way("Rockefeller Plaza", polyline(lambda n: at(ROCKEFELLER_PLAZA_X, n), 48, 51, 1.0)))
    ways.append(Way("Broadway", polyline(lambda n: at(broadway_x(n), n), 14, 59, 0.5)))

    aliases = {
        "Avenue of the Americas": "6th Avenue", "Sixth Avenue": "6th Avenue", "Fifth Avenue": "5th Avenue",
        "Seventh Avenue": "7th Avenue", "Eighth Avenue": "8th Avenue", "Ninth Avenue": "9th Avenue",
        "Tenth Avenue": "10th Avenue", "Eleventh Avenue": "11th Avenue", "Twelfth Avenue": "12th Avenue",
        "Third Avenue": "3rd Avenue", "Second Avenue": "2nd Avenue", "First Avenue": "1st Avenue",
        "Fourth Avenue": "Park Avenue South", "Columbus Circle": "Central Park South",
        "West Side Highway": "12th Avenue", "Amsterdam Avenue": "10th Avenue", "Columbus Avenue": "9th Avenue",
        "Central Park West": "8th Avenue", "Union Square West": "Broadway",
    }
    fit = grid.report("affine grid fit (feet grid frame -> local metres), least squares on surveyed intersections")
    fit["calibration_points"] = [c[0] for c in CALIBRATION]
    return CitySpec("manhattan", "Manhattan, New York City", "mn", ways, aliases, fit)
