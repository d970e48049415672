"""The trajectory viewer: one self-contained HTML page per graded run.

    from ewa_mcp.graders import grade_run
    from ewa_mcp.graders.viewer import write_html
    write_html([grade_run("runs/…")], Path("viewer/"))      # -> [viewer/<label>.html]

The page shows the run summary (the grader's tables), then every episode: task, intent, outcome,
error category, per-goal results and each step (tool, arguments, result, environment, duration,
observation and the step's images). It needs nothing but itself: images are data: URIs, CSS is
inline, there is no script at all (collapsing uses <details>), and a Content-Security-Policy
forbids every fetch. Everything read from the run is HTML-escaped, because runs hold text an agent
or a web page chose. The page is the Jinja2 template templates/viewer.html (autoescaped); this
module reads the run, embeds the images and hands the template plain values.
"""

from __future__ import annotations

import base64
import html
import io
import json
import os
import re
from dataclasses import dataclass, field
from datetime import UTC, datetime
from functools import lru_cache
from pathlib import Path
from typing import Any, cast

import jinja2
from markupsafe import Markup
from PIL import Image

from .errors import CATEGORIES, GROUP_LABELS
from .models import EpisodeResult, RunReport
from .report_tables import Table, demo_table, error_tables, geolocation_section, main_table, navigation_table
from .rundir import episode_dirs, read_jsonl

MAX_IMAGE_SIDE = 512  # px; larger images are downscaled (a page of street views stays browsable)
REENCODE_ABOVE_BYTES = 96_000  # smaller images within MAX_IMAGE_SIDE are embedded byte for byte
PAGE_IMAGE_BUDGET_BYTES = 40_000_000  # past this, images are listed by path, not embedded
JPEG_QUALITY = 80
MAX_IMAGE_FILE_BYTES = 40_000_000  # no observation is this big; such a file is not an observation
TEXT_LIMIT = 4_000  # characters of one argument block or observation shown
EMBEDDABLE = {"PNG": "image/png", "JPEG": "image/jpeg", "GIF": "image/gif", "WEBP": "image/webp"}

# No script, no fetch: only inline styles and data: images may load.
CSP = "default-src 'none'; img-src data:; style-src 'unsafe-inline'; base-uri 'none'; form-action 'none'"

STYLE = """
body{font:14px/1.45 system-ui,sans-serif;margin:0 auto;max-width:1100px;padding:0 16px 48px;color:#1d1d1f}
h1{font-size:24px;margin:20px 0 4px}h2{font-size:19px;margin:28px 0 8px;border-bottom:2px solid #ddd}
h3{font-size:15px;margin:16px 0 6px}h4{font-size:14px;margin:0;display:inline}
table{border-collapse:collapse;margin:6px 0 10px}th,td{border:1px solid #ccc;padding:3px 8px;text-align:left;
vertical-align:top}th{background:#f3f3f3}caption{text-align:left;font-weight:600;padding:4px 0}
.note,.muted{color:#666;font-size:12px}pre{white-space:pre-wrap;word-break:break-word;margin:4px 0;
background:#f7f7f7;padding:4px 6px;border-radius:4px;font-size:12px}
.episode{border:1px solid #ccc;border-radius:6px;padding:4px 14px 12px;margin:18px 0}
.episode>summary{cursor:pointer}.episode>summary h2{display:inline;border:0}
.pass{background:#d8f3dc;color:#1b5e20}.fail{background:#fde2e1;color:#8e1b10}.unknown{background:#eee;color:#555}
.badge{display:inline-block;border-radius:10px;padding:0 8px;font-size:12px;font-weight:600;margin-right:4px}
.env-web{background:#dbe8ff;color:#123f8c}.env-embodied{background:#ffe7c7;color:#7a4100}
.env-none{background:#eee;color:#555}
.step{border-left:4px solid #bbb;margin:8px 0;padding:4px 10px}.step.web{border-color:#5b8def}
.step.embodied{border-color:#f0a030}.step.failed{background:#fff6f5}
.switch-mark{margin:12px 0 4px;padding:4px 10px;background:repeating-linear-gradient(45deg,#f4f0ff,#f4f0ff 8px,
#ebe4ff 8px,#ebe4ff 16px);border:1px dashed #7a5cc7;border-radius:4px;font-weight:600;color:#4b2e9a}
.error-text{color:#8e1b10}figure{display:inline-block;margin:6px 10px 0 0}
figure img{max-width:min(100%,512px);height:auto;border:1px solid #ccc}figcaption{font-size:11px;color:#666}
nav table td{font-size:13px}
"""


