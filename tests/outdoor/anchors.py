"""Known positions used to check the generated graphs. None of these is a generator fit or
calibration point (see ewa_mcp/envs/street/specs/*.py FIT_POINTS and CALIBRATION); each is a published
coordinate of a station or square that stands on the named intersection."""

# (city, "street & street", lat, lng, source)
INTERSECTION_ANCHORS = [
    ("manhattan", "5th Ave & W 53rd St", 40.760326, -73.975754, "Fifth Avenue/53rd Street station"),
    ("manhattan", "8th Ave & W 42nd St", 40.757222, -73.989722, "42nd Street-Port Authority Bus Terminal station"),
    ("manhattan", "7th Ave & W 57th St", 40.765461, -73.980088, "57th Street-Seventh Avenue station"),
    ("manhattan", "Union Square East & E 14th St", 40.734720, -73.990280, "14th Street-Union Square station"),
    ("philadelphia", "N 19th St & Benjamin Franklin Pkwy", 39.958300, -75.170800, "Logan Circle (Logan Square)"),
]
ANCHOR_TOLERANCE_M = 30.0
