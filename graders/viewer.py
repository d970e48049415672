"""The trajectory viewer: one self-contained HTML page per graded run.

    from ewa_mcp.graders import grade_run
    from ewa_mcp.graders.viewer import write_html
    write_html([grade_run("runs/…")], Path("viewer/"))      # -> [viewer/<label>.html]

The page shows the run summary (the grader's tables), then every episode: task, intent, outcome,
error category, per-goal results and each step (tool, arguments, result, environment, duration,
observation and the step's images). It needs nothing but itself: images are data: URIs, CSS is
inline, there is no script at all (collapsing uses <details>), and a Content-Security-Policy
forbids every fetch. Everything read from the run is HTML-escaped, because runs hold text an agent
or a web page chose.
"""

from __future__ import annotations

import base64
import html
import io
import json
import os
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from PIL import Image

from .errors import CATEGORIES, GROUP_LABELS
from .models import ConditionResult, EpisodeResult, RunReport
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
    if image.mode in ("RGBA", "LA") and image.getchannel("A").getextrema()[0] < 255:
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


# ------------------------------------------------------------------ small HTML helpers
def esc(value: Any) -> str:
    return html.escape(value if isinstance(value, str) else str(value), quote=True)


def clip(text: str, limit: int = TEXT_LIMIT) -> str:
    return text if len(text) <= limit else text[:limit] + f"… [{len(text) - limit} more characters]"


def as_json(value: Any) -> str:
    try:
        return json.dumps(value, ensure_ascii=False, indent=1, sort_keys=True, default=str)
    except (TypeError, ValueError):
        return repr(value)


def verdict(value: bool | None, *, unknown: str = "not gradable") -> str:
    if value is True:
        return '<span class="badge pass">pass</span>'
    if value is False:
        return '<span class="badge fail">fail</span>'
    return f'<span class="badge unknown">{esc(unknown)}</span>'


def table_html(table: Table, caption_level: str = "h3") -> str:
    head = "".join(f'<th scope="col">{esc(h)}</th>' for h in table.headers)
    rows = "".join("<tr>" + "".join(f"<td>{esc(c)}</td>" for c in row) + "</tr>" for row in table.rows)
    note = f'<p class="note">{esc(table.note)}</p>' if table.note else ""
    return f"<{caption_level}>{esc(table.title)}</{caption_level}><table><thead><tr>{head}</tr></thead>" \
           f"<tbody>{rows}</tbody></table>{note}"


def definition_list(items: Iterable[tuple[str, str]]) -> str:
    """Label/value rows; values are already HTML."""
    return "<table><tbody>" + "".join(f'<tr><th scope="row">{esc(k)}</th><td>{v}</td></tr>' for k, v in items) \
        + "</tbody></table>"


# ------------------------------------------------------------------ steps
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


def _switch_mark(step: StepView, previous_env: str | None) -> str:
    """A banner before each successful switch, and before any other change of environment between steps."""
    if step.tool == "switch_environment" and step.ok is not False:
        target = step.args.get("target") if isinstance(step.args, dict) else None
        message = step.args.get("message") if isinstance(step.args, dict) else None
        said = f" — “{esc(clip(str(message), 300))}”" if message else ""
        return (f'<div class="switch-mark" role="note">⇄ Switch {esc(previous_env or "?")} → '
                f'{esc(target or step.environment or "?")}{said}</div>')
    if previous_env is not None and step.environment is not None and step.environment != previous_env:
        return (f'<div class="switch-mark" role="note">⇄ Environment changed {esc(previous_env)} → '
                f'{esc(step.environment)}</div>')
    return ""


def step_html(step: StepView, episode_dir: Path, anchor: str, budget: ImageBudget) -> str:
    env = step.environment if step.environment in ("web", "embodied") else None
    status = {True: '<span class="badge pass">ok</span>', False: '<span class="badge fail">error</span>',
              None: '<span class="badge unknown">outcome not recorded</span>'}[step.ok]
    badges = f'<span class="badge env-{env or "none"}">{esc(step.environment or "no environment")}</span>{status}'
    meta: list[str] = []
    if step.duration_ms is not None:
        meta.append(f"{step.duration_ms:.1f} ms")
    if step.offset_s is not None:
        meta.append(f"at +{step.offset_s:.1f} s")
    if step.counted is False:
        meta.append('<span class="muted">not counted</span>')
    parts = [f'<article class="step {env or "none"}{" failed" if step.ok is False else ""}" '
             f'aria-labelledby="{anchor}">',
             f'<h4 id="{anchor}">Step {esc(step.number)}: {esc(step.tool)}</h4> {badges} ' + " · ".join(meta)]
    if step.args not in ({}, None):
        parts.append(f'<pre class="args" aria-label="arguments">{esc(clip(as_json(step.args)))}</pre>')
    if step.error:
        parts.append(f'<p class="error-text">Error: {esc(clip(step.error))}</p>')
    if step.observation and step.observation != step.error:
        parts.append(f'<pre class="observation" aria-label="observation">{esc(clip(step.observation))}</pre>')
    for k, relative in enumerate(step.images):
        shown = embed_image(episode_dir, relative, budget)
        alt = f"Step {step.number} image {k + 1} ({step.environment or 'no environment'})"
        if shown.data_uri is None:
            parts.append(f'<p class="note">Image {k + 1}: {esc(shown.caption)}</p>')
        else:
            parts.append(f'<figure><img src="{shown.data_uri}" alt="{esc(alt)}" loading="lazy">'
                         f"<figcaption>{esc(shown.caption)}</figcaption></figure>")
    parts.append("</article>")
    return "".join(parts)


