"""No single read answers a two-hop traveling task (issue 26, principle 6): the article of a style or an
architect lists none or several of a city's landmarks of that style or by that architect, never one alone; a
hard task's landmark and the landmarks X (and Y) it is named by do not name each other."""

from __future__ import annotations

import json
from collections import defaultdict
from pathlib import Path

from ewa_mcp.envs.street.taskgen.traveling import article_text, concept_articles, cue_value, landmarks_of, names_place
from ewa_mcp.envs.street.world import get_world
from ewa_mcp.websites.wiki import store as wiki

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def test_a_style_or_architect_article_names_none_or_several_of_a_citys_landmarks_sharing_it() -> None:
    world = get_world()
    groups: dict[tuple[str, str], list] = defaultdict(list)
    articles = {}
    for place in landmarks_of(world):
        if wiki.by_poi_id(place.id) is None:
            continue
        for key in ("architectural_style", "architect"):
            value = cue_value(key, place)
            for article in concept_articles(key, value) if value else []:
                groups[(article.slug, place.city)].append(place)
                articles[article.slug] = article
    assert len(articles) >= 20  # the styles and architects are there to be checked
    lone = [(slug, city, [p.id for p in places if names_place(article_text(articles[slug]), p)])
            for (slug, city), places in sorted(groups.items()) if len(places) >= 2]
    assert not [entry for entry in lone if len(entry[2]) == 1], [entry for entry in lone if len(entry[2]) == 1]


def test_a_hard_task_and_its_named_landmark_do_not_name_each_other() -> None:
    world = get_world()
    hard = [t for p in sorted((TASKS_DIR / "traveling").glob("*.json")) for t in json.loads(p.read_text("utf-8"))
            if t["difficulty"] == "hard"]
    assert hard
    for task in hard:
        cue = task["metadata"]["cue"]
        target, via = world.places[task["metadata"]["poi_id"]], world.places[cue["via"]]
        assert not names_place(article_text(wiki.by_poi_id(target.id)), via), task["id"]
        assert not names_place(article_text(wiki.by_poi_id(via.id)), target), task["id"]
        pair = task["metadata"].get("pair_cue")
        if pair:  # a two-fact task's Y, like its X, neither names the answer nor is named by it
            y = world.places[pair["via"]]
            assert not names_place(article_text(wiki.by_poi_id(target.id)), y), task["id"]
            assert not names_place(article_text(wiki.by_poi_id(y.id)), target), task["id"]
        sharing = [p for p in landmarks_of(world) if p.city == target.city and p.id != via.id
                   and wiki.by_poi_id(p.id) is not None and cue_value(cue["key"], p) == cue["value"]]
        for article in concept_articles(cue["key"], cue["value"]):
            named = [p.id for p in sharing if names_place(article_text(article), p)]
            assert named != [target.id], (task["id"], article.slug)  # the style's article alone is not the answer
