"""The task schema shared by the generator, the server and the graders.

A task is a JSON document; its shape is versioned (``schema_version``) so that run
directories written today can still be graded after the schema grows.
"""

from __future__ import annotations

import json
from pathlib import Path
from collections.abc import Callable, Sized
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Discriminator, Field, Tag, ValidationError, field_validator

from . import registry

SCHEMA_VERSION = 1

# A task's domain is one of the registry's (ewa_mcp/core/registry.py); checked by Task, listed in the exported schema.
Domain = str
Difficulty = Literal["easy", "medium", "hard"]
DIFFICULTIES: tuple[str, ...] = ("easy", "medium", "hard")
EnvSide = Literal["web", "embodied"]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


# ---------------------------------------------------------------- start state
class WebStart(_Strict):
    # Site-relative URL such as "recipes:/" or "shop:/product/7"; the server maps site names
    # to the loopback ports it serves them on, so tasks never hard-code a host.
    start_url: str = "home:/"


class KitchenStart(_Strict):
    kind: Literal["kitchen"] = "kitchen"
    scene: str = "FloorPlan1"
    seed: int = 0


class StreetStart(_Strict):
    kind: Literal["street"] = "street"
    city: str
    node: str
    heading: float = 0.0


class GeoStart(_Strict):
    kind: Literal["geo"] = "geo"
    location_id: str
    setting: Literal["baseline", "embodied"] = "embodied"


_BUILTIN_STARTS = {"kitchen", "street", "geo"}


def _excluding(kinds: set[str]) -> Any:
    """JSON Schema for the open model's ``kind``: any string but the built-in kinds (so oneOf stays exclusive)."""

    def extra(schema: dict[str, Any]) -> None:
        schema["not"] = {"enum": sorted(kinds)}

    return extra


class DomainStart(BaseModel):
    """The start of an embodied environment that a registered domain declares (ewa_mcp/core/registry.py) beside the
    built-in ones; its fields are that environment's to read."""

    model_config = ConfigDict(extra="allow")
    kind: str = Field(json_schema_extra=_excluding(_BUILTIN_STARTS))

    @field_validator("kind")
    @classmethod
    def _registered(cls, kind: str) -> str:
        names = sorted(n for n, e in registry.environments().items() if e.side == "embodied")
        if kind in _BUILTIN_STARTS or kind not in names:
            raise ValueError(f"unknown embodied environment {kind[:100]!r}; the embodied environments are: "
                             f"{', '.join(names)}")
        return kind


def _kind_tag(builtin: set[str], other: str) -> Any:
    """A discriminator: the built-in model of the value's ``kind``, else the open model of registered kinds."""

    def tag(value: Any) -> str | None:
        kind = value.get("kind") if isinstance(value, dict) else getattr(value, "kind", None)
        if not isinstance(kind, str):
            return None
        return kind if kind in builtin else other

    return Discriminator(tag, custom_error_type="invalid_kind",
                         custom_error_message="the object needs a 'kind' naming a known kind")


EmbodiedStart = Annotated[
    Annotated[KitchenStart, Tag("kitchen")] | Annotated[StreetStart, Tag("street")] | Annotated[GeoStart, Tag("geo")]
    | Annotated[DomainStart, Tag("other")],
    _kind_tag(_BUILTIN_STARTS, "other"),
]


class StartState(_Strict):
    environment: EnvSide = "web"
    web: WebStart | None = None
    embodied: EmbodiedStart | None = None


# ---------------------------------------------------------------- goals
class RecipeCompleted(_Strict):
    """Web: the right recipe's last step was displayed."""

    kind: Literal["recipe_completed"] = "recipe_completed"
    recipe_id: str


class OrderPlaced(_Strict):
    """Web: an order exists with this product (and size, quantity, pickup store when given)."""

    kind: Literal["order_placed"] = "order_placed"
    product_id: str
    size: str | None = None
    quantity: int = 1
    store_id: str | None = None


