"""The task schema shared by the generator, the server and the graders.

A task is a JSON document; its shape is versioned (``schema_version``) so that run
directories written today can still be graded after the schema grows.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable, Sized
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal, Union

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    GetCoreSchemaHandler,
    GetJsonSchemaHandler,
    Tag,
    TypeAdapter,
    ValidationError,
    field_validator,
)
from pydantic.json_schema import JsonSchemaValue
from pydantic_core import core_schema

from . import registry

SCHEMA_VERSION = 1

# A task's domain is one of the registry's (ewa_mcp/core/registry.py); checked by Task, listed in the exported schema.
Domain = str
Difficulty = Literal["easy", "medium", "hard"]
DIFFICULTIES: tuple[str, ...] = ("easy", "medium", "hard")
EnvSide = Literal["web", "embodied"]


class StrictModel(BaseModel):
    """The base of every task part: unknown fields are refused (a typo is an error, not a silent default)."""

    model_config = ConfigDict(extra="forbid")




# ---------------------------------------------------------------- the parts the worlds declare
# The start of an episode, its goals and its answer checks are models the environments declare
# (``EnvironmentSpec.start``, ``.goals``, ``.answers`` in ewa_mcp/core/registry.py; the built-in worlds in their
# goals.py, a plugin in its own). The kernel names none of them: it assembles the task schema from what is
# registered when a task is validated or the schema exported, so a world registered at run time
# (``registry.register_domain``) is read exactly as a built-in one.

@dataclass(frozen=True)
class Declared:
    """The task models the registered environments declare, by kind, in registration order."""

    web_start: type[BaseModel] | None
    embodied_starts: dict[str, type[BaseModel]]  # environment name (= start.embodied.kind) -> model
    web_goals: dict[str, type[BaseModel]]
    embodied_goals: dict[str, type[BaseModel]]
    answers: dict[str, type[BaseModel]]


def _declared_model(path: str, what: str) -> type[BaseModel]:
    model = registry.load_object(path)
    if not (isinstance(model, type) and issubclass(model, BaseModel)):
        raise registry.RegistryError(f"{path!r}, declared as {what}, is not a pydantic model; name a BaseModel class")
    return model


def _kind_of(model: type[BaseModel], path: str, what: str) -> str:
    field = model.model_fields.get("kind")
    if field is None or not isinstance(field.default, str):
        raise registry.RegistryError(f"{path!r}, declared as {what}, has no 'kind' field with a default; give it "
                                     "kind: Literal[\"<its kind>\"] = \"<its kind>\"")
    return field.default


def _put(table: dict[str, type[BaseModel]], kind: str, model: type[BaseModel], path: str) -> None:
    if table.setdefault(kind, model) is not model:
        raise registry.RegistryError(f"{path!r} declares the kind {kind!r}, which {table[kind].__name__} already "
                                     "declares; a kind has one model")


_declared_cache: tuple[tuple[int, ...], Declared] | None = None


def declared() -> Declared:
    """What the registered environments declare (recomputed when the registered domains change)."""
    global _declared_cache
    key = tuple(id(d) for d in registry.domains())
    if _declared_cache is not None and _declared_cache[0] == key:
        return _declared_cache[1]
    web_start: type[BaseModel] | None = None
    starts: dict[str, type[BaseModel]] = {}
    goals: dict[str, dict[str, type[BaseModel]]] = {"web": {}, "embodied": {}}
    answers: dict[str, type[BaseModel]] = {}
    for env in registry.environments().values():
        if env.start is not None:
            model = _declared_model(env.start, f"the start of {env.name!r}")
            if env.side == "web":
                web_start = web_start or model
            else:
                kind = model.model_fields["kind"].default if "kind" in model.model_fields else None
                if kind != env.name:
                    raise registry.RegistryError(
                        f"{env.start!r}, the start of the embodied environment {env.name!r}, must have "
                        f"kind: Literal[{env.name!r}] = {env.name!r} (start.embodied.kind names the environment)")
                starts[env.name] = model
        for path in env.goals:
            model = _declared_model(path, f"a goal of {env.name!r}")
            _put(goals[env.side], _kind_of(model, path, f"a goal of {env.name!r}"), model, path)
        for path in env.answers:
            model = _declared_model(path, f"an answer check of {env.name!r}")
            _put(answers, _kind_of(model, path, f"an answer check of {env.name!r}"), model, path)
    found = Declared(web_start, starts, goals["web"], goals["embodied"], answers)
    _declared_cache = (key, found)
    return found


def _excluding(kinds: Callable[[], Iterable[str]]) -> Any:
    """JSON Schema for an open model's ``kind``: any string but the declared kinds (so oneOf stays exclusive)."""

    def extra(schema: dict[str, Any]) -> None:
        schema["not"] = {"enum": sorted(kinds())}

    return extra


class DomainStart(BaseModel):
    """The start of an embodied environment that a registered domain uses but declares no start model for
    (``EnvironmentSpec.start``); its fields are that environment's to read."""

    model_config = ConfigDict(extra="allow")
    kind: str = Field(json_schema_extra=_excluding(lambda: declared().embodied_starts))

    @field_validator("kind")
    @classmethod
    def _registered(cls, kind: str) -> str:
        names = sorted(n for n, e in registry.environments().items() if e.side == "embodied")
        if kind in declared().embodied_starts or kind not in names:
            raise ValueError(f"unknown embodied environment {kind[:100]!r}; the embodied environments are: "
                             f"{', '.join(names)}")
        return kind


