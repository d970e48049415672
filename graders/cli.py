"""ewa-grade: grade run directories written by ewa-mcp.

    ewa-grade RUN_DIR [--format table|json|markdown] [--plots DIR] [--compare RUN_DIR2 ...] [--radius M]
              [--html OUT]

Exit status: 0 graded (even when some episodes were damaged: they are listed), 2 when a RUN_DIR
does not exist or holds no episodes, or an option is invalid.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ewa_mcp.pipes import quiet_on_closed_pipe

from .models import RunReport
from .report import RunDirError, grade_run
from .report_tables import render


def _radius(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--radius takes metres as a number, got {text!r}") from None
    if not value > 0 or value != value or value == float("inf"):
        raise argparse.ArgumentTypeError(f"--radius must be a positive number of metres, got {text!r}")
    return value


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="ewa-grade",
        description="Grade ewa-mcp run directories: per-domain accuracies with 95 % intervals, error analysis, "
                    "plots and run comparisons. Reads only the run directories.",
    )
    parser.add_argument("run_dir", type=Path, help="a run directory (runs/<run_id>) holding episode folders")
    parser.add_argument("--format", choices=("table", "json", "markdown"), default="table",
                        help="output format (default: table)")
    parser.add_argument("--plots", type=Path, metavar="DIR", help="also write PNG plots into DIR")
    parser.add_argument("--compare", type=Path, nargs="+", default=[], metavar="RUN_DIR2",
                        help="more run directories, shown side by side (one column per run)")
    parser.add_argument("--radius", type=_radius, metavar="M",
                        help="arrival radius in metres for every street goal (default: each task's, 25 m)")
    parser.add_argument("--html", type=Path, metavar="OUT",
                        help="also write a self-contained HTML trajectory viewer per run (steps, images, grades): "
                             "OUT is a directory (created if missing) that gets OUT/<run name>.html for each run; "
                             "with a single run, an OUT ending in .html is the page itself")
    return parser


def _labels(paths: list[Path]) -> list[str]:
    """Run directory names, made unique with their parent's name when two runs share one."""
    names = [p.resolve().name for p in paths]
    return [
        f"{p.resolve().parent.name}/{name}" if names.count(name) > 1 else name for p, name in zip(paths, names)
    ]


@quiet_on_closed_pipe
def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    paths = [args.run_dir, *args.compare]
    labels = _labels(paths)
    if args.html is not None:
        from .viewer import ViewerError, output_paths

        try:  # refuse a bad OUT before printing anything
            output_paths(labels, args.html)
        except ViewerError as exc:
            print(f"ewa-grade: {exc}", file=sys.stderr)
            return 2
    reports: list[RunReport] = []
    for path, label in zip(paths, labels):
        try:
            reports.append(grade_run(path, radius_m=args.radius, label=label))
        except RunDirError as exc:
            print(f"ewa-grade: {exc}", file=sys.stderr)
            return 2
    sys.stdout.write(render(reports, args.format))
    if args.plots is not None:
        from .plots import PlotError, write_plots

        try:
            written = write_plots(reports, args.plots)
        except PlotError as exc:
            print(f"ewa-grade: {exc}", file=sys.stderr)
            return 2
        except OSError as exc:
            print(f"ewa-grade: cannot write plots to {args.plots} ({exc}); pass a writable directory",
                  file=sys.stderr)
            return 2
        print("plots: " + ", ".join(str(p) for p in written), file=sys.stderr)
    if args.html is not None:
        from .viewer import write_html

        try:
            pages = write_html(reports, args.html)
        except OSError as exc:
            print(f"ewa-grade: cannot write the HTML viewer to {args.html} ({exc}); pass a writable directory",
                  file=sys.stderr)
            return 2
        print("html: " + ", ".join(str(p) for p in pages), file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