class DirectionsShown(_Strict):
    """Web: the map site showed walking directions between these two places."""

    kind: Literal["directions_shown"] = "directions_shown"
    origin: str
    destination: str


class PageVisited(_Strict):
    """Web: a page of a site whose path starts with ``path_prefix`` was viewed."""

    kind: Literal["page_visited"] = "page_visited"
    site: str
    path_prefix: str


class ObjectState(_Strict):
    """Embodied (kitchen): some object of exactly this type has ``state[prop] == value``.

    Sliced or cracked pieces count for their source type (TomatoSliced for Tomato)."""

    kind: Literal["object_state"] = "object_state"
    object_type: str
    prop: Literal["isSliced", "isCooked", "isBroken", "isToggled", "isOpen", "isPickedUp"]
    value: bool = True


class ObjectIn(_Strict):
    """Embodied (kitchen): some object of this type (or a piece of it) is in/on this receptacle type."""

    kind: Literal["object_in"] = "object_in"
    object_type: str
    receptacle_type: str
    # When set, the object must also satisfy these states (e.g. cooked tomato slices on a plate).
    with_state: dict[str, bool] = Field(default_factory=dict)


class _StreetTarget(_Strict):
    """A point of a city's street graph that a walk is checked against."""

    city: str
    node: str
    lat: float
    lng: float
    radius_m: float = 25.0
    place_id: str | None = None


class ReachedPlace(_StreetTarget):
    """Embodied (street): the walk ended (at the first street_stop, else when the episode finished)
    within ``radius_m`` of the target."""

    kind: Literal["reached_place"] = "reached_place"
    # Shopping: the store must be the pickup store of the order that matched the web goal.
    must_match_order_store: bool = False


class PassedPlace(_StreetTarget):
    """Embodied (street): the walk passed within ``radius_m`` of a waypoint before it ended."""

    kind: Literal["passed_place"] = "passed_place"


_BUILTIN_EMBODIED_GOALS = {"object_state", "object_in", "reached_place", "passed_place"}


class DomainGoal(BaseModel):
    """Embodied: a goal kind a registered domain declares (``Domain.goal_kinds``), graded by the check that
    domain names for it (``Domain.checks``) against the embodied final state. Its fields are that check's."""

    model_config = ConfigDict(extra="allow")
    kind: str = Field(json_schema_extra=_excluding(_BUILTIN_EMBODIED_GOALS))

    @field_validator("kind")
    @classmethod
    def _registered(cls, kind: str) -> str:
        if kind in _BUILTIN_EMBODIED_GOALS or registry.goal_check(kind) is None:
            known = sorted(_BUILTIN_EMBODIED_GOALS | {k for d in registry.domains() for k in d.checks})
            raise ValueError(f"unknown embodied goal kind {kind[:100]!r}; the kinds are: {', '.join(known)}")
        return kind


WebGoal = Annotated[RecipeCompleted | OrderPlaced | DirectionsShown | PageVisited, Field(discriminator="kind")]
EmbodiedGoal = Annotated[
    Annotated[ObjectState, Tag("object_state")] | Annotated[ObjectIn, Tag("object_in")]
    | Annotated[ReachedPlace, Tag("reached_place")] | Annotated[PassedPlace, Tag("passed_place")]
    | Annotated[DomainGoal, Tag("other")],
    _kind_tag(_BUILTIN_EMBODIED_GOALS, "other"),
]


# ---------------------------------------------------------------- answers
class AnswerNumbers(_Strict):
    """Which numbers in an answer are values of the asked kind (a year, calories, a size in oz).

    The answer may hold no such number besides the expected one: "1713 or 1720" and "120 kcal, maybe 140"
    fail even when 1720 or 140 is in no distractor list. A number followed by one of ``units`` is of the
    asked kind; one followed by another unit the grader knows (g, ml, ft, %, ...) is not; a number followed
    by no unit counts when ``bare`` is true. Only numbers within [``low``, ``high``] count (years: 1000-2100).
    """

    units: list[str] = Field(default_factory=list)
    bare: bool = True
    low: float | None = None
    high: float | None = None


