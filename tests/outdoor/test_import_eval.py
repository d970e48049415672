"""An imported release environment is a full task: the oracle solves it and a no-op agent fails it,
through the real eval runner (MCP server, Chromium, map site, street walk) and the grader."""

from __future__ import annotations

import shutil

import anyio
import pytest

from ewa_mcp.evaluation.agents import NoopAgent, OracleAgent
from ewa_mcp.evaluation.runner import run_eval
from ewa_mcp.graders import grade_run
from ewa_mcp.envs.street import world as world_module
from ewa_mcp.envs.street.taskgen import release
from ewa_mcp.core.taskmodel import TaskStore

from . import release_fixtures as fx

pytestmark = pytest.mark.skipif(not (shutil.which("chromium") or shutil.which("chromium-browser")),
                                reason="no Chromium: apt-get install chromium")


def test_oracle_solves_an_imported_task_and_noop_fails_it(tmp_path, monkeypatch):
    out = tmp_path / "imported"
    release.import_file(fx.write_release(tmp_path / "src", annotations=True), out)
    # the server adds out/streets to the world; restore the process-wide world afterwards
    monkeypatch.setenv(world_module.EXTRA_DATA_ENV, "")
    monkeypatch.setattr(world_module, "_world", None)
    tasks = TaskStore([out]).all()
    assert [t.id for t in tasks] == ["nav-import-navi-env-test-000"]
    for agent, expect in ((OracleAgent(), True), (NoopAgent(), False)):
        run = tmp_path / agent.name
        summary = anyio.run(lambda: run_eval(tasks, agent, run_dir=run, task_dirs=[out], progress=False))
        assert not [o for o in summary.outcomes if o.failure]
        (episode,) = grade_run(run).episodes
        assert episode.overall_success is expect, (agent.name, [(c.description, c.met, c.note)
                                                                for c in episode.conditions])
        if expect:
            assert all(c.met for c in episode.conditions) and episode.navigation[0].exact_node
