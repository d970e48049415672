"""Country profiles: the street-level cues of each country the locations use.

Everything here is a cue a traveller could see (sign languages, driving side, plates, road
markings, building style) plus a few facts for the wiki article. Names, capitals, calling
codes, currencies and continents come from the gazetteer (``gazetteer.py``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .plates import BLACK, BLUE, GREEN, RED, WHITE, YELLOW, PlateStyle


@dataclass(frozen=True)
class StreetSignStyle:
    bg: str
    fg: str
    border: str
    mount: str = "wall"  # "wall" (plaque on a building corner) or "pole"
    words: str = ""  # how the description names it, e.g. "blue enamel plaque"


WALL_BLUE = StreetSignStyle("#1d3f95", "#ffffff", "#ffffff", "wall", "blue plaque with white letters")
WALL_WHITE = StreetSignStyle("#f5f5f0", "#111111", "#111111", "wall", "white plaque with black letters and border")
POLE_GREEN = StreetSignStyle("#0b6b2e", "#ffffff", "#ffffff", "pole", "green street sign on a pole")
POLE_BLUE = StreetSignStyle("#1f5fb0", "#ffffff", "#ffffff", "pole", "blue street sign on a pole")
POLE_WHITE = StreetSignStyle("#f5f5f0", "#111111", "#111111", "pole", "white street sign on a pole")
POLE_BLACK = StreetSignStyle("#1a1a1a", "#ffffff", "#ffffff", "pole", "black street sign on a pole")
WALL_RED = StreetSignStyle("#b01818", "#ffffff", "#ffffff", "wall", "red plaque with white letters")
WALL_TILE = StreetSignStyle("#f3efe2", "#1d3f95", "#1d3f95", "wall", "glazed tile plaque with blue letters")
WALL_STONE = StreetSignStyle("#e6e0cf", "#222222", "#9a937f", "wall", "pale stone plaque with dark letters")


@dataclass(frozen=True)
class Country:
    iso: str
    name: str  # the canonical English name graders and tasks use
    langs: tuple[str, ...]  # sign languages (languages.py codes), most frequent first
    drive: str  # "left" or "right"
    plate: PlateStyle
    sign: StreetSignStyle
    phone: str  # "{a}" = the city's area code, "#" = a digit
    arch: str  # default building style (render.py draws each style)
    centre_line: str = "white"  # colour of the centre line on two-way streets
    edge_line: str = "white"
    aliases: tuple[str, ...] = ()  # other names for grading: exonyms, native names, short forms
    official_languages: str = ""  # for the wiki
    scripts: str = "Latin"  # for the wiki
    facts: tuple[str, ...] = field(default_factory=tuple)  # short, true statements for the wiki


def _eu(band: str, pattern: str, **kw) -> PlateStyle:
    return PlateStyle(pattern=pattern, band=band, **kw)


_C = Country
COUNTRIES_LIST: list[Country] = [
    # ------------------------------------------------------------------------------ Europe
    _C("FR", "France", ("fr",), "right", _eu("F", "AA-999-AA"), WALL_BLUE, "{a} ## ## ## ##", "haussmann",
       aliases=("French Republic", "République française"), official_languages="French",
       facts=("Street names in Paris are written on dark blue enamel plaques framed in green that also give the "
              "arrondissement.", "Plates since 2009 have the pattern AA-123-AA with a blue band marked F.")),
    _C("DE", "Germany", ("de",), "right", _eu("D", "{r} AA 9999"), WALL_WHITE, "{a} ### ####", "central_european",
       aliases=("Deutschland", "Federal Republic of Germany", "Allemagne"), official_languages="German",
       facts=("The first letters of a German plate name the district: B for Berlin, M for Munich, HH for Hamburg, "
              "K for Cologne.",)),
    _C("ES", "Spain", ("es",), "right", _eu("E", "9999 AAA"), WALL_WHITE, "{a} ### ## ##", "mediterranean",
       aliases=("España", "Espana", "Kingdom of Spain"), official_languages="Spanish (Catalan, Galician and Basque "
       "are co-official in their regions)",
       facts=("In Catalonia signs are written in Catalan (carrer, farmàcia, forn de pa).",
              "Spanish plates since 2000 carry four digits and three consonants.")),
    _C("IT", "Italy", ("it",), "right", _eu("I", "AA 999AA"), WALL_STONE, "{a} ### ####", "mediterranean",
       aliases=("Italia", "Italian Republic"), official_languages="Italian"),
    _C("GB", "United Kingdom", ("en-gb",), "left", PlateStyle("AA99 AAA", rear_bg=YELLOW, band="UK"),
       WALL_WHITE, "{a} #### ####", "british",
       aliases=("UK", "U.K.", "Great Britain", "Britain", "England", "Scotland", "Wales", "Northern Ireland",
                "United Kingdom of Great Britain and Northern Ireland"),
       official_languages="English (Welsh and Scottish Gaelic also used)",
       facts=("Rear number plates are yellow and front plates white.",
              "London street signs often add the postal district and borough, e.g. W1 City of Westminster.")),
    _C("IE", "Ireland", ("en-gb",), "left", _eu("IRL", "99{r}-9999"), WALL_WHITE, "{a} ### ####", "british",
       edge_line="yellow", aliases=("Éire", "Eire", "Republic of Ireland"), official_languages="Irish and English",
       facts=("Street signs are bilingual, Irish above English.",
              "Plates show the year and a county letter: D is Dublin.",
              "Road edges are marked with yellow lines.")),
    _C("PT", "Portugal", ("pt",), "right", _eu("P", "AA-99-AA"), WALL_TILE, "{a}# ### ###", "iberian",
       aliases=("Portuguese Republic", "República Portuguesa"), official_languages="Portuguese",
       facts=("Facades are often covered with glazed tiles (azulejos).",
              "Pavements are paved with black-and-white limestone mosaics (calçada portuguesa).")),
    _C("NL", "Netherlands", ("nl",), "right", _eu("NL", "AA-999-A", bg=YELLOW), WALL_BLUE, "{a} ### ####",
       "nordic", aliases=("The Netherlands", "Holland", "Nederland"), official_languages="Dutch",
       facts=("Dutch plates are yellow with black characters.", "Red-paved cycle paths line most city streets.")),
    _C("BE", "Belgium", ("fr", "nl"), "right", _eu("B", "1-AAA-999", fg=RED), WALL_WHITE, "{a} ### ## ##",
       "central_european", aliases=("Belgique", "België", "Belgie", "Kingdom of Belgium"),
       official_languages="Dutch, French and German",
       facts=("Plates are white with red characters.", "Brussels street names are given in French and Dutch.")),
    _C("CH", "Switzerland", ("de-ch",), "right", PlateStyle("{r} 999 999"), POLE_BLUE, "{a} ### ## ##",
       "central_european", aliases=("Schweiz", "Suisse", "Svizzera", "Swiss Confederation", "Confoederatio Helvetica"),
       official_languages="German, French, Italian and Romansh",
       facts=("Plates start with the canton's code: ZH is Zurich.",)),
    _C("AT", "Austria", ("de",), "right", _eu("A", "{r} 99999 A", bg=WHITE), WALL_BLUE, "{a} ### ## ##",
       "central_european", aliases=("Österreich", "Osterreich", "Republic of Austria"), official_languages="German",
       facts=("Plates start with the district code: W is Vienna.",)),
    _C("PL", "Poland", ("pl",), "right", _eu("PL", "{r} 99999"), WALL_BLUE, "{a} ### ## ##", "central_european",
       aliases=("Polska", "Republic of Poland"), official_languages="Polish",
       facts=("Plates start with a district code: WA to WZ for Warsaw, KR for Kraków.",)),
    _C("CZ", "Czechia", ("cs",), "right", _eu("CZ", "9{r}9 9999"), WALL_RED, "### ### ###", "central_european",
       aliases=("Czech Republic", "Česko", "Cesko", "Česká republika"), official_languages="Czech",
       facts=("Prague street names are on red plaques with white letters.",
              "The second character of a plate is the region: A is Prague.")),
    _C("HU", "Hungary", ("hu",), "right", _eu("H", "AA AA-999"), WALL_WHITE, "{a} ### ####", "central_european",
       aliases=("Magyarország", "Magyarorszag"), official_languages="Hungarian"),
    _C("GR", "Greece", ("el",), "right", _eu("GR", "{r}A-9999", letters="ABEZHIKMNOPTYX"), WALL_BLUE,
       "{a} ### ####", "mediterranean", aliases=("Hellas", "Ellada", "Ελλάδα", "Hellenic Republic"),
       official_languages="Greek", scripts="Greek",
       facts=("Street signs give the Greek name with a Latin transliteration below.",
              "The first letters of a plate name the prefecture: Y and Z for Attica (Athens), N for Thessaloniki.")),
    _C("RU", "Russia", ("ru",), "right", PlateStyle("A999AA {r}", letters="ABEKMHOPCTYX"), WALL_BLUE,
       "+7 ({a}) ###-##-##", "soviet", aliases=("Russian Federation", "Россия", "Rossiya"),
       official_languages="Russian", scripts="Cyrillic",
       facts=("Plates end with a region number and RUS: 77, 97, 99 and 177 for Moscow, 78, 98 and 178 for "
              "Saint Petersburg.",)),
    _C("UA", "Ukraine", ("uk",), "right", _eu("UA", "{r}9999AA", letters="ABCEHIKMOPTX"), WALL_BLUE,
       "+380 {a} ### ## ##", "soviet", aliases=("Україна", "Ukraina"), official_languages="Ukrainian",
       scripts="Cyrillic", facts=("Plates start with a region code: AA and KA for Kyiv.",)),
    _C("SE", "Sweden", ("sv",), "right", _eu("S", "AAA 99A"), WALL_BLUE, "{a}-### ## ##", "nordic",
       aliases=("Sverige", "Kingdom of Sweden"), official_languages="Swedish"),
    _C("NO", "Norway", ("no",), "right", _eu("N", "AA 99999"), WALL_WHITE, "### ## ###", "nordic",
       centre_line="yellow", aliases=("Norge", "Noreg", "Kingdom of Norway"), official_languages="Norwegian",
       facts=("The centre line of two-way roads is yellow.",)),
    _C("DK", "Denmark", ("da",), "right", _eu("DK", "AA 99 999", bg=WHITE), WALL_WHITE, "## ## ## ##",
       "nordic", aliases=("Danmark", "Kingdom of Denmark"), official_languages="Danish",
       facts=("Plates have a red border.",)),
    _C("FI", "Finland", ("fi", "sv"), "right", _eu("FIN", "AAA-999"), WALL_BLUE, "{a} ### ####", "nordic",
       centre_line="yellow", aliases=("Suomi", "Republic of Finland"), official_languages="Finnish and Swedish",
       facts=("Helsinki street signs give the Finnish name above the Swedish one (Aleksanterinkatu / "
              "Alexandersgatan).", "The centre line of two-way roads is yellow.")),
    _C("IS", "Iceland", ("is",), "right", PlateStyle("AA A99", band="IS"), WALL_WHITE, "### ####", "nordic",
       aliases=("Ísland", "Island"), official_languages="Icelandic",
       facts=("Houses are often clad in corrugated iron painted in bright colours.",)),
    _C("RO", "Romania", ("ro",), "right", _eu("RO", "{r} 999 AAA"), WALL_BLUE, "{a} ### ####", "central_european",
       aliases=("România",), official_languages="Romanian",
       facts=("A plate starting with B alone is from Bucharest.",)),
    _C("BG", "Bulgaria", ("bg",), "right", _eu("BG", "{r} 9999 AA", letters="ABEKMHOPCTYX"), WALL_BLUE,
       "{a} ### ####", "soviet", aliases=("България", "Balgariya"), official_languages="Bulgarian",
       scripts="Cyrillic", facts=("Plates start with a province code: C, CA and CB for Sofia.",)),
    _C("RS", "Serbia", ("sr",), "right", _eu("SRB", "{r} 999-AA"), WALL_BLUE, "{a} ### ####", "central_european",
       aliases=("Србија", "Srbija"), official_languages="Serbian", scripts="Cyrillic and Latin",
       facts=("Serbian is written in both Cyrillic and Latin; official signs use Cyrillic.",
              "Plates start with the city code: BG is Belgrade.")),
    _C("HR", "Croatia", ("hr",), "right", _eu("HR", "{r} 999-A"), WALL_WHITE, "{a} ### ####", "central_european",
       aliases=("Hrvatska",), official_languages="Croatian", facts=("Plates start with a city code: ZG is Zagreb.",)),
    _C("TR", "Turkey", ("tr",), "right", _eu("TR", "{r} AAA 99"), POLE_BLUE, "0 ({a}) ### ## ##", "ottoman",
       aliases=("Türkiye", "Turkiye", "Republic of Türkiye"), official_languages="Turkish",
       facts=("Plates start with a province number: 34 is Istanbul, 06 is Ankara.",
              "Turkish uses the Latin alphabet with ç, ğ, ı, ö, ş and ü.")),
    _C("LT", "Lithuania", ("lt",), "right", _eu("LT", "AAA 999"), WALL_WHITE, "{a} ### ####", "central_european",
       aliases=("Lietuva",), official_languages="Lithuanian"),
    _C("EE", "Estonia", ("et",), "right", _eu("EST", "999 AAA"), WALL_WHITE, "### ####", "nordic",
       aliases=("Eesti",), official_languages="Estonian"),
    _C("LV", "Latvia", ("lv",), "right", _eu("LV", "AA-9999"), WALL_BLUE, "### ## ###", "central_european",
       aliases=("Latvija",), official_languages="Latvian"),
    _C("GE", "Georgia", ("ka",), "right", _eu("GE", "AA-999-AA"), WALL_BLUE, "{a} ### ## ##", "soviet",
       aliases=("Georgia (country)", "Sakartvelo", "საქართველო"), official_languages="Georgian",
       scripts="Georgian (Mkhedruli)", facts=("Georgian is written in its own alphabet, Mkhedruli.",)),
    _C("AM", "Armenia", ("hy",), "right", _eu("AM", "99 AA 999"), WALL_BLUE, "{a} ## ## ##", "soviet",
       aliases=("Hayastan", "Հայաստան"), official_languages="Armenian", scripts="Armenian",
       facts=("Many buildings in the capital are built of pink volcanic tuff stone.",)),
    _C("CY", "Cyprus", ("el",), "left", _eu("CY", "AAA 999", rear_bg=YELLOW), WALL_BLUE, "{a} ######",
       "mediterranean", aliases=("Κύπρος", "Kypros", "Kıbrıs", "Republic of Cyprus"),
       official_languages="Greek and Turkish", scripts="Greek", facts=("Traffic drives on the left.",)),
    # ------------------------------------------------------------------------------ Asia
    _C("JP", "Japan", ("ja",), "left", PlateStyle("{r} 300 さ 99-99", fg=GREEN), POLE_BLUE, "{a}-####-####",
       "east_asian", aliases=("Nippon", "Nihon", "日本"), official_languages="Japanese",
       scripts="Kanji, hiragana and katakana",
       facts=("Plates are white with green characters and show the registration office in kanji: 品川 or 練馬 "
              "for Tokyo, なにわ for Osaka, 京都 for Kyoto.",
              "Streets are crowded with overhead power lines and vertical shop signs.")),
    _C("KR", "South Korea", ("ko",), "right", PlateStyle("99가 9999"), POLE_BLUE, "{a}-###-####", "east_asian",
       centre_line="yellow", aliases=("Korea", "Republic of Korea", "대한민국", "Hanguk"),
       official_languages="Korean", scripts="Hangul",
       facts=("Road-name signs are blue with the Hangul name and its romanisation.",
              "The centre line of two-way roads is yellow.")),
    _C("CN", "China", ("zh-hans",), "right", PlateStyle("{r}·A9999", bg=BLUE, fg=WHITE), POLE_BLUE,
       "{a}-####-####", "chinese_modern", centre_line="yellow",
       aliases=("People's Republic of China", "PRC", "中国", "Zhongguo"), official_languages="Standard Chinese",
       scripts="Simplified Chinese characters",
       facts=("Private cars have blue plates with white characters that start with the province's character: "
              "京 for Beijing, 沪 for Shanghai, 粤 for Guangdong (粤A is Guangzhou).",
              "Street signs are blue with white characters and pinyin below.")),
    _C("TW", "Taiwan", ("zh-hant",), "right", PlateStyle("AAA-9999"), POLE_GREEN, "{a}-####-####", "shophouse",
       centre_line="yellow", aliases=("Republic of China", "臺灣", "台灣", "Chinese Taipei"),
       official_languages="Mandarin Chinese", scripts="Traditional Chinese characters",
       facts=("Ground floors often have covered arcades (qilou) over the pavement.",)),
    _C("HK", "Hong Kong", ("yue", "en-gb"), "left", PlateStyle("AA 9999", rear_bg=YELLOW), WALL_BLUE, "####-####",
       "chinese_modern", aliases=("Hong Kong SAR", "香港", "Heung Gong", "HKSAR"),
       official_languages="Chinese (Cantonese) and English", scripts="Traditional Chinese characters and Latin",
       facts=("Street signs are bilingual: English above Chinese.",
              "Traffic drives on the left; red taxis and double-decker buses are common.")),
    _C("TH", "Thailand", ("th",), "left", PlateStyle("AA 9999", letters="กขคงจฉชญฎฐณดตถทธนบปผพภมยรลวศสหอฮ",
                                                      region_caption=True), POLE_BLUE, "0{a} ### ####", "shophouse",
       centre_line="yellow", aliases=("Siam", "Kingdom of Thailand", "ประเทศไทย", "Prathet Thai"),
       official_languages="Thai", scripts="Thai",
       facts=("Plates show the province name below the number: กรุงเทพมหานคร for Bangkok, เชียงใหม่ for Chiang Mai.",
              "Traffic drives on the left; tuk-tuks and pink or green-and-yellow taxis are common.")),
    _C("VN", "Vietnam", ("vi",), "right", PlateStyle("{r}A-999.99"), WALL_BLUE, "{a} #### ####", "shophouse",
       aliases=("Viet Nam", "Việt Nam"), official_languages="Vietnamese", scripts="Latin with many diacritics",
       facts=("Plates start with a province number: 29 to 33 for Hanoi, 50 to 59 for Ho Chi Minh City.",
              "Motorbikes dominate traffic; narrow 'tube houses' line the streets.")),
    _C("KH", "Cambodia", ("km", "en-af"), "right", PlateStyle("2A-9999", region_caption=True), POLE_BLUE,
       "0{a} ### ###", "shophouse", aliases=("Kampuchea", "Kingdom of Cambodia", "កម្ពុជា"),
       official_languages="Khmer", scripts="Khmer",
       facts=("Plates show the province name in Khmer and English.",)),
    _C("MY", "Malaysia", ("ms", "en-gb"), "left", PlateStyle("{r}AA 9999", bg=BLACK, fg=WHITE), POLE_BLUE,
       "0{a}-#### ####", "shophouse", aliases=("Federation of Malaysia",), official_languages="Malay",
       facts=("Plates are black with white characters; the first letter is the state: W for Kuala Lumpur.",
              "Street names begin with Jalan (road).")),
    _C("SG", "Singapore", ("en-gb", "zh-hans"), "left", PlateStyle("SAA 9999A", bg=BLACK, fg=WHITE),
       POLE_BLUE, "6### ####", "shophouse", aliases=("Republic of Singapore", "Singapura", "新加坡"),
       official_languages="English, Malay, Mandarin Chinese and Tamil",
       facts=("Traffic drives on the left; plates are black with white characters and begin with S.",)),
    _C("ID", "Indonesia", ("id",), "left", PlateStyle("{r} 9999 AAA", bg=BLACK, fg=WHITE), POLE_GREEN,
       "({a}) ###-####", "shophouse", aliases=("Republic of Indonesia",), official_languages="Indonesian",
       facts=("Plate prefixes name the region: B for Jakarta, AB for Yogyakarta.",
              "Street names begin with Jalan, often abbreviated Jl.")),
    _C("PH", "Philippines", ("en-us", "tl"), "right", PlateStyle("AAA 9999", caption="PILIPINAS"), POLE_GREEN,
       "({a}) ####-####", "shophouse", centre_line="yellow", aliases=("Pilipinas", "Republic of the Philippines"),
       official_languages="Filipino and English", facts=("Jeepneys, brightly decorated minibuses, are common.",)),
    _C("IN", "India", ("hi", "en-in"), "left", PlateStyle("{r} 99 AA 9999"), WALL_BLUE, "0{a} #### ####",
       "south_asian", aliases=("Bharat", "भारत", "Republic of India", "Hindustan"),
       official_languages="Hindi and English, with 22 scheduled languages", scripts="Devanagari, Latin and "
       "regional scripts",
       facts=("Plates start with the state code: MH (Maharashtra), DL (Delhi), KA (Karnataka), WB (West Bengal), "
              "TN (Tamil Nadu).", "Signs are often in the state's language and English: Marathi in Mumbai, Kannada in "
              "Bengaluru, Bengali in Kolkata, Tamil in Chennai.", "Auto-rickshaws are everywhere.")),
    _C("BD", "Bangladesh", ("bn",), "left", PlateStyle("{r}-গ 99-9999", digits="০১২৩৪৫৬৭৮৯"), WALL_BLUE,
       "0{a}-###-####", "south_asian", aliases=("People's Republic of Bangladesh", "বাংলাদেশ"),
       official_languages="Bengali", scripts="Bengali",
       facts=("Plates are written in Bengali and name the metropolitan area: ঢাকা মেট্রো (Dhaka Metro), "
              "চট্ট মেট্রো (Chatto Metro, Chattogram).", "Cycle rickshaws crowd the streets.")),
    _C("PK", "Pakistan", ("ur", "en-in"), "left", PlateStyle("AAA-999"), WALL_WHITE, "0{a}-#######",
       "south_asian", aliases=("Islamic Republic of Pakistan", "پاکستان"), official_languages="Urdu and English",
       scripts="Urdu (Perso-Arabic Nastaliq) and Latin",
       facts=("Brightly painted trucks and rickshaws are characteristic.",)),
    _C("LK", "Sri Lanka", ("si", "ta"), "left", PlateStyle("{r} AAA-9999"), WALL_WHITE, "0{a} ### ####",
       "south_asian", aliases=("Ceylon", "ශ්‍රී ලංකාව", "இலங்கை"), official_languages="Sinhala and Tamil",
       scripts="Sinhala, Tamil and Latin",
       facts=("Street signs are trilingual: Sinhala, Tamil and English.", "Plates start with the province: WP is "
              "the Western Province (Colombo).")),
    _C("NP", "Nepal", ("ne",), "left", PlateStyle("{r} 9 च 9999", bg=RED, fg=WHITE,
                                                    digits="०१२३४५६७८९"), WALL_WHITE, "0{a}-######",
       "south_asian", aliases=("Federal Democratic Republic of Nepal", "नेपाल"), official_languages="Nepali",
       scripts="Devanagari", facts=("Private car plates are red with white Devanagari characters; बा is the "
                                    "Bagmati zone around Kathmandu.",)),
    _C("AE", "United Arab Emirates", ("ar", "en-gb"), "right", PlateStyle("A 99999", region_caption=True),
       POLE_BLUE, "0{a} ### ####", "gulf_modern", aliases=("UAE", "U.A.E.", "Emirates", "الإمارات"),
       official_languages="Arabic", scripts="Arabic and Latin",
       facts=("Plates name the emirate: DUBAI, ABU DHABI, SHARJAH.", "Signs are bilingual Arabic and English.")),
    _C("IL", "Israel", ("he", "ar"), "right", _eu("IL", "99-999-99", bg=YELLOW), WALL_WHITE, "0{a}-###-####",
       "middle_eastern", aliases=("State of Israel", "ישראל", "Yisrael"), official_languages="Hebrew",
       scripts="Hebrew, Arabic and Latin",
       facts=("Street signs are trilingual: Hebrew, Arabic and English.", "Plates are yellow.",
              "Many buildings in Tel Aviv are white Bauhaus (International Style) apartment blocks.")),
    _C("JO", "Jordan", ("ar",), "right", PlateStyle("99-99999", caption="JORDAN الأردن"), WALL_WHITE,
       "0{a} ### ####", "middle_eastern", aliases=("Hashemite Kingdom of Jordan", "الأردن", "Al-Urdun"),
       official_languages="Arabic", scripts="Arabic",
       facts=("Buildings in Amman are faced with white or cream limestone by law.",)),
    _C("LB", "Lebanon", ("ar", "fr"), "right", PlateStyle("A 999999", caption="لبنان LIBAN"), WALL_BLUE,
       "0{a} ### ###", "middle_eastern", aliases=("Lebanese Republic", "لبنان", "Liban"),
       official_languages="Arabic (French widely used)", scripts="Arabic and Latin"),
    _C("IR", "Iran", ("fa",), "right", PlateStyle("99 A 999 ایران {r}", letters="بجدسصطقلمنوهی",
                                                                      digits="۰۱۲۳۴۵۶۷۸۹"), POLE_BLUE,
       "0{a} #### ####", "middle_eastern", aliases=("Islamic Republic of Iran", "Persia", "ایران"),
       official_languages="Persian", scripts="Perso-Arabic",
       facts=("Plates end with a two-digit province code after the word ایران; Tehran plates use codes such as 10, "
              "11, 22, 33 and 44.",)),
    _C("SA", "Saudi Arabia", ("ar", "en-gb"), "right", _eu("KSA", "9999 AAA"), POLE_BLUE, "0{a} ### ####",
       "gulf_modern", aliases=("Kingdom of Saudi Arabia", "KSA", "السعودية"), official_languages="Arabic",
       scripts="Arabic"),
    _C("KZ", "Kazakhstan", ("kk", "ru"), "right", _eu("KZ", "999 AAA {r}"), WALL_BLUE, "+7 {a} ### ####",
       "soviet", aliases=("Republic of Kazakhstan", "Қазақстан", "Qazaqstan"),
       official_languages="Kazakh and Russian", scripts="Cyrillic",
       facts=("Plates end with a region number: 02 is Almaty.",)),
    _C("UZ", "Uzbekistan", ("uz", "ru"), "right", PlateStyle("{r} A 999 AA"), WALL_BLUE, "{a} ### ## ##", "soviet",
       aliases=("O'zbekiston", "Oʻzbekiston", "Republic of Uzbekistan"), official_languages="Uzbek",
       scripts="Latin (and Cyrillic)", facts=("Plates start with a region number: 01 is Tashkent.",)),
    _C("MN", "Mongolia", ("mn",), "right", PlateStyle("9999 {r}A", letters="АБВГДЕЖЗИКЛМНОПРСТУФХЦЧШ"), WALL_BLUE,
       "{a}-##-####", "soviet", aliases=("Mongol Uls", "Монгол"), official_languages="Mongolian",
       scripts="Cyrillic", facts=("Plates end with letters naming the province; УБ is Ulaanbaatar.",)),
    # ------------------------------------------------------------------------------ Africa
    _C("EG", "Egypt", ("ar",), "right", PlateStyle("AAA 9999", caption="مصر EGYPT", letters="أبجدرسصطعفقلمنهوى",
                                                             digits="٠١٢٣٤٥٦٧٨٩"),
       WALL_BLUE, "0{a} #### ####", "middle_eastern", aliases=("Arab Republic of Egypt", "مصر", "Misr", "Masr"),
       official_languages="Arabic", scripts="Arabic",
       facts=("Plates carry Arabic letters and Eastern Arabic numerals under a band reading مصر EGYPT.",)),
    _C("MA", "Morocco", ("ar", "fr"), "right", PlateStyle("99999 | A | 9", letters="أبدهوط"), WALL_WHITE,
       "0{a}-##-##-##", "north_african", aliases=("Kingdom of Morocco", "Maroc", "المغرب", "Al-Maghrib"),
       official_languages="Arabic and Amazigh (Berber); French widely used", scripts="Arabic, Tifinagh and Latin",
       facts=("Street signs are in Arabic and French.",
              "Marrakesh buildings are painted a uniform ochre-red; Casablanca is known for white art-deco "
              "buildings.")),
    _C("TN", "Tunisia", ("ar", "fr"), "right", PlateStyle("999 تونس 9999", bg=BLACK, fg=WHITE), WALL_BLUE,
       "{a} ### ###", "north_african", aliases=("Tunisian Republic", "Tunisie", "تونس"),
       official_languages="Arabic; French widely used", scripts="Arabic and Latin",
       facts=("Plates are black with white characters and the word تونس in the middle.",)),
    _C("DZ", "Algeria", ("ar", "fr"), "right", PlateStyle("99999 999 {r}", rear_bg=YELLOW), WALL_BLUE,
       "0{a} ## ## ##", "french_colonial", aliases=("People's Democratic Republic of Algeria", "Algérie", "الجزائر"),
       official_languages="Arabic and Tamazight", scripts="Arabic and Latin",
       facts=("Plates end with the wilaya number: 16 is Algiers.",
              "Central Algiers has white Haussmann-style buildings with blue shutters.")),
    _C("SN", "Senegal", ("fr",), "right", PlateStyle("{r}-9999-A"), WALL_BLUE, "{a} ### ## ##", "african_urban",
       aliases=("Sénégal", "Republic of Senegal"), official_languages="French (Wolof widely spoken)",
       facts=("Plates start with the region: DK is Dakar.",
              "Yellow-and-black taxis and painted 'car rapide' minibuses are common in Dakar.")),
    _C("CI", "Ivory Coast", ("fr",), "right", PlateStyle("9999 AA {r}"), WALL_BLUE, "{a} ## ## ## ##",
       "african_urban", aliases=("Côte d'Ivoire", "Cote d'Ivoire", "Cote dIvoire", "Republic of Côte d'Ivoire"),
       official_languages="French",
       facts=("Plates end with a region number: 01 is Abidjan.", "Orange taxis (woro-woro and taxi compteur) are "
                                                                 "common in Abidjan.")),
    _C("GH", "Ghana", ("en-af",), "right", PlateStyle("{r} 9999-99"), POLE_WHITE, "0{a} ### ####",
       "african_urban", aliases=("Republic of Ghana",), official_languages="English",
       facts=("Plates start with a region code: GR, GT, GE... for Greater Accra.",)),
    _C("NG", "Nigeria", ("en-af",), "right", PlateStyle("AAA 999 AA", region_caption=True), POLE_WHITE,
       "0{a} ### ####", "african_urban", aliases=("Federal Republic of Nigeria", "Naija"),
       official_languages="English", facts=("Plates carry the state name across the top, e.g. LAGOS.",
                                             "Yellow minibuses (danfo) are the common transport in Lagos.")),
    _C("KE", "Kenya", ("en-af", "sw"), "left", PlateStyle("KAA 999A", rear_bg=YELLOW), POLE_WHITE,
       "0{a} ### ###", "african_urban", aliases=("Republic of Kenya",), official_languages="Swahili and English",
       facts=("Traffic drives on the left; rear plates are yellow.",
              "Colourfully painted minibuses (matatus) are the common transport.")),
    _C("TZ", "Tanzania", ("sw", "en-af"), "left", PlateStyle("T 999 AAA", bg=YELLOW), POLE_WHITE,
       "0{a} ### ####", "african_urban", aliases=("United Republic of Tanzania",), official_languages="Swahili and "
       "English", facts=("Plates are yellow and start with T.", "Minibuses are called dala dala.")),
    _C("UG", "Uganda", ("en-af",), "left", PlateStyle("UAA 999A", rear_bg=YELLOW), POLE_WHITE, "0{a} ######",
       "african_urban", aliases=("Republic of Uganda",), official_languages="English and Swahili",
       facts=("Motorbike taxis (boda boda) are everywhere.",)),
    _C("ET", "Ethiopia", ("am",), "right", PlateStyle("{r} 3-A99999"), POLE_BLUE, "0{a} ### ####",
       "african_urban", aliases=("Federal Democratic Republic of Ethiopia", "ኢትዮጵያ", "Abyssinia"),
       official_languages="Amharic and other regional languages", scripts="Ge'ez (Ethiopic)",
       facts=("Amharic is written in the Ge'ez (Ethiopic) script.", "Blue-and-white minibus taxis are common in "
                                                                    "Addis Ababa.")),
    _C("ZA", "South Africa", ("en-af", "af"), "left", PlateStyle("{r}"), POLE_WHITE, "0{a} ### ####",
       "african_urban", edge_line="yellow", aliases=("Republic of South Africa", "RSA", "Suid-Afrika"),
       official_languages="Twelve official languages, including Zulu, Xhosa, Afrikaans and English",
       facts=("Road edges are marked with yellow lines.",
              "Plates differ by province: Western Cape plates end in WP or start with CA (Cape Town); Gauteng plates "
              "end in GP; Durban plates start with ND.")),
    _C("NA", "Namibia", ("en-af", "af"), "left", PlateStyle("N 99999 {r}"), POLE_WHITE, "0{a} ### ###",
       "african_urban", edge_line="yellow", aliases=("Republic of Namibia",), official_languages="English",
       facts=("Plates start with N and end with the town letters: W is Windhoek.",)),
    _C("ZW", "Zimbabwe", ("en-af",), "left", PlateStyle("AAA 9999", rear_bg=YELLOW), POLE_WHITE,
       "0{a} ### ###", "african_urban", aliases=("Republic of Zimbabwe",), official_languages="English, Shona, "
       "Ndebele and others", facts=("Harare's avenues are lined with purple-flowering jacaranda trees.",)),
    _C("ZM", "Zambia", ("en-af",), "left", PlateStyle("AAA 9999", rear_bg=YELLOW), POLE_WHITE, "0{a} ### ###",
       "african_urban", aliases=("Republic of Zambia",), official_languages="English"),
    _C("MZ", "Mozambique", ("pt",), "left", PlateStyle("AAA 999 {r}"), WALL_BLUE, "{a} ### ###", "african_urban",
       aliases=("Moçambique", "Mocambique", "Republic of Mozambique"), official_languages="Portuguese",
       facts=("Unusually for a Portuguese-speaking country, traffic drives on the left.",
              "Plates end with the province: MC is Maputo City.")),
    _C("AO", "Angola", ("pt",), "right", PlateStyle("{r}-99-99-AA"), WALL_BLUE, "{a} ### ###", "african_urban",
       aliases=("Republic of Angola",), official_languages="Portuguese",
       facts=("Plates start with the province: LD is Luanda.", "Blue-and-white minibus taxis (candongueiros) are "
                                                               "common.")),
    _C("MG", "Madagascar", ("fr",), "right", PlateStyle("9999 TAA"), WALL_WHITE, "0{a} ## ### ##",
       "african_urban", aliases=("Republic of Madagascar", "Madagasikara"), official_languages="Malagasy and French",
       facts=("Old Renault 4 and Citroën 2CV taxis are common in the capital.",)),
    _C("MU", "Mauritius", ("en-gb", "fr"), "left", PlateStyle("9999 AA 99", rear_bg=YELLOW), WALL_WHITE,
       "### ####", "african_urban", aliases=("Republic of Mauritius", "Maurice"),
       official_languages="English and French (Mauritian Creole widely spoken)",
       facts=("Traffic drives on the left; street names are often French.",)),
    # ------------------------------------------------------------------------------ North America
    _C("US", "United States", ("en-us",), "right", PlateStyle("AAA-9999", region_caption=True), POLE_GREEN,
       "({a}) ###-####", "na_downtown", centre_line="yellow",
       aliases=("USA", "U.S.A.", "US", "U.S.", "United States of America", "America"),
       official_languages="English (de facto); Spanish widely spoken",
       facts=("Plates name the issuing state across the top.",
              "Street-name signs are usually green with white letters on poles at intersections.",
              "Two-way roads have a yellow centre line.")),
    _C("CA", "Canada", ("en-us", "fr-ca"), "right", PlateStyle("AAAA 999", region_caption=True), POLE_GREEN,
       "({a}) ###-####", "na_downtown", centre_line="yellow", official_languages="English and French",
       facts=("Plates name the province: ONTARIO, QUÉBEC, BRITISH COLUMBIA.",
              "In Quebec signs are in French (rue, dépanneur).")),
    _C("MX", "Mexico", ("es-la",), "right", PlateStyle("AAA-999-A", region_caption=True), WALL_WHITE,
       "{a} #### ####", "latin_colonial", centre_line="yellow",
       aliases=("México", "United Mexican States", "Estados Unidos Mexicanos"), official_languages="Spanish (de "
       "facto) and 68 Indigenous languages",
       facts=("Plates name the state at the top: CIUDAD DE MÉXICO, JALISCO, OAXACA.",
              "Mexico City taxis are pink and white.")),
    _C("GT", "Guatemala", ("es-la",), "right", PlateStyle("P-999AAA", caption="GUATEMALA"), WALL_WHITE,
       "####-####", "latin_colonial", centre_line="yellow", aliases=("Republic of Guatemala",),
       official_languages="Spanish", facts=("Brightly painted former school buses ('chicken buses') are common.",)),
    _C("CU", "Cuba", ("es-la",), "right", PlateStyle("P999 999", bg=YELLOW, caption="CUBA"), WALL_WHITE,
       "{a} ### ####", "latin_colonial", centre_line="yellow", aliases=("Republic of Cuba",),
       official_languages="Spanish", facts=("Classic American cars from the 1950s are still common.",
                                             "Private cars have yellow plates.")),
    _C("CR", "Costa Rica", ("es-la",), "right", PlateStyle("AAA-999", caption="COSTA RICA"), POLE_BLUE,
       "####-####", "latin_modern", centre_line="yellow", aliases=("Republic of Costa Rica",),
       official_languages="Spanish", facts=("San José taxis are red.",)),
    _C("PA", "Panama", ("es-la",), "right", PlateStyle("AA9999", caption="PANAMÁ"), POLE_GREEN, "###-####",
       "latin_modern", centre_line="yellow", aliases=("Panamá", "Republic of Panama"), official_languages="Spanish"),
    _C("DO", "Dominican Republic", ("es-la",), "right", PlateStyle("A999999", caption="REPÚBLICA DOMINICANA"),
       WALL_WHITE, "({a}) ###-####", "latin_colonial", centre_line="yellow",
       aliases=("República Dominicana", "Republica Dominicana", "DR"), official_languages="Spanish"),
    _C("JM", "Jamaica", ("en-gb",), "left", PlateStyle("9999 AA", caption="JAMAICA"), POLE_GREEN, "(876) ###-####",
       "latin_modern", centre_line="yellow", official_languages="English (Jamaican Patois widely spoken)",
       facts=("Traffic drives on the left.",)),
    # ------------------------------------------------------------------------------ South America
    _C("BR", "Brazil", ("pt-br",), "right", PlateStyle("AAA9A99", caption="BRASIL"), POLE_BLUE,
       "({a}) ####-####", "latin_modern", centre_line="yellow",
       aliases=("Brasil", "Federative Republic of Brazil"), official_languages="Portuguese",
       facts=("Mercosur plates are white with a blue band reading BRASIL.",
              "Rio de Janeiro's beachfront pavements have wave-patterned Portuguese mosaic.")),
    _C("AR", "Argentina", ("es-la",), "right", PlateStyle("AA 999 AA", caption="ARGENTINA"), POLE_BLUE,
       "({a}) ####-####", "latin_modern", centre_line="yellow", aliases=("Argentine Republic", "República Argentina"),
       official_languages="Spanish", facts=("Mercosur plates are white with a blue band reading ARGENTINA.",
                                            "Buenos Aires taxis are black and yellow.")),
    _C("CL", "Chile", ("es-la",), "right", PlateStyle("AAAA·99", caption="CHILE"), POLE_BLUE, "{a} #### ####",
       "latin_modern", centre_line="yellow", aliases=("Republic of Chile",), official_languages="Spanish"),
    _C("PE", "Peru", ("es-la",), "right", PlateStyle("AAA-999", caption="PERÚ"), WALL_WHITE, "({a}) ###-####",
       "latin_colonial", centre_line="yellow", aliases=("Perú", "Republic of Peru"),
       official_languages="Spanish, Quechua and Aymara",
       facts=("Colonial centres have carved wooden balconies.",)),
    _C("CO", "Colombia", ("es-la",), "right", PlateStyle("AAA 999", bg=YELLOW, region_caption=True), POLE_BLUE,
       "({a}) ### ####", "latin_modern", centre_line="yellow", aliases=("Republic of Colombia",),
       official_languages="Spanish",
       facts=("Plates are yellow with the registering city written below: BOGOTÁ D.C., MEDELLÍN.",
              "Streets are numbered: Calles run one way and Carreras the other.")),
    _C("EC", "Ecuador", ("es-la",), "right", PlateStyle("{r}AA-9999", caption="ECUADOR"), POLE_BLUE,
       "({a}) ###-####", "latin_colonial", centre_line="yellow", aliases=("Republic of Ecuador",),
       official_languages="Spanish", facts=("The first letter of a plate is the province: P is Pichincha (Quito).",)),
    _C("BO", "Bolivia", ("es-la",), "right", PlateStyle("9999AAA", caption="BOLIVIA"), POLE_BLUE, "{a} ### ####",
       "latin_colonial", centre_line="yellow", aliases=("Plurinational State of Bolivia",),
       official_languages="Spanish and 36 Indigenous languages"),
    _C("UY", "Uruguay", ("es-la",), "right", PlateStyle("{r}AA 9999", caption="URUGUAY"), POLE_BLUE,
       "{a} ### ####", "latin_modern", centre_line="yellow", aliases=("Oriental Republic of Uruguay",),
       official_languages="Spanish", facts=("The first letter of a plate is the department: S is Montevideo.",)),
    _C("VE", "Venezuela", ("es-la",), "right", PlateStyle("AA999AA", caption="VENEZUELA"), POLE_BLUE,
       "(0{a}) ###-####", "latin_modern", centre_line="yellow",
       aliases=("Bolivarian Republic of Venezuela",), official_languages="Spanish"),
    _C("PY", "Paraguay", ("es-la",), "right", PlateStyle("AAAA 999", caption="PARAGUAY"), POLE_BLUE,
       "(0{a}) ### ###", "latin_colonial", centre_line="yellow", aliases=("Republic of Paraguay", "Paraguái"),
       official_languages="Spanish and Guaraní"),
    # ------------------------------------------------------------------------------ Oceania
    _C("AU", "Australia", ("en-au",), "left", PlateStyle("AAA-99A", region_caption=True), POLE_BLUE,
       "({a}) #### ####", "australasian", aliases=("Commonwealth of Australia", "Oz"), official_languages="English "
       "(de facto)", facts=("Plates show the state: NSW, VIC, QLD, WA, SA.",
                            "Shopfronts have verandas (awnings on posts) over the footpath.")),
    _C("NZ", "New Zealand", ("en-au",), "left", PlateStyle("AAA999", caption="NZ"), POLE_BLUE, "(0{a}) ### ####",
       "australasian", aliases=("Aotearoa", "Aotearoa New Zealand"), official_languages="English, Māori and NZ Sign "
       "Language", facts=("Many places carry Māori names.",)),
    _C("FJ", "Fiji", ("en-au",), "left", PlateStyle("AA 999", caption="FIJI"), POLE_WHITE, "### ####", "pacific",
       aliases=("Republic of Fiji", "Viti"), official_languages="English, Fijian and Fiji Hindi"),
    _C("WS", "Samoa", ("sm", "en-au"), "left", PlateStyle("99999", caption="SAMOA"), POLE_WHITE, "## ###",
       "pacific", aliases=("Independent State of Samoa", "Western Samoa", "Sāmoa"),
       official_languages="Samoan and English", facts=("Samoa switched from right- to left-hand traffic in 2009.",)),
]

COUNTRIES: dict[str, Country] = {c.iso: c for c in COUNTRIES_LIST}
