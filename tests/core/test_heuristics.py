"""The heuristic agents (docs/verified.md): declared for the command line, reading only what an agent sees."""

from __future__ import annotations

import json
from pathlib import Path

from ewa_mcp.cli import build_parser
from ewa_mcp.evaluation.heuristics import NAMES, heuristic_agent
from ewa_mcp.evaluation.heuristics.table import HEURISTICS
from ewa_mcp.evaluation.heuristics.agents import (
    best_city,
    named_products,
    prior_answer,
    prior_location,
    question_of,
)
from ewa_mcp.core.taskmodel import TaskStore, TextAnswer
from ewa_mcp.envs.geo.goals import GeoAnswer
from ewa_mcp.websites.wiki import store as wiki

TASKS_DIR = Path(__file__).resolve().parents[2] / "tasks"


def test_every_heuristic_is_an_eval_agent() -> None:
    assert set(NAMES) == set(HEURISTICS)
    for name in NAMES:
        assert heuristic_agent(name).name == name
        assert build_parser().parse_args(["eval", "--agent", name]).agent == name


def test_the_question_is_read_from_the_intent() -> None:
    for task in TaskStore([TASKS_DIR]).all("traveling"):
        assert question_of(task.intent)[0] == task.metadata["question"], task.id


def test_priors_never_read_the_tasks_own_answer() -> None:
    tasks = [t for t in TaskStore([TASKS_DIR]).all("traveling") if isinstance(t.answer, TextAnswer)]
    task = tasks[0]
    own = task.answer.must_include[0]
    same = [t for t in tasks if question_of(t.intent)[0] == question_of(task.intent)[0]]
    if sum(t.answer.must_include[0] == own for t in same) == 1:  # a unique answer cannot be the prior
        assert prior_answer(task.id, task.intent) != own
    geo = next(t for t in TaskStore([TASKS_DIR]).all("geolocation") if isinstance(t.answer, GeoAnswer))
    guess = prior_location(geo.id)
    assert set(guess) == {"lat", "lng", "continent", "country", "city", "street"}


def test_named_products_are_read_from_the_intent() -> None:
    shopping = [t for t in TaskStore([TASKS_DIR]).all("shopping") if t.id.startswith("shopping-pair")]
    for task in shopping[:10]:
        got = [(p.id, size) for p, size in named_products(task.intent)]
        assert got == list(zip(task.metadata["products"], task.metadata["sizes"], strict=True)), task.id


def test_the_lexical_matcher_finds_a_city_from_its_own_article() -> None:
    city = next(a for a in wiki.load_articles() if a.category == "Cities" and a.coordinates and a.title == "Accra")
    assert best_city(wiki.plain_text(city.body))["title"] == "Accra"


def test_the_public_task_files_are_what_the_prior_reads() -> None:
    # The prior agent reads tasks/ as published: every geolocation answer there is a GeoAnswer.
    for path in sorted((TASKS_DIR / "geolocation").glob("*.json")):
        for raw in json.loads(path.read_text(encoding="utf-8")):
            assert raw["answer"]["kind"] == "geolocation"
