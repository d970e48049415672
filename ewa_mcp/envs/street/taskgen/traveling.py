"""Traveling tasks: walk to a landmark described by its look and address (never its name), identify it,
look it up on the wiki, and answer a question whose answer is in the wiki."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any, Iterator


from ewa_mcp.geometry import haversine_m
from ewa_mcp.graders.textnorm import contains_phrase, find_spans, tokens
from ..world import get_world
from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import PageVisited, WebStart
from ewa_mcp.envs.street.goals import ReachedPlace, StreetStart
from ewa_mcp.websites.wiki import store as wiki
from ewa_mcp.taskgen.answer_checks import METRES, YEARS, answer_rule, committed_answer
from ewa_mcp.taskgen.common import WALK_RULE, call, rng_for, site_url, step_budget
from .navigation import corner_phrase

TARGET = 130
HARD_TARGET = 30  # landmarks described only by their look (>= 15 % of the domain)
MIN_M, MAX_M = 200.0, 1000.0
HARD_MAX_M = 600.0  # the agent searches by sight, so the landmark is nearer
QUESTIONS = {
    "year_built": ("In what year was it built?", lambda v: str(v)),
    "architect": ("Who was its architect?", lambda v: str(v)),
    "architectural_style": ("What is its architectural style?", lambda v: str(v)),
    "height_m": ("How tall is it, in metres?", lambda v: f"{float(v):g}"),
    "opening_hours": ("When is it open?", lambda v: str(v)),
}
# The form each answer takes, said in the intent.
FORMS = {
    "year_built": "Answer with the year only.",
    "architect": "Answer with the architect's name as the wiki gives it.",
    "architectural_style": "Answer with the style's name only.",
    "height_m": "Answer with the height in metres (a number).",
    "opening_hours": "Answer with the opening hours as the wiki gives them.",
}
NUMBERS = {"year_built": YEARS, "height_m": METRES}
# The wiki infobox row that holds each fact, for the vocabulary of every attribute.
INFOBOX = {"year_built": "Year built", "architect": "Architect", "architectural_style": "Architectural style",
           "height_m": "Height", "opening_hours": "Opening hours"}


def article_text(article: Any) -> str:
    return " ".join([article.title, *article.infobox.values(), wiki.plain_text(article.body)])


def _fact_text(key: str, value: Any) -> str:
    if key == "height_m":
        number = str(value).split()[0] if str(value).split() else ""
        try:
            return f"{float(number):g}"
        except ValueError:
            return str(value)
    return wiki.plain_text(str(value)).strip()


@lru_cache(maxsize=None)
def vocabulary(key: str) -> tuple[str, ...]:
    """Every value the attribute takes across the world's places and the wiki's infoboxes, sorted: the
    candidates an answer about one landmark must be told apart from."""
    world = get_world()
    values = {_fact_text(key, p.facts[key]) for p in world.places.values() if key in p.facts}
    values |= {_fact_text(key, a.infobox[INFOBOX[key]]) for a in wiki.load_articles() if INFOBOX[key] in a.infobox}
    if key == "architect":  # and every architect the wiki has an article about
        values |= {a.title for a in wiki.load_articles() if a.group == "architects"}
    return tuple(sorted(v for v in values if v))


_FIRM_WORDS = ("&", " and ", "+", " with ", "Co.", "Company", "Partners", "Associates", "Studio", "Workshop")


def _is_person(name: str) -> bool:
    """One person's name: at least two words, no team or firm words, no digits or brackets."""
    return (len(tokens(name)) >= 2 and not any(w in f" {name} " for w in _FIRM_WORDS) and "," not in name
            and "(" not in name and not any(ch.isdigit() for ch in name))


def _is_firm(name: str) -> bool:
    return not any(ch.isdigit() for ch in name) and name[:1].isupper() and any(w in f" {name} " for w in _FIRM_WORDS)


def _parts(value: str) -> list[str]:
    """The names of a value listing several ("A (1847); B (tower, 1915)"), without their brackets."""
    return [re.sub(r"\s*\([^)]*\)", "", part).strip(" ,;:") for part in value.split(";")]