class TextAnswer(_Strict):
    """A short text answer (docs/grading.md, "Answers that must commit").

    ``must_include``: every phrase must be named (as whole words, after normalisation), or one of its
    ``aliases`` (accepted other wordings). ``distractors``: the other candidates the answer must be told
    apart from (the other products compared, the other sizes, every other architect in the wiki, ...);
    naming any of them fails, also in a negation. ``context``: phrases the answer may repeat freely (the
    product's name, the amount the intent asked for); they never count as a hedge, a distractor or a
    rival number. ``numbers``: which numbers are rival values. ``max_chars``: a longer answer fails.
    """

    kind: Literal["text"] = "text"
    must_include: list[str] = Field(default_factory=list)
    exact: str | None = None
    aliases: dict[str, list[str]] = Field(default_factory=dict)
    distractors: list[str] = Field(default_factory=list)
    context: list[str] = Field(default_factory=list)
    numbers: AnswerNumbers | None = None
    max_chars: int | None = Field(default=None, ge=1)


class GeoAnswer(_Strict):
    kind: Literal["geolocation"] = "geolocation"
    lat: float
    lng: float
    continent: str
    country: str
    city: str
    street: str


AnswerCheck = Annotated[TextAnswer | GeoAnswer, Field(discriminator="kind")]


class ToolCall(_Strict):
    """One step of an oracle solution: a tool name and its arguments (``episode_id`` is filled in)."""

    tool: str
    args: dict[str, Any] = Field(default_factory=dict)


class Task(_Strict):
    schema_version: int = SCHEMA_VERSION
    id: str = Field(pattern=r"^[a-z0-9][a-z0-9_.\-]*$")
    domain: Domain
    # How hard the task is within its domain; every generator sets it (docs/task.schema.json).
    difficulty: Difficulty = "medium"
    intent: str
    start: StartState = Field(default_factory=StartState)
    web_goals: list[WebGoal] = Field(default_factory=list)
    embodied_goals: list[EmbodiedGoal] = Field(default_factory=list)
    answer: AnswerCheck | None = None
    step_limit: int = Field(default=60, ge=1, le=10_000)
    oracle: list[ToolCall] = Field(default_factory=list)
    metadata: dict[str, Any] = Field(default_factory=dict)

    @field_validator("domain")
    @classmethod
    def _known_domain(cls, domain: str) -> str:
        names = registry.domain_names()
        if domain not in names:
            raise ValueError(f"unknown domain {domain[:100]!r}; the domains are: {', '.join(names)} "
                             "(ewa_mcp/core/registry.py)")
        return domain

    def environment_names(self) -> dict[EnvSide, str]:
        """Which environment implementations the task's episodes hold: slot (web/embodied) -> registry name."""
        names: dict[EnvSide, str] = {}
        if has_web_environment(self.start.web, self.web_goals):
            names["web"] = WEB_ENVIRONMENT
        if self.start.embodied is not None:
            names["embodied"] = self.start.embodied.kind
        return names


WEB_ENVIRONMENT = "browser"  # the registry name of the one web environment


def has_web_environment(web_start: object | None, web_goals: Sized) -> bool:
    """The rule: a task has a web environment if it sets start.web or has web goals (also read by the graders
    from a task.json that fails the schema)."""
    return web_start is not None or len(web_goals) > 0


class TaskFileError(ValueError):
    """A task file that cannot be loaded; the message names the file, the field and the fix."""


