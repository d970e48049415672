"""The grader's results as pydantic models: what grade_episode / grade_run return and the CLI prints."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

from pydantic import BaseModel, Field

Side = Literal["web", "embodied", "answer"]
ErrorGroup = Literal["cross_domain", "web_only", "embodied_only", "other"]


class ConditionResult(BaseModel):
    """One goal condition of a task and whether the final state meets it.

    ``met`` is None when the run directory lacks the data to decide (e.g. no final_state.json)."""

    side: Side
    kind: str
    description: str
    met: bool | None
    detail: dict[str, Any] = Field(default_factory=dict)
    note: str | None = None


@dataclass
class CheckContext:
    """What a goal check may read: only the episode's record (docs/grading.md). A check is declared by the
    world that owns its goal kind (``Domain.checks``: kind -> "module:function(goal, ctx) -> ConditionResult")
    and never raises on odd data: it returns ``met=None`` with a note."""

    state: dict[str, Any] | None  # the embodied environment's final state, or None when there is none
    why_no_state: str | None  # why ``state`` is None
    events: list[dict[str, Any]]  # the sites' events (web_events.jsonl)
    metadata: dict[str, Any]  # the task's metadata
    orders: list[dict[str, Any]] = field(default_factory=list)  # the orders a pickup walk may refer to
    radius_m: float | None = None  # overrides every street goal's radius when set
    navigation: list[NavigationResult] = field(default_factory=list)  # street checks add their metrics here
    # The task's web goals, all of them: a check that judges over-acting (an order no goal asks for) must
    # know what the other goals of the task ask.
    web_goals: list[Any] = field(default_factory=list)

    def unknown(self, side: Side, goal: Any, why: str | None) -> ConditionResult:
        return ConditionResult(side=side, kind=goal.kind, description=goal.kind, met=None, note=why)


class NavigationResult(BaseModel):
    """Street metrics for one ReachedPlace goal."""

    goal_node: str
    final_node: str | None
    stopped: bool
    radius_m: float
    distance_to_goal_m: float | None
    within_radius: bool
    exact_node: bool
    success: bool
    shortest_path_m: float | None = Field(description="metadata.shortest_path_m, else the straight-line distance")
    shortest_path_source: Literal["metadata", "straight_line", "unknown"]
    path_length_m: float | None
    spl: float | None


class ErrorClassification(BaseModel):
    """Why a failed episode failed: the first matching rule (docs/grading.md) and every rule that matched."""

    category: str
    group: ErrorGroup
    matched: list[str]
    evidence: dict[str, str] = Field(default_factory=dict)


class EpisodeResult(BaseModel):
    episode_id: str
    task_id: str | None
    domain: str
    difficulty: str | None = Field(default=None, description="easy | medium | hard, from task.json")
    setting: str | None = None  # geolocation: baseline | embodied
    status: str = Field(description="finished | step_limit | aborted from final_state.json; incomplete when missing")
    end_reason: str | None = None
    gradable: bool = Field(description="false when the outcome could not be decided (see problems)")
    has_web_goals: bool
    has_embodied_goals: bool
    answer_checked: bool
    web_success: bool | None
    embodied_success: bool | None
    answer_correct: bool | None
    overall_success: bool | None
    completion: float | None
    conditions_met: int
    conditions_total: int
    conditions: list[ConditionResult]
    navigation: list[NavigationResult] = Field(default_factory=list)
    geolocation: dict[str, Any] | None = None
    answer: str | None = None
    steps: int
    calls: int
    switches: int
    wall_time_s: float | None
    error: ErrorClassification | None = None
    problems: list[str] = Field(default_factory=list)
    infrastructure_failure: str | None = Field(
        default=None, description="why the episode was cut off by something other than the agent (final_state.json); "
        "such an episode is reported apart and never scored")


class Proportion(BaseModel):
    successes: int
    n: int
    value: float | None
    ci_low: float
    ci_high: float
    method: Literal["wilson"] = "wilson"


class MeanEstimate(BaseModel):
    n: int
    value: float | None
    ci_low: float
    ci_high: float
    method: Literal["student_t"] = "student_t"


class NavigationAggregate(BaseModel):
    n: int
    success_within_radius: Proportion
    exact_node: Proportion
    mean_distance_to_goal_m: float | None
    median_distance_to_goal_m: float | None
    mean_spl: float | None
    spl_n: int


class DomainAggregate(BaseModel):
    domain: str
    n: int
    n_with_problems: int
    n_ungradable: int
    overall_accuracy: Proportion
    completion_rate: MeanEstimate
    web_only_accuracy: Proportion | None = Field(description="None (n/a) when no task of the domain has web goals")
    embodied_only_accuracy: Proportion | None = Field(description="None when no task has embodied goals")
    answer_accuracy: Proportion | None
    mean_steps: float
    mean_switches: float
    mean_wall_time_s: float | None
    navigation: NavigationAggregate | None = None
    geolocation: dict[str, Any] | None = None


class ErrorBreakdown(BaseModel):
    """Failed episodes by category and group; percentages are of the failures."""

    failures: int
    by_category: dict[str, int]
    percent_by_category: dict[str, float]
    by_group: dict[str, int]
    percent_by_group: dict[str, float]


class RunReport(BaseModel):
    run_dir: str
    label: str
    radius_m: float | None = Field(description="the --radius override; None = each task's own radius (25 m default)")
    n_episodes: int
    domains: dict[str, DomainAggregate]
    by_difficulty: dict[str, dict[str, DomainAggregate]] = Field(
        default_factory=dict, description="domain -> difficulty (easy, medium, hard) -> aggregate over those tasks")
    demo: DomainAggregate | None = None
    errors: dict[str, ErrorBreakdown] = Field(description="per domain, plus 'all' over every non-demo domain")
    episodes: list[EpisodeResult]
    problems: list[str] = Field(default_factory=list, description="every episode's problems, prefixed by its id")
    infrastructure: dict[str, int] = Field(
        default_factory=dict, description="per domain: episodes cut off by infrastructure (not scored, not in n)")
    infrastructure_failures: list[str] = Field(
        default_factory=list, description="each such episode: '<episode id> (<task id>): <reason>'")