def names_of(key: str, value: str) -> tuple[list[str], list[str]]:
    """(aliases, related) of one candidate value: aliases are other real names of the value itself
    ("Henry Hobson Richardson" for "H. H. Richardson", the firm in "Charles McKim (McKim, Mead & White)",
    "Châteauesque" in "French Renaissance (Châteauesque)", the names without the brackets); related are
    names the wiki files with it that name someone or something else (a partner, a firm of a person).
    Brackets that qualify ("(planting)", "(tower, 1915)", "(2004 expansion)") are never names."""
    aliases: list[str] = []
    related: list[str] = []
    parts = _parts(value)
    base = parts[0] if len(parts) == 1 else ""
    if len(parts) > 1:
        aliases += [" ".join(parts), " and ".join(parts), ", ".join(parts[:-1]) + " and " + parts[-1]]
    elif base != value:
        aliases.append(base)
    inner = re.findall(r"\(([^)]*)\)", value)
    if len(parts) == 1 and len(inner) == 1:
        word = inner[0].strip()
        if key == "architect" and _is_firm(word):
            aliases.append(word)
        elif key == "architectural_style" and word[:1].isupper() and not any(ch.isdigit() for ch in word):
            aliases.append(word)
    if key == "architect":
        own = base or value
        article = wiki.find(own)
        if article is not None and article.group == "architects":
            surname = tokens(own)[-1:] if _is_person(own) else None
            for name in [article.title, *article.aliases]:
                if tokens(name) == tokens(own):
                    continue
                if surname and _is_person(name) and tokens(name)[-1:] == surname:
                    aliases.append(name)  # the same person spelled out: "Daniel Hudson Burnham"
                else:
                    related.append(name)  # a partner, the firm of a person, a team
    keep = [a for a in dict.fromkeys(aliases) if tokens(a) and tokens(a) != tokens(value)]
    return keep, [r for r in dict.fromkeys(related) if r not in keep]


def answer_check(key: str, answer: str) -> Any:
    """The committed-answer check of one question, or None when no short answer can be told apart from
    the other candidates (a value such as "Modernism (green skyscraper)" whose plain form, "Modernism",
    is itself another candidate). The distractors are every other candidate with each of its aliases
    and related names, so naming another candidate in any of its spellings fails."""
    others = [v for v in vocabulary(key) if tokens(v) != tokens(answer)]
    other_keys = {tuple(tokens(v)) for v in others}
    aliases, related = names_of(key, answer)
    base = _parts(answer)[0]
    if len(_parts(answer)) == 1 and base != answer and tuple(tokens(base)) in other_keys:
        return None
    rival_names: list[str] = []
    rival_keys: set[tuple[str, ...]] = set()  # what names another candidate itself (not its partners)
    for other in others:
        other_aliases, other_related = names_of(key, other)
        rival_names += [other, *other_aliases, *other_related]
        rival_keys |= {tuple(tokens(n)) for n in (other, *other_aliases)}
    # An alias that is also another candidate's name would let one answer pass two questions: it may be
    # repeated, but it does not name the answer.
    shared = [a for a in aliases if tuple(tokens(a)) in rival_keys]
    aliases = [a for a in aliases if a not in shared]
    own = {tuple(tokens(answer)), *(tuple(tokens(a)) for a in aliases)}
    rival_names = [n for n in rival_names if tuple(tokens(n)) not in own]
    # A rival that is part of the answer ("Arthur Gilman" in "Gridley J. F. Bryant and Arthur Gilman") may be
    # repeated with it; alone it does not name the answer.
    inside = [n for n in rival_names if find_spans(tokens(answer), tokens(n))]
    rival_names = [n for n in rival_names if n not in inside]
    return committed_answer(answer, rival_names, aliases=aliases, context=[*related, *shared, *inside],
                            numbers=NUMBERS.get(key))


def start_place(world: Any, target: Any, rng: Any, max_m: float = MAX_M) -> tuple[Any, Any] | None:
    """A nearby street corner to start from, MIN_M..max_m away on foot."""
    graph = world.city(target.city)
    ids = sorted(graph.ids)
    for _ in range(60):
        node_id = rng.choice(ids)
        node = world.node(node_id)
        if len(node.streets) < 2:
            continue
        try:
            route = world.directions(node_id, target.node)
        except ValueError:
            continue
        if MIN_M <= route.distance_m <= max_m:
            return world.place(node_id), route
    return None


# Hard tasks name the landmark in two hops (issue 26, principle 6): by a wiki fact it shares with another
# named landmark X of its city ("the same architectural style as X", "built in the same decade as X", "designed
# by the architect of X"), and a walking range from the corner. The agent reads X's article for the fact, finds
# the landmarks sharing it (several do, the others beyond the range), and measures the walks to pick the one in
# range: no single search or single walk answers it.
CUES = {"architectural_style": "has the same architectural style as {x}",
        "year_built": "was built in the same decade as {x}",
        "architect": "was designed by the same architect as {x}"}
CUE_LABEL = {"architectural_style": "their architectural style",
             "year_built": "the year each was built (a decade is 1920 to 1929, and so on)",
             "architect": "their architect"}