# ------------------------------------------------------------------ images
@dataclass
class ImageBudget:
    """Bytes of image data a page may still embed; shared by all episodes of one page."""

    remaining: int = PAGE_IMAGE_BUDGET_BYTES
    omitted: int = 0


@dataclass
class EmbeddedImage:
    data_uri: str | None
    caption: str


def _encoded(image: Image.Image) -> tuple[bytes, str, tuple[int, int]]:
    """A downscaled copy and its size: JPEG for opaque pictures (renders, street photos), PNG when
    transparency matters."""
    if image.mode == "P" or "transparency" in image.info:
        image = image.convert("RGBA")
    image.thumbnail((MAX_IMAGE_SIDE, MAX_IMAGE_SIDE), Image.Resampling.LANCZOS)
    buffer = io.BytesIO()
    # One channel's extrema are (min, max); Pillow types them with the multi-band case.
    if image.mode in ("RGBA", "LA") and cast(tuple[float, float], image.getchannel("A").getextrema())[0] < 255:
        image.save(buffer, format="PNG", optimize=True)
        return buffer.getvalue(), "image/png", image.size
    image.convert("RGB").save(buffer, format="JPEG", quality=JPEG_QUALITY)
    return buffer.getvalue(), "image/jpeg", image.size


def embed_image(episode_dir: Path, relative: Any, budget: ImageBudget) -> EmbeddedImage:
    """A data: URI for one recorded image, or why it is not shown. Only files inside the episode
    directory are read: a trajectory line must not pull in files from elsewhere on the machine."""
    if not isinstance(relative, str) or not relative:
        return EmbeddedImage(None, f"image entry {relative!r} is not a path; skipped")
    path = episode_dir / relative
    try:
        inside = path.resolve().is_relative_to(episode_dir.resolve())
    except (OSError, ValueError):
        inside = False
    if not inside or Path(relative).is_absolute():
        return EmbeddedImage(None, f"{relative}: outside the episode directory; not read")
    if budget.remaining <= 0:
        budget.omitted += 1
        return EmbeddedImage(None, f"{relative}: not embedded, the page's image budget "
                                   f"({PAGE_IMAGE_BUDGET_BYTES // 1_000_000} MB) is spent")
    try:
        if path.stat().st_size > MAX_IMAGE_FILE_BYTES:
            return EmbeddedImage(None, f"{relative}: larger than {MAX_IMAGE_FILE_BYTES // 1_000_000} MB; not read")
        raw = path.read_bytes()
        with Image.open(io.BytesIO(raw)) as image:
            mime = EMBEDDABLE.get(image.format or "")
            width, height = image.size
            if mime is None:
                return EmbeddedImage(None, f"{relative}: {image.format} images are not embedded")
            if max(width, height) > MAX_IMAGE_SIDE or len(raw) > REENCODE_ABOVE_BYTES:
                image.load()
                data, mime, (new_width, new_height) = _encoded(image)
                shown = f"{width}×{height}, shown at {new_width}×{new_height}"
            else:
                image.verify()  # a corrupt file is reported here, not as a broken picture
                data, shown = raw, f"{width}×{height}"
    except FileNotFoundError:
        return EmbeddedImage(None, f"{relative}: file missing")
    except (OSError, SyntaxError, ValueError, Image.DecompressionBombError) as exc:
        return EmbeddedImage(None, f"{relative}: unreadable image ({type(exc).__name__}: {exc})")
    budget.remaining -= len(data)
    return EmbeddedImage(f"data:{mime};base64,{base64.b64encode(data).decode('ascii')}", f"{relative} ({shown})")


# ------------------------------------------------------------------ values for the template
def clip(text: str, limit: int = TEXT_LIMIT) -> str:
    return text if len(text) <= limit else text[:limit] + f"… [{len(text) - limit} more characters]"


def as_json(value: Any) -> str:
    try:
        return json.dumps(value, ensure_ascii=False, indent=1, sort_keys=True, default=str)
    except (TypeError, ValueError):
        return repr(value)


@dataclass
class StepView:
    """One trajectory line, read leniently: a damaged line still shows what it has."""

    number: str
    tool: str
    args: Any
    ok: bool | None
    error: str | None
    environment: str | None
    duration_ms: float | None
    counted: bool | None
    observation: str
    offset_s: float | None
    images: list[Any] = field(default_factory=list)


