"""Visual vocabularies shared by the renderer and the text describer: building styles,
climates (sky and trees) and vehicles. Descriptions use plain visual words and never a
place name ("plane trees", not "London planes")."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class ArchStyle:
    palette: tuple[str, ...]  # facade colours
    floors: tuple[int, int]  # min, max storeys
    roof: str  # mansard, pitched, flat, gabled, curved_tile
    description: str
    window: str = "square"  # tall, square, arched, strip, shuttered, glass
    balconies: bool = False
    awnings: bool = False
    veranda: bool = False  # covered walkway on posts over the pavement
    arcade: bool = False  # arched ground-floor arcade
    wires: bool = False  # dense overhead cables on poles
    vertical_signs: bool = False
    ac_units: bool = False
    roof_colour: str = "#6b6b6b"
    pavement: str = "#b9b4aa"
    # What the renderer draws so that the picture shows what ``description`` says (a test checks
    # that every feature the words name is drawn): the wall material's texture, chimney stacks,
    # soot streaks, roof dormers, window shutters and frames, fire escapes, rooftop water tanks,
    # corrugated roofs.
    material: str = "plaster"  # plaster, brick, stone, wood, concrete, glass
    tiled_colours: tuple[str, ...] = ()  # facades in these colours are faced with glazed tiles
    brick_colours: tuple[str, ...] = ()  # facades in these colours are bare brick (whatever the material)
    chimneys: bool = False
    soot: bool = False
    dormers: bool = False
    shutters: str | None = None  # shutter colour
    window_frame: str | None = None  # a light frame round each window (sash windows, stucco surrounds)
    fire_escapes: bool = False
    water_tanks: bool = False
    corrugated: bool = False


ARCH: dict[str, ArchStyle] = {
    "haussmann": ArchStyle(("#e8dcc0", "#e3d5b5", "#ece2cb"), (5, 7), "mansard",
                           "cream limestone apartment buildings of six or seven storeys with long wrought-iron "
                           "balconies and grey zinc mansard roofs with dormers", window="tall", balconies=True,
                           awnings=True,
                           roof_colour="#5f6b73", material="stone", dormers=True),
    "central_european": ArchStyle(("#e9d8a6", "#d8c3a5", "#c9d6c2", "#e3c7b8", "#f0e6d2"), (4, 5), "pitched",
                                  "four- and five-storey pastel-plastered buildings with ornate stucco window "
                                  "frames and steep tiled roofs", roof_colour="#9c4a32",
                                  window_frame="#f6f1e4"),
    "nordic": ArchStyle(("#d9a35f", "#b5493a", "#e6d3a8", "#7a8f6a", "#c9c1b0"), (4, 6), "gabled",
                        "narrow colourful plastered and brick buildings with tall windows and steep gables",
                        roof_colour="#3e3e44", window_frame="#f4f4f0", brick_colours=("#b5493a",)),
    "british": ArchStyle(("#9b4a35", "#a6583f", "#d8cfc0", "#8c3f2f"), (3, 5), "pitched",
                         "terraced brick buildings of three or four storeys with white sash windows, chimney pots "
                         "and painted shopfronts with fascia boards", roof_colour="#4b4f57",
                         material="brick", chimneys=True, window_frame="#f4f4f0"),
    "stone_terrace": ArchStyle(("#a49a88", "#8f8676", "#b3aa98"), (4, 5), "pitched",
                               "tall grey sandstone terraces, soot-darkened, with sash windows and chimney stacks",
                               roof_colour="#3f434a", material="stone", soot=True, chimneys=True,
                               window_frame="#d8d4c8"),
    "mediterranean": ArchStyle(("#e7b98a", "#d9895b", "#f0d39b", "#e8cfa8", "#c96f4a"), (3, 6), "pitched",
                               "ochre, terracotta and pale yellow stuccoed buildings with green wooden shutters, "
                               "small balconies and terracotta roof tiles", balconies=True, awnings=True,
                               roof_colour="#b5542f", shutters="#3c7a4e"),
    "iberian": ArchStyle(("#2f6fae", "#e9d9a0", "#d5e4ef", "#f2eee4", "#e3a27a"), (3, 5), "pitched",
                         "three- to five-storey buildings, some faced with glazed blue-and-white tiles, with "
                         "wrought-iron balconies; the pavement is a mosaic of small black and white stones",
                         balconies=True, roof_colour="#b5542f", pavement="#dcd8cc",
                         tiled_colours=("#2f6fae",)),
    "modernist": ArchStyle(("#c9c9c4", "#8e9aa3", "#b3b0a6", "#6e7b85"), (6, 14), "flat",
                           "post-war modernist office and apartment blocks of concrete and glass", window="strip",
                           material="concrete"),
    "soviet": ArchStyle(("#d6c7a7", "#c2b49a", "#a9a39a", "#e0d4bd"), (5, 9), "flat",
                        "massive neoclassical apartment blocks of beige stone and stucco with heavy cornices, and "
                        "plain concrete blocks further on", roof_colour="#7a776f", material="stone",
                        window_frame="#ece4d0"),
    "ottoman": ArchStyle(("#d9c6a5", "#c98f6a", "#e6dccb", "#b7a48a"), (3, 6), "flat",
                         "late-19th-century stone buildings with bay windows and cast-iron balconies, some with "
                         "projecting upper floors", balconies=True, material="stone"),
    "tuff": ArchStyle(("#d49a8c", "#c98b7c", "#dcae9f", "#b97c6f"), (4, 6), "flat",
                      "four- to six-storey buildings built of pinkish volcanic stone blocks with carved "
                      "ornaments", material="stone"),
    "east_asian": ArchStyle(("#d8d5cc", "#b9b7b0", "#e6e1d4", "#9aa0a6"), (4, 9), "flat",
                            "narrow tiled and concrete buildings of many storeys packed side by side, with "
                            "vertical signboards stacked up their fronts", wires=True, vertical_signs=True,
                            window="strip", material="concrete"),
    "machiya": ArchStyle(("#5a4632", "#6b5440", "#4a3b2c"), (2, 2), "curved_tile",
                         "low two-storey dark wooden townhouses with slatted lattice fronts and grey tiled roofs",
                         wires=True, roof_colour="#4a4d52", window="square", material="wood"),
    "chinese_modern": ArchStyle(("#cfcac0", "#b8b9b5", "#e1ddd2", "#a7b2bb"), (6, 20), "flat",
                                "tall concrete and glass towers above shops with big illuminated red and gold "
                                "signboards", vertical_signs=True, ac_units=True, window="strip", material="concrete"),
    "shophouse": ArchStyle(("#e3c77a", "#9cc3b5", "#e8b4a0", "#f1e4c3", "#c6d7a8"), (2, 4), "flat",
                           "two- to four-storey shophouses with covered five-foot walkways in front, shutters, "
                           "air-conditioner units and signboards across the facades", arcade=True, wires=True,
                           ac_units=True, window="shuttered", shutters="#5b7f6a"),
    "south_asian": ArchStyle(("#e8d9b0", "#cfd8c4", "#e2b99a", "#d4c6b8", "#f0e2a8"), (3, 6), "flat",
                             "weathered concrete buildings of three to six storeys covered with painted signboards "
                             "and hoardings, with balconies and tangled overhead cables", balconies=True, wires=True,
                             ac_units=True, window="square", material="concrete"),
    "colonial_south_asian": ArchStyle(("#c9b79a", "#b8a58a", "#d9c9a8"), (3, 5), "pitched",
                                      "grand Victorian Gothic and Art Deco stone buildings with arcades and "
                                      "balconies", arcade=True, balconies=True, window="arched", material="stone"),
    "middle_eastern": ArchStyle(("#e4d6b8", "#d9c8a4", "#efe6d3", "#cdbb98"), (3, 7), "flat",
                                "flat-roofed buildings of pale limestone and render with small balconies, "
                                "air-conditioner units and rooftop water tanks", balconies=True, ac_units=True,
                                window="square", material="stone", water_tanks=True),
    "bauhaus": ArchStyle(("#f2f0ea", "#ebe8df", "#e6e3da"), (3, 4), "flat",
                         "white rounded-corner apartment blocks of three or four storeys with long horizontal "
                         "balconies and strip windows, on pilotis", balconies=True, window="strip"),
    "gulf_modern": ArchStyle(("#b9c7d3", "#8fa7bb", "#d8d2c4", "#6f8aa3"), (15, 40), "flat",
                             "glass and steel skyscrapers along a very wide multi-lane road", window="glass",
                             material="glass"),
    "north_african": ArchStyle(("#c8704a", "#d2825a", "#bf6a45", "#e0a77b"), (2, 4), "flat",
                               "low flat-roofed buildings with ochre-red walls, small windows and carved wooden "
                               "doors", window="arched", roof_colour="#b0603e"),
    "french_colonial": ArchStyle(("#f2f0ea", "#ece6d8", "#e9e4dc"), (4, 6), "flat",
                                 "white art-deco and Haussmann-style buildings with ornate balconies, blue or green "
                                 "shutters and arcades", balconies=True, arcade=True, window="shuttered",
                                 shutters="#3f6f9a"),
    "african_urban": ArchStyle(("#e6d5a8", "#d9c0a0", "#c4d4c2", "#efe0c4", "#d7b48a"), (2, 6), "flat",
                               "two- to six-storey concrete buildings with painted walls, shop signs and "
                               "advertisements, some modernist office blocks and corrugated-iron awnings",
                               awnings=True, window="square", material="concrete"),
    "latin_colonial": ArchStyle(("#e8b04f", "#4f8fbf", "#e07a5f", "#f2e2ba", "#8fbf7f"), (1, 3), "flat",
                                "one- and two-storey colonial buildings painted in bright colours, with tall "
                                "windows behind wrought-iron grilles and wooden balconies", balconies=True,
                                window="tall"),
    "latin_modern": ArchStyle(("#d8d2c4", "#c4c9cc", "#e4dccb", "#b0b8bc"), (6, 20), "flat",
                              "mid-rise concrete apartment towers with balconies and security grilles above "
                              "street-level shops", balconies=True, wires=True, window="square", material="concrete"),
    "creole": ArchStyle(("#e8b3a3", "#a9c8d8", "#f1dd9c", "#b9d3a6"), (2, 3), "pitched",
                        "two- and three-storey pastel townhouses with lacy cast-iron galleries and hanging ferns",
                        balconies=True, window="tall"),
    "na_downtown": ArchStyle(("#9c5a45", "#b9b3a8", "#7d8c99", "#c7c0b0"), (5, 30), "flat",
                             "brick and stone buildings with metal fire escapes next to glass office towers",
                             window="square", material="stone", brick_colours=("#9c5a45",), fire_escapes=True),
    "australasian": ArchStyle(("#d8c8a8", "#b9876a", "#e4e0d6", "#9eb3bf"), (2, 12), "flat",
                              "Victorian shopfronts with verandas on posts over the footpath next to modern office "
                              "towers", veranda=True, window="tall"),
    "pacific": ArchStyle(("#f0ead8", "#b8d8c8", "#e8c89a", "#c8d8e8"), (1, 3), "pitched",
                         "low timber and concrete buildings with corrugated-iron roofs and verandas",
                         veranda=True, roof_colour="#8a8f96", window="square", corrugated=True, material="wood"),
}


@dataclass(frozen=True)
class Climate:
    sky_top: str
    sky_bottom: str
    clouds: int  # how many clouds to draw
    trees: tuple[str, ...]
    sky_words: str
    ground_tint: str = "#7a7a78"  # asphalt


CLIMATE: dict[str, Climate] = {
    "oceanic": Climate("#8fa9c4", "#d6dde4", 5, ("plane", "linden", "maple"), "a soft grey-blue sky with many clouds"),
    "continental": Climate("#6f9fd0", "#cfe0ee", 3, ("linden", "chestnut", "maple"), "a clear blue sky with a few "
                                                                                      "clouds"),
    "nordic": Climate("#9db3c7", "#e3e8ec", 4, ("birch", "spruce", "linden"), "a pale sky with the sun low over the roofs"),
    "mediterranean": Climate("#4d8fd6", "#bcd8f0", 1, ("plane", "umbrella_pine", "cypress", "palm"),
                             "a deep blue, almost cloudless sky"),
    "humid_subtropical": Climate("#7fa8cf", "#dfe6e8", 3, ("plane", "camphor", "palm"), "a milky, hazy sky"),
    "tropical": Climate("#3f8ed8", "#cfe6f5", 4, ("coconut_palm", "banana", "rain_tree", "frangipani"),
                        "a bright blue sky with towering white cumulus clouds"),
    "arid": Climate("#9bbfd9", "#efe3c8", 0, ("date_palm", "acacia"), "a pale sky washed out by a sand-coloured haze",
                    ground_tint="#8a8476"),
    "semi_arid": Climate("#78a9d6", "#e8e0cc", 1, ("acacia", "jacaranda", "eucalyptus", "pepper_tree"),
                         "a bright, hard blue sky"),
    "highland": Climate("#4f86c6", "#d4e2ee", 2, ("eucalyptus", "pine", "jacaranda"),
                          "a thin, intensely blue sky with mountains on the horizon"),
}

# What a passer-by sees of each kind of tree (the views): shape, bark, leaves, flowers, never the
# species' name, which is how the wiki files it (TREE_NAMES); the agent connects the two.
TREE_WORDS: dict[str, str] = {
    "plane": "broad trees whose bark flakes off in grey, olive and cream patches",
    "linden": "rounded trees with heart-shaped leaves",
    "maple": "leafy trees with five-pointed leaves",
    "chestnut": "big trees with hand-shaped leaves and upright white flower spikes",
    "birch": "slender trees with white, black-streaked bark",
    "spruce": "dark conical evergreens",
    "umbrella_pine": "tall needle trees with bare trunks and flat, spreading crowns",
    "cypress": "tall narrow dark-green columns of foliage",
    "palm": "trees with a single bare trunk topped by a tuft of fronds",
    "fan_palm": "very tall thin trunks topped by small tufts of fan-shaped fronds",
    "camphor": "dense glossy evergreen trees",
    "coconut_palm": "leaning trunks topped by long feathery fronds and clusters of green nuts",
    "banana": "soft-stemmed plants with huge paddle-shaped leaves",
    "rain_tree": "wide umbrella-shaped trees with feathery leaves",
    "frangipani": "stubby-branched small trees with waxy white flowers",
    "date_palm": "straight ridged trunks topped by stiff grey-green fronds",
    "acacia": "thorny trees with flat tops",
    "jacaranda": "trees covered in purple blossom",
    "eucalyptus": "tall pale-trunked trees with bark hanging in strips",
    "pepper_tree": "trees with long drooping feathery branches and pink berries",
    "pine": "needle-leaved evergreens",
    "ginkgo": "trees with small fan-shaped leaves",
    "zelkova": "vase-shaped trees with small saw-edged leaves",
    "willow": "trees whose long thin branches hang down to the ground",
    "locust": "trees with small paired leaflets and creamy flower clusters",
    "banyan": "massive trees with roots hanging from the branches",
    "orange": "small round-crowned trees hung with orange fruit",
    "olive": "gnarled trees with small silvery leaves",
    "fig": "huge trees with glossy leathery leaves and buttressed trunks",
    "araucaria": "tall conifers with branches in level tiers like a candelabra",
    "flamboyant": "spreading trees covered in scarlet blossom",
}

# The species as the wiki names them (no word shared with TREE_WORDS; a test checks).
TREE_NAMES: dict[str, str] = {
    "plane": "London plane (Platanus)", "linden": "lime (Tilia)", "maple": "maple (Acer)",
    "chestnut": "horse chestnut (Aesculus)", "birch": "birch (Betula)", "spruce": "spruce (Picea)",
    "umbrella_pine": "Pinus pinea", "cypress": "Italian cypress (Cupressus)",
    "palm": "Phoenix canariensis", "fan_palm": "Washingtonia robusta", "camphor": "camphor laurel (Cinnamomum)",
    "coconut_palm": "coconut (Cocos nucifera)", "banana": "banana (Musa)", "rain_tree": "rain tree (Samanea)",
    "frangipani": "frangipani (Plumeria)", "date_palm": "date (Phoenix dactylifera)", "acacia": "acacia (Vachellia)",
    "jacaranda": "jacaranda", "eucalyptus": "eucalyptus (gum)", "pepper_tree": "Peruvian pepper (Schinus)",
    "pine": "pine (Pinus)", "ginkgo": "ginkgo", "zelkova": "zelkova (keyaki)", "willow": "weeping willow (Salix)",
    "locust": "Japanese pagoda (Styphnolobium)", "banyan": "banyan (Ficus benghalensis)",
    "orange": "bitter citrus (Citrus aurantium)", "olive": "Olea europaea", "fig": "Ficus macrophylla",
    "araucaria": "Paraná pine (Araucaria)", "flamboyant": "flamboyant (Delonix)",
}

# How each kind of city vehicle looks; colour comes from the "kind:colour" feature. Plain visual
# words: the vehicle's local name is the wiki's (VEHICLE_NAMES).
VEHICLE_WORDS: dict[str, str] = {
    "tram": "a {colour} electric rail car running on tracks in the road",
    "double_decker": "a {colour} bus with two passenger decks",
    "taxi": "a {colour} car with a lit sign on its roof, picking up passengers",
    "minibus": "a {colour} van-sized bus crowded with passengers",
    "matatu": "a van-sized bus painted all over in graffiti-style art, with loud music",
    "tuk_tuk": "a small three-wheeled motor cab with an open passenger bench",
    "auto_rickshaw": "a {colour} three-wheeled motor cab with a canvas top",
    "cycle_rickshaw": "a pedalled three-wheeler carrying passengers under a decorated hood",
    "becak": "a pedalled three-wheeler with the passenger seat in front of the rider",
    "motorbikes": "dozens of motor scooters filling the road",
    "boda_boda": "a swarm of motorcycles carrying paying passengers on the back",
    "jeepney": "a long, chrome-decorated, brightly painted passenger vehicle built like a stretched jeep",
    "songthaew": "a {colour} pick-up truck with benches in the back, carrying passengers",
    "classic_car": "a 1950s car with tail fins and chrome, in bright paint",
    "chicken_bus": "a brightly repainted old school bus",
    "painted_bus": "a bus covered with ornate painted decorations and chrome",
    "trolleybus": "a {colour} bus drawing power from two overhead wires",
    "skytrain": "an elevated railway viaduct on concrete pillars above the road",
    "bicycles": "many people riding upright bicycles on a red-paved lane beside the road",
}

# The vehicles as the wiki names them (no word shared with VEHICLE_WORDS; a test checks).
VEHICLE_NAMES: dict[str, str] = {
    "tram": "trams (streetcars)", "double_decker": "bilevel buses", "taxi": "{colour} taxicabs",
    "minibus": "share-minibuses", "matatu": "matatus", "tuk_tuk": "tuk-tuks", "auto_rickshaw": "auto-rickshaws",
    "cycle_rickshaw": "cycle rickshaws", "becak": "becaks", "motorbikes": "mopeds",
    "boda_boda": "boda-bodas", "jeepney": "jeepneys", "songthaew": "songthaews",
    "classic_car": "vintage American automobiles", "chicken_bus": "chicken buses", "painted_bus": "phool-patti buses",
    "trolleybus": "trolleybuses", "skytrain": "an overground rapid-transit line (skytrain)", "bicycles": "cycling infrastructure",
}

COLOUR_HEX: dict[str, str] = {
    "yellow": "#f2c200", "red": "#c62828", "blue": "#1f5fb0", "green": "#2e7d32", "white": "#f2f2f2",
    "black": "#222222", "orange": "#ef7d1a", "pink": "#e36a9c", "beige": "#d9c8a0", "silver": "#b8bcc0",
    "grey": "#8a8f96",
}


def is_colour(words: str) -> bool:
    """Whether a transport feature's second part is a colour ("minibus:trotro" names the vehicle instead)."""
    return any(word in COLOUR_HEX for word in words.replace("-", " ").split())


