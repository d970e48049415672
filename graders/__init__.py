"""Graders: read a run directory (never the live server) and score it.

    from ewa_mcp.graders import grade_run, grade_episode
    report = grade_run("runs/20260101-120000-abc123")      # RunReport
    result = grade_episode("runs/20260101-120000-abc123/ep-0123456789ab")  # EpisodeResult
    print(render_report(report, fmt="table"))                # or "markdown", "json"

The rules are documented in docs/grading.md.
"""

from __future__ import annotations

from .episode import grade_episode
from .models import DomainAggregate, EpisodeResult, ErrorBreakdown, RunReport
from .report_tables import render_report
from .report import RunDirError, grade_run

__all__ = ["DomainAggregate", "EpisodeResult", "ErrorBreakdown", "RunDirError", "RunReport", "grade_episode",
           "grade_run", "render_report"]