# The range is a hard edge measured on the map, and the choice is made at that edge (issue 26, principle 6): the
# answer's walk ends BOUNDARY_IN_M or less inside the range, and at least MIN_RIVALS other places sharing the
# fact lie just beyond it (at most BOUNDARY_OUT_M over), most of them nearer than the answer as the crow flies,
# so neither the straight line nor a guess from addresses settles it: only the map's walks do. The map gives
# walks to the metre; BOUNDARY_GAP_M keeps every walk that clear of the edge.
BOUNDARY_IN_M = 70.0
BOUNDARY_OUT_M = 80.0
BOUNDARY_GAP_M = 8.0
BOUNDARY_STEP_M = 50  # the range is a multiple of this
BOUNDARY_DRAWS = 90  # corners drawn near the target: the edge's constraints leave few of them
MIN_RIVALS = 1


def boundary_limit(walk_m: float) -> int | None:
    """The round range (a multiple of BOUNDARY_STEP_M) whose edge a walk of ``walk_m`` ends just inside
    (BOUNDARY_GAP_M..BOUNDARY_IN_M short of it), or None when no such range exists."""
    limit = int(-(-(walk_m + BOUNDARY_GAP_M) // BOUNDARY_STEP_M) * BOUNDARY_STEP_M)
    return limit if limit - walk_m <= BOUNDARY_IN_M else None


CUE_MAX_M = 900.0  # the walk from the corner (the range holds other landmarks, so it is wider than by sight)
MIN_SHARING = 1  # landmarks sharing the fact besides the target and X: the fact alone never singles it out
# Words that do not make two style or architect names alike ("Greek Revival" and "Gothic Revival" differ).
_GENERIC = {"revival", "architecture", "style", "and", "the", "of", "with", "base", "tower", "co", "company",
            "partners", "associates", "studio", "workshop"}


def cue_value(key: str, place: Any) -> str | None:
    """The value two landmarks must share for ``key``: the style or architect as the wiki gives it, or the
    decade of the year built ("1920s")."""
    if key not in place.facts:
        return None
    if key == "year_built":
        try:
            return f"{int(str(place.facts[key]).strip()) // 10 * 10}s"
        except ValueError:
            return None
    return _fact_text(key, place.facts[key]) or None


def _alike(key: str, a: str, b: str) -> bool:
    """Whether two values could be read as the same one (they share a distinctive word: "International Style"
    and "International Style / Modernism", "Charles McKim" and "McKim, Mead & White"). Decades are exact."""
    if key == "year_built":
        return a == b
    return bool({t for t in tokens(a) if t not in _GENERIC} & {t for t in tokens(b) if t not in _GENERIC})


def article_of(place: Any) -> Any:
    """The wiki article of a landmark that has one (every landmark a hard task names or targets)."""
    article = wiki.by_poi_id(place.id)
    if article is None:
        raise ValueError(f"{place.id} has no wiki article; a hard traveling task names only landmarks with one")
    return article


def names_of_place(place: Any) -> list[str]:
    """Every name an article could give the landmark: its place name, its article's title and aliases."""
    article = wiki.by_poi_id(place.id)
    names = [place.name, *([article.title, *article.aliases] if article is not None else [])]
    return [n for n in dict.fromkeys(names) if len(tokens(n)) >= 1]


def names_place(text: str, place: Any) -> bool:
    return any(contains_phrase(text, n) for n in names_of_place(place))


def concept_articles(key: str, value: str) -> list[Any]:
    """The wiki's articles about a shared value itself (the style's or the architect's article): the pages
    a search for the fact opens first."""
    if key == "year_built":
        return []
    found = [wiki.find(value), *(wiki.find(a) for a in names_of(key, value)[0])]
    out: dict[str, Any] = {a.slug: a for a in found if a is not None and a.group in ("architecture", "architects")}
    return list(out.values())


def near_starts(world: Any, target: Any, rng: Any, draws: int = 60) -> list[tuple[Any, Any]]:
    """Street corners MIN_M..CUE_MAX_M on foot from the landmark, in a seeded random order (drawn among the
    corners near it as the crow flies: a draw over the whole city rarely lands in range)."""
    return list(iter_near_starts(world, target, rng, draws))


def iter_near_starts(world: Any, target: Any, rng: Any, draws: int = 60) -> Iterator[tuple[Any, Any]]:
    """``near_starts`` one at a time: the shuffle is drawn first, each walk measured only when reached."""
    graph = world.city(target.city)
    end = world.node(target.node)
    ids = [i for i in sorted(graph.ids) if haversine_m(end.lat, end.lng, world.node(i).lat, world.node(i).lng)
           <= CUE_MAX_M and len(world.node(i).streets) >= 2]
    rng.shuffle(ids)
    for node_id in ids[:draws]:
        try:
            route = world.directions(node_id, target.node)
        except ValueError:
            continue
        if MIN_M <= route.distance_m <= CUE_MAX_M:
            yield world.place(node_id), route


def cue_task(world: Any, target: Any, rng: Any) -> tuple[str, str, Any, Any, Any, int] | None:
    """(cue key, shared value, X, start, route, range in m) for a hard task about ``target``, or None.

    Two hops: X is another landmark of the city whose article gives the shared value; at least MIN_SHARING
    landmarks besides the target and X share it too, every one of them beyond the range, and at least MIN_RIVALS
    of them just beyond it (``boundary_limit``: the answer just inside; X may stand anywhere: the intent names
    it, so it is never the answer). A corner where a rival just beyond is nearer than the answer as the crow
    flies is taken first; else one where a rival just beyond is within the range as the crow flies. The range alone does not
    single the target out (another landmark with an article stands within it), and no landmark within the
    range (no place with an article, a station included) has a value that could be read as the same one. Nothing names the answer in one read: the target's
    article does not name X, X's article does not name the target, and the value's own article (the style's,
    the architect's) names none or several of the city's landmarks sharing it, never the target alone."""
    peers = [p for p in landmarks_of(world) if p.city == target.city and p.id != target.id
             and wiki.by_poi_id(p.id) is not None]
    # Every other place of the city whose article could give the fact (a station's too): none in range may
    # read as sharing it.
    with_articles = sorted((p for p in world.places.values() if p.city == target.city and p.id != target.id
                            and wiki.by_poi_id(p.id) is not None), key=lambda p: p.id)
    target_text = article_text(wiki.by_poi_id(target.id))
    keys = [k for k in CUES if k in target.facts]
    rng.shuffle(keys)
    keys.sort(key=lambda k: k == "year_built")  # a decade is shared most widely: the other facts first
    for key in keys:
        value = cue_value(key, target)
        if value is None or (key == "architect" and answer_check(key, value) is None):
            continue
        sharing = [p for p in peers if cue_value(key, p) == value]
        if len(sharing) < MIN_SHARING + 1:
            continue
        if key != "year_built" and not all(contains_phrase(article_text(wiki.by_poi_id(p.id)), value)
                                           for p in [target, *sharing]):
            continue  # the wiki must state the fact of the landmark and of those sharing it
        vias = [x for x in sharing if not names_place(target_text, x)
                and not names_place(article_text(wiki.by_poi_id(x.id)), target)
                and not names_place(article_of(x).title, target)]
        if not vias:
            continue
        alike = [p for p in with_articles if (v := cue_value(key, p)) is not None and _alike(key, value, v)]
        weak: tuple[str, str, Any, Any, Any, int] | None = None
        for start, route in near_starts(world, target, rng, BOUNDARY_DRAWS):
            limit = boundary_limit(route.distance_m)
            if limit is None:
                continue  # the answer's walk must end just inside a round range
            walks: dict[str, float] = {}

            def walk_m(p: Any) -> float:
                if p.id not in walks:
                    try:
                        walks[p.id] = float(world.directions(start.node, p.node).distance_m)
                    except ValueError:
                        walks[p.id] = float("inf")
                return walks[p.id]

            if not any(walk_m(p) <= limit - 60 for p in peers):
                continue  # the range alone would single it out
            here, end = world.node(start.node), world.node(target.node)
            target_crow = haversine_m(here.lat, here.lng, end.lat, end.lng)
            for via in rng.sample(vias, len(vias)):
                others = [p for p in sharing if p.id != via.id]
                if any(p.id != via.id and walk_m(p) <= limit + BOUNDARY_GAP_M for p in alike):
                    continue  # another place within the range (or at its very edge) shares the fact, or reads so
                rivals = [p for p in others if walk_m(p) <= limit + BOUNDARY_OUT_M]
                if len(rivals) < MIN_RIVALS:
                    continue  # a rival just beyond the range is what makes the walks worth measuring
                named = {p.id for a in concept_articles(key, value) for p in [target, *others]
                         if names_place(article_text(a), p)}
                if target.id in named and len(named) < 2:
                    continue  # the style's (or architect's) article would name the answer alone
                if len(others) < MIN_SHARING:
                    continue
                crows = [haversine_m(here.lat, here.lng, (n := world.node(p.node)).lat, n.lng) for p in rivals]
                if any(c < target_crow for c in crows):
                    return key, value, via, start, route, limit  # the straight line picks a rival
                if weak is None and any(c <= limit for c in crows):
                    weak = (key, value, via, start, route, limit)  # a rival within the range as the crow flies
        if weak is not None:
            return weak
    return None


def landmark_task(world: Any, tid: str, target: Any, article: Any, question_key: str, start: Any, route: Any,
                  trng: Any, hard: bool, cue: tuple[str, str, Any, int] | None = None,
                  pair: tuple[str, str, Any] | None = None) -> Task:
    """One task: walk to the landmark, look it up, answer. A hard task with a ``cue`` (key, shared value, X,
    range) names the landmark by the fact it shares with the named landmark X plus a walking range from the
    corner, which single it out only together; with a ``pair`` too (key, shared value, Y) it names the place
    sharing X's fact and Y's together within the range (``pair_task``); one without describes it only by its
    look (no address, no name)."""
    question, answer = QUESTIONS[question_key][0], QUESTIONS[question_key][1](target.facts[question_key])
    corner = corner_phrase(start.name)
    if cue is not None and pair is not None:
        key, value, via, limit = cue
        city = world.city(target.city).name.split(" (")[0]
        x, y = article_of(via).title, article_of(pair[2]).title
        intent = (f"You are at the corner of {corner} in {city}. Of the places with a wiki article (buildings, "
                  f"parks, squares, stations) whose walk from this corner is at most {limit} m by the map's "
                  f"directions, exactly one other "
                  f"than {x} and {y} {CUES[key].format(x=x)} and {CUES[pair[0]].format(x=y)}, as their wiki "
                  f"articles give {CUE_LABEL[key]} and {CUE_LABEL[pair[0]]}. Other places within that range "
                  "share only one of the two facts, and another place shares both just beyond it: only the two "
                  f"facts and the measured walks together single it out. Find it: the wiki articles of {x} and {y} give "
                  "the facts, the wiki's articles give each place's address, and the map measures walks. "
                  f"{WALK_RULE} When you are there, look it up on the wiki and answer: {question} "
                  + answer_rule(FORMS[question_key]))
    elif cue is not None:
        key, value, via, limit = cue
        city = world.city(target.city).name.split(" (")[0]
        x = article_of(via).title
        # "places with a wiki article", not "landmarks": the wiki files some of them under parks or
        # squares, and a player read "landmarks" as the wiki's Landmarks category
        intent = (f"You are at the corner of {corner} in {city}. Of the places with a wiki article (buildings, "
                  f"parks, squares, stations) whose walk from this corner is at most {limit} m by the map's "
                  f"directions, exactly one other "
                  f"than {x} {CUES[key].format(x=x)}, as their wiki articles give {CUE_LABEL[key]}; other places "
                  "of the city share it too, one or more of them just beyond that walk though within it as the "
                  f"crow flies, so measure each one's walk on the map. Find it: {x}'s wiki article gives the fact, the "
                  "wiki's articles give each place's address, and the map measures walks. "
                  f"{WALK_RULE} When you are there, look it up on the wiki and answer: {question} "
                  + answer_rule(FORMS[question_key]))
    elif hard:
        intent = (f"You are at the corner of {corner}. Within about {int(round(route.distance_m, -2)) or 100} m "
                  f"on foot stands a landmark you will know only by its look: {target.description_hint} "
                  "No address or name is given: find it by what you see in the street views. "
                  f"{WALK_RULE} When you are there, look it up on the wiki and answer: {question} "
                  + answer_rule(FORMS[question_key]))
    else:
        intent = (f"You are at the corner of {corner}. Walk to {target.address}: {target.description_hint} "
                  f"{WALK_RULE} When you are there, look it up on the wiki and answer: {question} "
                  + answer_rule(FORMS[question_key]))
    end = world.node(target.node)
    oracle = [
        *([call("browser_goto", url=site_url("wiki", f"/wiki/{article_of(cue[2]).slug}"))] if cue else []),
        *([call("browser_goto", url=site_url("wiki", f"/wiki/{article_of(pair[2]).slug}"))] if pair else []),
        call("browser_goto", url=site_url("map", "/directions", **{"from": start.id, "to": target.id})),
        call("switch_environment", target="embodied", message="walk to the landmark"),
        *[call("street_move", neighbour=n) for n in route.nodes[1:]], call("street_stop"),
        call("switch_environment", target="web", message="look it up"),
        call("browser_goto", url=site_url("wiki", f"/wiki/{article.slug}")),
        call("finish_episode", answer=answer),
    ]
    links = world.neighbours(start.node)
    return Task(
        id=tid,
        domain="traveling",
        difficulty="hard" if hard else "medium",
        intent=intent,
        start=StartState(environment="web", web=WebStart(start_url="map:/"),
                         embodied=StreetStart(city=target.city, node=start.node,
                                              heading=round(trng.choice([lk.heading for lk in links]), 1))),
        web_goals=[PageVisited(site="wiki", path_prefix=f"/wiki/{article.slug}")],
        embodied_goals=[ReachedPlace(city=target.city, node=target.node, lat=end.lat, lng=end.lng,
                                     place_id=target.id)],
        answer=answer_check(question_key, answer),
        step_limit=step_budget("traveling", "hard" if hard else "medium", len(oracle)),
        oracle=oracle,
        metadata={"poi_id": target.id, "article": article.slug, "question": question_key,
                  "shortest_path_m": route.distance_m, "start_lat": world.node(start.node).lat,
                  "start_lng": world.node(start.node).lng, "visual_only": hard and cue is None,
                  "cue": {"key": cue[0], "value": cue[1], "via": cue[2].id, "via_article": article_of(cue[2]).slug,
                          "range_m": cue[3]} if cue else None,
                  **({"pair_cue": {"key": pair[0], "value": pair[1], "via": pair[2].id,
                                   "via_article": article_of(pair[2]).slug}} if pair else {})},
    )


def answerable_questions(target: Any, article: Any) -> list[str]:
    """The fact keys whose answer the article states and a short answer can single out."""
    text = article_text(article)
    return [k for k, v in sorted(target.facts.items())
            if k in QUESTIONS and contains_phrase(text, QUESTIONS[k][1](v))
            and answer_check(k, QUESTIONS[k][1](v)) is not None]


def landmarks_of(world: Any) -> list[Any]:
    return sorted((p for p in world.places.values() if p.description_hint and p.kind not in
                   ("store", "restaurant", "intersection", "address", "station")), key=lambda p: p.id)


def generate() -> list[Task]:
    world = get_world()
    tasks: list[Task] = []
    landmarks = landmarks_of(world)
    rng = rng_for("traveling")
    rng.shuffle(landmarks)
    rounds = 0
    while len(tasks) < TARGET and rounds < 3:
        for target in landmarks:
            if len(tasks) >= TARGET:
                break
            article = wiki.by_poi_id(target.id)
            if article is None:
                continue
            answerable = answerable_questions(target, article)
            if len(answerable) <= rounds:
                continue  # validation: the answer must be in our wiki, and a short answer must single it out
            trng = rng_for("traveling", target.id, rounds)
            found = start_place(world, target, trng)
            if found is None:
                continue
            tasks.append(landmark_task(world, f"traveling-{target.city}-{len(tasks):03d}", target, article,
                                       answerable[rounds], *found, trng, hard=False))
        rounds += 1
    return tasks + hard_tasks(world)


# The hard tasks' ids as released (city, slot): kept when the rule that picks landmarks changes, so that
# results stay comparable task by task.
HARD_SLOTS = tuple(tuple(i.rsplit("-", 2)[-2:]) for i in (
    "traveling-hard-manhattan-000 traveling-hard-manhattan-001 traveling-hard-pittsburgh-002 "
    "traveling-hard-manhattan-003 traveling-hard-manhattan-004 traveling-hard-boston-005 "
    "traveling-hard-manhattan-006 traveling-hard-manhattan-007 traveling-hard-pittsburgh-008 "
    "traveling-hard-manhattan-009 traveling-hard-manhattan-010 traveling-hard-pittsburgh-011 "
    "traveling-hard-manhattan-012 traveling-hard-philadelphia-013 traveling-hard-philadelphia-014 "
    "traveling-hard-manhattan-015 traveling-hard-manhattan-016 traveling-hard-manhattan-017 "
    "traveling-hard-manhattan-018 traveling-hard-philadelphia-019 traveling-hard-manhattan-020 "
    "traveling-hard-manhattan-021 traveling-hard-manhattan-022 traveling-hard-manhattan-023 "
    "traveling-hard-manhattan-024 traveling-hard-manhattan-025 traveling-hard-manhattan-026 "
    "traveling-hard-manhattan-027 traveling-hard-philadelphia-028 traveling-hard-pittsburgh-029").split())
assert len(HARD_SLOTS) == HARD_TARGET


def hard_tasks(world: Any) -> list[Task]:
    """Hard by composition: a landmark named by the wiki fact it shares with another named landmark of its city
    (which others share too) and a walking range that holds other landmarks (``cue_task``); the answer is
    another fact of its article."""
    tasks: list[Task] = []
    landmarks = landmarks_of(world)
    hints = [p.description_hint for p in landmarks]
    rng = rng_for("traveling", "hard")
    rng.shuffle(landmarks)
    # The released ids name a city and a slot; each slot takes its city's next landmark that makes a task.
    free = {city: sorted((int(n) for c, n in HARD_SLOTS if c == city), reverse=True)
            for city in dict.fromkeys(c for c, _ in HARD_SLOTS)}
    slots: dict[int, Task] = {}
    for target in landmarks:
        if len(slots) >= HARD_TARGET:
            break
        if not free.get(target.city):
            continue  # the city's slots are filled (or it has none)
        article = wiki.by_poi_id(target.id)
        if article is None or hints.count(target.description_hint) > 1:
            continue
        answerable = answerable_questions(target, article)
        if not answerable:
            continue
        trng = rng_for("traveling", "hard", target.id)
        found = cue_task(world, target, trng)
        if found is None:
            continue
        key, value, via, start, route, limit = found
        # the answer is another fact than the cue, and not one X's article would give as well (X's own
        # year would answer "built in 1931" for a target built in 1931 too, without finding the target)
        questions = [k for k in answerable if k != key and via.facts.get(k) != target.facts.get(k)]
        if not questions:
            continue
        slot = free[target.city].pop()
        slots[slot] = landmark_task(world, f"traveling-hard-{target.city}-{slot:03d}", target, article,
                                    trng.choice(questions), start, route, trng, hard=True,
                                    cue=(key, value, via, limit))
    if len(slots) < HARD_TARGET:
        raise ValueError(f"traveling hard: no landmark fits slots {sorted(n for c in free.values() for n in c)}; "
                         "widen BOUNDARY_IN_M / BOUNDARY_OUT_M or BOUNDARY_DRAWS in envs/street/taskgen/traveling.py")
    tasks = [slots[i] for i in sorted(slots)]
    return with_pairs(world, tasks, landmarks)


def with_pairs(world: Any, tasks: list[Task], landmarks: list[Any]) -> list[Task]:
    """The hard tasks with about PAIR_SHARE of their slots, drawn by a seeded shuffle, made two-fact tasks
    (``pair_task``) about a landmark of the slot's city: ids and the count are kept. A slot whose city has no
    unused landmark with such a pair stays as it was (the pairs need a city dense in shared decades and styles)."""
    slots = list(range(len(tasks)))
    rng_for("traveling", "hard", "pairs").shuffle(slots)
    want = round(PAIR_SHARE * len(tasks))
    singles = {t.metadata["poi_id"]: i for i, t in enumerate(tasks)}
    found: dict[str, Any] = {}
    out, used, made = list(tasks), set(), 0
    for i in slots:
        if made >= want:
            break
        city = tasks[i].id.rsplit("-", 2)[-2]
        for target in landmarks:
            if target.city != city or target.id in used or singles.get(target.id, i) != i:
                continue  # each landmark is the answer of one hard task at most
            article = wiki.by_poi_id(target.id)
            if article is None:
                continue
            if target.id not in found:
                found[target.id] = pair_task(world, target, rng_for("traveling", "hard", "pair", target.id))
            pair = found[target.id]
            if pair is None:
                continue
            (kx, vx, x), (ky, vy, y), start, route, limit = pair
            # the answer is a third fact, one neither X's nor Y's article gives the same way
            questions = [k for k in answerable_questions(target, article) if k not in (kx, ky)
                         and x.facts.get(k) != target.facts.get(k) and y.facts.get(k) != target.facts.get(k)]
            if not questions:
                continue
            trng = rng_for("traveling", "hard", "pair", target.id, "task")
            out[i] = landmark_task(world, tasks[i].id, target, article, trng.choice(questions), start, route, trng,
                                   hard=True, cue=(kx, vx, x, limit), pair=(ky, vy, y))
            used.add(target.id)
            made += 1
            break
    return out


# Hard tasks that only combine (issue 26, principle 6): two named landmarks X and Y, the place within the range
# that shares one fact with X (its decade, say) AND another with Y (its style). Within the range other places
# share X's fact only and Y's fact only, so neither fact alone (nor the nearest place sharing it) finds the
# answer; farther away another place shares both, so the pair without the range does not either.
PAIR_SHARE = 0.5  # of the hard slots, drawn by a seeded shuffle (where the data has such a pair)
PAIR_CLEAR_M = 60.0  # the one-fact places stand this much inside the range (the target just inside: BOUNDARY_IN_M)
PAIR_ONLY = 1  # places within the range sharing one of the facts only, for each fact, at least
PAIR_STARTS = 120  # corners drawn near the target: a pair's constraints leave few of them


def pair_task(world: Any, target: Any, rng: Any) -> tuple[tuple[str, str, Any], tuple[str, str, Any], Any, Any, int] | None:
    """((key, value, X), (key, value, Y), start, route, range in m) for a two-fact hard task about ``target``,
    or None. X shares the first fact with the target and not the second, Y the second and not the first; X
    and Y are landmarks other than the target and each other and do not name it nor it them. From the corner,
    within the range: the target, at least one place sharing the first fact only and one sharing the second
    only (each exactly, the other fact unlike); no place other than X and Y that could be read as sharing both
    stands within the range (nor BOUNDARY_GAP_M beyond it); at least one place sharing both stands just beyond
    it (at most BOUNDARY_OUT_M over), and the answer's walk ends just inside it (``boundary_limit``)."""
    peers = [p for p in landmarks_of(world) if p.city == target.city and p.id != target.id
             and wiki.by_poi_id(p.id) is not None]
    with_articles = sorted((p for p in world.places.values() if p.city == target.city and p.id != target.id
                            and wiki.by_poi_id(p.id) is not None), key=lambda p: p.id)
    target_text = article_text(wiki.by_poi_id(target.id))
    keys = [k for k in CUES if cue_value(k, target) is not None
            and not (k == "architect" and answer_check(k, cue_value(k, target) or "") is None)]
    pairs = [(a, b) for a in keys for b in keys if a != b]
    rng.shuffle(pairs)

    def value(key: str, p: Any) -> str | None:
        return cue_value(key, p)

    def like(key: str, v: str, p: Any) -> bool:
        w = value(key, p)
        return w is not None and _alike(key, v, w)

    def stated(key: str, v: str, p: Any) -> bool:
        return key == "year_built" or contains_phrase(article_text(wiki.by_poi_id(p.id)), v)

    def apart(p: Any) -> bool:
        return (not names_place(target_text, p) and not names_place(article_text(wiki.by_poi_id(p.id)), target)
                and not names_place(article_of(p).title, target))

    for kx, ky in pairs:
        vx, vy = value(kx, target), value(ky, target)
        if vx is None or vy is None or not stated(kx, vx, target) or not stated(ky, vy, target):
            continue
        both = [p for p in with_articles if value(kx, p) == vx and value(ky, p) == vy and stated(kx, vx, p)
                and stated(ky, vy, p)]
        if not both:
            continue
        xs = [p for p in peers if value(kx, p) == vx and not like(ky, vy, p) and stated(kx, vx, p) and apart(p)]
        ys = [p for p in peers if value(ky, p) == vy and not like(kx, vx, p) and stated(ky, vy, p) and apart(p)]
        if not xs or not ys:
            continue
        only_x = [p for p in with_articles if value(kx, p) == vx and not like(ky, vy, p) and stated(kx, vx, p)]
        only_y = [p for p in with_articles if value(ky, p) == vy and not like(kx, vx, p) and stated(ky, vy, p)]
        alike_both = [p for p in with_articles if like(kx, vx, p) and like(ky, vy, p)]
        for start, route in iter_near_starts(world, target, rng, PAIR_STARTS):
            limit = boundary_limit(route.distance_m)
            if limit is None:
                continue  # the answer's walk must end just inside a round range
            walks: dict[str, float] = {}
            here = world.node(start.node)

            def walk_m(p: Any, within: float) -> float:
                """The walk to ``p``, or its crow-fly distance where that alone is beyond ``within`` (a walk
                is never shorter): only what could fall within is measured."""
                if p.id in walks:
                    return walks[p.id]
                node = world.node(p.node)
                crow = haversine_m(here.lat, here.lng, node.lat, node.lng)
                if crow > within:
                    return crow
                try:
                    walks[p.id] = float(world.directions(start.node, p.node).distance_m)
                except ValueError:
                    walks[p.id] = float("inf")
                return walks[p.id]

            near, inner = limit + BOUNDARY_GAP_M, limit - PAIR_CLEAR_M
            for x in rng.sample(xs, len(xs)):
                for y in rng.sample(ys, len(ys)):
                    named = {x.id, y.id}
                    if any(p.id not in named and walk_m(p, near) <= near for p in alike_both):
                        continue  # another place near the range could be read as sharing both
                    if not any(p.id not in named and walk_m(p, limit + BOUNDARY_OUT_M) <= limit + BOUNDARY_OUT_M
                               for p in both):
                        continue  # a place sharing both just beyond the range: only the walks tell it apart
                    if sum(p.id not in named and walk_m(p, inner) <= inner for p in only_x) < PAIR_ONLY:
                        continue  # the second fact alone would find it
                    if sum(p.id not in named and walk_m(p, inner) <= inner for p in only_y) < PAIR_ONLY:
                        continue  # the first fact alone would find it
                    return (kx, vx, x), (ky, vy, y), start, route, limit
    return None
