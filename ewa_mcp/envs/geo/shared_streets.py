"""Street names that many cities of one country share, for the hard locations.

A hard location (hardness.py) shows only cues that several cities share, so that the city follows
from their combination alone. Its street-name sign is read two steps from the start, and a name that
only one city has (Avenida Paulista, Pike Street, Rue Oberkampf) names the city outright. So a hard
location stands on a street whose name is one of the most common of its country: nearly every
Brazilian city has a Rua XV de Novembro, every German town a Bahnhofstraße, every American one a Main
Street. The sign is still there, read and graded (the street level), but it decides nothing between
the country's cities.

Each entry is (answer, sign lines in the country's sign convention and scripts, aliases). A location
keeps its coordinates; only its street's name, sign and aliases are replaced, in ``LOCATIONS_LIST``
(locations.py), so the tasks, the views, the grader and the wiki all read the same name.
"""

from __future__ import annotations

import hashlib
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import Any

from .cities import CITIES
from .cue_sets import hard_city_keys


@dataclass(frozen=True)
class SharedStreet:
    name: str  # the canonical answer
    sign: tuple[str, ...]  # the street-name sign's lines
    aliases: tuple[str, ...] = ()


def _s(name: str, sign: str, *aliases: str) -> SharedStreet:
    return SharedStreet(name, tuple(sign.split("|")), aliases)


# Per country, names that most of its towns and cities have (written from general knowledge of
# street naming: national heroes, dates, "main", "station", "church" and "high" streets).
SHARED_STREETS: dict[str, tuple[SharedStreet, ...]] = {
    "FR": (_s("Rue de la République", "RUE DE LA RÉPUBLIQUE", "Rue de la Republique"),
           _s("Rue Victor Hugo", "RUE VICTOR HUGO", "Victor Hugo Street"),
           _s("Avenue Jean Jaurès", "AVENUE JEAN JAURÈS", "Avenue Jean Jaures"),
           _s("Rue Pasteur", "RUE PASTEUR")),
    "DE": (_s("Bahnhofstraße", "Bahnhofstraße", "Bahnhofstrasse", "Station Street"),
           _s("Hauptstraße", "Hauptstraße", "Hauptstrasse", "Main Street"),
           _s("Schillerstraße", "Schillerstraße", "Schillerstrasse"),
           _s("Goethestraße", "Goethestraße", "Goethestrasse")),
    "ES": (_s("Calle Mayor", "Calle|MAYOR", "Mayor"),
           _s("Calle Real", "Calle|REAL", "Real"),
           _s("Calle Nueva", "Calle|NUEVA", "Nueva")),
    "GB": (_s("High Street", "HIGH STREET", "High St"),
           _s("Station Road", "STATION ROAD", "Station Rd"),
           _s("Church Street", "CHURCH STREET", "Church St")),
    "PT": (_s("Rua Direita", "RUA DIREITA"),
           _s("Rua 5 de Outubro", "RUA 5 DE OUTUBRO", "Rua Cinco de Outubro"),
           _s("Rua de Santo António", "RUA DE SANTO ANTÓNIO", "Rua de Santo Antonio")),
    "PL": (_s("Mickiewicza", "ul.|MICKIEWICZA", "ulica Mickiewicza", "Adama Mickiewicza"),
           _s("Kościuszki", "ul.|KOŚCIUSZKI", "ulica Kościuszki", "Kosciuszki"),
           _s("Sienkiewicza", "ul.|SIENKIEWICZA", "ulica Sienkiewicza")),
    "GR": (_s("Venizelou Street", "ΒΕΝΙΖΕΛΟΥ|VENIZELOU", "Venizelou", "Eleftheriou Venizelou"),
           _s("Kolokotroni Street", "ΚΟΛΟΚΟΤΡΩΝΗ|KOLOKOTRONI", "Kolokotroni")),
    "RU": (_s("Lenin Street", "улица Ленина|ulitsa Lenina", "Ulitsa Lenina", "Lenina"),
           _s("Sovetskaya Street", "Советская улица|Sovetskaya ulitsa", "Sovetskaya ulitsa", "Sovetskaya")),
    "TR": (_s("Cumhuriyet Caddesi", "CUMHURİYET CADDESİ", "Cumhuriyet Avenue", "Cumhuriyet"),
           _s("İnönü Caddesi", "İNÖNÜ CADDESİ", "Inonu Caddesi", "İnönü Avenue"),
           _s("Atatürk Caddesi", "ATATÜRK CADDESİ", "Ataturk Caddesi", "Atatürk Avenue")),
    "JP": (_s("Chūō-dōri", "中央通り|Chuo-dori", "Chuo-dori", "Chuo Dori", "中央通り"),
           _s("Ekimae-dōri", "駅前通り|Ekimae-dori", "Ekimae-dori", "Ekimae Dori", "駅前通り")),
    "KR": (_s("Jungang-ro", "중앙로|Jungang-ro", "Jungangno", "중앙로"),
           _s("Munhwa-ro", "문화로|Munhwa-ro", "Munhwaro", "문화로")),
    "CN": (_s("Renmin Road", "人民路|Renmin Rd.", "Renmin Lu", "人民路"),
           _s("Jiefang Road", "解放路|Jiefang Rd.", "Jiefang Lu", "解放路")),
    "VN": (_s("Lê Lợi", "ĐƯỜNG LÊ LỢI", "Le Loi", "Đường Lê Lợi"),
           _s("Trần Hưng Đạo", "ĐƯỜNG TRẦN HƯNG ĐẠO", "Tran Hung Dao", "Đường Trần Hưng Đạo"),
           _s("Hai Bà Trưng", "ĐƯỜNG HAI BÀ TRƯNG", "Hai Ba Trung", "Đường Hai Bà Trưng")),
    "ID": (_s("Jalan Jenderal Sudirman", "JL. JEND. SUDIRMAN", "Jalan Sudirman", "Jl. Sudirman", "Sudirman"),
           _s("Jalan Diponegoro", "JL. DIPONEGORO", "Jl. Diponegoro", "Diponegoro")),
    "EG": (_s("El Gomhoreya Street", "شارع الجمهورية|El Gomhoreya St.", "Gomhoreya Street", "Gomhuria Street",
              "شارع الجمهورية"),
           _s("Saad Zaghloul Street", "شارع سعد زغلول|Saad Zaghloul St.", "Saad Zaghloul", "شارع سعد زغلول")),
    "MA": (_s("Avenue Hassan II", "شارع الحسن الثاني|Avenue Hassan II", "Hassan II Avenue", "Bd Hassan II"),
           _s("Avenue Mohammed V", "شارع محمد الخامس|Avenue Mohammed V", "Mohammed V Avenue")),
    "ZA": (_s("Church Street", "CHURCH STREET", "Church St"),
           _s("Main Road", "MAIN ROAD", "Main Rd"),
           _s("Station Road", "STATION ROAD", "Station Rd")),
    "US": (_s("Main Street", "Main St", "Main St"),
           _s("Oak Street", "Oak St", "Oak St"),
           _s("Second Street", "2nd St", "2nd Street", "2nd St")),
    "CA": (_s("Main Street", "MAIN ST", "Main St"),
           _s("Victoria Street", "VICTORIA ST", "Victoria St"),
           _s("Church Street", "CHURCH ST", "Church St")),
    "MX": (_s("Avenida Juárez", "AV. JUÁREZ", "Avenida Juarez", "Juárez"),
           _s("Avenida Hidalgo", "AV. HIDALGO", "Hidalgo"),
           _s("Avenida Independencia", "AV. INDEPENDENCIA", "Independencia")),
    "BR": (_s("Rua XV de Novembro", "RUA XV DE NOVEMBRO", "Rua Quinze de Novembro", "XV de Novembro"),
           _s("Rua Sete de Setembro", "RUA SETE DE SETEMBRO", "Rua 7 de Setembro", "Sete de Setembro"),
           _s("Rua Tiradentes", "RUA TIRADENTES", "Tiradentes")),
    "AR": (_s("Avenida San Martín", "AV. SAN MARTÍN", "Avenida San Martin", "San Martín"),
           _s("Calle Belgrano", "BELGRANO", "Belgrano"),
           _s("Calle Rivadavia", "RIVADAVIA", "Rivadavia")),
    "PE": (_s("Avenida Grau", "AV. GRAU", "Grau"),
           _s("Avenida Bolognesi", "AV. BOLOGNESI", "Bolognesi")),
    "CO": (_s("Carrera 5", "CARRERA 5", "Cra. 5", "Carrera Quinta"),
           _s("Calle 12", "CALLE 12", "Cl. 12")),
    "AU": (_s("High Street", "HIGH ST", "High St"),
           _s("Victoria Street", "VICTORIA ST", "Victoria St"),
           _s("Church Street", "CHURCH ST", "Church St")),
}


