"""The wiki's climate articles: what each climate's weather looks like overhead, in the wiki's own words.

A view shows a city's climate only as its sky (``styles.CLIMATE``'s ``sky_words``), and a city article
names the climate by its seasons. Without an article that says how each climate's sky tends to look, an
agent that tells two cities apart by the sky connects the two on world knowledge alone, and play-testers
called that thin. These articles state the convention (issue 26, principle 4: the encyclopedia describes
conventions, the agent connects them to what is seen) in words no view uses, so matching a view's words to
them finds nothing. Climates whose skies the renderer draws alike (``cue_sets.SKY_ALIKE``) are described
alike, so an article never promises a difference the views do not show.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class ClimateArticle:
    title: str
    aliases: tuple[str, ...]
    overhead: str  # how the weather looks from the street
    seasons: str


CLIMATE_ARTICLES: dict[str, ClimateArticle] = {
    "oceanic": ClimateArticle(
        "Oceanic climate", ("Oceanic",),
        "Weather blows in off the sea all year: overcast and broken cloud cover the heavens on most days, the "
        "light is muted and diffuse, and a wholly cloud-free day is the exception.",
        "Mild, damp and changeable, without a dry season; summers are cool and winters seldom severe."),
    "continental": ClimateArticle(
        "Continental climate", ("Continental",),
        "On a fine day the heavens are open and blue, with scattered fair-weather cloud; from the street it "
        "reads much like a Mediterranean or semi-arid summer day.",
        "Warm summers and cold winters, with snow and frost far from the sea's moderating influence."),
    "nordic": ClimateArticle(
        "Cool climate", (),
        "Far from the equator, the midday solar elevation stays small for much of the year: daylight comes in "
        "at a slant and shadows fall long across the streets.",
        "Short, cool summers with long evenings; long, dark winters."),
    "mediterranean": ClimateArticle(
        "Mediterranean climate", ("Mediterranean",),
        "Through the dry season the heavens stay cloud-free and strongly blue for weeks; from the street it "
        "reads much like a continental or semi-arid fine day.",
        "Hot, dry summers and mild, wet winters."),
    "humid_subtropical": ClimateArticle(
        "Humid subtropical climate", ("Humid subtropical",),
        "In summer, moisture whitens the blue overhead and softens far outlines, so daylight is diffuse "
        "rather than sharp; thunderstorms build on summer afternoons. Dust does much the same to a desert's "
        "heavens, and from the street the two read alike.",
        "Hot, humid summers and mild winters, with rain in every season."),
    "tropical": ClimateArticle(
        "Tropical climate", ("Tropical",),
        "Heat and moisture lift tall, heaped clouds over a vivid blue by midday, and short, intense downpours "
        "follow, above all in the rainy season.",
        "Hot and humid all year, with a rainy season and a drier one."),
    "arid": ClimateArticle(
        "Desert climate", ("Desert",),
        "Fine dust raised by the wind hangs about much of the year and whitens the blue overhead, most of all "
        "close to the street; cloud is rare. Summer moisture does much the same elsewhere, and from the "
        "street the two read alike.",
        "Hot, dry and dusty, with little rain in any season."),
    "semi_arid": ClimateArticle(
        "Semi-arid climate", ("Semi-arid",),
        "Sunny most days, under open, strong blue with little cloud; from the street it reads much like a "
        "Mediterranean or continental fine day.",
        "Sunny and dry, with a short rainy season."),
    "highland": ClimateArticle(
        "Highland climate", ("Highland",),
        "At altitude the atmosphere is rarefied and dry: the blue overhead is dark and vivid, and ridges and "
        "peaks loom close about the city.",
        "Mild days and cool nights all year, owing to height above the sea rather than latitude."),
}
