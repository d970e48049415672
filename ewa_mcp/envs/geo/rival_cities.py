"""Rival cities: real cities with a wiki article and no location, there to be told apart.

A hard location's city must follow only from three or more of its cues put together (issue 26,
principle 6): every single cue a walk shows, and every pair of them, must still fit at least one other
city of the country, so that the wiki's city articles leave a real choice until the last cue is read
(cue_sets.py). The location set alone rarely gives that: most countries have two to four cities in it,
each with a cue of its own. These cities close the gap. Each differs from a hard city in exactly one
convention (its climate, its street trees, its local transport or its buildings) and agrees with it in
the rest, so the tempting shortcut — the first two cues that fit — names a rival.

Their conventions are this world's, stated in their articles in the same words as every other city's,
chosen to be plausible for the real city; they are not a survey. No view ever shows a rival city (no
location stands in one), so nothing here can leak an answer.

A rival that differs only in climate has one whose sky reads apart from the hard city's (a grey cloudy
oceanic sky against a clear continental one, mountains on a highland horizon, a humid haze, towering
tropical cumulus); never a Mediterranean against a semi-arid sky, which look alike (cue_sets.SKY_ALIKE).
"""

from __future__ import annotations

from .cities import City

_ = City
# Trees written out where a rival keeps a hard city's trees under another climate, or the climate's
# trees under another convention.
CLM = ("chestnut", "linden", "maple")
LMP = ("linden", "maple", "plane")
MED = ("cypress", "palm", "plane", "umbrella_pine")
CPP = ("camphor", "palm", "plane")
EJP = ("eucalyptus", "jacaranda", "pine")
TROPIC = ("banana", "coconut_palm", "frangipani", "rain_tree")

