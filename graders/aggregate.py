"""Per-domain aggregates (the paper's four metrics with 95 % intervals) and error breakdowns.

An episode that could not be graded counts as a failure with completion 0: a crashed episode
must not vanish from the denominator and flatter the agent. The count is reported beside it.
"""

from __future__ import annotations

import statistics
from collections import Counter
from typing import Any

from .answers import geo_module
from .errors import CATEGORIES, GROUP_LABELS
from .models import DomainAggregate, EpisodeResult, ErrorBreakdown, MeanEstimate, NavigationAggregate, Proportion
from .stats import mean_t_interval, wilson_interval

GEO_LEVELS = ("continent", "country", "city", "street", "all_levels")


def episode_completion(episode: EpisodeResult) -> float:
    """An episode's completion for the aggregate: 0 when it could not be graded. A geolocation
    episode's is the fraction of its four levels right (ewa_mcp/envs/geo/checks.py), as in its own result."""
    geo = episode.geolocation or {}
    value = geo.get("completion")
    if isinstance(value, int | float) and not isinstance(value, bool) and episode.completion is not None:
        return float(value)
    return episode.completion or 0.0


def proportion(successes: int, n: int) -> Proportion:
    low, high = wilson_interval(successes, n)
    return Proportion(successes=successes, n=n, value=successes / n if n else None, ci_low=low, ci_high=high)


def mean_estimate(values: list[float]) -> MeanEstimate:
    mean, low, high = mean_t_interval(values)
    return MeanEstimate(n=len(values), value=mean if values else None, ci_low=low, ci_high=high)


def _mean(values: list[float]) -> float | None:
    return statistics.fmean(values) if values else None


def navigation_aggregate(episodes: list[EpisodeResult]) -> NavigationAggregate | None:
    navs = [nav for e in episodes for nav in e.navigation]
    if not navs:
        return None
    distances = [n.distance_to_goal_m for n in navs if n.distance_to_goal_m is not None]
    spls = [n.spl for n in navs if n.spl is not None]
    return NavigationAggregate(
        n=len(navs),
        success_within_radius=proportion(sum(n.success for n in navs), len(navs)),
        exact_node=proportion(sum(n.exact_node and n.stopped for n in navs), len(navs)),
        mean_distance_to_goal_m=_mean(distances),
        median_distance_to_goal_m=statistics.median(distances) if distances else None,
        mean_spl=_mean(spls),
        spl_n=len(spls),
    )


def geolocation_rows(episodes: list[EpisodeResult]) -> list[dict[str, Any]]:
    return [
        {**e.geolocation, "setting": e.setting, "episode_id": e.episode_id, "task_id": e.task_id}
        for e in episodes
        if e.geolocation is not None
    ]


def geolocation_aggregate(episodes: list[EpisodeResult]) -> dict[str, Any] | None:
    """Geolocation metrics come from ewa_mcp/envs/geo/checks.py (aggregate_geolocation); a per-level Wilson
    summary stands in only when that module lacks the function."""
    rows = geolocation_rows(episodes)
    if not rows:
        return None
    module, _ = geo_module()
    if module is not None and hasattr(module, "aggregate_geolocation"):
        try:
            return dict(module.aggregate_geolocation(rows))
        except Exception as exc:
            return {"error": f"aggregate_geolocation raised {type(exc).__name__}: {exc}"}
    by_setting: dict[str, Any] = {}
    for setting in sorted({str(r.get("setting")) for r in rows}):
        subset = [r for r in rows if str(r.get("setting")) == setting]
        by_setting[setting] = {
            level: proportion(sum(r.get(level) is True for r in subset), len(subset)).model_dump()
            for level in GEO_LEVELS
        }
    return {"by_setting": by_setting, "source": "fallback"}


def domain_aggregate(domain: str, episodes: list[EpisodeResult]) -> DomainAggregate:
    n = len(episodes)
    with_web = any(e.has_web_goals for e in episodes)
    with_embodied = any(e.has_embodied_goals for e in episodes)
    answered = [e for e in episodes if e.answer_checked]
    walls = [e.wall_time_s for e in episodes if e.wall_time_s is not None]
    return DomainAggregate(
        domain=domain,
        n=n,
        n_with_problems=sum(1 for e in episodes if e.problems),
        n_ungradable=sum(1 for e in episodes if not e.gradable),
        overall_accuracy=proportion(sum(e.overall_success is True for e in episodes), n),
        completion_rate=mean_estimate([episode_completion(e) for e in episodes]),
        # Over every episode of the domain (a task without web goals passes vacuously), so that
        # overall <= web-only and overall <= embodied-only hold per domain; n/a when no task has any.
        web_only_accuracy=proportion(sum(e.web_success is True for e in episodes), n) if with_web else None,
        embodied_only_accuracy=(
            proportion(sum(e.embodied_success is True for e in episodes), n) if with_embodied else None
        ),
        answer_accuracy=(
            proportion(sum(e.answer_correct is True for e in answered), len(answered)) if answered else None
        ),
        mean_steps=statistics.fmean(e.steps for e in episodes) if episodes else 0.0,
        mean_switches=statistics.fmean(e.switches for e in episodes) if episodes else 0.0,
        mean_wall_time_s=_mean(walls),
        navigation=navigation_aggregate(episodes),
        geolocation=geolocation_aggregate(episodes) if domain == "geolocation" else None,
    )


def error_breakdown(episodes: list[EpisodeResult]) -> ErrorBreakdown:
    failed = [e for e in episodes if e.error is not None]
    by_category = Counter(e.error.category for e in failed if e.error)
    by_group: Counter[str] = Counter(e.error.group for e in failed if e.error)
    total = len(failed)

    def pct(count: int) -> float:
        return round(100.0 * count / total, 2) if total else 0.0

    categories = {key: by_category.get(key, 0) for key in CATEGORIES}
    groups = {key: by_group.get(key, 0) for key in GROUP_LABELS}
    return ErrorBreakdown(
        failures=total,
        by_category=categories,
        percent_by_category={k: pct(v) for k, v in categories.items()},
        by_group=groups,
        percent_by_group={k: pct(v) for k, v in groups.items()},
    )
