"""The cities the locations are in: gazetteer id, city-level cues and a few wiki facts.

City-level cues are deliberately realistic: telephone area codes on shop signs, region codes
on number plates, local transport (trams, taxis of a colour), street-sign styles. The wiki
article of each city states the same facts so that an agent can match what it sees.

Over 500 lines because it is a data table (one entry per city, 164 cities), not logic.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .countries import StreetSignStyle

PARIS_SIGN = StreetSignStyle("#1d3557", "#ffffff", "#2e7d32", "wall",
                             "dark blue enamel plaque framed in green with white letters")
MADRID_SIGN = StreetSignStyle("#f3efe2", "#1d3f95", "#b5651d", "wall",
                              "painted ceramic tile plaque with blue letters and a decorated border")
NYC_SIGN = StreetSignStyle("#0b6b2e", "#ffffff", "#ffffff", "pole", "green street sign on a pole")
LONDON_SIGN = StreetSignStyle("#ffffff", "#111111", "#111111", "wall",
                              "white plaque with black letters, the postal district in red")


@dataclass(frozen=True)
class City:
    key: str
    geonameid: int
    name: str  # canonical English name (the task answer)
    iso: str
    climate: str
    area_code: str | None = None  # telephone area code as written locally
    plate_region: str | None = None  # region code or caption on local plates
    aliases: tuple[str, ...] = ()  # names graders accept besides the gazetteer's alternate names
    arch: str | None = None  # overrides the country's building style
    trees: tuple[str, ...] = ()  # overrides the climate's trees
    transport: tuple[str, ...] = ()  # city-level vehicles: "tram:<colour>", "taxi:<colour>", "minibus:<colour>", ...
    sign: StreetSignStyle | None = None
    langs: tuple[str, ...] = ()  # overrides the country's sign languages (regional languages and scripts)
    about: str = ""  # one or two true sentences for the wiki article
    places: dict[str, str] = field(default_factory=dict)  # notable squares/landmarks -> what they look like


_ = City
CITIES_LIST: list[City] = [
    # ------------------------------------------------------------------ Europe
    _("paris", 2988507, "Paris", "FR", "oceanic", "01", sign=PARIS_SIGN,
      about="Capital of France on the Seine, known for its uniform 19th-century limestone apartment blocks with "
            "wrought-iron balconies and grey zinc mansard roofs.",
      places={"Place de la Concorde": "the largest square in Paris, with the 3,000-year-old Luxor Obelisk (its tip "
                                      "gilded) at its centre between two monumental fountains"}),
    _("lyon", 2996944, "Lyon", "FR", "oceanic", "04", transport=("tram:white and grey",),
      about="Third-largest city of France at the confluence of the Rhône and the Saône; the Presqu'île between "
            "them is crossed by the long shopping street Rue de la République."),
    _("marseille", 2995469, "Marseille", "FR", "mediterranean", "04",
      about="France's oldest city and largest Mediterranean port; La Canebière runs down to the Old Port."),
    _("berlin", 2950159, "Berlin", "DE", "continental", "030", "B", transport=("tram:yellow",),
      about="Capital of Germany; plates start with B and the telephone area code is 030."),
    _("munich", 2867714, "Munich", "DE", "continental", "089", "M", aliases=("München", "Muenchen"),
      transport=("tram:blue and white",),
      about="Capital of Bavaria; plates start with M and the area code is 089.",
      places={"Marienplatz": "the central square, dominated by the neo-Gothic New Town Hall with its tall clock "
                             "tower and glockenspiel, and the golden Virgin Mary on the Mariensäule column"}),
    _("hamburg", 2911298, "Hamburg", "DE", "oceanic", "040", "HH",
      about="Germany's largest port, a city-state on the Elbe; plates start with HH (Hansestadt Hamburg) and the "
            "area code is 040. Brick (Backstein) buildings are typical."),
    _("cologne", 2886242, "Cologne", "DE", "oceanic", "0221", "K", aliases=("Köln", "Koln", "Koeln"),
      about="City on the Rhine with a twin-spired Gothic cathedral; plates start with K, area code 0221."),
    _("madrid", 3117735, "Madrid", "ES", "mediterranean", "91", sign=MADRID_SIGN,
      about="Capital of Spain; its street names are on painted ceramic tile plaques, and phone numbers start "
            "with 91.",
      places={"Plaza Mayor": "a rectangular arcaded square of red-brown three-storey buildings with balconies, "
                             "an equestrian bronze statue of King Philip III in its centre"}),
    _("barcelona", 3128760, "Barcelona", "ES", "mediterranean", "93", transport=("taxi:black and yellow",),
      langs=("ca", "es"),
      about="Capital of Catalonia; signs are in Catalan, taxis are black and yellow and phone numbers start with "
            "93. The Eixample district is a grid of blocks with chamfered corners.",
      places={"Sagrada Família": "Gaudí's unfinished basilica, a cluster of tall spindle-shaped stone spires, on "
                                 "Carrer de Mallorca"}),
    _("seville", 2510911, "Seville", "ES", "mediterranean", "954", aliases=("Sevilla",), trees=("orange", "palm"),
      about="Capital of Andalusia; orange trees line its streets and houses are whitewashed with ochre trim."),
    _("valencia", 2509954, "Valencia", "ES", "mediterranean", "96", aliases=("València",),
      langs=("es", "ca"), about="Spain's third-largest city on the Mediterranean; phone numbers start with 96."),
    _("rome", 3169070, "Rome", "IT", "mediterranean", "06", aliases=("Roma",), trees=("umbrella_pine", "plane"),
      about="Capital of Italy; buildings are ochre and terracotta, and umbrella pines line the avenues. Area code "
            "06.",
      places={"Piazza Navona": "a long oval baroque square with Bernini's Fountain of the Four Rivers, crowned by "
                               "an Egyptian-style obelisk, in front of a domed church"}),
    _("milan", 3173435, "Milan", "IT", "humid_subtropical", "02", aliases=("Milano",),
      transport=("tram:orange",), about="Capital of Lombardy; orange trams run through the city. Area code 02."),
    _("naples", 3172394, "Naples", "IT", "mediterranean", "081", aliases=("Napoli",),
      about="Capital of Campania on the Bay of Naples, with Vesuvius behind; area code 081."),
    _("florence", 3176959, "Florence", "IT", "mediterranean", "055", aliases=("Firenze",),
      about="Capital of Tuscany and cradle of the Renaissance; area code 055."),
    _("london", 2643743, "London", "GB", "oceanic", "020", sign=LONDON_SIGN,
      transport=("double_decker:red", "taxi:black cab"),
      about="Capital of the United Kingdom; red double-decker buses and black cabs, area code 020.",
      places={"Trafalgar Square": "a large square with Nelson's Column, a tall granite column topped by a statue "
                                  "and guarded by four bronze lions, and fountains"}),
    _("manchester", 2643123, "Manchester", "GB", "oceanic", "0161", transport=("tram:yellow",),
      about="City in north-west England known for red-brick Victorian warehouses; yellow Metrolink trams, area "
            "code 0161."),
    _("edinburgh", 2650225, "Edinburgh", "GB", "oceanic", "0131", arch="stone_terrace",
      transport=("tram:white and red",),
      about="Capital of Scotland, built of grey sandstone; area code 0131. Princes Street faces the castle rock; "
            "the Royal Mile (High Street) climbs to the castle."),
    _("dublin", 2964574, "Dublin", "IE", "oceanic", "01", "D", transport=("tram:silver",),
      about="Capital of Ireland on the Liffey; Georgian red-brick terraces, Luas trams, area code 01, plates "
            "with D.",
      places={"The Spire": "a 120-metre stainless-steel needle, the Monument of Light, in the middle of O'Connell "
                           "Street"}),
    _("lisbon", 2267057, "Lisbon", "PT", "mediterranean", "21", aliases=("Lisboa",), transport=("tram:yellow",),
      about="Capital of Portugal, on hills above the Tagus; yellow trams and tiled facades. Numbers start with 21.",
      places={"Praça do Comércio": "a vast riverside square enclosed on three sides by yellow arcaded buildings, "
                                   "with a triumphal arch (Arco da Rua Augusta) and an equestrian statue of King "
                                   "José I"}),
    _("porto", 2735943, "Porto", "PT", "mediterranean", "22", aliases=("Oporto",),
      about="Portugal's second city on the Douro, with steep streets and tile-covered churches; numbers start with "
            "22."),
    _("amsterdam", 2759794, "Amsterdam", "NL", "oceanic", "020", transport=("tram:white and blue", "bicycles"),
      about="Capital of the Netherlands with narrow gabled canal houses; trams and bicycles everywhere, area code "
            "020."),
    _("rotterdam", 2747891, "Rotterdam", "NL", "oceanic", "010", arch="modernist",
      transport=("tram:grey and red", "bicycles"),
      about="Port city rebuilt after 1940 with modern architecture; area code 010."),
    _("brussels", 2800866, "Brussels", "BE", "oceanic", "02", aliases=("Bruxelles", "Brussel"),
      about="Capital of Belgium; street names are in French and Dutch (Rue Neuve / Nieuwstraat). Area code 02."),
    _("zurich", 2657896, "Zurich", "CH", "continental", "044", "ZH", aliases=("Zürich", "Zuerich"),
      transport=("tram:blue and white",),
      about="Switzerland's largest city; blue-and-white trams run along the Bahnhofstrasse. Plates ZH, area code "
            "044."),
    _("vienna", 2761369, "Vienna", "AT", "continental", "01", "W", aliases=("Wien",),
      transport=("tram:red and white",),
      about="Capital of Austria with grand imperial buildings; plates start with W, area code 01."),
    _("warsaw", 756135, "Warsaw", "PL", "continental", "22", "WA", aliases=("Warszawa",),
      about="Capital of Poland; plates start with W (WA to WZ), area code 22."),
    _("krakow", 3094802, "Kraków", "PL", "continental", "12", "KR", aliases=("Krakow", "Cracow"),
      transport=("tram:blue",),
      about="Poland's former royal capital with a medieval old town; plates KR, area code 12."),
    _("prague", 3067696, "Prague", "CZ", "continental", None, "A", aliases=("Praha", "Prag"),
      transport=("tram:red and cream",),
      about="Capital of Czechia; red street plaques, red-and-cream trams.",
      places={"Wenceslas Square": "a long, wide boulevard-square sloping up to the domed National Museum, with the "
                                  "equestrian statue of Saint Wenceslas in front of it"}),
    _("budapest", 3054643, "Budapest", "HU", "continental", "1", transport=("tram:yellow",),
      about="Capital of Hungary on the Danube; yellow trams, area code 1."),
    _("athens", 264371, "Athens", "GR", "mediterranean", "210", "Y", aliases=("Athina", "Αθήνα"),
      trees=("orange", "olive"),
      about="Capital of Greece below the Acropolis; white concrete apartment blocks with awnings over balconies; "
            "numbers start with 210."),
    _("thessaloniki", 734077, "Thessaloniki", "GR", "mediterranean", "2310", "N",
      aliases=("Salonica", "Salonika", "Θεσσαλονίκη", "Thessaloníki"),
      about="Greece's second city on the Thermaic Gulf; numbers start with 2310."),
    _("moscow", 524901, "Moscow", "RU", "continental", "495", "77", aliases=("Moskva", "Москва"),
      about="Capital of Russia; plates end in 77, 97, 99 or 177, phone area codes 495 and 499.",
      places={"Red Square": "a vast cobbled square beside the red-brick Kremlin walls and towers, with the "
                            "colourful onion domes of Saint Basil's Cathedral at one end"}),
    _("saint-petersburg", 498817, "Saint Petersburg", "RU", "nordic", "812", "78",
      aliases=("St. Petersburg", "St Petersburg", "Sankt-Peterburg", "Санкт-Петербург", "Leningrad", "Petersburg"),
      transport=("trolleybus:blue",),
      about="Russia's second city on the Neva, with baroque and neoclassical palaces in pastel colours; plates "
            "78, 98 or 178, area code 812."),
    _("kyiv", 703448, "Kyiv", "UA", "continental", "44", "AA", aliases=("Kiev", "Київ"),
      about="Capital of Ukraine on the Dnipro; Khreshchatyk is lined with monumental post-war buildings. Plates "
            "AA or KA, area code 44."),
    _("stockholm", 2673730, "Stockholm", "SE", "nordic", "08",
      about="Capital of Sweden on islands between lake Mälaren and the Baltic; area code 08."),
    _("oslo", 3143244, "Oslo", "NO", "nordic", None, transport=("tram:blue",),
      about="Capital of Norway at the head of the Oslofjord; Karl Johans gate leads to the Royal Palace."),
    _("copenhagen", 2618425, "Copenhagen", "DK", "oceanic", None, aliases=("København", "Kobenhavn"),
      transport=("bicycles",), about="Capital of Denmark; cyclists everywhere and the pedestrian Strøget."),
    _("helsinki", 658225, "Helsinki", "FI", "nordic", "09", aliases=("Helsingfors",),
      transport=("tram:green and white",),
      about="Capital of Finland; street signs give Finnish and Swedish names, green-and-white trams, area code 09."),
    _("reykjavik", 3413829, "Reykjavík", "IS", "nordic", None, aliases=("Reykjavik",), trees=("birch",),
      about="Capital of Iceland; small houses clad in brightly painted corrugated iron, few trees."),
    _("bucharest", 683506, "Bucharest", "RO", "continental", "021", "B", aliases=("București", "Bucuresti"),
      about="Capital of Romania; plates start with B alone, area code 021."),
    _("sofia", 727011, "Sofia", "BG", "continental", "2", "CA", aliases=("София", "Sofiya"),
      about="Capital of Bulgaria below Mount Vitosha; plates start with C, CA or CB, area code 2."),
    _("belgrade", 792680, "Belgrade", "RS", "continental", "011", "BG", aliases=("Beograd", "Београд"),
      about="Capital of Serbia at the confluence of the Sava and the Danube; plates BG, area code 011."),
    _("zagreb", 3186886, "Zagreb", "HR", "continental", "01", "ZG", transport=("tram:blue",),
      about="Capital of Croatia; blue trams run along Ilica. Plates ZG, area code 01."),
    _("istanbul", 745044, "Istanbul", "TR", "mediterranean", "212", "34",
      aliases=("İstanbul", "Constantinople", "Stambul"), transport=("tram:red",),
      about="Turkey's largest city on both sides of the Bosphorus; the European side's area code is 212 and "
            "plates start with 34. A red nostalgic tram runs along İstiklal Avenue.",
      places={"Sultanahmet Square": "the former Hippodrome, with an ancient Egyptian obelisk, facing domed mosques "
                                    "with slender pencil minarets"}),
    _("vilnius", 593116, "Vilnius", "LT", "nordic", "5",
      about="Capital of Lithuania with a baroque old town; Gediminas Avenue is the main street. Area code 5."),
    _("tallinn", 588409, "Tallinn", "EE", "nordic", None,
      about="Capital of Estonia with a walled medieval old town; Viru Street leads through the Viru Gate."),
    _("riga", 456172, "Riga", "LV", "nordic", None, aliases=("Rīga",), transport=("trolleybus:red",),
      about="Capital of Latvia, famous for its Art Nouveau buildings; Brīvības iela leads to the Freedom "
            "Monument."),
    _("tbilisi", 611717, "Tbilisi", "GE", "humid_subtropical", "32", aliases=("Tiflis", "თბილისი"),
      about="Capital of Georgia on the Kura river, with carved wooden balconies in the old town; Rustaveli Avenue "
            "is the main boulevard. Area code 32."),
    _("yerevan", 616052, "Yerevan", "AM", "semi_arid", "10", aliases=("Erevan", "Երևան"), arch="tuff",
      about="Capital of Armenia, called the Pink City for its buildings of pink volcanic tuff; area code 10."),
    _("nicosia", 146268, "Nicosia", "CY", "mediterranean", "22", aliases=("Lefkosia", "Λευκωσία", "Lefkoşa"),
      about="Capital of Cyprus, a divided city inside Venetian walls; Ledra Street leads to the crossing point."),
    # ------------------------------------------------------------------ Asia
    _("tokyo", 1850147, "Tokyo", "JP", "humid_subtropical", "03", "品川", aliases=("Tōkyō", "東京"),
      trees=("ginkgo", "zelkova"),
      about="Capital of Japan; area code 03, plates from the Shinagawa (品川) or Nerima (練馬) offices."),
    _("osaka", 1853909, "Osaka", "JP", "humid_subtropical", "06", "なにわ", aliases=("Ōsaka", "大阪"),
      trees=("ginkgo",),
      about="Japan's third-largest city; Midōsuji boulevard is lined with ginkgo trees. Area code 06, plates "
            "なにわ (Naniwa) or 大阪."),
    _("kyoto", 1857910, "Kyoto", "JP", "humid_subtropical", "075", "京都", aliases=("Kyōto", "京都"),
      arch="machiya",
      about="Former imperial capital with wooden townhouses (machiya); area code 075, plates 京都."),
    _("seoul", 1835848, "Seoul", "KR", "continental", "02", aliases=("서울",), trees=("ginkgo",),
      about="Capital of South Korea; ginkgo trees line the avenues. Area code 02.",
      places={"Gwanghwamun Square": "a long plaza on Sejong-daero with a large golden seated statue of King Sejong "
                                    "in front of the Gwanghwamun palace gate with its tiled roof"}),
    _("busan", 1838524, "Busan", "KR", "humid_subtropical", "051", aliases=("Pusan", "부산"),
      about="South Korea's largest port; area code 051."),
    _("beijing", 1816670, "Beijing", "CN", "continental", "010", "京A", aliases=("Peking", "北京"),
      trees=("willow", "locust"),
      about="Capital of China; plates start with 京, area code 010.",
      places={"Tiananmen Square": "an immense paved square before the red Gate of Heavenly Peace with its "
                                  "yellow-tiled roof and a large portrait"}),
    _("shanghai", 1796236, "Shanghai", "CN", "humid_subtropical", "021", "沪A", aliases=("上海",),
      trees=("plane",), about="China's largest city; plates start with 沪, area code 021. Plane trees shade the "
                              "old streets."),
    _("guangzhou", 1809858, "Guangzhou", "CN", "humid_subtropical", "020", "粤A", aliases=("Canton", "广州"),
      arch="shophouse", trees=("banyan",),
      about="Capital of Guangdong; arcaded shophouses (qilou) and banyan trees; plates 粤A, area code 020."),
    _("taipei", 1668341, "Taipei", "TW", "humid_subtropical", "02", aliases=("臺北", "台北", "Taipei City"),
      transport=("motorbikes",), about="Capital of Taiwan; streets crowded with scooters. Area code 02."),
    _("hong-kong", 1819729, "Hong Kong", "HK", "humid_subtropical", None, aliases=("香港", "Kowloon"),
      transport=("double_decker:white and red", "taxi:red"),
      about="Dense high-rise city with bilingual signs, red taxis and double-decker buses and trams."),
    _("bangkok", 1609350, "Bangkok", "TH", "tropical", "2", "กรุงเทพมหานคร",
      aliases=("Krung Thep", "Krung Thep Maha Nakhon", "กรุงเทพมหานคร"),
      transport=("tuk_tuk", "taxi:pink", "skytrain"),
      about="Capital of Thailand; plates read กรุงเทพมหานคร, phone numbers start with 02. The BTS Skytrain runs "
            "above Sukhumvit Road."),
    _("chiang-mai", 1153671, "Chiang Mai", "TH", "tropical", "53", "เชียงใหม่", aliases=("เชียงใหม่",),
      transport=("songthaew:red",),
      about="Northern Thai city with a moated old town; red songthaew pick-up taxis, plates เชียงใหม่, area code 053."),
    _("hanoi", 1581130, "Hanoi", "VN", "humid_subtropical", "24", "30", aliases=("Hà Nội", "Ha Noi"),
      transport=("motorbikes",),
      about="Capital of Vietnam; the Old Quarter's streets are named after crafts (Hàng Bạc = silver). Plates "
            "29 to 33, area code 024."),
    _("ho-chi-minh-city", 1566083, "Ho Chi Minh City", "VN", "tropical", "28", "51",
      aliases=("Saigon", "Sài Gòn", "HCMC", "Thành phố Hồ Chí Minh"), transport=("motorbikes",),
      about="Vietnam's largest city; plates 50 to 59, area code 028."),
    _("phnom-penh", 1821306, "Phnom Penh", "KH", "tropical", "23", "PHNOM PENH", aliases=("ភ្នំពេញ",),
      transport=("tuk_tuk",),
      about="Capital of Cambodia at the confluence of the Mekong and Tonlé Sap; Sisowath Quay is the riverfront."),
    _("kuala-lumpur", 1735161, "Kuala Lumpur", "MY", "tropical", "3", "W", aliases=("KL",),
      about="Capital of Malaysia; plates start with W, area code 03.",
      places={"Petronas Twin Towers": "two 452-metre steel-clad skyscrapers joined by a skybridge, on Jalan Ampang"}),
    _("singapore", 1880252, "Singapore", "SG", "tropical", None, aliases=("Singapura",),
      about="City-state; Orchard Road is its shopping boulevard, lined with rain trees."),
    _("jakarta", 1642911, "Jakarta", "ID", "tropical", "021", "B", aliases=("Djakarta", "Batavia"),
      transport=("motorbikes",), about="Capital of Indonesia; plates start with B, area code 021."),
    _("yogyakarta", 1621177, "Yogyakarta", "ID", "tropical", "0274", "AB", aliases=("Jogja", "Jogjakarta", "Yogya"),
      transport=("becak", "motorbikes"),
      about="Javanese cultural capital. Plates AB, area code 0274."),
    _("manila", 1701668, "Manila", "PH", "tropical", "2", aliases=("Maynila",), transport=("jeepney",),
      about="Capital of the Philippines; jeepneys fill the streets. Area code 02."),
    _("mumbai", 1275339, "Mumbai", "IN", "tropical", "22", "MH 01", aliases=("Bombay",),
      arch="colonial_south_asian", transport=("taxi:black and yellow",),
      langs=("mr", "en-in"),
      about="India's financial capital; signs in Marathi and English, black-and-yellow taxis, plates MH 01 to MH "
            "03, area code 022."),
    _("new-delhi", 1261481, "New Delhi", "IN", "semi_arid", "11", "DL", aliases=("Delhi", "Dilli", "नई दिल्ली"),
      transport=("auto_rickshaw:green and yellow",),
      langs=("hi", "en-in"),
      about="Capital of India within Delhi; plates DL, area code 011, green-and-yellow auto-rickshaws run on CNG."),
    _("bengaluru", 1277333, "Bengaluru", "IN", "tropical", "80", "KA 01", aliases=("Bangalore",),
      transport=("auto_rickshaw:green and yellow",),
      langs=("kn", "en-in"), about="Capital of Karnataka; signs in Kannada and English, plates KA, area code 080."),
    _("kolkata", 1275004, "Kolkata", "IN", "tropical", "33", "WB", aliases=("Calcutta",),
      transport=("taxi:yellow",), arch="colonial_south_asian",
      langs=("bn", "en-in"),
      about="Capital of West Bengal; yellow Ambassador taxis, signs in Bengali and English, plates WB, area code "
            "033."),
    _("chennai", 1264527, "Chennai", "IN", "tropical", "44", "TN", aliases=("Madras",),
      transport=("auto_rickshaw:yellow",),
      langs=("ta", "en-in"), about="Capital of Tamil Nadu; signs in Tamil and English, plates TN, area code 044."),
    _("chattogram", 1205733, "Chattogram", "BD", "tropical", "31", "চট্ট মেট্রো",
      aliases=("Chittagong", "Chottogram", "চট্টগ্রাম"), transport=("cycle_rickshaw", "auto_rickshaw:green"),
      about="Bangladesh's main port city; plates read চট্ট মেট্রো, area code 031."),
    _("dhaka", 1185241, "Dhaka", "BD", "tropical", "2", "ঢাকা মেট্রো", aliases=("Dacca", "ঢাকা"),
      transport=("cycle_rickshaw", "auto_rickshaw:green"),
      about="Capital of Bangladesh, famous for its cycle rickshaws; plates read ঢাকা মেট্রো, area code 02."),
    _("lahore", 1172451, "Lahore", "PK", "semi_arid", "42", aliases=("لاہور",), transport=("auto_rickshaw:blue",),
      about="Capital of Punjab province with Mughal monuments; The Mall is its colonial main road. Area code 042."),
    _("karachi", 1174872, "Karachi", "PK", "arid", "21", aliases=("کراچی",), transport=("painted_bus",),
      about="Pakistan's largest city and port; I. I. Chundrigar Road is its financial street. Area code 021."),
    _("colombo", 1248991, "Colombo", "LK", "tropical", "11", "WP", aliases=("කොළඹ", "கொழும்பு"),
      transport=("tuk_tuk",),
      langs=("si", "ta", "en-gb"),
      about="Commercial capital of Sri Lanka; Galle Road runs along the coast. Plates WP, area code 011."),
    _("kathmandu", 1283240, "Kathmandu", "NP", "highland", "1", "बा", aliases=("काठमाडौं", "Kantipur"),
      about="Capital of Nepal in a Himalayan valley; Durbar Marg leads to the former royal palace. Area code 01."),
    _("dubai", 292223, "Dubai", "AE", "arid", "4", "DUBAI", aliases=("دبي",),
      about="Largest city of the UAE; plates read DUBAI, area code 04.",
      places={"Burj Khalifa": "the world's tallest building, a tapering silver spire of 828 metres rising from "
                              "Downtown Dubai"}),
    _("tel-aviv", 293397, "Tel Aviv", "IL", "mediterranean", "3", aliases=("Tel Aviv-Yafo", "תל אביב"),
      arch="bauhaus", about="Israel's economic centre, the White City of Bauhaus buildings; area code 03."),
    _("amman", 250441, "Amman", "JO", "semi_arid", "6", aliases=("عمّان", "عمان"),
      about="Capital of Jordan on hills of white limestone buildings; area code 06."),
    _("beirut", 276781, "Beirut", "LB", "mediterranean", "1", aliases=("Beyrouth", "بيروت"),
      about="Capital of Lebanon; Hamra Street is the shopping street of West Beirut. Area code 01."),
    _("tehran", 112931, "Tehran", "IR", "semi_arid", "21", "۱۱", aliases=("Teheran", "تهران"),
      trees=("plane",), about="Capital of Iran below the Alborz mountains; Valiasr Street, lined with plane trees, "
                              "is among the longest streets in the Middle East. Area code 021.",
      places={"Azadi Tower": "a white marble monument shaped like an inverted Y, with a great arch, in Azadi Square"}),
    _("riyadh", 108410, "Riyadh", "SA", "arid", "11", aliases=("الرياض", "Ar-Riyad"),
      about="Capital of Saudi Arabia; Olaya Street is its business spine. Area code 011."),
    _("ankara", 323786, "Ankara", "TR", "continental", "312", "06",
      about="Capital of Turkey on the Anatolian plateau; plates start with 06, area code 312."),
    _("almaty", 1526384, "Almaty", "KZ", "continental", "727", "02", aliases=("Alma-Ata", "Алматы"),
      about="Kazakhstan's largest city at the foot of the Tian Shan; plates end in 02, area code 727."),
    _("tashkent", 1512569, "Tashkent", "UZ", "continental", "71", "01", aliases=("Toshkent", "Ташкент"),
      about="Capital of Uzbekistan; plates start with 01, area code 71."),
    _("ulaanbaatar", 2028462, "Ulaanbaatar", "MN", "continental", "11", "УБ",
      aliases=("Ulan Bator", "Ulaanbaatar", "Улаанбаатар"),
      about="Capital of Mongolia; Peace Avenue crosses the city east to west. Plates carry УБ."),
    # ------------------------------------------------------------------ Africa
    _("cairo", 360630, "Cairo", "EG", "arid", "2", aliases=("القاهرة", "Al-Qahira"),
      about="Capital of Egypt; downtown (Wust El Balad) has European-style buildings on Talaat Harb Street. Area "
            "code 02."),
    _("alexandria", 361058, "Alexandria", "EG", "mediterranean", "3", aliases=("الإسكندرية", "Iskandariya"),
      transport=("tram:blue and yellow",),
      about="Egypt's Mediterranean port; El Horreya Road (formerly Fouad Street) is the ancient Canopic Way. Area "
            "code 03."),
    _("marrakesh", 2542997, "Marrakesh", "MA", "semi_arid", "524", aliases=("Marrakech", "مراكش"),
      arch="north_african",
      about="Red-ochre city at the foot of the Atlas; area code 0524.",
      places={"Jemaa el-Fnaa": "a vast open square full of food stalls and performers, overlooked by the tall "
                               "square minaret of the Koutoubia Mosque"}),
    _("casablanca", 2553604, "Casablanca", "MA", "mediterranean", "522", aliases=("Dar el Beida", "الدار البيضاء"),
      arch="french_colonial", about="Morocco's largest city, known for white art-deco buildings; area code 0522."),
    _("tunis", 2464470, "Tunis", "TN", "mediterranean", "71", aliases=("تونس",), arch="french_colonial",
      about="Capital of Tunisia; Avenue Habib Bourguiba is a tree-lined colonial boulevard. Area code 71."),
    _("algiers", 2507480, "Algiers", "DZ", "mediterranean", "21", "16", aliases=("Alger", "الجزائر", "El Djazair"),
      about="Capital of Algeria, 'Alger la Blanche'; plates end in 16, area code 021."),
    _("dakar", 2253354, "Dakar", "SN", "semi_arid", "33", "DK", transport=("taxi:yellow and black",),
      about="Capital of Senegal on the Cap-Vert peninsula; plates DK, numbers start with 33."),
    _("abidjan", 2293538, "Abidjan", "CI", "tropical", "27 20", "01", transport=("taxi:orange",),
      about="Economic capital of Ivory Coast; the Plateau is its business district. Orange taxis, plates ending "
            "in 01."),
    _("accra", 2306104, "Accra", "GH", "tropical", "30", "GR", transport=("minibus:trotro",),
      about="Capital of Ghana; Oxford Street in Osu is its busiest shopping street. Plates start with GR, area "
            "code 030."),
    _("lagos", 2332459, "Lagos", "NG", "tropical", "1", "LAGOS", transport=("minibus:yellow",),
      about="Nigeria's largest city; yellow danfo minibuses, plates with LAGOS across the top, area code 01."),
    _("nairobi", 184745, "Nairobi", "KE", "highland", "20", transport=("matatu",), trees=("jacaranda", "eucalyptus"),
      about="Capital of Kenya at 1,795 m; area code 020."),
    _("mombasa", 186301, "Mombasa", "KE", "tropical", "41", transport=("tuk_tuk", "matatu"),
      about="Kenya's coastal port with a Swahili old town; Moi Avenue is crossed by the famous aluminium "
            "elephant-tusk arches. Area code 041."),
    _("dar-es-salaam", 160263, "Dar es Salaam", "TZ", "tropical", "22", aliases=("Dar", "Dar-es-Salaam"),
      transport=("minibus:dala dala", "tuk_tuk"),
      about="Tanzania's largest city and port; area code 022."),
    _("kampala", 232422, "Kampala", "UG", "tropical", "414", transport=("boda_boda",),
      about="Capital of Uganda on hills near Lake Victoria; area code 0414."),
    _("addis-ababa", 344979, "Addis Ababa", "ET", "highland", "11", "AA", aliases=("Addis Abeba", "አዲስ አበባ",
                                                                                     "Finfinne"),
      transport=("minibus:blue and white",), trees=("eucalyptus",),
      about="Capital of Ethiopia at 2,355 m; blue-and-white minibus taxis, plates with AA, area code 011."),
    _("cape-town", 3369157, "Cape Town", "ZA", "mediterranean", "21", "CA ###-###", aliases=("Kaapstad",),
      about="South Africa's legislative capital below Table Mountain; plates start with CA, area code 021. Long "
            "Street has Victorian buildings with iron balconies."),
    _("johannesburg", 993800, "Johannesburg", "ZA", "highland", "11", "@@ ## @@ GP",
      aliases=("Joburg", "Jozi", "eGoli"), trees=("jacaranda",), transport=("minibus:white",),
      about="South Africa's largest city, in Gauteng; plates end in GP, area code 011."),
    _("durban", 1007311, "Durban", "ZA", "humid_subtropical", "31", "ND ###-###", aliases=("eThekwini",),
      about="Port city in KwaZulu-Natal; plates start with ND, area code 031."),
    _("windhoek", 3352136, "Windhoek", "NA", "semi_arid", "61", "W", trees=("acacia",),
      about="Capital of Namibia; German colonial buildings on Independence Avenue, plates ending in W, area code "
            "061."),
    _("harare", 890299, "Harare", "ZW", "highland", "242", trees=("jacaranda",),
      about="Capital of Zimbabwe; avenues lined with jacarandas. Area code 0242."),
    _("lusaka", 909137, "Lusaka", "ZM", "highland", "211", transport=("minibus:blue",),
      about="Capital of Zambia; Cairo Road is its commercial spine. Area code 0211."),
    _("maputo", 1040652, "Maputo", "MZ", "tropical", "21", "MC", aliases=("Lourenço Marques",),
      trees=("jacaranda", "flamboyant"), transport=("minibus:chapa",),
      about="Capital of Mozambique; avenues named after dates and revolutionaries, plates ending in MC."),
    _("luanda", 2240449, "Luanda", "AO", "semi_arid", "222", "LD", transport=("minibus:blue and white",),
      about="Capital of Angola; the Marginal (Avenida 4 de Fevereiro) follows the bay. Plates start with LD."),
    _("antananarivo", 1070940, "Antananarivo", "MG", "highland", "20 22", aliases=("Tana", "Tananarive"),
      transport=("taxi:beige",),
      about="Capital of Madagascar on hills; beige Renault 4 taxis climb its streets."),
    _("port-louis", 934154, "Port Louis", "MU", "tropical", None,
      about="Capital of Mauritius; Royal Street (Rue Royale) runs through Chinatown."),
    # ------------------------------------------------------------------ North America
    _("new-york", 5128581, "New York City", "US", "humid_subtropical", "212", "NEW YORK",
      aliases=("New York", "NYC", "Manhattan", "NY"), sign=NYC_SIGN, transport=("taxi:yellow",),
      trees=("ginkgo", "linden", "plane"),
      about="Largest city of the United States; yellow cabs, area code 212 for Manhattan, plates NEW YORK.",
      places={"Times Square": "a bow-tie-shaped plaza where Broadway crosses Seventh Avenue, walled with giant "
                              "illuminated billboards and screens"}),
    _("chicago", 4887398, "Chicago", "US", "continental", "312", "ILLINOIS",
      about="Third-largest US city on Lake Michigan; area code 312, plates ILLINOIS."),
    _("san-francisco", 5391959, "San Francisco", "US", "mediterranean", "415", "CALIFORNIA", aliases=("SF",),
      transport=("tram:historic streetcar",),
      about="Hilly city on the Golden Gate; Market Street carries historic streetcars. Area code 415."),
    _("los-angeles", 5368361, "Los Angeles", "US", "mediterranean", "323", "CALIFORNIA", aliases=("LA", "L.A."),
      trees=("fan_palm",),
      about="Second-largest US city; Hollywood Boulevard has the Walk of Fame stars in its pavement. Area code "
            "323."),
    _("new-orleans", 4335045, "New Orleans", "US", "humid_subtropical", "504", "LOUISIANA", aliases=("NOLA",),
      arch="creole",
      langs=("en-us",),
      about="Louisiana city on the Mississippi; the French Quarter's Creole townhouses have cast-iron galleries. "
            "Area code 504."),
    _("boston", 4930956, "Boston", "US", "continental", "617", "MASSACHUSETTS",
      about="Capital of Massachusetts; Back Bay's Newbury Street is lined with brownstones. Area code 617."),
    _("miami", 4164138, "Miami", "US", "tropical", "305", "FLORIDA",
      langs=("es-la", "en-us"),
      about="Florida city with a large Cuban community in Little Havana (Calle Ocho); area code 305."),
    _("washington", 4140963, "Washington", "US", "humid_subtropical", "202", "DISTRICT OF COLUMBIA",
      aliases=("Washington, D.C.", "Washington DC", "Washington D.C."), trees=("ginkgo", "linden", "maple", "plane"),
      about="Capital of the United States, laid out on a grid cut by broad diagonal avenues; a height limit keeps "
            "its buildings low, so the domes and monuments of the federal city dominate the skyline."),
    _("austin", 4671654, "Austin", "US", "humid_subtropical", "512", "TEXAS",
      about="Capital of Texas on the Colorado River, a fast-growing city of glass office towers around a "
            "pink-granite capitol."),
    _("seattle", 5809844, "Seattle", "US", "oceanic", "206", "WASHINGTON",
      about="Largest city of Washington state; Pike Street leads down to Pike Place Market. Area code 206."),
    _("toronto", 6167865, "Toronto", "CA", "continental", "416", "ONTARIO", transport=("tram:red",),
      langs=("en-us",), about="Canada's largest city; red streetcars, area code 416, plates ONTARIO."),
    _("montreal", 6077243, "Montreal", "CA", "continental", "514", "QUÉBEC", aliases=("Montréal",),
      langs=("fr-ca",),
      about="Largest city of Quebec; signs in French, exterior staircases on row houses, area code 514."),
    _("vancouver", 6173331, "Vancouver", "CA", "oceanic", "604", "BRITISH COLUMBIA",
      langs=("en-us",),
      about="Pacific port city in British Columbia; Granville Street is its entertainment strip. Area code 604."),
    _("mexico-city", 3530597, "Mexico City", "MX", "highland", "55", "CIUDAD DE MÉXICO",
      aliases=("Ciudad de México", "CDMX", "México", "Mexico D.F.", "Distrito Federal"),
      transport=("taxi:pink and white",), trees=("jacaranda",),
      about="Capital of Mexico at 2,240 m; pink-and-white taxis, area code 55.",
      places={"Zócalo": "the immense Plaza de la Constitución with a giant national flag on a flagpole, the "
                        "Metropolitan Cathedral and the National Palace"}),
    _("guadalajara", 4005539, "Guadalajara", "MX", "humid_subtropical", "33", "JALISCO",
      about="Capital of Jalisco; area code 33."),
    _("oaxaca", 3522507, "Oaxaca", "MX", "highland", "951", "OAXACA", aliases=("Oaxaca de Juárez",),
      about="Colonial city of green stone (cantera) buildings; the pedestrian Macedonio Alcalá street leads to "
            "Santo Domingo church. Area code 951."),
    _("guatemala-city", 3598132, "Guatemala City", "GT", "highland", None,
      aliases=("Ciudad de Guatemala", "Guatemala", "Guate"), transport=("chicken_bus",),
      about="Capital of Guatemala; Sexta Avenida is the historic shopping street of Zona 1."),
    _("havana", 3553478, "Havana", "CU", "tropical", "7", aliases=("La Habana", "Habana"),
      transport=("classic_car",),
      about="Capital of Cuba; colonnaded colonial buildings and 1950s American cars. Calle Obispo crosses Old "
            "Havana."),
    _("san-jose", 3621849, "San José", "CR", "highland", None, aliases=("San Jose",), transport=("taxi:red",),
      about="Capital of Costa Rica; red taxis, and the pedestrian Avenida Central."),
    _("panama-city", 3703443, "Panama City", "PA", "tropical", None, aliases=("Ciudad de Panamá", "Panamá"),
      about="Capital of Panama; skyscrapers line Avenida Balboa along the bay."),
    _("santo-domingo", 3492908, "Santo Domingo", "DO", "tropical", "809",
      about="Capital of the Dominican Republic; Calle El Conde is the pedestrian street of the Colonial Zone."),
    _("kingston", 3489854, "Kingston", "JM", "tropical", None,
      about="Capital of Jamaica; Knutsford Boulevard is the hub of New Kingston."),
    # ------------------------------------------------------------------ South America
    _("rio-de-janeiro", 3451190, "Rio de Janeiro", "BR", "tropical", "21", aliases=("Rio",),
      about="Brazil's former capital; Avenida Atlântica follows Copacabana beach with its wave-patterned mosaic "
            "promenade. Area code 21."),
    _("sao-paulo", 3448439, "São Paulo", "BR", "humid_subtropical", "11", aliases=("Sao Paulo", "Sampa"),
      arch="latin_modern", about="Brazil's largest city; Avenida Paulista is its skyscraper avenue. Area code 11."),
    _("salvador", 3450554, "Salvador", "BR", "tropical", "71", aliases=("Salvador da Bahia",),
      arch="latin_colonial", about="Capital of Bahia with a colourful colonial Pelourinho; area code 71."),
    _("curitiba", 3464975, "Curitiba", "BR", "oceanic", "41", trees=("araucaria",),
      about="Capital of Paraná; Rua XV de Novembro (Rua das Flores) was Brazil's first pedestrian mall. Area code "
            "41."),
    _("buenos-aires", 3435910, "Buenos Aires", "AR", "humid_subtropical", "11", aliases=("Capital Federal", "CABA"),
      arch="haussmann", transport=("taxi:black and yellow",), trees=("jacaranda", "plane"),
      about="Capital of Argentina with Parisian-style buildings; black-and-yellow taxis, area code 11.",
      places={"Obelisco": "a white 67-metre obelisk standing in the middle of the very wide Avenida 9 de Julio"}),
    _("mendoza", 3844421, "Mendoza", "AR", "semi_arid", "261", trees=("plane",),
      about="Wine city at the foot of the Andes; streets shaded by trees watered by open irrigation channels "
            "(acequias). Area code 261."),
    _("santiago", 3871336, "Santiago", "CL", "mediterranean", "2", aliases=("Santiago de Chile",),
      about="Capital of Chile below the Andes; Paseo Ahumada is a pedestrian street in the centre."),
    _("lima", 3936456, "Lima", "PE", "arid", "1",
      about="Capital of Peru on a desert coast under grey skies; Jirón de la Unión links its two main squares. "
            "Area code 01."),
    _("cusco", 3941584, "Cusco", "PE", "highland", "84", aliases=("Cuzco", "Qusqu"),
      about="Former Inca capital at 3,400 m; Spanish buildings on Inca stone walls. Area code 084."),
    _("bogota", 3688689, "Bogotá", "CO", "highland", "601", "BOGOTÁ D.C.", aliases=("Bogota", "Santa Fe de Bogotá"),
      transport=("taxi:yellow",),
      about="Capital of Colombia at 2,640 m; Carrera Séptima is its historic avenue. Plates say BOGOTÁ D.C."),
    _("medellin", 3674962, "Medellín", "CO", "highland", "604", "MEDELLÍN", aliases=("Medellin",),
      about="Colombia's second city in the Aburrá valley; red-brick buildings climb the hillsides."),
    _("quito", 3652462, "Quito", "EC", "highland", "2", "P",
      about="Capital of Ecuador at 2,850 m; plates start with P (Pichincha)."),
    _("la-paz", 3911925, "La Paz", "BO", "highland", "2", aliases=("Nuestra Señora de La Paz",),
      transport=("minibus:white",),
      about="Seat of Bolivia's government at 3,640 m, in a canyon; El Prado (Avenida 16 de Julio) is its main "
            "avenue."),
    _("montevideo", 3441575, "Montevideo", "UY", "humid_subtropical", "2", "S",
      about="Capital of Uruguay; Avenida 18 de Julio is the main avenue. Plates start with S."),
    _("caracas", 3646738, "Caracas", "VE", "tropical", "212",
      about="Capital of Venezuela in a valley below El Ávila; Sabana Grande is a pedestrian boulevard. Area code "
            "0212."),
    _("asuncion", 3439389, "Asunción", "PY", "humid_subtropical", "21", aliases=("Asuncion",),
      about="Capital of Paraguay on the Paraguay River; Calle Palma is the historic shopping street."),
    # ------------------------------------------------------------------ Oceania
    _("sydney", 2147714, "Sydney", "AU", "humid_subtropical", "02", "NSW",
      about="Australia's largest city; plates say NSW, area code 02."),
    _("melbourne", 2158177, "Melbourne", "AU", "oceanic", "03", "VIC", transport=("tram:green and white",),
      about="Capital of Victoria with the largest tram network in the world; plates VIC, area code 03."),
    _("brisbane", 2174003, "Brisbane", "AU", "humid_subtropical", "07", "QLD", trees=("jacaranda", "fig"),
      about="Capital of Queensland; plates QLD, area code 07."),
    _("perth", 2063523, "Perth", "AU", "mediterranean", "08", "WA",
      about="Capital of Western Australia; plates WA, area code 08."),
    _("adelaide", 2078025, "Adelaide", "AU", "mediterranean", "08", "SA",
      about="Capital of South Australia; plates SA, area code 08. Rundle Mall is its pedestrian shopping street."),
    _("auckland", 2193733, "Auckland", "NZ", "oceanic", "9", aliases=("Tāmaki Makaurau",),
      about="New Zealand's largest city; Queen Street is its main street. Area code 09."),
    _("wellington", 2179537, "Wellington", "NZ", "oceanic", "4", aliases=("Te Whanganui-a-Tara",),
      about="Capital of New Zealand; Lambton Quay follows the old shoreline. Area code 04."),
    _("christchurch", 2192362, "Christchurch", "NZ", "oceanic", "3", aliases=("Ōtautahi",),
      transport=("tram:green heritage",),
      about="Largest city of the South Island, rebuilt after the 2011 earthquake; area code 03."),
    _("suva", 2198148, "Suva", "FJ", "tropical", None,
      about="Capital of Fiji; Victoria Parade runs along the harbour front."),
    _("apia", 4035413, "Apia", "WS", "tropical", None,
      about="Capital of Samoa on Upolu; Beach Road follows the harbour."),
]

CITIES: dict[str, City] = {c.key: c for c in CITIES_LIST}