# ------------------------------------------------------------------ episodes
def _task_fields(episode_dir: Path) -> dict[str, Any]:
    """intent and step limit straight from task.json (the grade does not carry them); {} when unreadable."""
    try:
        raw = json.loads((episode_dir / "task.json").read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return {}
    return raw if isinstance(raw, dict) else {}


def _condition_row(condition: ConditionResult) -> str:
    detail = as_json(condition.detail) if condition.detail else ""
    return (f"<tr><td>{esc(condition.side)}</td><td>{esc(condition.kind)}</td><td>{esc(condition.description)}</td>"
            f"<td>{verdict(condition.met, unknown='unknown')}</td><td>{esc(condition.note or '')}"
            f"{f'<pre>{esc(clip(detail, 1500))}</pre>' if detail else ''}</td></tr>")


def _outcome_html(result: EpisodeResult) -> str:
    completion = f"{100 * result.completion:.1f} % ({result.conditions_met}/{result.conditions_total} conditions)" \
        if result.completion is not None else "unknown"
    rows = [
        ("Overall", verdict(result.overall_success)),
        ("Web", verdict(result.web_success) + ("" if result.has_web_goals else ' <span class="muted">no web goals'
                                                                               "</span>")),
        ("Embodied", verdict(result.embodied_success) + ("" if result.has_embodied_goals else
                                                         ' <span class="muted">no embodied goals</span>')),
        ("Answer", verdict(result.answer_correct, unknown="not checked" if not result.answer_checked
                           else "not gradable")
         + (f" <q>{esc(clip(result.answer, 1000))}</q>" if result.answer is not None else "")),
        ("Completion", esc(completion)),
        ("Status", esc(result.status) + (f" — {esc(result.end_reason)}" if result.end_reason else "")),
        ("Steps / calls / switches", f"{result.steps} / {result.calls} / {result.switches}"),
        ("Wall time", f"{result.wall_time_s:.1f} s" if result.wall_time_s is not None else "unknown"),
    ]
    if result.error is not None:
        category = CATEGORIES.get(result.error.category, ("other", result.error.category))[1]
        group = GROUP_LABELS.get(result.error.group, result.error.group)
        also = [CATEGORIES.get(m, ("", m))[1] for m in result.error.matched if m != result.error.category]
        evidence = "".join(f"<li>{esc(k)}: {esc(clip(v, 600))}</li>" for k, v in result.error.evidence.items())
        rows.append(("Error category", f'<strong class="error-category">{esc(category)}</strong> ({esc(group)})'
                     + (f"; also matched: {esc(', '.join(also))}" if also else "")
                     + (f"<ul>{evidence}</ul>" if evidence else "")))
    return "<h3>Outcome</h3>" + definition_list(rows)


def _goals_html(result: EpisodeResult) -> str:
    if not result.conditions:
        return "<h3>Goals</h3><p class=\"muted\">No goal could be read for this episode.</p>"
    out = ['<h3>Goals</h3><table><thead><tr><th scope="col">Side</th><th scope="col">Kind</th>'
           '<th scope="col">Goal</th><th scope="col">Met</th><th scope="col">Note</th></tr></thead><tbody>',
           *(_condition_row(c) for c in result.conditions), "</tbody></table>"]
    if result.navigation:
        out.append('<table><caption>Street navigation</caption><thead><tr><th scope="col">Goal node</th>'
                   '<th scope="col">Final node</th><th scope="col">Stopped</th><th scope="col">Distance (m)</th>'
                   '<th scope="col">Radius (m)</th><th scope="col">SPL</th></tr></thead><tbody>')
        for nav in result.navigation:
            distance = f"{nav.distance_to_goal_m:.1f}" if nav.distance_to_goal_m is not None else "?"
            spl = f"{nav.spl:.3f}" if nav.spl is not None else "?"
            out.append(f"<tr><td>{esc(nav.goal_node)}</td><td>{esc(nav.final_node or '?')}</td>"
                       f"<td>{'yes' if nav.stopped else 'no'}</td><td>{distance}</td><td>{nav.radius_m:g}</td>"
                       f"<td>{spl}</td></tr>")
        out.append("</tbody></table>")
    if result.geolocation:
        out.append(f"<h4>Geolocation</h4><pre>{esc(clip(as_json(result.geolocation)))}</pre>")
    return "".join(out)


def episode_html(result: EpisodeResult, episode_dir: Path | None, index: int, budget: ImageBudget) -> str:
    anchor = f"episode-{index}"
    task = _task_fields(episode_dir) if episode_dir is not None else {}
    intent = task.get("intent") if isinstance(task.get("intent"), str) else None
    title = f"Episode {result.episode_id}: {result.task_id or 'unknown task'}"
    parts = [f'<section aria-labelledby="{anchor}-h"><details class="episode" id="{anchor}" open>',
             f'<summary><h2 id="{anchor}-h">{esc(title)}</h2> {verdict(result.overall_success)}</summary>',
             definition_list([("Domain", esc(result.domain) + (f" ({esc(result.setting)})" if result.setting else "")),
                              ("Intent", esc(clip(intent)) if intent else '<span class="muted">unknown</span>')]),
             _outcome_html(result), _goals_html(result)]
    if result.problems:
        parts.append("<h3>Problems</h3><ul>" + "".join(f"<li>{esc(p)}</li>" for p in result.problems) + "</ul>")
    problems: list[str] = []
    trajectory = read_jsonl(episode_dir / "trajectory.jsonl", problems) if episode_dir is not None else []
    steps = step_views(trajectory)
    parts.append(f'<h3 id="{anchor}-steps">Steps ({len(steps)})</h3>')
    if episode_dir is None:
        parts.append('<p class="muted">The episode directory is gone; only the grade is shown.</p>')
    elif not steps:
        parts.append('<p class="muted">No trajectory was recorded.</p>')
    previous_env: str | None = None
    for k, step in enumerate(steps, start=1):
        parts.append(_switch_mark(step, previous_env))
        parts.append(step_html(step, episode_dir or Path("."), f"{anchor}-step-{k}", budget))
        previous_env = step.environment or previous_env
    parts.append("</details></section>")
    return "".join(parts)


def _index_html(report: RunReport) -> str:
    rows = []
    for k, result in enumerate(report.episodes, start=1):
        category = CATEGORIES.get(result.error.category, ("", result.error.category))[1] if result.error else ""
        rows.append(f'<tr><td><a href="#episode-{k}">{esc(result.episode_id)}</a></td>'
                    f"<td>{esc(result.task_id or '?')}</td><td>{esc(result.domain)}</td>"
                    f"<td>{verdict(result.overall_success)}</td><td>{esc(category)}</td><td>{result.steps}</td></tr>")
    return ('<nav aria-labelledby="index-h"><h2 id="index-h">Episodes</h2><table><thead><tr>'
            '<th scope="col">Episode</th><th scope="col">Task</th><th scope="col">Domain</th>'
            '<th scope="col">Outcome</th><th scope="col">Error category</th><th scope="col">Steps</th></tr>'
            f"</thead><tbody>{''.join(rows)}</tbody></table></nav>")


def _summary_html(report: RunReport) -> str:
    parts = ['<section aria-labelledby="summary-h"><h2 id="summary-h">Run summary</h2>']
    for section in [main_table([report]), navigation_table([report]), geolocation_section([report]),
                    *error_tables([report]), demo_table([report])]:
        if isinstance(section, Table):
            parts.append(table_html(section))
        elif isinstance(section, str):
            parts.append(f"<h3>Geolocation</h3><pre>{esc(section)}</pre>")
    if report.problems:
        parts.append("<h3>Problems</h3><ul>" + "".join(f"<li>{esc(p)}</li>" for p in report.problems) + "</ul>")
    return "".join(parts) + "</section>"


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


def render_html(report: RunReport) -> str:
    """The whole page for one graded run, read from report.run_dir for the steps and images."""
    budget = ImageBudget()
    episodes = [episode_html(result, directory, k, budget)
                for k, (result, directory) in enumerate(zip(report.episodes, _episode_directories(report)), start=1)]
    omitted = (f'<p class="note">{budget.omitted} image(s) were not embedded: the page holds at most '
               f"{PAGE_IMAGE_BUDGET_BYTES // 1_000_000} MB of images; they remain in the run directory.</p>"
               if budget.omitted else "")
    generated = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f'<meta http-equiv="Content-Security-Policy" content="{CSP}">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>ewa-grade trajectories: {esc(report.label)}</title><style>{STYLE}</style></head><body>"
        f"<header><h1>Trajectories of run {esc(report.label)}</h1>"
        f'<p class="muted">{esc(report.run_dir)} · {report.n_episodes} episode(s) · generated {generated} by '
        "ewa-grade</p></header><main>"
        f"{_summary_html(report)}{_index_html(report)}{omitted}{''.join(episodes)}</main></body></html>\n"
    )


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
