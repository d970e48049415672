"""Shop-sign vocabulary per language: what a passer-by reads on shopfronts.

Each word is a ``(native, latin)`` pair: the native spelling is drawn when a font for its
script exists; the Latin transliteration is the deterministic fallback (and what the text
description adds in brackets for non-Latin scripts, as a reader of that script would).
"""

from __future__ import annotations

from dataclasses import dataclass

# The shop kinds every language provides, in a fixed order (scene composition indexes them).
SHOP_KINDS: tuple[str, ...] = ("pharmacy", "bakery", "cafe", "restaurant", "bank", "hotel", "grocery", "books")


@dataclass(frozen=True)
class Language:
    code: str
    name: str  # English name, used by the wiki articles only (never in observations)
    script: str  # Latin, Cyrillic, Greek, Arabic, Hebrew, Devanagari, Han, ...
    words: dict[str, tuple[str, str]]


def _latin(code: str, name: str, *words: str) -> Language:
    return Language(code, name, "Latin", {k: (w, w) for k, w in zip(SHOP_KINDS, words, strict=True)})


def _other(code: str, name: str, script: str, *pairs: tuple[str, str]) -> Language:
    return Language(code, name, script, dict(zip(SHOP_KINDS, pairs, strict=True)))


_ALL: list[Language] = [
    # ------------------------------------------------------------ Latin script
    _latin("en-us", "English", "Pharmacy", "Bakery", "Coffee Shop", "Diner", "Bank", "Hotel", "Grocery", "Books"),
    _latin("en-gb", "English", "Chemist", "Bakery", "Café", "Restaurant", "Bank", "Hotel", "Off Licence", "Bookshop"),
    _latin("en-au", "English", "Chemist", "Bakery", "Espresso Bar", "Bistro", "Bank", "Hotel", "Milk Bar", "Bookshop"),
    _latin("en-in", "English", "Medical Store", "Bakery", "Tea Stall", "Restaurant", "Bank", "Lodge", "General Store",
           "Book Depot"),
    _latin("en-af", "English", "Pharmacy", "Bakery", "Coffee", "Restaurant", "Bank", "Hotel", "Supermarket",
           "Bookshop"),
    _latin("fr", "French", "Pharmacie", "Boulangerie", "Café", "Restaurant", "Banque", "Hôtel", "Épicerie",
           "Librairie"),
    _latin("fr-ca", "French", "Pharmacie", "Boulangerie", "Café", "Casse-croûte", "Caisse populaire", "Hôtel",
           "Dépanneur", "Librairie"),
    _latin("de", "German", "Apotheke", "Bäckerei", "Café", "Gaststätte", "Sparkasse", "Hotel", "Lebensmittel",
           "Buchhandlung"),
    _latin("de-ch", "German", "Apotheke", "Bäckerei-Konditorei", "Café", "Restaurant", "Kantonalbank", "Hotel",
           "Lebensmittel", "Buchhandlung"),
    _latin("es", "Spanish", "Farmacia", "Panadería", "Cafetería", "Restaurante", "Banco", "Hotel", "Supermercado",
           "Librería"),
    _latin("es-la", "Spanish", "Farmacia", "Panadería", "Cafetería", "Comedor", "Banco", "Hotel", "Abarrotes",
           "Librería"),
    _latin("ca", "Catalan", "Farmàcia", "Forn de pa", "Cafeteria", "Restaurant", "Banc", "Hotel", "Supermercat",
           "Llibreria"),
    _latin("it", "Italian", "Farmacia", "Panificio", "Bar Caffè", "Trattoria", "Banca", "Albergo", "Alimentari",
           "Libreria"),
    _latin("pt", "Portuguese", "Farmácia", "Padaria", "Café", "Restaurante", "Banco", "Hotel", "Mercearia",
           "Livraria"),
    _latin("pt-br", "Portuguese", "Drogaria", "Padaria", "Lanchonete", "Restaurante", "Banco", "Hotel",
           "Mercadinho", "Livraria"),
    _latin("nl", "Dutch", "Apotheek", "Bakkerij", "Koffiehuis", "Eetcafé", "Bank", "Hotel", "Supermarkt",
           "Boekhandel"),
    _latin("pl", "Polish", "Apteka", "Piekarnia", "Kawiarnia", "Restauracja", "Bank", "Hotel", "Sklep spożywczy",
           "Księgarnia"),
    _latin("cs", "Czech", "Lékárna", "Pekařství", "Kavárna", "Restaurace", "Banka", "Hotel", "Potraviny",
           "Knihkupectví"),
    _latin("hu", "Hungarian", "Gyógyszertár", "Pékség", "Kávézó", "Étterem", "Bank", "Szálloda", "Élelmiszer",
           "Könyvesbolt"),
    _latin("ro", "Romanian", "Farmacie", "Brutărie", "Cafenea", "Restaurant", "Bancă", "Hotel", "Magazin alimentar",
           "Librărie"),
    _latin("hr", "Croatian", "Ljekarna", "Pekara", "Kafić", "Restoran", "Banka", "Hotel", "Trgovina", "Knjižara"),
    _latin("sv", "Swedish", "Apotek", "Bageri", "Kafé", "Restaurang", "Bank", "Hotell", "Livsmedel", "Bokhandel"),
    _latin("no", "Norwegian", "Apotek", "Bakeri", "Kafé", "Spiseri", "Bank", "Hotell", "Dagligvarer", "Bokhandel"),
    _latin("da", "Danish", "Apotek", "Bageri", "Café", "Spisested", "Bank", "Hotel", "Købmand", "Boghandel"),
    _latin("fi", "Finnish", "Apteekki", "Leipomo", "Kahvila", "Ravintola", "Pankki", "Hotelli", "Ruokakauppa",
           "Kirjakauppa"),
    _latin("is", "Icelandic", "Apótek", "Bakarí", "Kaffihús", "Veitingahús", "Banki", "Hótel", "Matvöruverslun",
           "Bókabúð"),
    _latin("lt", "Lithuanian", "Vaistinė", "Kepykla", "Kavinė", "Restoranas", "Bankas", "Viešbutis",
           "Maisto prekės", "Knygynas"),
    _latin("lv", "Latvian", "Aptieka", "Maiznīca", "Kafejnīca", "Restorāns", "Banka", "Viesnīca",
           "Pārtikas veikals", "Grāmatnīca"),
    _latin("et", "Estonian", "Apteek", "Pagariäri", "Kohvik", "Restoran", "Pank", "Hotell", "Toidupood",
           "Raamatupood"),
    _latin("tr", "Turkish", "Eczane", "Fırın", "Kahve Evi", "Lokanta", "Banka", "Otel", "Bakkal", "Kitapçı"),
    _latin("vi", "Vietnamese", "Nhà thuốc", "Tiệm bánh", "Cà phê", "Quán cơm", "Ngân hàng", "Khách sạn", "Tạp hóa",
           "Nhà sách"),
    _latin("ms", "Malay", "Farmasi", "Kedai Roti", "Kedai Kopi", "Restoran", "Bank", "Hotel", "Kedai Runcit",
           "Kedai Buku"),
    _latin("id", "Indonesian", "Apotek", "Toko Roti", "Warung Kopi", "Rumah Makan", "Bank", "Hotel",
           "Toko Kelontong", "Toko Buku"),
    _latin("tl", "Filipino", "Botika", "Panaderya", "Kapihan", "Karinderya", "Bangko", "Hotel", "Sari-sari Store",
           "Aklatan"),
    _latin("sw", "Swahili", "Duka la Dawa", "Mikate", "Kahawa", "Mgahawa", "Benki", "Hoteli", "Duka la Vyakula",
           "Vitabu"),
    _latin("af", "Afrikaans", "Apteek", "Bakkery", "Koffiewinkel", "Restaurant", "Bank", "Hotel", "Kruidenier",
           "Boekwinkel"),
    _latin("uz", "Uzbek", "Dorixona", "Novvoyxona", "Qahvaxona", "Oshxona", "Bank", "Mehmonxona", "Oziq-ovqat",
           "Kitob do'koni"),
    _latin("sm", "Samoan", "Fale Talavai", "Fale Falaoa", "Kofe", "Fale 'Aiga", "Faletupe", "Faletalimalo",
           "Fale'oloa", "Tusi"),
    # ------------------------------------------------------------ other scripts
    _other("ru", "Russian", "Cyrillic", ("Аптека", "Apteka"), ("Пекарня", "Pekarnya"), ("Кофейня", "Kofeynya"),
           ("Столовая", "Stolovaya"), ("Банк", "Bank"), ("Гостиница", "Gostinitsa"), ("Продукты", "Produkty"),
           ("Книги", "Knigi")),
    _other("uk", "Ukrainian", "Cyrillic", ("Аптека", "Apteka"), ("Пекарня", "Pekarnia"), ("Кав'ярня", "Kaviarnia"),
           ("Їдальня", "Yidalnia"), ("Банк", "Bank"), ("Готель", "Hotel"), ("Продукти", "Produkty"),
           ("Книгарня", "Knyharnia")),
    _other("bg", "Bulgarian", "Cyrillic", ("Аптека", "Apteka"), ("Пекарна", "Pekarna"), ("Кафе", "Kafe"),
           ("Механа", "Mehana"), ("Банка", "Banka"), ("Хотел", "Hotel"), ("Хранителни стоки", "Hranitelni stoki"),
           ("Книжарница", "Knizharnitsa")),
    _other("sr", "Serbian", "Cyrillic", ("Апотека", "Apoteka"), ("Пекара", "Pekara"), ("Кафана", "Kafana"),
           ("Ресторан", "Restoran"), ("Банка", "Banka"), ("Хотел", "Hotel"), ("Продавница", "Prodavnica"),
           ("Књижара", "Knjižara")),
    _other("kk", "Kazakh", "Cyrillic", ("Дәріхана", "Därihana"), ("Наубайхана", "Naubaihana"),
           ("Кофехана", "Kofehana"), ("Асхана", "Ashana"), ("Банк", "Bank"), ("Қонақ үй", "Qonaq üi"),
           ("Азық-түлік", "Azyq-tülik"), ("Кітаптар", "Kitaptar")),
    _other("mn", "Mongolian", "Cyrillic", ("Эмийн сан", "Emiin san"), ("Талх", "Talkh"), ("Кофе шоп", "Kofe shop"),
           ("Гуанз", "Guanz"), ("Банк", "Bank"), ("Зочид буудал", "Zochid buudal"), ("Хүнсний дэлгүүр",
           "Khünsnii delgüür"), ("Номын дэлгүүр", "Nomyn delgüür")),
    _other("el", "Greek", "Greek", ("Φαρμακείο", "Farmakeio"), ("Φούρνος", "Fournos"), ("Καφενείο", "Kafeneio"),
           ("Ταβέρνα", "Taverna"), ("Τράπεζα", "Trapeza"), ("Ξενοδοχείο", "Xenodocheio"),
           ("Παντοπωλείο", "Pantopoleio"), ("Βιβλιοπωλείο", "Vivliopoleio")),
    _other("ka", "Georgian", "Georgian", ("აფთიაქი", "aptiaki"), ("საცხობი", "satskhobi"), ("კაფე", "kape"),
           ("სასადილო", "sasadilo"), ("ბანკი", "banki"), ("სასტუმრო", "sastumro"), ("მარკეტი", "marketi"),
           ("წიგნები", "tsignebi")),
    _other("hy", "Armenian", "Armenian", ("Դեղատուն", "Deghatun"), ("Հացատուն", "Hatsatun"),
           ("Սրճարան", "Srcharan"), ("Ճաշարան", "Chasharan"), ("Բանկ", "Bank"), ("Հյուրանոց", "Hyuranots"),
           ("Մթերք", "Mterk"), ("Գրքեր", "Grker")),
    _other("ja", "Japanese", "Han+Kana", ("薬局", "yakkyoku"), ("パン屋", "pan-ya"), ("喫茶店", "kissaten"),
           ("食堂", "shokudō"), ("銀行", "ginkō"), ("ホテル", "hoteru"), ("スーパー", "sūpā"), ("書店", "shoten")),
    _other("ko", "Korean", "Hangul", ("약국", "yakguk"), ("빵집", "ppangjip"), ("카페", "kape"), ("식당", "sikdang"),
           ("은행", "eunhaeng"), ("호텔", "hotel"), ("마트", "mateu"), ("서점", "seojeom")),
    _other("zh-hans", "Chinese (Mandarin)", "Han (simplified)", ("药店", "yàodiàn"), ("面包店", "miànbāo diàn"),
           ("咖啡馆", "kāfēi guǎn"), ("饭店", "fàndiàn"), ("银行", "yínháng"), ("宾馆", "bīnguǎn"),
           ("超市", "chāoshì"), ("书店", "shūdiàn")),
    _other("zh-hant", "Chinese (Mandarin)", "Han (traditional)", ("藥局", "yàojú"), ("麵包店", "miànbāo diàn"),
           ("咖啡廳", "kāfēi tīng"), ("小吃店", "xiǎochī diàn"), ("銀行", "yínháng"), ("飯店", "fàndiàn"),
           ("便利商店", "biànlì shāngdiàn"), ("書店", "shūdiàn")),
    _other("yue", "Cantonese", "Han (traditional)", ("藥房", "yeuk fong"), ("餅店", "beng dim"),
           ("咖啡室", "ga fe sat"), ("茶餐廳", "cha chaan teng"), ("銀行", "ngan hong"), ("酒店", "zau dim"),
           ("士多", "si do"), ("書局", "syu guk")),
    _other("th", "Thai", "Thai", ("ร้านขายยา", "ran khai ya"), ("เบเกอรี่", "bakery"), ("ร้านกาแฟ", "ran kafae"),
           ("ร้านอาหาร", "ran ahan"), ("ธนาคาร", "thanakhan"), ("โรงแรม", "rongraem"),
           ("ร้านขายของชำ", "ran khai khong cham"), ("ร้านหนังสือ", "ran nangsue")),
    _other("km", "Khmer", "Khmer", ("ឱសថស្ថាន", "osotha sthan"), ("នំប៉័ង", "num pang"), ("កាហ្វេ", "kafe"),
           ("ភោជនីយដ្ឋាន", "phochniyathan"), ("ធនាគារ", "thoneakear"), ("សណ្ឋាគារ", "sonthakear"),
           ("ផ្សារ", "phsar"), ("បណ្ណាគារ", "bannakear")),
    _other("hi", "Hindi", "Devanagari", ("दवा की दुकान", "dava ki dukan"), ("बेकरी", "bekari"),
           ("चाय की दुकान", "chay ki dukan"), ("भोजनालय", "bhojanalay"), ("बैंक", "baink"), ("होटल", "hotal"),
           ("किराना स्टोर", "kirana stor"), ("पुस्तक भंडार", "pustak bhandar")),
    _other("mr", "Marathi", "Devanagari", ("औषधालय", "aushadhalay"), ("बेकरी", "bekari"), ("चहा", "chaha"),
           ("उपहारगृह", "upaharagriha"), ("बँक", "bank"), ("हॉटेल", "hotel"), ("किराणा", "kirana"),
           ("पुस्तके", "pustake")),
    _other("ne", "Nepali", "Devanagari", ("औषधि पसल", "aushadhi pasal"), ("बेकरी", "bekari"),
           ("चिया पसल", "chiya pasal"), ("भोजनालय", "bhojanalaya"), ("बैंक", "baink"), ("होटल", "hotal"),
           ("किराना पसल", "kirana pasal"), ("किताब पसल", "kitab pasal")),
    _other("bn", "Bengali", "Bengali", ("ফার্মেসি", "pharmesi"), ("বেকারি", "bekari"), ("চায়ের দোকান", "chayer dokan"),
           ("রেস্তোরাঁ", "restora"), ("ব্যাংক", "byank"), ("হোটেল", "hotel"), ("মুদি দোকান", "mudi dokan"),
           ("বইয়ের দোকান", "boier dokan")),
    _other("ta", "Tamil", "Tamil", ("மருந்தகம்", "marunthagam"), ("பேக்கரி", "bekkari"), ("காபி", "kaapi"),
           ("உணவகம்", "unavagam"), ("வங்கி", "vangi"), ("விடுதி", "viduthi"), ("மளிகை", "maligai"),
           ("புத்தகக் கடை", "puthagak kadai")),
    _other("kn", "Kannada", "Kannada", ("ಔಷಧಾಲಯ", "aushadhalaya"), ("ಬೇಕರಿ", "bekari"), ("ಕಾಫಿ", "kaphi"),
           ("ಉಪಾಹಾರ ಮಂದಿರ", "upahara mandira"), ("ಬ್ಯಾಂಕ್", "byank"), ("ವಸತಿ ಗೃಹ", "vasati griha"),
           ("ದಿನಸಿ", "dinasi"), ("ಪುಸ್ತಕ ಮಳಿಗೆ", "pustaka malige")),
    _other("si", "Sinhala", "Sinhala", ("ඔසුසල", "osusala"), ("බේකරිය", "bekariya"), ("තේ කඩේ", "the kade"),
           ("ආපනශාලාව", "apanashalawa"), ("බැංකුව", "bankuwa"), ("හෝටලය", "hotalaya"),
           ("සිල්ලර කඩේ", "sillara kade"), ("පොත් හල", "poth hala")),
    _other("ur", "Urdu", "Arabic (Nastaliq)", ("دواخانہ", "dawakhana"), ("بیکری", "bakery"),
           ("چائے خانہ", "chae khana"), ("ہوٹل", "hotel"), ("بینک", "bank"), ("مہمان خانہ", "mehman khana"),
           ("کریانہ", "kiryana"), ("کتاب گھر", "kitab ghar")),
    _other("ar", "Arabic", "Arabic", ("صيدلية", "saydaliya"), ("مخبز", "makhbaz"), ("مقهى", "maqha"),
           ("مطعم", "mat'am"), ("بنك", "bank"), ("فندق", "funduq"), ("بقالة", "baqala"), ("مكتبة", "maktaba")),
    _other("fa", "Persian", "Arabic (Persian)", ("داروخانه", "darukhaneh"), ("نانوایی", "nanvayi"),
           ("کافه", "kafe"), ("رستوران", "restoran"), ("بانک", "bank"), ("هتل", "hotel"),
           ("سوپرمارکت", "supermarket"), ("کتاب‌فروشی", "ketab-forushi")),
    _other("he", "Hebrew", "Hebrew", ("בית מרקחת", "beit merkachat"), ("מאפייה", "ma'afiya"), ("בית קפה", "beit kafe"),
           ("מסעדה", "mis'ada"), ("בנק", "bank"), ("מלון", "malon"), ("מכולת", "makolet"),
           ("חנות ספרים", "chanut sfarim")),
    _other("am", "Amharic", "Ge'ez (Ethiopic)", ("መድኃኒት ቤት", "medhanit bet"), ("ዳቦ ቤት", "dabo bet"),
           ("ቡና ቤት", "buna bet"), ("ምግብ ቤት", "migib bet"), ("ባንክ", "bank"), ("ሆቴል", "hotel"),
           ("ሱቅ", "suq"), ("መጻሕፍት", "metsahift")),
]

