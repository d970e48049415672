"""Turn the paper's released navigation environments into full tasks: a street graph with the
annotated start and destination as places the map site finds, and per environment a navigation task
(map directions, then the walk) with web and embodied goals and an oracle.

    ewa-mcp tasks import-ewa navi_env_merge_v1.json [--annotations navi_anno_merge_v1_2.json] [--out DIR]
    ewa-mcp eval --tasks-dir DIR          # or: ewa-mcp serve --tasks DIR

DIR (default ``default_out_dir()``) receives ``streets/<city>.json.gz`` (loaded by the world when DIR
is a task directory), ``navigation/<city>/<task id>.json`` and ``<city>.import-report.txt``.

The release keeps its start and end annotations in a separate file (``navi_anno_merge_v1_2.json``,
found beside the environments when not given): per environment ``general.startpoint_coordinate``,
``general.endpoint_coordinate`` and ``general.generated_name`` (the destination's address),
``embodied[].start`` / ``embodied[].end`` and, for map sub-tasks, ``web[].instantiation_dict`` whose
``intent_template`` says which value is the destination ("to {{destination1}}") and which the start
("from {{destination2}}"). Without annotations, places are named after their route and street.
"""

from __future__ import annotations

import gzip
import json
import os
import re
import shutil
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ewa_mcp.geometry import haversine_m
from ..importer import (
    UNNAMED, CityBuild, Environment, ImportFormatError, ImportReport, build_city, endpoint_node, environments,
    parse_environment, quote,
)

ANNOTATION_NEAR_M = 150.0  # annotation coordinates further than this from the environment are not its own
MAX_RADIUS_M = 10.0
CURRENT_LOCATION = re.compile(r"^(my |the )?current location$", re.IGNORECASE)
COORD = re.compile(r"^\s*\(?\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*\)?\s*$")
INTENT = ('Starting at "{start}", get walking directions on the map site to "{destination}", then walk there '
          'and stop when you arrive.')