def _offset(city_key: str) -> int:
    return int.from_bytes(hashlib.sha256(f"shared-street|{city_key}".encode()).digest()[:4], "big")


def with_shared_streets(locations: Iterable[Any]) -> list[Any]:
    """The locations (locations.py's ``Location``, untyped here: this module sits below that one), each
    hard one on one of its country's shared street names (its own where it already
    is one): a city's hard locations take different names (in a seeded rotation), so no two of its tasks
    share an answer."""
    locations = list(locations)
    hard = hard_city_keys((CITIES[loc.city_key] for loc in locations),
                          pedestrian={loc.city_key for loc in locations if loc.pedestrian and loc.difficulty != "easy"})
    taken: dict[str, int] = defaultdict(int)
    # Names a city's hard locations already stand on (High Street in Edinburgh, Chūō-dōri in Tokyo): the
    # rotation skips them, so a second hard location of that city never takes the same answer.
    kept: dict[str, set[str]] = defaultdict(set)
    for loc in locations:
        if loc.difficulty != "easy" and loc.city_key in hard:
            if loc.street in {street.name for street in SHARED_STREETS.get(loc.city.iso, ())}:
                kept[loc.city_key].add(loc.street)
    out: list[Any] = []
    for loc in locations:
        if loc.difficulty == "easy" or loc.city_key not in hard:
            out.append(loc)
            continue
        pool = SHARED_STREETS.get(loc.city.iso)
        if not pool:
            raise ValueError(f"location {loc.id} ({loc.city_key}) is hard, but its country {loc.city.iso} has no "
                             f"shared street names: add some to SHARED_STREETS in shared_streets.py")
        if loc.street in {street.name for street in pool}:
            out.append(loc)  # its surveyed street already has a shared name (Avenida Juárez in Guadalajara)
            continue
        free = [street for street in pool if street.name not in kept[loc.city_key]]
        if not free:
            raise ValueError(f"location {loc.id} ({loc.city_key}) is hard, but its city's other hard locations "
                             f"use every shared street name of {loc.city.iso}: add names to SHARED_STREETS")
        pick = free[(_offset(loc.city_key) + taken[loc.city_key]) % len(free)]
        taken[loc.city_key] += 1
        kept[loc.city_key].add(pick.name)
        out.append(replace(loc, street=pick.name, sign=pick.sign, street_aliases=pick.aliases))
    return out