def load_task_file(path: Path) -> list[Task]:
    """A task file holds one task object or a list of them.

    Raises TaskFileError, naming the file, the reason and the fix, for anything that is not a readable
    UTF-8 JSON file of valid tasks: a directory named ``*.json``, an unreadable file, bytes that are not
    UTF-8, JSON nested too deeply to parse, a schema violation."""
    if path.is_dir():
        raise TaskFileError(f"{path}: a directory named like a task file; rename it so it does not end in .json, "
                            "or move it out of the task directory")
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise TaskFileError(f"{path}: not UTF-8 text (byte {exc.start} is not valid UTF-8); save the file as "
                            "UTF-8 JSON, or move it out of the task directory") from exc
    except OSError as exc:
        raise TaskFileError(f"{path}: cannot be read ({exc.strerror or type(exc).__name__}); make it a readable "
                            "file, or move it out of the task directory") from exc
    try:
        raw = json.loads(text)
    except json.JSONDecodeError as exc:
        raise TaskFileError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno}); fix the file's syntax") from exc
    except RecursionError as exc:
        raise TaskFileError(f"{path}: JSON nested too deeply to read (a task is a few levels deep); fix or "
                            "remove the file") from exc
    items = raw if isinstance(raw, list) else [raw]
    tasks = []
    for i, item in enumerate(items):
        try:
            tasks.append(Task.model_validate(item))
        except RecursionError as exc:
            where = f"{path}" + (f" item {i}" if isinstance(raw, list) else "")
            raise TaskFileError(f"{where}: nested too deeply to be a task; fix or remove it "
                                "(see docs/task.schema.json)") from exc
        except ValidationError as exc:
            where = f"{path}" + (f" item {i}" if isinstance(raw, list) else "")
            problems = "; ".join(
                f"{'.'.join(str(p) for p in e['loc']) or '<root>'}: {e['msg']}" for e in exc.errors()[:5]
            )
            raise TaskFileError(f"{where}: invalid task ({problems}); see docs/task.schema.json") from exc
    return tasks


def task_files(root: Path) -> list[Path]:
    """Every ``*.json`` under ``root`` in a stable order (directories named so included: they are reported as
    bad files). A root that is missing or unreadable holds none; a file that is one is one."""
    root = Path(root)
    if root.is_file():
        return [root]
    try:
        return sorted(root.rglob("*.json"))
    except OSError:
        return []


class TaskStore:
    """All tasks under one or more directories, indexed by id. A file that cannot be loaded is skipped and
    reported in ``errors`` (its path, the reason and the fix); every good task is still served."""

    def __init__(self, roots: list[Path], on_error: Callable[[str], None] | None = None):
        self.roots = roots
        self.on_error = on_error  # told each skipped file once, when the tasks are first read (the server logs it)
        self._tasks: dict[str, Task] | None = None
        self.errors: list[str] = []
        self.sources: dict[str, Path] = {}  # task id -> the file it was read from

    def _load(self) -> dict[str, Task]:
        if self._tasks is None:
            tasks: dict[str, Task] = {}
            for root in self.roots:
                for path in task_files(root):
                    try:
                        for task in load_task_file(path):
                            if task.id in tasks:
                                self.errors.append(f"{path}: duplicate task id {task.id!r}; ids must be unique")
                                continue
                            tasks[task.id] = task
                            self.sources[task.id] = path
                    except TaskFileError as exc:
                        # One bad file must not take the whole suite down; it is reported instead.
                        self.errors.append(str(exc))
            self._tasks = tasks
            if self.on_error is not None:
                for err in self.errors:
                    self.on_error(err)
        return self._tasks

    def add(self, task: Task) -> None:
        self._load()[task.id] = task

    def get(self, task_id: str) -> Task | None:
        return self._load().get(task_id)

    def all(self, domain: str | None = None) -> list[Task]:
        tasks = self._load().values()
        return [t for t in tasks if domain is None or t.domain == domain]

    def __len__(self) -> int:
        return len(self._load())


def export_json_schema() -> dict[str, Any]:
    schema = Task.model_json_schema()
    schema["properties"]["domain"] = {"enum": registry.domain_names(), "title": "Domain", "type": "string"}
    schema["$id"] = f"https://ewa-mcp.invalid/task.schema.v{SCHEMA_VERSION}.json"
    return schema
