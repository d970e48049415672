"""Facts about a trajectory that the error analysis reads: visits to each environment, actions,
repeated identical actions and page loops. The thresholds are documented in docs/grading.md."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any

# Protocol tools: they act on the episode, not on an environment.
LIFECYCLE_TOOLS = frozenset(
    {"list_tasks", "start_episode", "get_observation", "switch_environment", "finish_episode", "episode_status",
     "submit_location"}
)
# Tools that only look: they never change an environment, so they are not "meaningful" actions.
LOOK_SUFFIXES = ("_observe", "_look", "_observation", "_snapshot", "_screenshot", "_status")

REPEAT_MIN = 3  # this many identical consecutive actions with an identical result is a repetition
LOOP_WINDOW = 6  # page views examined at a time for a loop
LOOP_MAX_PAGES = 3  # a window cycling among at most this many pages, each seen twice, is a loop


@dataclass
class Visit:
    """A stay in one environment: from the episode start or a switch until the next switch."""

    env: str | None
    via_switch: bool
    actions: list[dict[str, Any]] = field(default_factory=list)

    @property
    def meaningful(self) -> int:
        return sum(1 for a in self.actions if is_meaningful(a))


def is_action(record: dict[str, Any]) -> bool:
    return record.get("counted") is not False and record.get("tool") not in LIFECYCLE_TOOLS


def is_meaningful(record: dict[str, Any]) -> bool:
    """An environment action that succeeded and could change state (not a look)."""
    tool = str(record.get("tool", ""))
    return is_action(record) and record.get("ok") is True and not tool.endswith(LOOK_SUFFIXES)


def visits(trajectory: list[dict[str, Any]]) -> list[Visit]:
    result: list[Visit] = []
    current: Visit | None = None
    for record in trajectory:
        if record.get("tool") == "switch_environment" and record.get("ok") is True:
            args = given if isinstance(given := record.get("args"), dict) else {}
            current = Visit(env=args.get("target") or record.get("environment"), via_switch=True)
            result.append(current)
            continue
        if not is_action(record):
            continue
        env = record.get("environment")
        if current is None or current.env != env:
            # No switch record before a change of environment (a damaged trajectory): start a new visit anyway.
            current = Visit(env=env, via_switch=False)
            result.append(current)
        current.actions.append(record)
    return result


def actions(trajectory: list[dict[str, Any]], env: str | None = None) -> list[dict[str, Any]]:
    return [r for r in trajectory if is_action(r) and (env is None or r.get("environment") == env)]


def _signature(record: dict[str, Any]) -> str:
    return json.dumps(
        [record.get("tool"), record.get("args"), record.get("ok"), record.get("error"), record.get("observation")],
        sort_keys=True, default=str,
    )


def longest_repeat(trajectory: list[dict[str, Any]], env: str) -> tuple[int, str | None]:
    """The longest run of identical consecutive actions in ``env`` with identical results.

    The observation digest is part of the identity: clicking "Next" through a recipe repeats the
    call but changes the page, which is progress, not repetition."""
    best, best_tool, run, previous = 0, None, 0, None
    for record in actions(trajectory):
        if record.get("environment") != env:
            run, previous = 0, None
            continue
        signature = _signature(record)
        run = run + 1 if signature == previous else 1
        previous = signature
        if run > best:
            best, best_tool = run, str(record.get("tool"))
    return best, best_tool


def page_sequence(events: list[dict[str, Any]]) -> list[str]:
    """Pages viewed, in order, with reloads of the same page collapsed. A search with another query
    is another page (the sites put the query in the page_view event), so refining a search is not a loop."""
    pages: list[str] = []
    for e in events:
        if e.get("type") != "page_view":
            continue
        page = f"{e.get('site')}:{e.get('path')}" + (f"?{e['query']}" if e.get("query") else "")
        if not pages or pages[-1] != page:
            pages.append(page)
    return pages


def page_loop(events: list[dict[str, Any]]) -> list[str] | None:
    """The pages of the first loop found: a window of LOOP_WINDOW views among ≤ LOOP_MAX_PAGES pages,
    each viewed at least twice (A→B→A→B→A→B or A→B→C→A→B→C)."""
    pages = page_sequence(events)
    for start in range(0, len(pages) - LOOP_WINDOW + 1):
        window = pages[start : start + LOOP_WINDOW]
        distinct = set(window)
        if len(distinct) <= LOOP_MAX_PAGES and all(window.count(p) >= 2 for p in distinct):
            return sorted(distinct)
    return None