def vehicle_look(kind: str, colour: str) -> str:
    """The view's words for a vehicle: its colours only; a local name given with or in place of a colour
    ("black cab", "trotro") is the wiki's word, never said."""
    seen = " ".join(w for w in colour.split() if w == "and" or all(p in COLOUR_HEX or p == "cream"
                                                                    for p in w.split("-")))
    seen = seen if is_colour(seen) else ""
    text = " ".join(VEHICLE_WORDS[kind].format(colour=seen).split())
    return "an " + text[2:] if text.startswith("a ") and text[2:3] and text[2:3] in "aeiou" else text


def vehicle_name(kind: str, colour: str) -> str:
    """The wiki's words for a vehicle: its name, with the colour or the local name the city uses."""
    if is_colour(colour) and "{colour}" not in VEHICLE_NAMES[kind]:
        return f"{colour} {VEHICLE_NAMES[kind]}"
    if is_colour(colour) or not colour:
        return " ".join(VEHICLE_NAMES[kind].format(colour=colour).split())
    return " ".join(VEHICLE_NAMES[kind].format(colour="").split()) + f" (locally: {colour})"


def colour_hex(words: str) -> str:
    """The first colour word in a phrase ("black and yellow" -> black)."""
    for word in words.replace("-", " ").split():
        if word in COLOUR_HEX:
            return COLOUR_HEX[word]
    return "#c9c9c9"
