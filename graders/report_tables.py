"""Rendering reports: a text or Markdown table shaped like the paper's Tables 1–2 (domains × metrics,
one column per run), the error breakdown, navigation and geolocation extras, and JSON."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from .aggregate import GEO_LEVELS
from .answers import geo_module
from .compare import comparisons
from .errors import CATEGORIES, GROUP_LABELS
from .models import DomainAggregate, MeanEstimate, Proportion, RunReport

MAIN_METRICS = (
    ("overall_accuracy", "Overall Accuracy"),
    ("completion_rate", "Overall Completion Rate"),
    ("web_only_accuracy", "Web-only Accuracy"),
    ("embodied_only_accuracy", "Embodied-only Accuracy"),
    ("answer_accuracy", "Answer Accuracy"),
)
PROBLEMS_SHOWN = 10


@dataclass
class Table:
    title: str
    headers: list[str]
    rows: list[list[str]]
    note: str | None = None


def pct(estimate: Proportion | MeanEstimate | None, with_ci: bool = True) -> str:
    if estimate is None or estimate.value is None:
        return "n/a"
    text = f"{100 * estimate.value:.1f}"
    if with_ci:
        text += f" [{100 * estimate.ci_low:.1f}, {100 * estimate.ci_high:.1f}]"
    return text


def _episodes_cell(agg: DomainAggregate | None) -> str:
    if agg is None:
        return "-"
    if agg.n_ungradable:
        return f"{agg.n} ({agg.n_ungradable} not gradable*)"
    return str(agg.n)


def _all_domains(reports: list[RunReport]) -> list[str]:
    seen: list[str] = []
    for report in reports:
        seen.extend(d for d in report.domains if d not in seen)
    return seen


def difference(first: Proportion | MeanEstimate | None, other: Proportion | MeanEstimate | None) -> str:
    """other minus first, in percentage points ("-" when either is unknown)."""
    if first is None or other is None or first.value is None or other.value is None:
        return "-"
    return f"{100 * (other.value - first.value):+.1f}"


def difference_headers(reports: list[RunReport]) -> list[str]:
    return [f"Δ {r.label} − {reports[0].label}" for r in reports[1:]]


def main_table(reports: list[RunReport]) -> Table:
    rows: list[list[str]] = []
    gaps = [""] * (len(reports) - 1)  # the difference columns of rows that have none
    for domain in _all_domains(reports):
        aggs = [r.domains.get(domain) for r in reports]
        rows.append([domain, "Episodes", *(_episodes_cell(a) for a in aggs), *gaps])
        if any(r.infrastructure.get(domain) for r in reports):
            rows.append(["", "Not scored: infrastructure failures",
                         *(str(r.infrastructure.get(domain, 0)) for r in reports), *gaps])
        for key, label in MAIN_METRICS:
            values = [getattr(a, key) if a is not None else None for a in aggs]
            if key == "answer_accuracy" and all(v is None for v in values):
                continue
            rows.append(["", label, *(pct(v) if a is not None else "-" for a, v in zip(aggs, values)),
                         *(difference(values[0], v) for v in values[1:])])
    note = ("Percent with 95 % intervals: Wilson for accuracies, Student's t for the completion mean. "
            "n/a: no task of the domain has goals of that side.")
    if len(reports) > 1:
        note += (" Δ: the run's value minus the first run's, in percentage points, over each run's own episodes "
                 "(the paired comparison below uses only the tasks both runs played).")
    if any(a.n_ungradable for r in reports for a in r.domains.values()):
        note += " *Episodes that could not be graded count as failures (see the problems list)."
    if any(r.infrastructure for r in reports):
        note += (" Infrastructure failures (the server shut down, a worker died, no browser) are not the agent's: "
                 "they are left out of the episodes and every metric; resume the run to play them.")
    return Table("Results by domain", ["Domain", "Metric", *(r.label for r in reports), *difference_headers(reports)],
                 rows, note)


def p_text(p: float) -> str:
    return "<0.001" if p < 0.001 else f"{p:.3f}"


def paired_table(reports: list[RunReport]) -> Table | None:
    """The paired comparison of each run with the first over the tasks both played (graders/compare.py)."""
    if len(reports) < 2:
        return None
    rows = []
    for c in comparisons(reports, _all_domains(reports)):
        rows.append([c.domain, f"{c.other} vs {c.baseline}", str(c.shared_tasks), str(c.both_pass),
                     str(c.only_baseline), str(c.only_other), str(c.neither),
                     f"{100 * c.difference:+.1f}" if c.difference is not None else "-",
                     p_text(c.p_value) if c.shared_tasks else "-"])
    note = ("Overall success on the tasks both runs played (by task id; episodes cut off by infrastructure left "
            "out). Δ: the compared run's accuracy minus the first run's, in percentage points. p: McNemar's exact "
            "test (two-sided) of no difference, from the tasks only one of the two runs passed.")
    duplicates = sum(c.duplicates for c in comparisons(reports, []) if c.domain == "all")
    if duplicates:
        note += f" {duplicates} task(s) were played more than once in a run; each is paired by its first episode."
    return Table("Paired comparison over shared tasks (McNemar's exact test)",
                 ["Domain", "Runs", "Shared tasks", "Both pass", "Only first run", "Only compared run", "Neither",
                  "Δ accuracy", "p"], rows, note)


def difficulty_table(reports: list[RunReport]) -> Table | None:
    """Overall accuracy and completion per domain and difficulty (tasks record easy / medium / hard)."""
    rows: list[list[str]] = []
    for domain in _all_domains(reports):
        levels = [lv for lv in ("easy", "medium", "hard") if any(lv in r.by_difficulty.get(domain, {}) for r in reports)]
        for level in levels:
            aggs = [r.by_difficulty.get(domain, {}).get(level) for r in reports]
            rows.append([domain, level, *(f"{pct(a.overall_accuracy, False)} / {pct(a.completion_rate, False)} "
                                          f"(n={a.n})" if a is not None else "-" for a in aggs)])
    if not rows:
        return None
    return Table("By difficulty: overall accuracy / completion", ["Domain", "Difficulty", *(r.label for r in reports)],
                 rows, "Percent of the episodes of that domain and difficulty.")


def navigation_table(reports: list[RunReport]) -> Table | None:
    rows: list[list[str]] = []
    for domain in _all_domains(reports):
        navs = [r.domains[domain].navigation if domain in r.domains else None for r in reports]
        if all(n is None for n in navs):
            continue
        rows.append([domain, "Stopped within radius", *(pct(n.success_within_radius) if n else "-" for n in navs)])
        rows.append(["", "Stopped at the exact node", *(pct(n.exact_node) if n else "-" for n in navs)])
        rows.append(["", "Mean distance to goal (m)", *(
            f"{n.mean_distance_to_goal_m:.1f}" if n and n.mean_distance_to_goal_m is not None else "-" for n in navs)])
        rows.append(["", "Mean SPL", *(
            f"{n.mean_spl:.3f} (n={n.spl_n})" if n and n.mean_spl is not None else "-" for n in navs)])
    if not rows:
        return None
    radii = {r.radius_m for r in reports}
    radius = "each task's radius (25 m default)" if radii == {None} else ", ".join(
        f"{r:g} m" if r is not None else "task radius" for r in radii)
    return Table(f"Street navigation (radius: {radius})", ["Domain", "Metric", *(r.label for r in reports)], rows)


def error_tables(reports: list[RunReport]) -> list[Table]:
    tables: list[Table] = []
    for domain in ["all", *_all_domains(reports)]:
        breakdowns = [r.errors.get(domain) for r in reports]
        if all(b is None or b.failures == 0 for b in breakdowns):
            continue
        rows = [["Failed episodes", *(str(b.failures) if b else "-" for b in breakdowns)]]
        for group, group_label in GROUP_LABELS.items():
            keys = [k for k, (g, _) in CATEGORIES.items() if g == group]
            if all(not b or (b.by_group.get(group, 0) == 0) for b in breakdowns):
                continue
            rows.append([group_label, *(f"{b.percent_by_group[group]:.1f}" if b else "-" for b in breakdowns)])
            for key in keys:
                if all(not b or b.by_category.get(key, 0) == 0 for b in breakdowns):
                    continue
                rows.append([f"  {CATEGORIES[key][1]}", *(
                    f"{b.percent_by_category[key]:.1f}" if b else "-" for b in breakdowns)])
        title = "Error analysis, all domains" if domain == "all" else f"Error analysis, {domain}"
        tables.append(Table(title + " (% of failed episodes)", ["Category", *(r.label for r in reports)], rows))
    return tables


def geolocation_section(reports: list[RunReport]) -> Table | str | None:
    aggs = {r.label: r.domains["geolocation"].geolocation for r in reports
            if "geolocation" in r.domains and r.domains["geolocation"].geolocation is not None}
    if not aggs:
        return None
    if all(a.get("source") != "fallback" for a in aggs.values()):
        module, _ = geo_module()
        if module is not None and hasattr(module, "render_geolocation_table"):
            try:
                return str(module.render_geolocation_table(aggs))
            except Exception as exc:
                return f"(geolocation table unavailable: render_geolocation_table raised {type(exc).__name__}: {exc})"
    rows: list[list[str]] = []
    settings = sorted({s for a in aggs.values() for s in (a.get("by_setting") or {})})
    for setting in settings:
        for level in GEO_LEVELS:
            cells = []
            for label in aggs:
                value = ((aggs[label].get("by_setting") or {}).get(setting) or {}).get(level)
                cells.append(pct(Proportion(**value)) if isinstance(value, dict) else "-")
            rows.append([setting if level == GEO_LEVELS[0] else "", level, *cells])
    return Table("Geolocation accuracy by level", ["Setting", "Level", *aggs], rows)


def demo_table(reports: list[RunReport]) -> Table | None:
    if all(r.demo is None for r in reports):
        return None
    rows = [["Episodes", *(_episodes_cell(r.demo) for r in reports)],
            ["Overall Accuracy", *(pct(r.demo.overall_accuracy) if r.demo else "-" for r in reports)]]
    return Table("Demo tasks (not part of the benchmark)", ["Metric", *(r.label for r in reports)], rows)


def infrastructure_lines(reports: list[RunReport]) -> list[str]:
    lines: list[str] = []
    for r in reports:
        if not r.infrastructure_failures:
            continue
        lines.append(f"{r.label}: {len(r.infrastructure_failures)} episode(s) not scored; first "
                     f"{min(PROBLEMS_SHOWN, len(r.infrastructure_failures))}:")
        lines.extend(f"  - {p}" for p in r.infrastructure_failures[:PROBLEMS_SHOWN])
    return lines


def problems_lines(reports: list[RunReport]) -> list[str]:
    lines: list[str] = []
    for r in reports:
        if not r.problems:
            continue
        affected = sum(1 for e in r.episodes if e.problems)
        lines.append(f"{r.label}: {affected} episode(s) with problems; first {min(PROBLEMS_SHOWN, len(r.problems))}:")
        lines.extend(f"  - {p}" for p in r.problems[:PROBLEMS_SHOWN])
    return lines


# ------------------------------------------------------------------ formatting
def _text_table(table: Table) -> str:
    widths = [max(len(row[i]) for row in [table.headers, *table.rows]) for i in range(len(table.headers))]

    def line(cells: list[str]) -> str:
        return "  ".join(c.ljust(w) for c, w in zip(cells, widths)).rstrip()

    out = [table.title, "=" * len(table.title), line(table.headers), line(["-" * w for w in widths])]
    out += [line(row) for row in table.rows]
    if table.note:
        out.append(table.note)
    return "\n".join(out)


def _markdown_table(table: Table) -> str:
    def esc(cell: str) -> str:
        return cell.replace("|", "\\|")

    out = [f"### {table.title}", "", "| " + " | ".join(esc(h) for h in table.headers) + " |",
           "|" + "|".join("---" for _ in table.headers) + "|"]
    out += ["| " + " | ".join(esc(c) if c else " " for c in row) + " |" for row in table.rows]
    if table.note:
        out += ["", table.note]
    return "\n".join(out)


def render(reports: list[RunReport], fmt: str) -> str:
    """The report(s) as "table" (plain text), "markdown" or "json"."""
    if fmt == "json":
        payload: Any = reports[0].model_dump(mode="json") if len(reports) == 1 else {
            "runs": [r.model_dump(mode="json") for r in reports],
            "comparisons": [c.model_dump(mode="json") for c in comparisons(reports, _all_domains(reports))]}
        return json.dumps(payload, indent=2, ensure_ascii=False)
    if fmt not in ("table", "markdown"):
        raise ValueError(f"unknown format {fmt!r}; use table, markdown or json")
    as_text = _text_table if fmt == "table" else _markdown_table
    parts: list[str] = []
    heading = "Runs: " + ", ".join(f"{r.label} ({r.run_dir}, {r.n_episodes} episodes)" for r in reports)
    parts.append(heading if fmt == "table" else f"## ewa-grade report\n\n{heading}")
    sections: list[Table | str | None] = [main_table(reports), paired_table(reports), difficulty_table(reports),
                                          navigation_table(reports),
                                          geolocation_section(reports), *error_tables(reports), demo_table(reports)]
    for section in sections:
        if section is None:
            continue
        parts.append(as_text(section) if isinstance(section, Table) else
                     (section if fmt == "table" else f"### Geolocation\n\n{section}"))
    infrastructure = infrastructure_lines(reports)
    if infrastructure:
        title = "Infrastructure failures (not scored)"
        parts.append((f"{title}\n{'=' * len(title)}\n" if fmt == "table" else f"### {title}\n\n")
                     + "\n".join(infrastructure))
    problems = problems_lines(reports)
    if problems:
        parts.append(("Problems\n========\n" if fmt == "table" else "### Problems\n\n") + "\n".join(problems))
    return "\n\n".join(parts) + "\n"


def render_report(report: RunReport | list[RunReport], fmt: str = "table") -> str:
    """One report or several side by side; the entry point the eval runner prints after a run."""
    return render(report if isinstance(report, list) else [report], fmt)
