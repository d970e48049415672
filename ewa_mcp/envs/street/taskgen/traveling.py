"""Traveling tasks: walk to a landmark described by its look and address (never its name), identify it,
look it up on the wiki, and answer a question whose answer is in the wiki."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any


from ewa_mcp.geometry import haversine_m
from ewa_mcp.graders.textnorm import contains_phrase, find_spans, tokens
from ..world import get_world
from ewa_mcp.core.taskmodel import StartState, Task
from ewa_mcp.envs.browser.goals import PageVisited, WebStart
from ewa_mcp.envs.street.goals import ReachedPlace, StreetStart
from ewa_mcp.websites.wiki import store as wiki
from ewa_mcp.taskgen.answer_checks import METRES, YEARS, answer_rule, committed_answer
from ewa_mcp.taskgen.common import WALK_RULE, call, rng_for, site_url, step_budget

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


# Hard tasks name the landmark by a wiki fact it shares with other landmarks of its city, and a walking range
# from the corner that holds other landmarks: only the two together single it out (issue 26, principle 6).
CUES = {"architectural_style": "is in the {v} style", "year_built": "was built in {v}",
        "architect": "was designed by {v}"}
CUE_LABEL = {"architectural_style": "its architectural style", "year_built": "the year it was built",
             "architect": "its architect"}
RANGE_MARGIN_M = 150.0
CUE_MAX_M = 900.0  # the walk from the corner (the range holds other landmarks, so it is wider than by sight)  # a landmark sharing the fact lies this much beyond the range, at least


def near_starts(world: Any, target: Any, rng: Any) -> list[tuple[Any, Any]]:
    """Street corners MIN_M..CUE_MAX_M on foot from the landmark, in a seeded random order (drawn among the
    corners near it as the crow flies: a draw over the whole city rarely lands in range)."""
    graph = world.city(target.city)
    end = world.node(target.node)
    ids = [i for i in sorted(graph.ids) if haversine_m(end.lat, end.lng, world.node(i).lat, world.node(i).lng)
           <= CUE_MAX_M and len(world.node(i).streets) >= 2]
    rng.shuffle(ids)
    out = []
    for node_id in ids[:60]:
        try:
            route = world.directions(node_id, target.node)
        except ValueError:
            continue
        if MIN_M <= route.distance_m <= CUE_MAX_M:
            out.append((world.place(node_id), route))
    return out


def cue_task(world: Any, target: Any, rng: Any) -> tuple[str, str, Any, Any, int] | None:
    """(cue key, cue value, start, route, range in m) for a hard task about ``target``, or None.

    The fact alone does not single the landmark out (another landmark of the city shares it); the range
    alone does not (another landmark with an article stands within it); together they do, with margins
    (every other landmark sharing the fact is RANGE_MARGIN_M beyond the range)."""
    peers = [p for p in landmarks_of(world) if p.city == target.city and p.id != target.id
             and wiki.by_poi_id(p.id) is not None]
    keys = [k for k in CUES if k in target.facts]
    rng.shuffle(keys)
    for key in keys:
        value = _fact_text(key, target.facts[key])
        sharing = [p for p in peers if key in p.facts and _fact_text(key, p.facts[key]) == value]
        if not sharing or (key == "architect" and answer_check(key, value) is None):
            continue
        if not all(contains_phrase(article_text(wiki.by_poi_id(p.id)), value) for p in [target, *sharing]):
            continue  # the wiki must state the fact of the landmark and of those sharing it
        for start, route in near_starts(world, target, rng)[:30]:
            limit = int(-(-(route.distance_m + 60) // 100) * 100)  # rounded up, 60 m clear of the walk

            def walk_m(p: Any) -> float:
                try:
                    return float(world.directions(start.node, p.node).distance_m)
                except ValueError:
                    return float("inf")

            if any(walk_m(p) <= limit + RANGE_MARGIN_M for p in sharing):
                continue
            if not any(walk_m(p) <= limit - 60 for p in peers):
                continue  # the range alone would single it out
            return key, value, start, route, limit
    return None


def landmark_task(world: Any, tid: str, target: Any, article: Any, question_key: str, start: Any, route: Any,
                  trng: Any, hard: bool, cue: tuple[str, str, int] | None = None) -> Task:
    """One task: walk to the landmark, look it up, answer. A hard task with a ``cue`` (key, value, range)
    names the landmark by a wiki fact plus a walking range from the corner, which single it out only
    together; one without describes it only by its look (no address, no name)."""
    question, answer = QUESTIONS[question_key][0], QUESTIONS[question_key][1](target.facts[question_key])
    corner = start.name.replace(" & ", " and ")
    if cue is not None:
        key, value, limit = cue
        city = world.city(target.city).name.split(" (")[0]
        intent = (f"You are at the corner of {corner} in {city}. Of the landmarks within about {limit} m of this "
                  f"corner on foot, exactly one {CUES[key].format(v=value)}, as its wiki article gives "
                  f"{CUE_LABEL[key]} (other landmarks of the city share that, farther away). Find it: the wiki's "
                  "articles give each landmark's address, and the map measures walks. "
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
                  "cue": {"key": cue[0], "value": cue[1], "range_m": cue[2]} if cue else None},
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


def hard_tasks(world: Any) -> list[Task]:
    """Hard by composition: a landmark named by a wiki fact it shares with others of its city and a walking
    range that holds other landmarks (``cue_task``); the answer is another fact of its article."""
    tasks: list[Task] = []
    landmarks = landmarks_of(world)
    hints = [p.description_hint for p in landmarks]
    rng = rng_for("traveling", "hard")
    rng.shuffle(landmarks)
    for target in landmarks:
        if len(tasks) >= HARD_TARGET:
            break
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
        key, value, start, route, limit = found
        questions = [k for k in answerable if k != key]  # the answer is another fact than the cue
        if not questions:
            continue
        tasks.append(landmark_task(world, f"traveling-hard-{target.city}-{len(tasks):03d}", target, article,
                                   trng.choice(questions), start, route, trng, hard=True, cue=(key, value, limit)))
    return tasks
