"""The geolocation locations: a real street in a real city, at coordinates on that street.

Coordinates are on the named street (checked against the gazetteer's city centre by the
tests); ``bearing`` is the street's direction in degrees (0–179). ``sign`` is what the
street-name sign says, line by line, in the local script(s).

Difficulty says which level is hard, and decides where the cues appear (see scene.py):
  easy    a famous square or landmark and the street sign in the start's north view;
  city    country cues everywhere, city cues only after moving or looking around, the
          street sign one step away;
  street  country and city cues at the start, the street sign only two steps away.

Hard locations (hardness.py) stand on a street whose name many cities of their country share
(shared_streets.py): the list below gives every location's surveyed street, and ``LOCATIONS_LIST``
is that list with the hard ones renamed, so a street sign never names their city.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from .cities import CITIES, City
from .countries import COUNTRIES, Country
from .shared_streets import with_shared_streets

DIFFICULTIES = ("easy", "city", "street")


@dataclass(frozen=True)
class Landmark:
    kind: str  # what view_images.py draws: obelisk, column, spire, clock_tower, arch, onion_domes, ...
    description: str  # what the view shows, in plain visual words (never a name)


@dataclass(frozen=True)
class Location:
    id: str
    city_key: str
    street: str  # canonical answer
    sign: tuple[str, ...]  # street-name sign lines
    lat: float
    lng: float
    bearing: int  # street axis, degrees clockwise from north, 0..179
    difficulty: str
    landmark: Landmark | None = None
    pedestrian: bool = False  # no traffic, no road markings
    street_aliases: tuple[str, ...] = ()
    continent: str | None = None  # only where it differs from the country's (European Istanbul)

    @property
    def city(self) -> City:
        return CITIES[self.city_key]

    @property
    def country(self) -> Country:
        return COUNTRIES[self.city.iso]


def _l(id_: str, city: str, street: str, sign: str, lat: float, lng: float, bearing: int, difficulty: str,
       landmark: Landmark | None = None, ped: bool = False, aliases: tuple[str, ...] = (),
       continent: str | None = None) -> Location:
    diff = {"e": "easy", "c": "city", "s": "street"}[difficulty]
    return Location(id_, city, street, tuple(sign.split("|")), lat, lng, bearing, diff, landmark, ped, aliases,
                    continent)


L = Landmark
LOCATIONS_LIST: list[Location] = [
    # ----------------------------------------------------------------------------- Europe
    _l("g001", "paris", "Place de la Concorde", "8e Arrt|PLACE DE LA CONCORDE", 48.8656, 2.3212, 0, "e",
       L("obelisk", "a tall slender stone obelisk covered with hieroglyphs, its pointed tip gilded, stands in the "
                    "middle of a vast paved square; ornate bronze fountains and gilded lamp posts stand on "
                    "either side")),
    _l("g002", "paris", "Rue Oberkampf", "11e Arrt|RUE OBERKAMPF", 48.8655, 2.3760, 60, "c"),
    _l("g003", "lyon", "Rue de la République", "RUE DE LA RÉPUBLIQUE", 45.7620, 4.8360, 10, "s", ped=True,
       aliases=("Rue de la Republique",)),
    _l("g004", "marseille", "La Canebière", "LA CANEBIÈRE", 43.2975, 5.3790, 80, "c", aliases=("Canebière",
                                                                                              "La Canebiere")),
    _l("g005", "berlin", "Friedrichstraße", "Friedrichstraße", 52.5190, 13.3885, 0, "c",
       aliases=("Friedrichstrasse", "Friedrich Street")),
    _l("g006", "berlin", "Kurfürstendamm", "Kurfürstendamm", 52.5035, 13.3280, 70, "s",
       aliases=("Ku'damm", "Kudamm", "Kurfuerstendamm")),
    _l("g007", "munich", "Marienplatz", "Marienplatz", 48.1374, 11.5755, 90, "e",
       L("clock_tower", "a long, richly ornamented dark-grey neo-Gothic town hall with pinnacles and a tall "
                        "clock tower fills one side of a paved square; in front, a tall column carries a golden "
                        "statue of a woman"), ped=True),
    _l("g008", "hamburg", "Mönckebergstraße", "Mönckebergstraße", 53.5507, 10.0010, 80, "s",
       aliases=("Moenckebergstrasse", "Mönckebergstrasse", "Mö")),
    _l("g009", "cologne", "Hohe Straße", "Hohe Straße", 50.9370, 6.9565, 0, "c", ped=True,
       aliases=("Hohe Strasse",)),
    _l("g010", "madrid", "Plaza Mayor", "PLAZA MAYOR", 40.4155, -3.7074, 90, "e",
       L("equestrian_square", "an enclosed rectangular square surrounded by uniform red-brown three-storey "
                              "buildings with arcades, many balconies and slate spires; a bronze equestrian "
                              "statue of a king stands in the centre"), ped=True),
    _l("g011", "madrid", "Gran Vía", "Calle|GRAN VÍA", 40.4200, -3.7040, 70, "c", aliases=("Gran Via",)),
    _l("g012", "barcelona", "La Rambla", "La Rambla", 41.3810, 2.1735, 150, "c", ped=True,
       aliases=("Las Ramblas", "Les Rambles", "Rambla")),
    _l("g013", "barcelona", "Carrer de Mallorca", "Carrer de|Mallorca", 41.4028, 2.1736, 45, "e",
       L("basilica_spires", "behind the street rises an enormous stone basilica with a cluster of tall, "
                            "honeycomb-textured, spindle-shaped spires and construction cranes")),
    _l("g014", "seville", "Calle Sierpes", "C/ SIERPES", 37.3925, -5.9945, 0, "s", ped=True,
       aliases=("Sierpes",)),
    _l("g015", "valencia", "Carrer de Colón", "Calle de Colón|Carrer de Colom", 39.4705, -0.3720, 160, "c",
       aliases=("Calle de Colón", "Calle Colón", "Carrer de Colom")),
    _l("g016", "rome", "Piazza Navona", "PIAZZA NAVONA", 41.8992, 12.4731, 0, "e",
       L("fountain_obelisk", "a long oval square of ochre palazzi; at its centre a large baroque fountain with "
                             "marble giants on a rock carries an obelisk, in front of a church with a dome and "
                             "two bell towers"), ped=True),
    _l("g017", "rome", "Via del Corso", "VIA DEL CORSO", 41.9000, 12.4805, 170, "c", aliases=("Corso",)),
    _l("g018", "milan", "Corso Buenos Aires", "CORSO BUENOS AIRES", 45.4790, 9.2105, 45, "s"),
    _l("g019", "naples", "Via Toledo", "VIA TOLEDO", 40.8420, 14.2490, 0, "c", ped=True,
       aliases=("Via Roma",)),
    _l("g020", "florence", "Via dei Calzaiuoli", "VIA DEI CALZAIUOLI", 43.7710, 11.2552, 0, "s", ped=True,
       aliases=("Via de' Calzaiuoli", "Via de Calzaiuoli")),
    _l("g021", "london", "Trafalgar Square", "TRAFALGAR SQUARE|WC2|CITY OF WESTMINSTER", 51.5080, -0.1281, 0, "e",
       L("column", "a very tall granite column topped by a small statue rises from a large paved square, four "
                   "big bronze lions at its base, fountains in front and a columned gallery building behind")),
    _l("g022", "london", "Oxford Street", "OXFORD STREET|W1|CITY OF WESTMINSTER", 51.5150, -0.1420, 90, "c",
       aliases=("Oxford St",)),
    _l("g023", "manchester", "Deansgate", "DEANSGATE", 53.4800, -2.2490, 170, "s"),
    _l("g024", "edinburgh", "Princes Street", "PRINCES STREET", 55.9520, -3.1960, 75, "c",
       aliases=("Princes St",)),
    _l("g025", "edinburgh", "High Street", "HIGH STREET", 55.9500, -3.1890, 90, "c",
       aliases=("Royal Mile", "The Royal Mile")),
    _l("g026", "dublin", "O'Connell Street", "Sráid Uí Chonaill|O'Connell Street", 53.3497, -6.2603, 0, "e",
       L("spire", "a gigantic, extremely thin stainless-steel needle, many times taller than the buildings, "
                  "rises from the central median of a wide street with tram tracks")),
    _l("g027", "dublin", "Grafton Street", "Sráid Grafton|Grafton Street", 53.3410, -6.2600, 0, "s", ped=True),
    _l("g028", "lisbon", "Praça do Comércio", "PRAÇA DO COMÉRCIO", 38.7077, -9.1365, 0, "e",
       L("arch_square", "a huge square enclosed by yellow arcaded buildings; a monumental triumphal arch with "
                        "statues opens in the middle, and a bronze equestrian statue stands in the centre"), ped=True),
    _l("g029", "lisbon", "Rua Augusta", "RUA AUGUSTA", 38.7105, -9.1377, 170, "c", ped=True),
    _l("g030", "porto", "Rua de Santa Catarina", "RUA DE SANTA CATARINA", 41.1480, -8.6065, 0, "s", ped=True,
       aliases=("Rua Santa Catarina",)),
    _l("g031", "amsterdam", "Damrak", "Damrak", 52.3755, 4.8960, 170, "c"),
    _l("g032", "rotterdam", "Coolsingel", "Coolsingel", 51.9210, 4.4780, 170, "s"),
    _l("g033", "brussels", "Rue Neuve", "Rue Neuve|Nieuwstraat", 50.8525, 4.3565, 0, "c", ped=True,
       aliases=("Nieuwstraat",)),
    _l("g034", "zurich", "Bahnhofstrasse", "Bahnhofstrasse", 47.3720, 8.5390, 170, "c",
       aliases=("Bahnhofstraße",)),
    _l("g035", "vienna", "Kärntner Straße", "Kärntner Straße", 48.2055, 16.3710, 170, "s", ped=True,
       aliases=("Kärntnerstraße", "Kaerntner Strasse", "Karntner Strasse")),
    _l("g036", "warsaw", "Nowy Świat", "ul.|NOWY ŚWIAT", 52.2330, 21.0195, 0, "c", aliases=("Nowy Swiat",)),
    _l("g037", "krakow", "Floriańska", "ul.|FLORIAŃSKA", 50.0635, 19.9395, 170, "s", ped=True,
       aliases=("Florianska", "Ulica Floriańska")),
    _l("g038", "prague", "Wenceslas Square", "Václavské náměstí", 50.0813, 14.4275, 130, "e",
       L("museum_statue", "a long, broad boulevard-square climbs gently towards a large neo-Renaissance museum "
                          "building with a glass-and-gilt dome; a bronze equestrian statue of a saint stands in "
                          "front of it"), ped=True, aliases=("Václavské náměstí", "Vaclavske namesti")),
    _l("g039", "budapest", "Andrássy út", "ANDRÁSSY ÚT", 47.5050, 19.0620, 50, "c",
       aliases=("Andrassy ut", "Andrássy Avenue")),
    _l("g040", "athens", "Ermou Street", "ΟΔΟΣ ΕΡΜΟΥ|ERMOU ST.", 37.9760, 23.7300, 90, "s", ped=True,
       aliases=("Ermou", "Οδός Ερμού")),
    _l("g041", "thessaloniki", "Tsimiski Street", "ΤΣΙΜΙΣΚΗ|TSIMISKI", 40.6320, 22.9440, 125, "c",
       aliases=("Tsimiski", "Τσιμισκή", "Odos Tsimiski")),
    _l("g042", "moscow", "Red Square", "Красная площадь|Krasnaya ploshchad", 55.7539, 37.6208, 160, "e",
       L("onion_domes", "a vast cobbled square beside a long red-brick fortress wall with pointed towers topped by "
                        "red stars; at its end a church with a cluster of colourful striped onion domes"), ped=True,
       aliases=("Krasnaya Ploshchad", "Красная площадь")),
    _l("g043", "moscow", "Tverskaya Street", "Тверская улица|Tverskaya ulitsa", 55.7620, 37.6080, 140, "c",
       aliases=("Tverskaya", "Тверская улица", "Tverskaya ulitsa")),
    _l("g044", "saint-petersburg", "Nevsky Prospect", "Невский проспект|Nevsky prospekt", 59.9340, 30.3350, 100,
       "s", aliases=("Nevsky Prospekt", "Nevskiy Prospekt", "Невский проспект", "Nevsky")),
    _l("g045", "kyiv", "Khreshchatyk", "вулиця Хрещатик|Khreshchatyk St", 50.4470, 30.5220, 20, "c",
       aliases=("Хрещатик", "Kreshchatik", "Khreshchatyk Street")),
    _l("g046", "stockholm", "Drottninggatan", "DROTTNINGGATAN", 59.3335, 18.0630, 170, "s", ped=True),
    _l("g047", "oslo", "Karl Johans gate", "KARL JOHANS GATE", 59.9130, 10.7400, 90, "c", ped=True,
       aliases=("Karl Johan", "Karl Johans Street")),
    _l("g048", "copenhagen", "Frederiksberggade", "FREDERIKSBERGGADE", 55.6768, 12.5705, 60, "s", ped=True,
       aliases=("Strøget", "Stroget")),
    _l("g049", "helsinki", "Aleksanterinkatu", "ALEKSANTERINKATU|ALEXANDERSGATAN", 60.1690, 24.9460, 90, "c",
       aliases=("Alexandersgatan",)),
    _l("g050", "reykjavik", "Laugavegur", "LAUGAVEGUR", 64.1445, -21.9290, 80, "c"),
    _l("g051", "bucharest", "Calea Victoriei", "CALEA VICTORIEI", 44.4400, 26.0965, 170, "s",
       aliases=("Victoriei",)),
    _l("g052", "sofia", "Vitosha Boulevard", "бул. ВИТОША|Vitosha Blvd", 42.6925, 23.3205, 170, "c", ped=True,
       aliases=("Vitosha", "Bulevard Vitosha", "бул. Витоша")),
    _l("g053", "belgrade", "Knez Mihailova", "Кнез Михаилова|Knez Mihailova", 44.8170, 20.4570, 130, "s",
       ped=True, aliases=("Knez Mihailova Street", "Кнез Михаилова")),
    _l("g054", "zagreb", "Ilica", "ILICA", 45.8130, 15.9720, 90, "c"),
    _l("g055", "istanbul", "İstiklal Avenue", "İSTİKLAL CADDESİ|Beyoğlu", 41.0340, 28.9780, 40, "c", ped=True,
       aliases=("İstiklal Caddesi", "Istiklal Caddesi", "Istiklal Street", "Grande Rue de Péra"),
       continent="Europe"),
    _l("g056", "istanbul", "Sultanahmet Square", "SULTANAHMET MEYDANI", 41.0058, 28.9768, 30, "e",
       L("obelisk_mosque", "a long open square with an ancient obelisk covered in hieroglyphs on a carved "
                           "pedestal; behind it a great mosque with a cascade of grey domes and several slender "
                           "pencil-shaped minarets"), ped=True, aliases=("Sultanahmet Meydanı", "Hippodrome"),
       continent="Europe"),
    _l("g057", "vilnius", "Gediminas Avenue", "GEDIMINO PR.", 54.6870, 25.2770, 90, "s",
       aliases=("Gedimino prospektas", "Gedimino pr")),
    _l("g058", "tallinn", "Viru", "VIRU", 59.4365, 24.7490, 90, "c", ped=True, aliases=("Viru Street",
                                                                                       "Viru tänav")),
    _l("g059", "riga", "Brīvības iela", "BRĪVĪBAS IELA", 56.9535, 24.1150, 60, "s",
       aliases=("Brivibas iela", "Freedom Street", "Brīvības bulvāris")),
    _l("g060", "tbilisi", "Rustaveli Avenue", "შოთა რუსთაველის გამზირი|Shota Rustaveli Ave", 41.6990, 44.7975,
       150, "c", aliases=("Rustaveli", "Shota Rustaveli Avenue", "რუსთაველის გამზირი"), continent=None),
    _l("g061", "yerevan", "Abovyan Street", "Աբովյան փողոց|Abovyan St", 40.1830, 44.5165, 30, "s",
       aliases=("Abovyan", "Աբովյան")),
    _l("g062", "nicosia", "Ledra Street", "ΟΔΟΣ ΛΗΔΡΑΣ|LEDRA STREET", 35.1735, 33.3615, 0, "c", ped=True,
       aliases=("Ledras", "Οδός Λήδρας", "Lidras")),
    # ----------------------------------------------------------------------------- Asia
    _l("g063", "tokyo", "Omotesandō", "表参道|Omotesando", 35.6665, 139.7090, 50, "c",
       aliases=("Omotesando", "表参道", "Omotesando Avenue")),
    _l("g064", "tokyo", "Chūō-dōri", "中央通り|Chuo-dori", 35.6715, 139.7650, 30, "s",
       aliases=("Chuo-dori", "Chuo Dori", "Chuo Street", "中央通り", "Ginza Chuo-dori")),
    _l("g065", "osaka", "Midōsuji", "御堂筋|Midosuji", 34.6875, 135.5005, 0, "c",
       aliases=("Midosuji", "御堂筋", "Midosuji Boulevard")),
    _l("g066", "kyoto", "Shijō-dōri", "四条通|Shijo-dori", 35.0037, 135.7690, 90, "s",
       aliases=("Shijo-dori", "Shijo Street", "四条通", "Shijo dori")),
    _l("g067", "seoul", "Sejong-daero", "세종대로|Sejong-daero", 37.5725, 126.9769, 0, "e",
       L("seated_statue_gate", "a long plaza in the middle of a wide boulevard; a large golden statue of a seated "
                               "king on a stone pedestal, and far behind it a palace gate with a tiled, curved "
                               "double roof in front of mountains"), aliases=("Sejongno", "세종대로",
                                                                              "Gwanghwamun Square")),
    _l("g068", "seoul", "Insadong-gil", "인사동길|Insadong-gil", 37.5740, 126.9855, 20, "c", ped=True,
       aliases=("Insadong", "인사동길", "Insa-dong")),
    _l("g069", "busan", "Gwangbok-ro", "광복로|Gwangbok-ro", 35.0995, 129.0325, 60, "s",
       aliases=("Gwangbokro", "광복로", "Gwangbok-dong")),
    _l("g070", "beijing", "Wangfujing Street", "王府井大街|Wangfujing Dajie", 39.9135, 116.4115, 0, "s", ped=True,
       aliases=("Wangfujing", "王府井大街", "Wangfujing Dajie")),
    _l("g071", "beijing", "Tiananmen Square", "天安门广场|Tian'anmen Guangchang", 39.9042, 116.3976, 90, "e",
       L("gate_tower", "an immense paved square; across a wide avenue stands a long red gate tower with a "
                       "double yellow-tiled roof, five arched passages and a large portrait over the central "
                       "arch"), aliases=("Tian'anmen Square", "天安门广场", "Chang'an Avenue")),
    _l("g072", "shanghai", "Nanjing Road", "南京东路|East Nanjing Rd.", 31.2355, 121.4805, 90, "c", ped=True,
       aliases=("Nanjing Road East", "East Nanjing Road", "南京东路", "Nanjing Donglu")),
    _l("g073", "guangzhou", "Beijing Road", "北京路|Beijing Lu", 23.1255, 113.2695, 0, "s", ped=True,
       aliases=("北京路", "Beijing Lu")),
    _l("g074", "taipei", "Zhongxiao East Road", "忠孝東路|Zhongxiao E. Rd.", 25.0415, 121.5440, 90, "c",
       aliases=("Zhongxiao East Rd", "忠孝東路", "Zhongxiao Road")),
    _l("g075", "hong-kong", "Nathan Road", "NATHAN ROAD|彌敦道", 22.3010, 114.1720, 0, "s",
       aliases=("彌敦道",)),
    _l("g076", "bangkok", "Sukhumvit Road", "ถนนสุขุมวิท|Sukhumvit Rd.", 13.7375, 100.5600, 100, "c",
       aliases=("Thanon Sukhumvit", "Sukhumvit", "ถนนสุขุมวิท")),
    _l("g077", "bangkok", "Khao San Road", "ถนนข้าวสาร|Khao San Rd.", 13.7590, 100.4975, 90, "s", ped=True,
       aliases=("Khaosan Road", "Thanon Khao San", "ถนนข้าวสาร")),
    _l("g078", "chiang-mai", "Tha Phae Road", "ถนนท่าแพ|Tha Phae Rd.", 18.7880, 98.9930, 90, "c",
       aliases=("Thapae Road", "Tha Phae", "ถนนท่าแพ")),
    _l("g079", "hanoi", "Hàng Bạc", "PHỐ HÀNG BẠC", 21.0340, 105.8525, 90, "c",
       aliases=("Hang Bac", "Phố Hàng Bạc", "Hang Bac Street")),
    _l("g080", "ho-chi-minh-city", "Đồng Khởi", "ĐƯỜNG ĐỒNG KHỞI", 10.7765, 106.7030, 40, "s",
       aliases=("Dong Khoi", "Đường Đồng Khởi", "Dong Khoi Street", "Rue Catinat")),
    _l("g081", "phnom-penh", "Sisowath Quay", "PREAH SISOWATH QUAY", 11.5705, 104.9305, 0, "c",
       aliases=("Preah Sisowath Quay", "Sisowath Boulevard")),
    _l("g082", "kuala-lumpur", "Jalan Bukit Bintang", "JALAN BUKIT BINTANG", 3.1465, 101.7110, 40, "c",
       aliases=("Bukit Bintang",)),
    _l("g083", "kuala-lumpur", "Jalan Ampang", "JALAN AMPANG", 3.1579, 101.7116, 90, "e",
       L("twin_towers", "two identical silver skyscrapers with stepped, faceted tops and spires, joined high up "
                        "by a two-storey skybridge, tower over the street")),
    _l("g084", "singapore", "Orchard Road", "ORCHARD ROAD", 1.3045, 103.8320, 120, "s", aliases=("Orchard Rd",)),
    _l("g085", "jakarta", "Jalan M.H. Thamrin", "JL. M.H. THAMRIN", -6.1930, 106.8225, 0, "c",
       aliases=("Jalan Thamrin", "Thamrin", "Jalan Mohammad Husni Thamrin")),
    _l("g086", "yogyakarta", "Jalan Malioboro", "JL. MALIOBORO", -7.7925, 110.3660, 0, "s",
       aliases=("Malioboro", "Malioboro Street")),
    _l("g087", "manila", "Escolta Street", "ESCOLTA ST.", 14.5970, 120.9780, 80, "c", aliases=("Escolta",
                                                                                              "Calle Escolta")),
    _l("g088", "mumbai", "Marine Drive", "NETAJI SUBHASH CHANDRA BOSE ROAD|नेताजी सुभाषचंद्र बोस मार्ग", 18.9430,
       72.8235, 10, "c", aliases=("Netaji Subhash Chandra Bose Road", "Queen's Necklace", "NS Road")),
    _l("g089", "mumbai", "Colaba Causeway", "SHAHID BHAGAT SINGH ROAD|शहीद भगतसिंग मार्ग", 18.9160, 72.8300, 10,
       "s", aliases=("Shahid Bhagat Singh Road", "Colaba Causeway Road")),
    _l("g090", "new-delhi", "Janpath", "जनपथ|JANPATH", 28.6240, 77.2190, 0, "c", aliases=("Janpath Road",
                                                                                          "Queen's Way")),
    _l("g091", "bengaluru", "Mahatma Gandhi Road", "ಮಹಾತ್ಮ ಗಾಂಧಿ ರಸ್ತೆ|MAHATMA GANDHI ROAD", 12.9755, 77.6070, 90,
       "s", aliases=("MG Road", "M.G. Road", "M G Road")),
    _l("g092", "kolkata", "Park Street", "মাদার টেরেসা সরণি|MOTHER TERESA SARANI|(PARK STREET)", 22.5530,
       88.3525, 90, "c", aliases=("Mother Teresa Sarani",)),
    _l("g093", "chennai", "Anna Salai", "அண்ணா சாலை|ANNA SALAI", 13.0605, 80.2640, 45, "s",
       aliases=("Mount Road", "அண்ணா சாலை")),
    _l("g094", "chattogram", "CDA Avenue", "সিডিএ এভিনিউ|CDA AVENUE", 22.3600, 91.8215, 0, "c",
       aliases=("C.D.A. Avenue",)),
    _l("g095", "dhaka", "Manik Mia Avenue", "মানিক মিয়া এভিনিউ|MANIK MIA AVENUE", 23.7595, 90.3790, 90, "s",
       aliases=("Manik Miah Avenue",)),
    _l("g096", "lahore", "The Mall", "مال روڈ|MALL ROAD", 31.5600, 74.3240, 100, "c",
       aliases=("Mall Road", "Shahrah-e-Quaid-e-Azam")),
    _l("g097", "karachi", "I. I. Chundrigar Road", "آئی آئی چندریگر روڈ|I.I. CHUNDRIGAR ROAD", 24.8490, 67.0080, 70,
       "s", aliases=("II Chundrigar Road", "McLeod Road", "Chundrigar Road")),
    _l("g098", "colombo", "Galle Road", "ගාලු පාර|காலி வீதி|GALLE ROAD", 6.9000, 79.8530, 0, "c",
       aliases=("Galle Rd",)),
    _l("g099", "kathmandu", "Durbar Marg", "दरबार मार्ग|DURBAR MARG", 27.7110, 85.3180, 0, "s",
       aliases=("King's Way", "दरबार मार्ग")),
    _l("g100", "dubai", "Sheikh Zayed Road", "شارع الشيخ زايد|Sheikh Zayed Rd", 25.2050, 55.2720, 40, "c",
       aliases=("Sheikh Zayed Rd", "E11")),
    _l("g101", "dubai", "Sheikh Mohammed bin Rashid Boulevard", "بوليفارد الشيخ محمد بن راشد|Sheikh Mohammed bin "
       "Rashid Blvd", 25.1955, 55.2765, 0, "e",
       L("supertall", "a single, impossibly tall silver skyscraper tapers in setbacks to a needle spire far above "
                      "every other tower, across a palm-lined boulevard"),
       aliases=("Mohammed bin Rashid Boulevard", "Downtown Dubai Boulevard")),
    _l("g102", "tel-aviv", "Rothschild Boulevard", "שדרות רוטשילד|شارع روتشيلد|Rothschild Blvd", 32.0640, 34.7745,
       20, "c", aliases=("Sderot Rothschild", "Rothschild", "שדרות רוטשילד")),
    _l("g103", "amman", "Rainbow Street", "شارع الرينبو|Rainbow St.", 31.9520, 35.9260, 90, "s",
       aliases=("Abu Bakr Al-Siddiq Street",)),
    _l("g104", "beirut", "Hamra Street", "شارع الحمرا|Rue Hamra", 33.8960, 35.4830, 90, "c",
       aliases=("Rue Hamra", "Hamra")),
    _l("g105", "tehran", "Valiasr Street", "خیابان ولیعصر|Valiasr St.", 35.7200, 51.4070, 0, "c",
       aliases=("Vali Asr Street", "Valiasr", "Pahlavi Street")),
    _l("g106", "tehran", "Azadi Square", "میدان آزادی|Azadi Sq.", 35.6997, 51.3380, 90, "e",
       L("tower_arch", "in the middle of a huge roundabout stands a white marble monument shaped like an inverted "
                       "Y: four legs sweep up into a tower above a great pointed arch"),
       aliases=("Meydan-e Azadi", "میدان آزادی")),
    _l("g107", "riyadh", "Olaya Street", "شارع العليا|Olaya St.", 24.6950, 46.6855, 160, "s",
       aliases=("Al Olaya Street", "Olaya")),
    _l("g108", "ankara", "Atatürk Boulevard", "ATATÜRK BULVARI", 39.9200, 32.8540, 0, "c",
       aliases=("Atatürk Bulvarı", "Ataturk Bulvari")),
    _l("g109", "almaty", "Abylai Khan Avenue", "Абылай хан даңғылы|Abylai Khan Ave", 43.2565, 76.9450, 0, "s",
       aliases=("Abylai Khan", "проспект Абылай хана", "Ablai Khan Avenue")),
    _l("g110", "tashkent", "Amir Temur Avenue", "AMIR TEMUR SHOH KO'CHASI", 41.3160, 69.2795, 0, "c",
       aliases=("Amir Temur Street", "Amir Temur shoh ko'chasi")),
    _l("g111", "ulaanbaatar", "Peace Avenue", "Энх тайвны өргөн чөлөө|Peace Avenue", 47.9180, 106.9170, 90, "s",
       aliases=("Enkh Taivny Örgön Chölöö", "Enkhtaivny Avenue")),
    # ----------------------------------------------------------------------------- Africa
    _l("g112", "cairo", "Talaat Harb Street", "شارع طلعت حرب|Talaat Harb St.", 30.0480, 31.2395, 30, "c",
       aliases=("Talaat Harb", "Soliman Pasha Street")),
    _l("g113", "alexandria", "El Horreya Road", "طريق الحرية|El Horreya Rd.", 31.1980, 29.9060, 90, "s",
       aliases=("Horreya Road", "Fouad Street", "Tariq al-Horreya")),
    _l("g114", "marrakesh", "Jemaa el-Fnaa", "ساحة جامع الفنا|Place Jemaa El Fna", 31.6258, -7.9891, 0, "e",
       L("minaret_square", "an immense open square crowded with food stalls, awnings and carts, ringed by low "
                           "ochre-red buildings; beyond them rises a tall square sandstone minaret with a small "
                           "lantern tower on top"), ped=True, aliases=("Jemaa el-Fna", "Djemaa el Fna",
                                                             "Place Jemaa el-Fna")),
    _l("g115", "casablanca", "Boulevard Mohammed V", "شارع محمد الخامس|Boulevard Mohammed V", 33.5960, -7.6160, 70,
       "c", aliases=("Bd Mohammed V", "Mohammed V Boulevard")),
    _l("g116", "tunis", "Avenue Habib Bourguiba", "شارع الحبيب بورقيبة|Avenue Habib Bourguiba", 36.8000, 10.1820,
       90, "c", aliases=("Habib Bourguiba Avenue", "Av. Habib Bourguiba")),
    _l("g117", "algiers", "Rue Didouche Mourad", "شارع ديدوش مراد|Rue Didouche Mourad", 36.7700, 3.0520, 150, "s",
       aliases=("Didouche Mourad", "Rue Michelet")),
    _l("g118", "dakar", "Avenue Georges Pompidou", "AVENUE GEORGES POMPIDOU", 14.6700, -17.4365, 90, "c",
       aliases=("Avenue Pompidou", "Avenue William Ponty")),
    _l("g119", "abidjan", "Boulevard de la République", "BOULEVARD DE LA RÉPUBLIQUE", 5.3225, -4.0185, 0, "s",
       aliases=("Boulevard de la Republique",)),
    _l("g120", "accra", "Oxford Street", "OXFORD STREET|OSU", 5.5565, -0.1815, 0, "c",
       aliases=("Cantonments Road", "Osu Oxford Street")),
    _l("g121", "lagos", "Broad Street", "BROAD STREET|LAGOS ISLAND", 6.4515, 3.3905, 90, "s"),
    _l("g122", "nairobi", "Moi Avenue", "MOI AVENUE", -1.2840, 36.8255, 160, "c"),
    _l("g123", "mombasa", "Moi Avenue", "MOI AVENUE", -4.0630, 39.6725, 100, "c"),
    _l("g124", "dar-es-salaam", "Samora Avenue", "SAMORA AVENUE", -6.8165, 39.2890, 120, "s",
       aliases=("Samora Machel Avenue",)),
    _l("g125", "kampala", "Kampala Road", "KAMPALA ROAD", 0.3140, 32.5800, 80, "c"),
    _l("g126", "addis-ababa", "Churchill Avenue", "ቸርችል ጎዳና|Churchill Avenue", 9.0260, 38.7470, 0, "s",
       aliases=("Churchill Road",)),
    _l("g127", "cape-town", "Long Street", "LONG STREET|LANGSTRAAT", -33.9235, 18.4185, 40, "c"),
    _l("g128", "johannesburg", "Commissioner Street", "COMMISSIONER STREET", -26.2055, 28.0450, 90, "s",
       aliases=("Commissioner St",)),
    _l("g129", "durban", "Florida Road", "FLORIDA ROAD", -29.8345, 31.0115, 30, "c"),
    _l("g130", "windhoek", "Independence Avenue", "INDEPENDENCE AVENUE", -22.5675, 17.0840, 0, "s",
       aliases=("Kaiserstrasse", "Kaiserstraße")),
    _l("g131", "harare", "Samora Machel Avenue", "SAMORA MACHEL AVENUE", -17.8275, 31.0490, 90, "c",
       aliases=("Jameson Avenue",)),
    _l("g132", "lusaka", "Cairo Road", "CAIRO ROAD", -15.4180, 28.2830, 0, "s"),
    _l("g133", "maputo", "Avenida 24 de Julho", "AVENIDA 24 DE JULHO", -25.9680, 32.5850, 90, "c",
       aliases=("Av. 24 de Julho", "24 de Julho")),
    _l("g134", "luanda", "Avenida 4 de Fevereiro", "AVENIDA 4 DE FEVEREIRO|MARGINAL", -8.8130, 13.2330, 40, "s",
       aliases=("Marginal de Luanda", "Avenida Quatro de Fevereiro", "Marginal")),
    _l("g135", "antananarivo", "Avenue de l'Indépendance", "ARABEN'NY FAHALEOVANTENA|Avenue de l'Indépendance",
       -18.9075, 47.5225, 40, "c", aliases=("Avenue de l'Independance", "Araben'ny Fahaleovantena")),
    _l("g136", "port-louis", "Royal Street", "ROYAL STREET|RUE ROYALE", -20.1615, 57.5020, 40, "s",
       aliases=("Rue Royale",)),
    # ----------------------------------------------------------------------------- North America
    _l("g137", "washington", "Constitution Avenue", "Constitution Ave NW", 38.8920, -77.0330, 90, "e",
       L("obelisk", "a very tall, plain white stone obelisk without any carving rises from a wide grassy park, "
                    "ringed at its foot by a circle of flagpoles all flying the same striped flag")),
    _l("g138", "new-york", "Bleecker Street", "Bleecker St", 40.7285, -74.0010, 55, "s"),
    _l("g139", "chicago", "Michigan Avenue", "N Michigan Av", 41.8920, -87.6245, 0, "c",
       aliases=("North Michigan Avenue", "Magnificent Mile", "Michigan Ave")),
    _l("g140", "san-francisco", "Market Street", "Market St", 37.7890, -122.4015, 45, "s"),
    _l("g141", "los-angeles", "Hollywood Boulevard", "Hollywood Blvd", 34.1016, -118.3267, 90, "c",
       aliases=("Hollywood Blvd",)),
    _l("g142", "new-orleans", "Bourbon Street", "Bourbon St|Rue Bourbon", 29.9580, -90.0660, 45, "c",
       aliases=("Rue Bourbon",)),
    _l("g143", "austin", "Congress Avenue", "Congress Ave", 30.2680, -97.7428, 0, "s"),
    _l("g144", "miami", "Southwest 8th Street", "SW 8 St|Calle Ocho", 25.7655, -80.2190, 90, "c",
       aliases=("SW 8th Street", "Calle Ocho", "Tamiami Trail", "8th Street")),
    _l("g145", "seattle", "Pike Street", "Pike St", 47.6105, -122.3400, 50, "s"),
    _l("g146", "toronto", "Yonge Street", "YONGE ST", 43.6560, -79.3805, 165, "c"),
    _l("g147", "montreal", "Rue Sainte-Catherine", "Rue|Sainte-Catherine", 45.5030, -73.5710, 60, "s",
       aliases=("Sainte-Catherine Street", "St. Catherine Street", "Rue Ste-Catherine")),
    _l("g148", "vancouver", "Granville Street", "GRANVILLE ST", 49.2820, -123.1195, 135, "c"),
    _l("g149", "mexico-city", "Zócalo", "PLAZA DE LA CONSTITUCIÓN", 19.4326, -99.1332, 0, "e",
       L("flag_cathedral", "an immense empty paved square with a gigantic flag on a tall flagpole in the centre; "
                           "behind it a huge baroque cathedral with two bell towers and a dome"),
       aliases=("Plaza de la Constitución", "Zocalo", "Plaza de la Constitucion")),
    _l("g150", "mexico-city", "Paseo de la Reforma", "PASEO DE LA REFORMA|Cuauhtémoc", 19.4270, -99.1675, 60, "c",
       aliases=("Reforma", "Avenida Reforma")),
    _l("g151", "guadalajara", "Avenida Juárez", "AV. JUÁREZ", 20.6745, -103.3500, 90, "s",
       aliases=("Avenida Juarez", "Juárez")),
    _l("g152", "oaxaca", "Calle Macedonio Alcalá", "MACEDONIO ALCALÁ", 17.0640, -96.7235, 0, "c", ped=True,
       aliases=("Macedonio Alcalá", "Andador Turístico", "Macedonio Alcala")),
    _l("g153", "guatemala-city", "Sexta Avenida", "6a. AVENIDA|ZONA 1", 14.6400, -90.5135, 0, "s", ped=True,
       aliases=("6a Avenida", "6th Avenue", "Paseo de la Sexta")),
    _l("g154", "havana", "Calle Obispo", "CALLE OBISPO", 23.1380, -82.3520, 90, "c", ped=True,
       aliases=("Obispo", "Obispo Street")),
    _l("g155", "san-jose", "Avenida Central", "AVENIDA CENTRAL", 9.9330, -84.0790, 90, "s", ped=True,
       aliases=("Bulevar Avenida Central",)),
    _l("g156", "panama-city", "Avenida Balboa", "AVENIDA BALBOA", 8.9760, -79.5225, 60, "c"),
    _l("g157", "santo-domingo", "Calle El Conde", "CALLE EL CONDE", 18.4735, -69.8860, 90, "s", ped=True,
       aliases=("El Conde", "Calle del Conde")),
    _l("g158", "kingston", "Knutsford Boulevard", "KNUTSFORD BLVD", 18.0070, -76.7840, 0, "c"),
    # ----------------------------------------------------------------------------- South America
    _l("g159", "rio-de-janeiro", "Avenida Atlântica", "AV. ATLÂNTICA|Copacabana", -22.9700, -43.1855, 40, "c",
       aliases=("Avenida Atlantica", "Av. Atlântica")),
    _l("g160", "sao-paulo", "Avenida Paulista", "AV. PAULISTA|Bela Vista", -23.5630, -46.6545, 130, "s",
       aliases=("Paulista",)),
    _l("g161", "salvador", "Rua Chile", "RUA CHILE", -12.9735, -38.5125, 20, "c"),
    _l("g162", "curitiba", "Rua XV de Novembro", "RUA XV DE NOVEMBRO|Centro", -25.4300, -49.2710, 90, "s",
       ped=True, aliases=("Rua das Flores", "Rua Quinze de Novembro")),
    _l("g163", "buenos-aires", "Avenida 9 de Julio", "AV. 9 DE JULIO", -34.6037, -58.3816, 0, "e",
       L("obelisk_avenue", "a white, smooth, four-sided obelisk stands in a small plaza in the middle of an "
                           "extremely wide avenue with many lanes of traffic, black-and-yellow taxis"),
       aliases=("Avenida Nueve de Julio", "9 de Julio", "Obelisco")),
    _l("g164", "buenos-aires", "Calle Florida", "FLORIDA", -34.6010, -58.3750, 150, "c", ped=True,
       aliases=("Florida", "Florida Street")),
    _l("g165", "mendoza", "Avenida San Martín", "AV. SAN MARTÍN", -32.8900, -68.8440, 0, "s",
       aliases=("Avenida San Martin", "San Martín")),
    _l("g166", "santiago", "Paseo Ahumada", "PASEO AHUMADA", -33.4395, -70.6510, 0, "c", ped=True,
       aliases=("Ahumada",)),
    _l("g167", "lima", "Jirón de la Unión", "JR. DE LA UNIÓN", -12.0480, -77.0330, 40, "s", ped=True,
       aliases=("Jiron de la Union", "Jirón Unión")),
    _l("g168", "cusco", "Avenida El Sol", "AV. EL SOL", -13.5205, -71.9760, 150, "c",
       aliases=("Avenida del Sol", "El Sol")),
    _l("g169", "bogota", "Carrera Séptima", "CARRERA 7|AV. CARRERA 7", 4.6000, -74.0725, 0, "c",
       aliases=("Carrera 7", "Carrera Septima", "La Séptima")),
    _l("g170", "medellin", "Avenida La Playa", "AVENIDA LA PLAYA|CALLE 51", 6.2480, -75.5640, 90, "s",
       aliases=("Calle 51", "La Playa")),
    _l("g171", "quito", "Avenida Amazonas", "AV. AMAZONAS", -0.2000, -78.4905, 0, "c", aliases=("Amazonas",)),
    _l("g172", "la-paz", "Avenida 16 de Julio", "AV. 16 DE JULIO|EL PRADO", -16.5020, -68.1320, 140, "c",
       aliases=("El Prado", "Avenida Dieciséis de Julio")),
    _l("g173", "montevideo", "Avenida 18 de Julio", "AV. 18 DE JULIO", -34.9055, -56.1900, 90, "s",
       aliases=("18 de Julio", "Avenida Dieciocho de Julio")),
    _l("g174", "caracas", "Bulevar de Sabana Grande", "BULEVAR DE SABANA GRANDE", 10.4965, -66.8760, 90, "c",
       ped=True, aliases=("Sabana Grande", "Boulevard de Sabana Grande")),
    _l("g175", "asuncion", "Calle Palma", "PALMA", -25.2820, -57.6370, 90, "s", aliases=("Palma",)),
    # ----------------------------------------------------------------------------- Oceania
    _l("g176", "sydney", "George Street", "GEORGE ST", -33.8700, 151.2070, 0, "c", aliases=("George St",)),
    _l("g177", "melbourne", "Swanston Street", "SWANSTON ST", -37.8130, 144.9655, 160, "c"),
    _l("g178", "brisbane", "Queen Street", "QUEEN ST", -27.4695, 153.0255, 45, "c", ped=True,
       aliases=("Queen Street Mall",)),
    _l("g179", "perth", "Hay Street", "HAY ST", -31.9540, 115.8570, 90, "s", ped=True,
       aliases=("Hay Street Mall",)),
    _l("g180", "adelaide", "Rundle Mall", "RUNDLE MALL", -34.9225, 138.6025, 90, "s", ped=True,
       aliases=("Rundle Street",)),
    _l("g181", "auckland", "Queen Street", "QUEEN ST", -36.8480, 174.7650, 0, "c"),
    _l("g182", "wellington", "Lambton Quay", "LAMBTON QUAY", -41.2830, 174.7765, 30, "s"),
    _l("g183", "christchurch", "Colombo Street", "COLOMBO ST", -43.5310, 172.6365, 0, "c"),
    _l("g184", "suva", "Victoria Parade", "VICTORIA PARADE", -18.1410, 178.4250, 0, "c"),
    _l("g185", "apia", "Beach Road", "BEACH ROAD", -13.8310, -171.7600, 90, "s"),
]

# A hard location's own street name would name its city two steps from the start; it takes a name that many
# cities of its country share (shared_streets.py) and keeps its coordinates.
SURVEYED_LOCATIONS_LIST: list[Location] = LOCATIONS_LIST
LOCATIONS_LIST = with_shared_streets(SURVEYED_LOCATIONS_LIST)

LOCATIONS: dict[str, Location] = {loc.id: loc for loc in LOCATIONS_LIST}


@lru_cache(maxsize=1)
def locations_by_coordinates() -> dict[tuple[float, float], Location]:
    """Index used by the grader to find a task's per-location aliases from its answer."""
    return {(round(loc.lat, 4), round(loc.lng, 4)): loc for loc in LOCATIONS_LIST}
