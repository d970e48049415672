"""Playing one (possibly altered) task through the real server and grading it from its run directory."""

from __future__ import annotations

import json
from pathlib import Path

import anyio

from ewa_mcp.core.taskmodel import Task
from ewa_mcp.evaluation.agents import OracleAgent
from ewa_mcp.evaluation.runner import run_eval
from ewa_mcp.graders import grade_run


def play(task: Task, tmp_path: Path, name: str) -> bool:
    """Play ``task``'s oracle (altered or not) and say whether the episode succeeded overall."""
    folder = tmp_path / name / "tasks" / task.domain
    folder.mkdir(parents=True)
    (folder / "t.json").write_text(json.dumps([task.model_dump(mode="json")]), "utf-8")
    run = tmp_path / name / "run"
    anyio.run(lambda: run_eval([task], OracleAgent(), run_dir=run, task_dirs=[folder.parent], workers=1,
                               progress=False))
    (episode,) = grade_run(run).episodes
    return episode.overall_success
