"""Paired comparison of runs (``ewa-grade A --compare B``): on the tasks both runs played, how often each passed
where the other failed, the difference in accuracy, and McNemar's exact test of "no difference".

Pairing by task id is what makes the test sharp: two agents on the same tasks share the tasks' difficulty, so
only the tasks where they disagree speak to which is better. Each run's own table still reports every episode;
here an episode cut off by infrastructure has no outcome and its task is left out of the pairing, and a task
a run played more than once is paired by its first episode (the count is noted).
"""

from __future__ import annotations

from pydantic import BaseModel

from .models import EpisodeResult, RunReport
from .stats import mcnemar_exact

ALL = "all"


class PairedComparison(BaseModel):
    domain: str  # a domain, or "all" (every scored domain)
    baseline: str  # the first run's label
    other: str
    shared_tasks: int
    both_pass: int
    only_baseline: int
    only_other: int
    neither: int
    difference: float | None  # other's accuracy minus the baseline's, on the shared tasks (a fraction)
    p_value: float  # McNemar's exact test, two-sided
    duplicates: int = 0  # tasks played more than once in either run (paired by their first episode)


def _outcomes(report: RunReport) -> tuple[dict[str, EpisodeResult], int]:
    """task id -> its first scored episode; and how many tasks had more than one."""
    first: dict[str, EpisodeResult] = {}
    repeated: set[str] = set()
    for episode in report.episodes:
        if episode.task_id is None or episode.infrastructure_failure is not None or episode.domain == "demo":
            continue
        if episode.task_id in first:
            repeated.add(episode.task_id)
        else:
            first[episode.task_id] = episode
    return first, len(repeated)


def paired(baseline: RunReport, other: RunReport, domains: list[str]) -> list[PairedComparison]:
    """One comparison over every scored domain ("all"), then one per domain that has shared tasks."""
    base, base_dups = _outcomes(baseline)
    comp, comp_dups = _outcomes(other)
    shared = sorted(set(base) & set(comp))
    rows = []
    for domain in [ALL, *domains]:
        ids = [t for t in shared if domain == ALL or base[t].domain == domain]
        if not ids and domain != ALL:
            continue
        a = [base[t].overall_success is True for t in ids]
        b = [comp[t].overall_success is True for t in ids]
        only_a = sum(x and not y for x, y in zip(a, b))
        only_b = sum(y and not x for x, y in zip(a, b))
        both = sum(x and y for x, y in zip(a, b))
        rows.append(PairedComparison(
            domain=domain, baseline=baseline.label, other=other.label, shared_tasks=len(ids), both_pass=both,
            only_baseline=only_a, only_other=only_b, neither=len(ids) - both - only_a - only_b,
            difference=(only_b - only_a) / len(ids) if ids else None, p_value=mcnemar_exact(only_a, only_b),
            duplicates=base_dups + comp_dups if domain == ALL else 0))
    return rows


def comparisons(reports: list[RunReport], domains: list[str]) -> list[PairedComparison]:
    """Every run after the first, paired with the first."""
    return [row for other in reports[1:] for row in paired(reports[0], other, domains)]