def _number(value: Any) -> float | None:
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def step_views(trajectory: list[dict[str, Any]]) -> list[StepView]:
    times = [t for t in (_number(r.get("t")) for r in trajectory) if t is not None]
    start = min(times) if times else None
    views = []
    for position, record in enumerate(trajectory, start=1):
        step = record.get("step")
        t = _number(record.get("t"))
        images = record.get("images")
        views.append(StepView(
            number=str(step) if isinstance(step, int) and not isinstance(step, bool) else str(position),
            tool=str(record.get("tool")) if record.get("tool") is not None else "(no tool recorded)",
            args=record.get("args", {}),
            ok=record.get("ok") if isinstance(record.get("ok"), bool) else None,
            error=str(record["error"]) if record.get("error") is not None else None,
            environment=str(record["environment"]) if record.get("environment") is not None else None,
            duration_ms=_number(record.get("duration_ms")),
            counted=record.get("counted") if isinstance(record.get("counted"), bool) else None,
            observation=str(record.get("observation") or ""),
            offset_s=t - start if t is not None and start is not None else None,
            images=images if isinstance(images, list) else ([images] if images is not None else []),
        ))
    return views


@dataclass
class StepItem:
    """A step as the page shows it: the line, the banner before it, its metadata and its images."""

    view: StepView
    anchor: str
    meta: list[str]
    images: list[EmbeddedImage]
    switch_from: str | None = None  # a successful switch_environment: the banner "Switch A → B"
    switch_to: str | None = None
    switch_message: str | None = None
    changed_from: str | None = None  # another change of environment between steps


def step_item(step: StepView, previous_env: str | None, episode_dir: Path, anchor: str,
              budget: ImageBudget) -> StepItem:
    meta = []
    if step.duration_ms is not None:
        meta.append(f"{step.duration_ms:.1f} ms")
    if step.offset_s is not None:
        meta.append(f"at +{step.offset_s:.1f} s")
    if step.counted is False:
        meta.append("not counted")
    item = StepItem(step, anchor, meta, [embed_image(episode_dir, relative, budget) for relative in step.images])
    # A banner before each successful switch, and before any other change of environment between steps.
    if step.tool == "switch_environment" and step.ok is not False:
        args = step.args if isinstance(step.args, dict) else {}
        item.switch_from = previous_env or ""
        item.switch_to = str(args.get("target") or step.environment or "")
        item.switch_message = str(args["message"]) if args.get("message") else None
    elif previous_env is not None and step.environment is not None and step.environment != previous_env:
        item.changed_from = previous_env
    return item