RIVAL_CITIES_LIST: list[City] = [
    # Berlin (continental, chestnut/linden/maple, yellow trams): Munich differs in its trams.
    _("dresden", 2935022, "Dresden", "DE", "continental", "0351", "DD", trees=("birch", "linden", "plane"),
      transport=("tram:yellow",), about="Capital of Saxony on the Elbe, rebuilt after 1945."),
    _("bremen", 2944388, "Bremen", "DE", "oceanic", "0421", "HB", trees=CLM, transport=("tram:yellow",),
      about="Old Hanseatic city on the Weser, a city-state of its own."),
    # Kraków (continental, chestnut/linden/maple, blue trams): Warsaw has no trams in its article.
    _("wroclaw", 3081368, "Wrocław", "PL", "continental", "71", "DW", trees=("birch", "linden", "plane"),
      transport=("tram:blue",), about="Capital of Lower Silesia on the Oder, a city of many bridges."),
    _("gdansk", 3099434, "Gdańsk", "PL", "oceanic", "58", "GD", trees=CLM, transport=("tram:blue",),
      about="Baltic port at the mouth of the Vistula."),
    # Lisbon (Mediterranean, Mediterranean trees, yellow trams): Porto has no trams in its article.
    _("coimbra", 2740637, "Coimbra", "PT", "mediterranean", "239", trees=("olive", "orange", "palm"),
      transport=("tram:yellow",), about="Old university city on the Mondego."),
    _("braga", 2742032, "Braga", "PT", "oceanic", "253", trees=MED, transport=("tram:yellow",),
      about="City of the Minho region in the north, known for its churches."),
    # Manchester (British buildings, yellow trams): London has other vehicles in its article.
    _("sheffield", 2638077, "Sheffield", "GB", "oceanic", "0114", arch="stone_terrace", trees=LMP,
      transport=("tram:yellow",), about="City of seven hills in South Yorkshire, once the centre of steelmaking."),
    _("nottingham", 2641170, "Nottingham", "GB", "oceanic", "0115", trees=("birch", "chestnut", "linden"),
      transport=("tram:yellow",), about="City of the East Midlands on the Trent."),
    # Bogotá (highland, eucalyptus/jacaranda/pine, yellow taxis): Medellín has no taxis in its article.
    _("bucaramanga", 3688465, "Bucaramanga", "CO", "highland", "607", "BUCARAMANGA", trees=("fig", "jacaranda"),
      transport=("taxi:yellow",), about="Capital of Santander department, called the city of parks."),
    _("cali", 3687925, "Cali", "CO", "tropical", "602", "CALI", trees=EJP, transport=("taxi:yellow",),
      about="Capital of Valle del Cauca in the Cauca valley."),
    # New York (humid subtropical, ginkgo/linden/plane, yellow taxis): Washington has its trees and no taxis,
    # Baltimore its sky and taxis but not its trees, Minneapolis its trees and taxis under another sky.
    _("baltimore", 4347778, "Baltimore", "US", "humid_subtropical", "410", "MARYLAND", trees=LMP,
      transport=("taxi:yellow",),
      about="Port city of Maryland on Chesapeake Bay."),
    _("minneapolis", 5037649, "Minneapolis", "US", "continental", "612", "MINNESOTA",
      trees=("ginkgo", "linden", "maple", "plane"), transport=("taxi:yellow",),
      about="Largest city of Minnesota, on the Mississippi beside its twin, Saint Paul."),
    _("san-diego", 5391811, "San Diego", "US", "mediterranean", "619", "CALIFORNIA", trees=CPP,
      transport=("taxi:yellow",),
      about="Pacific port city of southern California near the Mexican border."),
    # Toronto (continental, chestnut/linden/maple, red streetcars, English signs): Montreal signs in French.
    _("ottawa", 6094817, "Ottawa", "CA", "continental", "613", "ONTARIO",
      about="Capital of Canada on the Ottawa River."),
    _("calgary", 5913490, "Calgary", "CA", "continental", "403", "ALBERTA", trees=("birch", "spruce"),
      transport=("tram:red",),
      langs=("en-us",),
      about="City of Alberta where the prairie meets the foothills of the Rockies."),
    _("edmonton", 5946768, "Edmonton", "CA", "nordic", "780", "ALBERTA", trees=CLM,
      transport=("tram:red",), langs=("en-us",),
      about="Capital of Alberta on the North Saskatchewan River."),
    # Istanbul (Mediterranean, Mediterranean trees, red trams).
    _("izmir", 311046, "İzmir", "TR", "mediterranean", "232", "35", trees=MED, aliases=("Izmir",),
      about="Port city on the Aegean coast, Turkey's third city."),
    _("antalya", 323777, "Antalya", "TR", "mediterranean", "242", "07", trees=("orange", "palm"),
      transport=("tram:red",),
      about="Resort city on the Mediterranean coast."),
    _("bursa", 750269, "Bursa", "TR", "humid_subtropical", "224", "16", trees=MED, transport=("tram:red",),
      about="First capital of the Ottoman state, below the Uludağ mountain."),
    # Johannesburg (highland, jacaranda, white minibus taxis).
    _("pretoria", 964137, "Pretoria", "ZA", "highland", "12", "@@ ## @@ GP", trees=("jacaranda",),
      about="Administrative capital of South Africa."),
    _("bloemfontein", 1018725, "Bloemfontein", "ZA", "highland", "51", "@@@ ### FS", trees=("acacia", "pepper_tree"),
      transport=("minibus:white",), about="Judicial capital of South Africa, in the Free State."),
    _("pietermaritzburg", 965301, "Pietermaritzburg", "ZA", "humid_subtropical", "33", "NP ###-###",
      trees=("jacaranda",),
      transport=("minibus:white",), about="Capital of KwaZulu-Natal."),
    # Melbourne (oceanic, linden/maple/plane, green and white trams).
    _("hobart", 2163355, "Hobart", "AU", "oceanic", "03", "TAS",
      trees=LMP, about="Capital of Tasmania on the Derwent."),
    _("ballarat", 2177091, "Ballarat", "AU", "oceanic", "03", "VIC", trees=("eucalyptus", "pine"),
      transport=("tram:green and white",), about="Inland city of Victoria that grew in the gold rush."),
    _("canberra", 2172517, "Canberra", "AU", "continental", "02", "ACT", trees=LMP, transport=("tram:green and white",),
      about="Capital of Australia, a planned city around a lake."),
    # Rio de Janeiro and Salvador (tropical, tropical trees; modern and colonial buildings).
    _("recife", 3390760, "Recife", "BR", "tropical", "81", trees=("coconut_palm", "flamboyant"),
      about="Port city of Pernambuco built on islands and rivers."),
    _("belo-horizonte", 3470127, "Belo Horizonte", "BR", "highland", "31", trees=TROPIC,
      about="Planned capital of Minas Gerais, ringed by hills."),
    _("sao-luis", 3388368, "São Luís", "BR", "tropical", "98", arch="latin_colonial",
      trees=("coconut_palm", "flamboyant"),
      aliases=("Sao Luis",), about="Capital of Maranhão on an island of the Atlantic coast."),
    _("ouro-preto", 3455671, "Ouro Preto", "BR", "highland", "31", arch="latin_colonial", trees=TROPIC,
      about="Colonial gold-mining town in the mountains of Minas Gerais."),
    # Shanghai (modern Chinese buildings, humid subtropical, plane trees).
    _("hangzhou", 1808926, "Hangzhou", "CN", "humid_subtropical", "0571", "浙A", trees=("camphor", "willow"),
      about="Capital of Zhejiang beside the West Lake."),
    _("xian", 1790630, "Xi'an", "CN", "continental", "029", "陕A", trees=("plane",), aliases=("Xian",),
      about="Ancient capital in the Wei valley, inside its Ming city wall."),
    _("xiamen", 1790645, "Xiamen", "CN", "humid_subtropical", "0592", "闽D", arch="shophouse", trees=("banyan", "plane"),
      about="Port city of Fujian facing the Taiwan Strait."),
    # Guadalajara and Oaxaca (colonial buildings).
    _("monterrey", 3995465, "Monterrey", "MX", "humid_subtropical", "81", "NUEVO LEÓN", arch="latin_modern", trees=CPP,
      about="Industrial capital of Nuevo León below the Cerro de la Silla."),
    _("morelia", 3995402, "Morelia", "MX", "humid_subtropical", "443", "MICHOACÁN", trees=("fig", "jacaranda"),
      transport=("taxi:pink and white",),
      about="Capital of Michoacán, its centre built of pink stone."),
    _("queretaro", 3991164, "Querétaro", "MX", "semi_arid", "442", "QUERÉTARO",
      trees=CPP, aliases=("Santiago de Querétaro",),
      about="Capital of Querétaro state, with a long colonial aqueduct."),
    _("toluca", 3515302, "Toluca", "MX", "highland", "722", "ESTADO DE MÉXICO", arch="latin_modern", trees=EJP,
      about="Capital of the State of Mexico, one of the highest cities of the country."),
    _("zacatecas", 3979844, "Zacatecas", "MX", "semi_arid", "492", "ZACATECAS", trees=EJP,
      about="Silver-mining city in a narrow valley of the north-central plateau."),
    # Marseille (Haussmann-style buildings, Mediterranean, Mediterranean trees).
    _("nice", 2990440, "Nice", "FR", "mediterranean", "04", arch="mediterranean", trees=MED,
      about="City of the Côte d'Azur on the Baie des Anges."),
    _("montpellier", 2992166, "Montpellier", "FR", "mediterranean", "04", trees=("olive", "plane"),
      about="University city of Occitania near the Mediterranean coast."),
    _("toulouse", 2972315, "Toulouse", "FR", "humid_subtropical", "05", trees=MED,
      about="The pink city on the Garonne, centre of the aircraft industry."),
    # Mendoza (modern buildings, semi-arid, plane trees).
    _("salta", 3838233, "Salta", "AR", "semi_arid", "387", arch="latin_colonial", trees=("jacaranda", "plane"),
      about="Colonial city of the north-west at the foot of the Andes."),
    _("san-juan-ar", 3837213, "San Juan", "AR", "semi_arid", "264", arch="latin_modern",
      trees=("acacia", "pepper_tree"),
      about="Wine-growing city of the Cuyo region, rebuilt after the earthquake of 1944."),
    _("rosario", 3838583, "Rosario", "AR", "humid_subtropical", "341", arch="latin_modern",
      trees=("jacaranda", "plane"),
      about="River port on the Paraná, Argentina's third city."),
    # Casablanca (French colonial buildings, Mediterranean, Mediterranean trees).
    _("rabat", 2538475, "Rabat", "MA", "mediterranean", "537", arch="french_colonial", trees=("jacaranda", "palm"),
      about="Capital of Morocco at the mouth of the Bou Regreg."),
    _("ifrane", 2546917, "Ifrane", "MA", "highland", "535", arch="french_colonial", trees=MED,
      about="Mountain resort of the Middle Atlas, laid out in the 1930s."),
    _("tangier", 2530335, "Tangier", "MA", "mediterranean", "539", arch="north_african", trees=MED,
      about="Port city on the Strait of Gibraltar."),
    # Edinburgh (stone terraces, linden/maple/plane, white and red trams): Sheffield differs in its trams.
    _("blackpool", 2655459, "Blackpool", "GB", "oceanic", "01253", trees=LMP, transport=("tram:white and red",),
      about="Seaside resort on the Irish Sea with a long promenade."),
    _("glasgow", 2648579, "Glasgow", "GB", "oceanic", "0141", arch="stone_terrace",
      trees=("birch", "chestnut", "linden"),
      transport=("tram:white and red",), about="Scotland's largest city, on the Clyde."),
    # Tokyo (East Asian buildings, humid subtropical, ginkgo and zelkova): Osaka has ginkgo only.
    _("sendai", 2111149, "Sendai", "JP", "continental", "022", "宮城", trees=("ginkgo", "zelkova"),
      about="Largest city of the Tōhoku region, called the city of trees."),
    _("kanazawa", 1860243, "Kanazawa", "JP", "humid_subtropical", "076", "金沢", arch="machiya",
      trees=("ginkgo", "zelkova"),
      about="Castle town on the Sea of Japan coast with preserved merchant quarters."),
    # Lyon (Haussmann-style buildings, oceanic, linden/maple/plane, white and grey trams): Paris has none.
    _("grenoble", 3014728, "Grenoble", "FR", "continental", "04", trees=LMP, transport=("tram:white and grey",),
      about="City of the Alps at the meeting of the Isère and the Drac."),
    _("bordeaux", 3031582, "Bordeaux", "FR", "oceanic", "05", trees=("birch", "chestnut", "linden"),
      transport=("tram:white and grey",), about="Port city on the Garonne, centre of a wine region."),
    # Mexico City (highland, jacaranda, pink and white taxis): Oaxaca has none; Morelia above differs in climate.
    _("puebla", 3521081, "Puebla", "MX", "highland", "222", "PUEBLA", trees=("fig", "pine"),
      transport=("taxi:pink and white",),
      about="Colonial city below the volcanoes east of the capital, known for its painted tiles."),
    # Yogyakarta (tropical, tropical trees, becaks and motorbikes): Jakarta has motorbikes only.
    _("surakarta", 1625812, "Surakarta", "ID", "tropical", "0271", "AD", trees=("banyan", "flamboyant"),
      transport=("becak", "motorbikes"), aliases=("Solo",), about="Royal city of Central Java on the Solo River."),
    _("malang", 1636722, "Malang", "ID", "highland", "0341", "N", trees=TROPIC, transport=("becak", "motorbikes"),
      about="Hill city of East Java ringed by volcanoes."),
    # Thessaloniki (Mediterranean buildings and climate, Mediterranean trees): Athens differs in its trees.
    _("chania", 260114, "Chania", "GR", "mediterranean", "28210", "XN", arch="ottoman", trees=MED, aliases=("Chaniá",),
      about="Port town of western Crete around a Venetian harbour."),
    _("ioannina", 261779, "Ioannina", "GR", "highland", "2651", "IN", trees=("olive", "orange", *MED),
      aliases=("Ioánnina",), about="Capital of Epirus on a mountain lake."),
    # Athens (Mediterranean buildings and climate, olive and orange trees): Ioannina above differs in climate.
    _("heraklion", 261745, "Heraklion", "GR", "mediterranean", "2810", "HK", arch="ottoman", trees=("olive", "orange"),
      aliases=("Irakleio", "Iráklion"), about="Capital of Crete, a port behind Venetian walls."),
    # Seville (Mediterranean buildings and climate, orange trees and palms): Madrid has other trees.
    _("granada", 2517117, "Granada", "ES", "highland", "958", trees=("orange", "palm"),
      about="City of Andalusia below the Sierra Nevada, crowned by the Alhambra."),
    _("cordoba-es", 2519240, "Córdoba", "ES", "mediterranean", "957", arch="iberian", trees=("orange", "palm"),
      aliases=("Cordoba",), about="City on the Guadalquivir around its great mosque-cathedral."),
    # São Paulo (modern buildings, humid subtropical, camphor/palm/plane).
    _("porto-alegre", 3452925, "Porto Alegre", "BR", "humid_subtropical", "51", trees=("fig", "jacaranda"),
      about="Capital of Rio Grande do Sul on the Guaíba."),
    _("santos", 3449433, "Santos", "BR", "humid_subtropical", "13", arch="latin_colonial", trees=CPP,
      about="Brazil's largest port, on the coast below the plateau."),
    _("goiania", 3462377, "Goiânia", "BR", "tropical", "62", trees=CPP, aliases=("Goiania",),
      about="Planned capital of Goiás on the central plateau."),
]

RIVAL_CITIES: dict[str, City] = {city.key: city for city in RIVAL_CITIES_LIST}