def _kind_tag(declared_kinds: Iterable[str], other: str) -> Any:
    """A discriminator: the declared model of the value's ``kind``, else the open model of registered kinds."""
    kinds = set(declared_kinds)

    def tag(value: Any) -> str | None:
        kind = value.get("kind") if isinstance(value, dict) else getattr(value, "kind", None)
        if not isinstance(kind, str):
            return None
        return kind if kind in kinds else other

    return Discriminator(tag, custom_error_type="invalid_kind",
                         custom_error_message="the object needs a 'kind' naming a known kind")


class DomainGoal(BaseModel):
    """Embodied: a goal kind a registered domain declares (``Domain.goal_kinds``), graded by the check that
    domain names for it (``Domain.checks``) against the embodied final state. Its fields are that check's."""

    # The model of the kinds no environment declares a model for (``EnvironmentSpec.goals``).
    model_config = ConfigDict(extra="allow")
    kind: str = Field(json_schema_extra=_excluding(lambda: declared().embodied_goals))

    @field_validator("kind")
    @classmethod
    def _registered(cls, kind: str) -> str:
        known_models = declared().embodied_goals
        if kind in known_models or registry.goal_check(kind) is None:
            known = sorted(set(known_models) | {k for d in registry.domains() for k in d.checks})
            raise ValueError(f"unknown embodied goal kind {kind[:100]!r}; the kinds are: {', '.join(known)}")
        return kind


def _tagged(models: dict[str, type[BaseModel]], other: type[BaseModel]) -> Any:
    """The declared models by kind, then the open one, chosen by ``kind``."""
    if not models:
        return other
    members = [Annotated[m, Tag(k)] for k, m in models.items()] + [Annotated[other, Tag("other")]]
    return Annotated[Union[tuple(members)], _kind_tag(models, "other")]  # noqa: UP007 (a union built at run time)


def _by_kind(models: list[type[BaseModel]], nothing: str) -> Any:
    """A union of models told apart by their ``kind`` field; ``nothing`` refuses every value when none exists."""
    if not models:
        def refuse(value: Any) -> Any:
            raise ValueError(nothing)

        return Annotated[Any, AfterValidator(refuse)]
    if len(models) == 1:
        return models[0]
    return Annotated[Union[tuple(models)], Field(discriminator="kind")]  # noqa: UP007 (a union built at run time)


def _assemble(part: str, found: Declared) -> Any:
    if part == "web_start":
        if found.web_start is None:
            return _by_kind([], "no registered web environment declares a start; remove start.web")
        return found.web_start
    if part == "embodied_start":
        return _tagged(found.embodied_starts, DomainStart)
    if part == "web_goal":
        return _by_kind(list(found.web_goals.values()), "no registered web environment declares a goal kind; "
                                                         "remove the web goals")
    if part == "embodied_goal":
        return _tagged(found.embodied_goals, DomainGoal)
    return _by_kind([TextAnswer, *found.answers.values()], "")


_adapters: dict[tuple[str, int], TypeAdapter[Any]] = {}


def _adapter(part: str) -> TypeAdapter[Any]:
    found = declared()
    key = (part, id(found))
    adapter = _adapters.get(key)
    if adapter is None:
        if len(_adapters) > 64:  # registries that came and went (tests): keep the cache small
            _adapters.clear()
        adapter = _adapters[key] = TypeAdapter(_assemble(part, found))
    return adapter


class Assembled:
    """Marks a task field whose type the registered environments declare: values are validated (and the
    schema exported) by the union of the models they declare for ``part`` at that moment."""

    def __init__(self, part: str):
        self.part = part

    def __get_pydantic_core_schema__(self, source: Any, handler: GetCoreSchemaHandler) -> core_schema.CoreSchema:
        part = self.part

        def schema(_: core_schema.CoreSchema, json_handler: GetJsonSchemaHandler) -> JsonSchemaValue:
            # As a union of one, so that a single declared model is a $ref into $defs as a model field's type is
            # (the handler writes the schema it is given in place; a union's members go through $defs).
            return json_handler(core_schema.union_schema([_adapter(part).core_schema]))

        return core_schema.no_info_plain_validator_function(lambda value: _adapter(part).validate_python(value),
                                                            metadata={"pydantic_js_annotation_functions": [schema]})


EmbodiedStart = Annotated[Any, Assembled("embodied_start")]


def _untitled_web(schema: dict[str, Any]) -> None:
    # start.web has no title, as a field whose type is one model has none (the schema names the model).
    schema["properties"]["web"].pop("title", None)


class StartState(StrictModel):
    model_config = ConfigDict(json_schema_extra=_untitled_web)

    environment: EnvSide = "web"
    web: Annotated[Any, Assembled("web_start")] | None = None
    embodied: EmbodiedStart | None = None


# ---------------------------------------------------------------- goals
WebGoal = Annotated[Any, Assembled("web_goal")]
EmbodiedGoal = Annotated[Any, Assembled("embodied_goal")]


# ---------------------------------------------------------------- answers
class AnswerNumbers(StrictModel):
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


class TextAnswer(StrictModel):
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


AnswerCheck = Annotated[Any, Assembled("answer")]


class ToolCall(StrictModel):
    """One step of an oracle solution: a tool name and its arguments (``episode_id`` is filled in)."""

    tool: str
    args: dict[str, Any] = Field(default_factory=dict)


class Task(StrictModel):
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
            names["web"] = web_environment()
        if self.start.embodied is not None:
            names["embodied"] = self.start.embodied.kind
        return names


def web_environment() -> str:
    """The registry name of the one web environment (the environment whose side is "web")."""
    names = [name for name, env in registry.environments().items() if env.side == "web"]
    if not names:
        raise registry.RegistryError("no registered domain has a web environment; a task with a web start or web "
                                     "goals needs one")
    return names[0]


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