def _task_fields(episode_dir: Path) -> dict[str, Any]:
    """intent and step limit straight from task.json (the grade does not carry them); {} when unreadable."""
    try:
        raw = json.loads((episode_dir / "task.json").read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return {}
    return raw if isinstance(raw, dict) else {}


@dataclass
class ErrorView:
    category: str
    group: str
    also: list[str]
    evidence: list[tuple[str, str]]


@dataclass
class EpisodeView:
    result: EpisodeResult
    anchor: str
    intent: str | None
    error: ErrorView | None
    steps: list[StepItem]
    directory_missing: bool


def _error_view(result: EpisodeResult) -> ErrorView | None:
    if result.error is None:
        return None
    return ErrorView(
        category=CATEGORIES.get(result.error.category, ("other", result.error.category))[1],
        group=GROUP_LABELS.get(result.error.group, result.error.group),
        also=[CATEGORIES.get(m, ("", m))[1] for m in result.error.matched if m != result.error.category],
        evidence=[(k, str(v)) for k, v in result.error.evidence.items()],
    )


def episode_view(result: EpisodeResult, episode_dir: Path | None, index: int, budget: ImageBudget) -> EpisodeView:
    anchor = f"episode-{index}"
    task = _task_fields(episode_dir) if episode_dir is not None else {}
    intent = task.get("intent") if isinstance(task.get("intent"), str) else None
    problems: list[str] = []
    trajectory = read_jsonl(episode_dir / "trajectory.jsonl", problems) if episode_dir is not None else []
    steps = []
    previous_env: str | None = None
    for k, step in enumerate(step_views(trajectory), start=1):
        steps.append(step_item(step, previous_env, episode_dir or Path("."), f"{anchor}-step-{k}", budget))
        previous_env = step.environment or previous_env
    return EpisodeView(result, anchor, intent, _error_view(result), steps, directory_missing=episode_dir is None)


def _summary_sections(report: RunReport) -> list[dict[str, Any]]:
    sections: list[dict[str, Any]] = []
    for section in [main_table([report]), navigation_table([report]), geolocation_section([report]),
                    *error_tables([report]), demo_table([report])]:
        if isinstance(section, Table):
            sections.append({"table": section})
        elif isinstance(section, str):
            sections.append({"text": section})
    return sections


def _episode_directories(report: RunReport) -> list[Path | None]:
    """The directory of each graded episode, in the report's order (grade_run grades them sorted)."""
    root = Path(report.run_dir)
    try:
        dirs = episode_dirs(root) if root.is_dir() else []
    except OSError:
        dirs = []
    if len(dirs) == len(report.episodes):
        return list(dirs)
    # The run directory changed since grading: match by name where possible.
    by_name = {d.name: d for d in dirs}
    return [by_name.get(e.episode_id) for e in report.episodes]


# ------------------------------------------------------------------ the page (templates/viewer.html)
def _escape(value: Any) -> Markup:
    """Every value the template prints, escaped as html.escape does (quotes included); Markup passes as it is."""
    if isinstance(value, Markup):
        return value
    return Markup(html.escape(value if isinstance(value, str) else str(value), quote=True))


@lru_cache(maxsize=1)
def _template() -> jinja2.Template:
    env = jinja2.Environment(loader=jinja2.PackageLoader(__package__ or "ewa_mcp.graders", "templates"),
                             autoescape=True, finalize=_escape, undefined=jinja2.StrictUndefined,
                             keep_trailing_newline=True)
    env.filters.update(clip=clip, as_json=as_json, short_number=lambda value: f"{value:g}")
    return env.get_template("viewer.html")


def render_html(report: RunReport) -> str:
    """The whole page for one graded run, read from report.run_dir for the steps and images."""
    budget = ImageBudget()
    episodes = [episode_view(result, directory, k, budget)
                for k, (result, directory) in enumerate(zip(report.episodes, _episode_directories(report)), start=1)]
    for episode in episodes:  # data: URIs are built here from image bytes, never from text of the run
        for step in episode.steps:
            for image in step.images:
                if image.data_uri is not None:
                    image.data_uri = Markup(image.data_uri)
    return _template().render(
        report=report, episodes=episodes, summary=_summary_sections(report), omitted=budget.omitted,
        budget_mb=PAGE_IMAGE_BUDGET_BYTES // 1_000_000, csp=Markup(CSP), style=Markup(STYLE),  # constants
        generated=datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"))


# ------------------------------------------------------------------ files
class ViewerError(ValueError):
    """The HTML output cannot be written where asked; the message says what to pass instead."""


def file_stem(label: str) -> str:
    """A run label as a file name: letters, digits, '.', '-', '_' (same-named runs are labelled parent/name)."""
    stem = re.sub(r"[^A-Za-z0-9._-]+", "_", label).strip("._") or "run"
    return stem[:120]


def output_paths(labels: list[str], out: Path) -> list[Path]:
    """OUT/<label>.html per run, or OUT itself when it ends in .html, is not a directory and there is one run."""
    if out.suffix.lower() == ".html" and not out.is_dir():
        if len(labels) != 1:
            raise ViewerError(f"--html {out} names one file but {len(labels)} runs were given; "
                              "pass a directory to get one page per run")
        return [out]
    if out.exists() and not out.is_dir():
        raise ViewerError(f"--html {out} is an existing file; pass a directory (one page per run) "
                          "or a path ending in .html")
    stems = [file_stem(label) for label in labels]
    paths = [out / f"{stem}.html" for stem in stems]
    if len(set(paths)) != len(paths):  # labels differing only in odd characters
        paths = [out / f"{stem}-{k}.html" for k, stem in enumerate(stems, start=1)]
    return paths


def write_html(reports: list[RunReport], out: Path) -> list[Path]:
    """Write one page per report; returns the files written. Each file appears complete or not at all."""
    paths = output_paths([r.label for r in reports], out)
    written = []
    for report, path in zip(reports, paths):
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f".{path.name}.tmp")
        tmp.write_text(render_html(report), encoding="utf-8")
        os.replace(tmp, path)
        written.append(path)
    return written