LANGUAGES: dict[str, Language] = {lang.code: lang for lang in _ALL}

# Where one language's countries write a shop kind differently: {country ISO code: {language code: {kind:
# words}}}. A shop in that country picks one of its own words (scene.py), never another country's: a
# corner grocery is an "almacén" in Buenos Aires and "abarrotes" in Mexico City, a pharmacy a "droguería"
# in Bogotá. Kinds and languages not listed keep the language's word.
COUNTRY_WORDS: dict[str, dict[str, dict[str, tuple[str, ...]]]] = {
    "MX": {"es-la": {"grocery": ("Abarrotes", "Tienda", "Miscelánea")}},
    "GT": {"es-la": {"grocery": ("Tienda", "Abarrotería")}},
    "CU": {"es-la": {"grocery": ("Bodega", "Mercado")}},
    "CR": {"es-la": {"grocery": ("Pulpería", "Minisúper")}},
    "PA": {"es-la": {"grocery": ("Minisúper", "Tienda")}},
    "DO": {"es-la": {"grocery": ("Colmado",)}},
    "AR": {"es-la": {"grocery": ("Almacén", "Kiosco", "Despensa")}},
    "CL": {"es-la": {"grocery": ("Almacén", "Minimarket")}},
    "PE": {"es-la": {"grocery": ("Bodega", "Abarrotes"), "pharmacy": ("Botica", "Farmacia")}},
    "CO": {"es-la": {"grocery": ("Tienda", "Granero"), "pharmacy": ("Droguería",)}},
    "EC": {"es-la": {"grocery": ("Tienda", "Víveres")}},
    "BO": {"es-la": {"grocery": ("Tienda", "Abarrotes")}},
    "UY": {"es-la": {"grocery": ("Almacén", "Autoservicio")}},
    "VE": {"es-la": {"grocery": ("Bodega", "Abasto")}},
    "PY": {"es-la": {"grocery": ("Despensa", "Almacén")}},
}


def shop_words(country: str, code: str, kind: str) -> tuple[tuple[str, str], ...]:
    """The (native, latin) words a shop of this kind may show in this language in this country."""
    own = COUNTRY_WORDS.get(country, {}).get(code, {}).get(kind)
    if own:
        return tuple((w, w) for w in own)  # every country-specific word so far is in Latin script
    return (language(code).words[kind],)


def language(code: str) -> Language:
    try:
        return LANGUAGES[code]
    except KeyError:
        raise KeyError(f"unknown sign language code {code!r}; known: {sorted(LANGUAGES)}") from None
