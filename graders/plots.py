"""PNG plots of one or more runs. matplotlib is imported here only, so grading never needs it."""

from __future__ import annotations

from pathlib import Path

from .errors import CATEGORIES
from .models import RunReport
from .report_tables import MAIN_METRICS, _all_domains


class PlotError(RuntimeError):
    """Plots were asked for but cannot be drawn; the message says how to fix it."""


def _pyplot():
    try:
        import matplotlib
    except ImportError as exc:
        raise PlotError("--plots needs matplotlib: pip install 'ewa-mcp[plots]'") from exc
    matplotlib.use("Agg")  # files only; never open a window
    import matplotlib.pyplot as plt

    return plt


def plot_metrics(reports: list[RunReport], path: Path) -> Path:
    """Grouped bars: for each domain the four paper metrics, one bar per run, with 95 % interval whiskers."""
    plt = _pyplot()
    domains = _all_domains(reports)
    metrics = [(k, label) for k, label in MAIN_METRICS if k != "answer_accuracy"]
    fig, axes = plt.subplots(1, len(metrics), figsize=(4.2 * len(metrics), 4.2), sharey=True, squeeze=False)
    width = 0.8 / max(1, len(reports))
    for ax, (key, label) in zip(axes[0], metrics):
        for i, report in enumerate(reports):
            xs, heights, low, high = [], [], [], []
            for j, domain in enumerate(domains):
                agg = report.domains.get(domain)
                estimate = getattr(agg, key) if agg is not None else None
                if estimate is None or estimate.value is None:
                    continue
                xs.append(j + (i - (len(reports) - 1) / 2) * width)
                heights.append(100 * estimate.value)
                low.append(100 * (estimate.value - estimate.ci_low))
                high.append(100 * (estimate.ci_high - estimate.value))
            ax.bar(xs, heights, width, yerr=[low, high], capsize=2, label=report.label)
        ax.set_title(label)
        ax.set_xticks(range(len(domains)), domains, rotation=30, ha="right")
        ax.set_ylim(0, 100)
        ax.grid(axis="y", alpha=0.3)
    axes[0][0].set_ylabel("%")
    axes[0][-1].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_errors(reports: list[RunReport], path: Path, domain: str = "all") -> Path | None:
    """Horizontal bars: share of failed episodes per error category, one bar per run."""
    breakdowns = [(r.label, r.errors.get(domain)) for r in reports]
    if all(b is None or b.failures == 0 for _, b in breakdowns):
        return None
    plt = _pyplot()
    keys = [k for k in CATEGORIES if any(b and b.by_category.get(k, 0) for _, b in breakdowns)]
    fig, ax = plt.subplots(figsize=(8, 0.45 * len(keys) * max(1, len(reports)) + 1.5))
    height = 0.8 / max(1, len(reports))
    for i, (label, breakdown) in enumerate(breakdowns):
        values = [breakdown.percent_by_category.get(k, 0.0) if breakdown else 0.0 for k in keys]
        ys = [j + (i - (len(reports) - 1) / 2) * height for j in range(len(keys))]
        ax.barh(ys, values, height, label=label)
    ax.set_yticks(range(len(keys)), [f"{CATEGORIES[k][1]} ({CATEGORIES[k][0].replace('_', '-')})" for k in keys])
    ax.invert_yaxis()
    ax.set_xlabel("% of failed episodes")
    ax.set_title(f"Error analysis ({domain})")
    ax.legend(fontsize="small")
    ax.grid(axis="x", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def write_plots(reports: list[RunReport], directory: Path) -> list[Path]:
    directory.mkdir(parents=True, exist_ok=True)
    written = [plot_metrics(reports, directory / "metrics_by_domain.png")]
    for domain in ["all", *_all_domains(reports)]:
        path = plot_errors(reports, directory / f"errors_{domain}.png", domain)
        if path is not None:
            written.append(path)
    return written