def default_out_dir() -> Path:
    """$EWA_IMPORT_DIR, else $XDG_DATA_HOME/ewa-mcp/imported (~/.local/share/ewa-mcp/imported)."""
    from ewa_mcp.settings import load_settings  # the import_dir setting (EWA_IMPORT_DIR)

    if (chosen := load_settings().import_dir) is not None:
        return chosen
    base = Path(os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share")
    return base / "ewa-mcp" / "imported"


# ---------------------------------------------------------------- annotations
@dataclass
class Annotation:
    start_text: str | None = None
    end_text: str | None = None
    start_coord: tuple[float, float] | None = None
    end_coord: tuple[float, float] | None = None
    general_name: str | None = None  # general.generated_name: the destination, tied to end_coord
    task_type: str | None = None


def _text(value: Any) -> str | None:
    if not isinstance(value, str):
        return None
    value = " ".join(value.split())
    if not value or CURRENT_LOCATION.match(value):
        return None
    return value[:200]


def _dict_field(record: dict[Any, Any], name: str) -> dict[Any, Any]:
    """``record[name]`` when it is a JSON object, else an empty one."""
    value = record.get(name)
    return value if isinstance(value, dict) else {}


def _str_field(record: dict[Any, Any], name: str) -> str:
    """``record[name]`` when it is a string, else an empty one."""
    value = record.get(name)
    return value if isinstance(value, str) else ""


def parse_annotation(raw: Any) -> Annotation:
    ann = Annotation()
    if not isinstance(raw, dict):
        return ann
    general = _dict_field(raw, "general")
    embodied = [e for e in raw.get("embodied") or [] if isinstance(e, dict)]
    web = [w for w in raw.get("web") or [] if isinstance(w, dict)]
    ann.task_type = _text(general.get("task_type"))
    for name, attr, text_attr in (("startpoint_coordinate", "start_coord", "start_text"),
                                  ("endpoint_coordinate", "end_coord", "end_text")):
        value = general.get(name)
        m = COORD.match(value) if isinstance(value, str) else None
        if m:
            setattr(ann, attr, (float(m.group(1)), float(m.group(2))))
        elif _text(value):  # the release has an address where a coordinate belongs
            setattr(ann, text_attr, _text(value))
    ann.general_name = _text(general.get("generated_name"))
    for w in web:
        template = _str_field(w, "intent_template")
        values = _dict_field(w, "instantiation_dict")
        for var, value in values.items():
            slot = r"\{\{\s*" + re.escape(str(var)) + r"\s*\}\}"
            if re.search(r"\bto (the )?" + slot, template) and _text(value):
                ann.end_text = _text(value)
            elif re.search(r"\bfrom (the )?" + slot, template) and _text(value):
                ann.start_text = _text(value)
    starts = [_text(e.get("start")) for e in embodied if _text(e.get("start"))]
    ends = [_text(e.get("end")) for e in embodied if _text(e.get("end"))]
    if starts:
        ann.start_text = starts[0]
    if ends:
        ann.end_text = ends[-1]
    return ann


def read_annotations(path: Path) -> dict[str, Annotation]:
    try:
        raw = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ImportFormatError(f"annotations {path}: cannot read it as JSON ({exc})") from None
    except RecursionError:
        raise ImportFormatError(f"annotations {path}: JSON nested too deeply to read; it is not the release's "
                                "annotation file (pass --annotations none to import without one)") from None
    if isinstance(raw, dict):
        return {str(k): parse_annotation(v) for k, v in raw.items()}
    if not isinstance(raw, list):
        raise ImportFormatError(f"annotations {path}: expected a list (or a mapping) of task annotations")
    out = {}
    for i, entry in enumerate(raw):
        general = _dict_field(entry, "general") if isinstance(entry, dict) else {}
        task_id = general.get("task_id", i)
        out[str(task_id if isinstance(task_id, int | str) else i)] = parse_annotation(entry)
    return out


def find_annotations(env_path: Path) -> Path | None:
    """The release keeps annotations beside the environments: navi_env_... -> navi_anno_..."""
    stem = env_path.stem
    if "env" not in stem:
        return None
    prefix = stem.split("env", 1)[0]
    found = sorted(p for p in env_path.parent.glob(f"{prefix}anno*.json") if p != env_path)
    return found[0] if len(found) == 1 else None


# ---------------------------------------------------------------- tasks
@dataclass
class Planned:
    env: Environment
    start: str
    dest: str
    start_place: str
    dest_place: str
    reversed: bool
    annotation: Annotation | None
    used_annotation: bool


@dataclass
class ImportResult:
    city: str
    graph_path: Path
    task_paths: list[Path]
    report: ImportReport
    annotations: Path | None = None
    tasks: list[dict[str, Any]] = field(default_factory=list)


def slugify(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "env"


def _orient(ann: Annotation, s: tuple[float, float], t: tuple[float, float]) -> tuple[bool, bool, str | None]:
    """(reverse the walk, the annotation belongs to this environment, note)."""
    def d(a: tuple[float, float], b: tuple[float, float]) -> float:
        return haversine_m(a[0], a[1], b[0], b[1])

    sp, ep = ann.start_coord, ann.end_coord
    near = [c for c in (sp, ep) if c is not None and min(d(c, s), d(c, t)) <= ANNOTATION_NEAR_M]
    if (sp or ep) and not near:
        far = min(min(d(c, s), d(c, t)) for c in (sp, ep) if c is not None)
        return False, False, (f"the annotation's coordinates lie {far:.0f} m from the environment; its start and "
                              "destination were not used")
    if sp in near and ep in near:
        return d(t, sp) + d(s, ep) < d(s, sp) + d(t, ep), True, None
    if ep in near:
        return d(s, ep) < d(t, ep), True, None
    if sp in near:
        return d(t, sp) < d(s, sp), True, None
    return False, True, None


def _fold(text: str) -> str:
    return " ".join(re.sub(r"[^\w]+", " ", text.casefold()).split())


class PlaceBook:
    """The named places of one imported city; one text at one node is one place, and the same text at
    another node is a second place with the route added to its name."""

    def __init__(self, city: str, build: CityBuild):
        self.city, self.build = city, build
        self.places: list[dict[str, Any]] = []
        self.by_name: dict[str, list[dict[str, Any]]] = {}

    def add(self, name: str, node: str, fallback: str) -> dict[str, Any]:
        lat, lng = self.build.position[node]
        for candidate in (name, f"{name} ({fallback})"):
            same = self.by_name.get(_fold(candidate), [])
            for p in same:
                if p["node"] == node:  # the task's walk starts/ends exactly where the map's place is
                    return p
            if not same:
                place = {"id": f"place-{self.city}-{len(self.places):04d}", "name": candidate, "kind": "address",
                         "address": candidate, "lat": lat, "lng": lng, "node": node}
                self.places.append(place)
                self.by_name.setdefault(_fold(candidate), []).append(place)
                return place
        raise ImportFormatError(f"two places are both named {quote(name)}")


def plan(envs: list[Environment], build: CityBuild, annotations: dict[str, Annotation] | None,
         report: ImportReport, book: PlaceBook) -> list[Planned]:
    from ..world import CityGraph

    graph = CityGraph(build.graph)
    planned = []
    for env in envs:
        s, t = endpoint_node(build, env, env.source), endpoint_node(build, env, env.target)
        if s is None or t is None:
            which = "source" if s is None else "target"
            key = env.source if s is None else env.target
            report.skip(env.label, f"its {which} {quote(key)} is not a panorama of its graph (nor within 5 m of one)")
            continue
        if s == t:
            spread = _key_distance(env)
            what = (f"are two panoramas of one spot, {spread:.2f} m apart" if spread else "are the same panorama")
            report.skip(env.label, f"its source and target {what}: there is nowhere to walk")
            continue
        try:
            graph.route(graph.index[s], graph.index[t])
        except ValueError:
            report.skip(env.label, "its links do not connect the source to the target (no walkable route)")
            continue
        ann = annotations.get(env.label) if annotations is not None else None
        reverse, belongs = False, False
        if ann is not None:
            reverse, belongs, note = _orient(ann, build.position[s], build.position[t])
            if note:
                report.notes.append(f"environment {env.label}: {note}")
            if reverse:
                s, t = t, s
                report.notes.append(f"environment {env.label}: its source is the annotated end point, so the task "
                                    f"walks from the annotated start (its target) to its source")
        start_text = end_text = None
        if ann is not None and belongs:
            start_text = ann.start_text
            end_text = ann.end_text or ann.general_name
            if start_text and end_text and _fold(start_text) == _fold(end_text):
                start_text = None  # one address for both ends: the start is named after the route
        label = f"route {env.label}"
        start_name = start_text or f"Start of {label} {_street(build, s)}"
        end_name = end_text or f"End of {label} {_street(build, t)}"
        sp = book.add(start_name, s, label)
        dp = book.add(end_name, t, label)
        if sp is dp:
            report.skip(env.label, f"its start and destination are the same place ({quote(sp['name'])})")
            continue
        planned.append(Planned(env, s, t, sp["id"], dp["id"], reverse, ann, bool(start_text or end_text)))
    return planned


def _key_distance(env: Environment) -> float | None:
    from ..importer import node_position

    start, end = env.nodes.get(str(env.source)), env.nodes.get(str(env.target))
    if str(env.source) == str(env.target) or not isinstance(start, dict) or not isinstance(end, dict):
        return None
    a, b = node_position(str(env.source), start), node_position(str(env.target), end)
    return haversine_m(*a, *b) if a and b else None


def _street(build: CityBuild, node: str) -> str:
    street = build.street_at.get(node, UNNAMED)
    if street == UNNAMED:
        return "on an unnamed street"
    return street if street.startswith("near ") else f"on {street}"


def make_task(p: Planned, city: str, source_name: str, world: Any, resolver: Any, report: ImportReport) -> dict:
    from ewa_mcp.taskgen.common import call, rng_for, site_url, step_budget
    from ..taskgen.navigation import start_heading, walk_oracle
    from ewa_mcp.core.taskmodel import StartState, Task
    from ewa_mcp.envs.browser.goals import DirectionsShown, WebStart
    from ewa_mcp.envs.street.goals import ReachedPlace, StreetStart

    start, dest = world.place(p.start_place), world.place(p.dest_place)
    typed = []
    for place in (start, dest):
        res = resolver.resolve(place.name)
        if res.place is not None and res.place.id == place.id:
            typed.append(place.name)
        else:  # never seen on the release; the oracle then names the place by id, which always resolves
            typed.append(place.id)
            report.notes.append(f"environment {p.env.label}: the map does not resolve {quote(place.name)} to one "
                                f"place; the oracle uses its id")
    route = world.directions(start.id, dest.id)
    a, b = world.node(p.start), world.node(p.dest)
    straight = haversine_m(a.lat, a.lng, b.lat, b.lng)
    radius = round(min(MAX_RADIUS_M, straight / 2), 2)
    label = p.env.label.zfill(3) if p.env.label.isdigit() else slugify(p.env.label)
    oracle = [call("browser_goto", url=site_url("map", "/directions", **{"from": typed[0], "to": typed[1]})),
              call("switch_environment", target="embodied", message="walk the route"),
              *walk_oracle(route.nodes), call("finish_episode")]
    rng = rng_for("import", city, p.env.label)
    task = Task(
        id=f"nav-{city}-{label}",
        domain="navigation",
        intent=INTENT.format(start=start.name, destination=dest.name),
        start=StartState(environment="web", web=WebStart(start_url="map:/"),
                         embodied=StreetStart(city=city, node=p.start, heading=start_heading(world, p.start, rng))),
        web_goals=[DirectionsShown(origin=start.id, destination=dest.id)],
        embodied_goals=[ReachedPlace(city=city, node=p.dest, lat=b.lat, lng=b.lng, radius_m=radius,
                                     place_id=dest.id)],
        step_limit=step_budget("navigation", "imported", len(oracle)),
        oracle=oracle,
        metadata={"source": "imported", "release_file": source_name, "environment": p.env.label,
                  "original_source": p.env.source, "original_target": p.env.target,
                  "reversed_to_match_annotation": p.reversed, "named_from_annotation": p.used_annotation,
                  "annotated_task_type": p.annotation.task_type if p.annotation else None,
                  "shortest_path_m": route.distance_m, "start_goal_distance_m": round(straight, 1),
                  "start_lat": a.lat, "start_lng": a.lng, "origin_node": p.start, "destination_node": p.dest,
                  "route_steps": len(route.steps)},
    )
    return task.model_dump(mode="json", exclude_none=True)


# ---------------------------------------------------------------- one file -> one city
def import_file(path: Path, out: Path, annotations_path: Path | None = None, *, find: bool = True) -> ImportResult:
    try:
        raw = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError) as exc:
        raise ImportFormatError(f"{path}: cannot read it ({exc})") from None
    except json.JSONDecodeError as exc:
        raise ImportFormatError(f"{path}: not JSON ({exc}); if it is a Git LFS pointer, run git lfs pull") from None
    except RecursionError:
        raise ImportFormatError(f"{path}: JSON nested too deeply to read; it is not a release environment file "
                                "(navi_env_merge_v1.json holds a few levels)") from None
    report = ImportReport()
    envs = []
    for label, env in environments(raw, path.stem):
        report.environments_read += 1
        try:
            envs.append(parse_environment(label, env))
        except ImportFormatError as exc:
            report.skip(label, str(exc))
    if annotations_path is None and find:
        annotations_path = find_annotations(path)
    annotations: dict[str, Annotation] | None = None
    if annotations_path is not None:
        annotations = read_annotations(annotations_path)
        missing = [e.label for e in envs if e.label not in annotations]
        if missing:
            report.notes.append(f"{len(missing)} environments have no annotation in {annotations_path.name} "
                                f"(first: {', '.join(missing[:5])}); their places are named after the route")
    slug = slugify(path.stem)
    city = f"import-{slug}"
    build = build_city(envs, city, f"Imported: {path.name}", report)
    book = PlaceBook(city, build)
    planned = plan(envs, build, annotations, report, book)
    if not planned:  # write nothing: an empty city graph and task folder would only confuse a later serve
        why = "; ".join(f"environment {s['environment']}: {s['reason']}" for s in report.skipped[:3])
        raise ImportFormatError(f"{path}: none of its {report.environments_read} environments can become a task"
                                + (f" ({why}{'; …' if len(report.skipped) > 3 else ''})" if why else
                                   " (it holds none: give the release's navi_env_merge_v1.json)")
                                + "; nothing was written")
    build.graph["places"] = book.places
    streets_dir, task_dir = out / "streets", out / "navigation" / city
    streets_dir.mkdir(parents=True, exist_ok=True)
    graph_path = streets_dir / f"{city}.json.gz"

    from ewa_mcp.websites.map.places import WorldAdapter
    from ..world import World

    for attempt in range(2):
        with open(graph_path, "wb") as fh, gzip.GzipFile(fileobj=fh, mode="wb", mtime=0) as gz:
            gz.write(json.dumps(build.graph, separators=(",", ":"), sort_keys=True, ensure_ascii=False).encode())
        world = World(data_dirs=[streets_dir])
        resolver = WorldAdapter(world)
        # A name another imported file or a packaged place also answers to gets the file's name added,
        # so that what the intent says is what the map finds.
        unclear = [pl for pl in book.places if getattr(resolver.resolve(pl["name"]).place, "id", None) != pl["id"]]
        if not unclear or attempt:
            break
        for pl in unclear:
            pl["name"] = pl["address"] = f"{pl['name']} ({path.stem})"
            report.notes.append(f"the map also knows another place named like {quote(pl['name'])}; "
                                f"the name now ends in ({path.stem})")
    tasks = [make_task(p, city, path.name, world, resolver, report) for p in planned]
    if task_dir.exists():
        shutil.rmtree(task_dir)  # a re-import replaces the city's tasks
    task_dir.mkdir(parents=True)
    task_paths = []
    for task in tasks:
        tp = task_dir / f"{task['id']}.json"
        tp.write_text(json.dumps(task, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
        task_paths.append(tp)
    result = ImportResult(city, graph_path, task_paths, report, annotations_path, tasks)
    (out / f"{city}.import-report.txt").write_text(render_report(path, result), encoding="utf-8")
    return result


def counts(result: ImportResult) -> dict[str, Any]:
    r = result.report
    return {"file_city": result.city, "environments": r.environments_read, "tasks": len(result.task_paths),
            "skipped": len(r.skipped), "panoramas": r.panoramas_read, "nodes": r.nodes, "edges": r.edges,
            "merged_groups": len(r.merged), "reversed": sum(t["metadata"]["reversed_to_match_annotation"]
                                                            for t in result.tasks),
            "named_from_annotations": sum(t["metadata"]["named_from_annotation"] for t in result.tasks)}


def render_report(path: Path, result: ImportResult) -> str:
    r = result.report
    lines = [f"Import of {path.name} as city {result.city}",
             f"annotations: {result.annotations or 'none (places are named after their route)'}",
             f"read {r.environments_read} environments, {r.panoramas_read} panoramas; graph has {r.nodes} nodes and "
             f"{r.edges} edges; wrote {len(result.task_paths)} tasks"]
    for reason, n in sorted(r.counts.items()):
        lines.append(f"  {n} {reason}")
    if r.merged:
        lines.append(f"merged {len(r.merged)} groups of panoramas into one node each (original keys kept as aliases "
                     f"under fit.node_aliases):")
        shared = sum(1 for m in r.merged if m["spread_m"] == 0)
        if shared:
            lines.append(f"  {shared} groups are one panorama listed by several environments")
        for m in r.merged:
            if m["spread_m"] > 0:
                lines.append(f"  {m['node']}: {len(m['keys'])} keys, panoramas {', '.join(m['pano_ids'])}, "
                             f"{m['spread_m']} m apart")
    if r.skipped:
        lines.append(f"skipped {len(r.skipped)} environments:")
        lines += [f"  environment {s['environment']}: {s['reason']}" for s in r.skipped]
    if r.notes:
        lines.append("notes:")
        lines += [f"  {n}" for n in r.notes]
    return "\n".join(lines) + "\n"


def run_cli(paths: list[str], out: str | None, annotations: str | None) -> int:
    """``ewa-mcp tasks import-ewa``: import each file, print its report summary and counts."""
    import sys

    if not paths:
        print("error: give the release's environment file, e.g. ewa-mcp tasks import-ewa navi_env_merge_v1.json",
              file=sys.stderr)
        return 2
    out_dir = Path(out) if out else default_out_dir()
    if out_dir.exists() and not out_dir.is_dir():
        print(f"error: the output {out_dir} is a file; import-ewa writes a directory (streets/ and navigation/): "
              "give -o a directory that does not exist yet or is one", file=sys.stderr)
        return 2
    ann = None if annotations in (None, "auto", "none") else Path(annotations)
    status = 0
    imported = 0
    for p in paths:
        try:
            result = import_file(Path(p), out_dir, ann, find=annotations != "none")
        except ImportFormatError as exc:
            print(f"error: {exc}", file=sys.stderr)
            status = 2
            continue
        except RecursionError:
            print(f"error: {p}: nested too deeply to be a release environment file", file=sys.stderr)
            status = 2
            continue
        except OSError as exc:  # the output cannot be written: every file after this one would fail the same way
            print(f"error: cannot write the import under {out_dir}: {exc.strerror or exc} "
                  f"({exc.filename or out_dir}); give -o a writable directory", file=sys.stderr)
            return 2
        imported += len(result.task_paths)
        print(render_report(Path(p), result), end="")
        print(json.dumps(counts(result)))
    if status == 0 and imported == 0:
        print("error: nothing was imported: no environment of the given files became a task (the report above "
              "says why each was skipped)", file=sys.stderr)
        return 1
    if status == 0:
        print(f"tasks and street graphs are in {out_dir}; run them with: ewa-mcp eval --tasks-dir {out_dir} "
              f"(or ewa-mcp serve --tasks-dir {out_dir})")
    return status


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description="Import the paper's released navigation environments as tasks.")
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--out")
    parser.add_argument("--annotations", help="annotation file; 'none' to ignore one found beside the environments")
    args = parser.parse_args()
    raise SystemExit(run_cli(args.paths, args.out, args.annotations))
