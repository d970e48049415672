"""The trajectory viewer on real runs of every domain in every observation mode: the oracle plays one task of
each domain through the real MCP server (real browser, kitchen, streets, geolocation views), the run is graded
and rendered, and the page is loaded in headless Chromium, which must raise no page error."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import anyio
import pytest
from mcp import Client

from ewa_mcp.evaluation.agents import OracleAgent, Session
from ewa_mcp.evaluation.runner import select_tasks
from ewa_mcp.graders import RunReport, grade_run
from ewa_mcp.graders.cli import main
from ewa_mcp.core.paths import tasks_dir
from ewa_mcp.server import ServerConfig, build_server
from ewa_mcp.core.taskmodel import TaskStore

CHROMIUM = Path("/usr/bin/chromium")
LAUNCH_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
               "--disable-background-networking", "--disable-component-update", "--disable-sync"]
MODES = ("text", "vision", "both")

pytestmark = [pytest.mark.browser, pytest.mark.slow,
              pytest.mark.skipif(not CHROMIUM.exists(), reason="no Chromium at /usr/bin/chromium "
                                 "(apt-get install chromium)")]


async def play_every_domain(run: Path) -> list[tuple[str, str, str]]:
    """(task id, domain, mode) of each episode played: one task per scored domain and the demo, per mode."""
    tasks = select_tasks(TaskStore([tasks_dir()]), None, 1)
    mcp, _ = build_server(ServerConfig(task_dirs=[tasks_dir()], run_dir=run))
    played = []
    async with Client(mcp) as client:
        for mode in MODES:
            for task in tasks:
                start = await client.call_tool("start_episode", {"task_id": task.id,
                                                                 "options": {"observation": mode}})
                assert not start.is_error, start.content
                session = Session(client=client, task=task, episode_id=start.structured_content["episode_id"],
                                  start=start)
                await OracleAgent().play(session)
                played.append((task.id, task.domain, mode))
    return played


@pytest.fixture(scope="module")
def run(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[tuple[str, str, str]]]:
    run = tmp_path_factory.mktemp("every-domain") / "all-modes"
    played = anyio.run(play_every_domain, run)
    return run, played


def test_the_run_covers_every_domain_and_mode(run: tuple[Path, list[tuple[str, str, str]]]) -> None:
    _, played = run
    domains = {domain for _, domain, _ in played}
    assert {"cooking", "navigation", "shopping", "traveling", "geolocation"} <= domains
    assert {(d, m) for _, d, m in played} == {(d, m) for d in domains for m in MODES}


def test_every_domain_renders_and_loads_without_a_page_error(run: tuple[Path, list[tuple[str, str, str]]],
                                                            tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    playwright_api = pytest.importorskip("playwright.sync_api")
    run_dir, played = run
    # Through the command line, as a user runs it: the geolocation summary is a text section of the page.
    assert main([str(run_dir), "--html", str(tmp_path / "pages")]) == 0
    assert "html: " in capsys.readouterr().err
    page_path = tmp_path / "pages" / f"{run_dir.name}.html"
    report: RunReport = grade_run(run_dir)
    assert report.n_episodes == len(played)
    with playwright_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=str(CHROMIUM), headless=True, args=LAUNCH_ARGS)
        try:
            page = browser.new_page()
            errors: list[Any] = []
            page.on("pageerror", lambda error: errors.append(error))
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.goto(page_path.as_uri())
            page.wait_for_load_state("load")
            summary = page.get_by_role("region", name="Run summary")
            assert summary.get_by_role("heading", name="Geolocation").count() == 1
            for result in report.episodes:
                section = page.get_by_role("region", name=f"Episode {result.episode_id}: {result.task_id}")
                assert section.count() == 1, result.task_id
                steps = section.get_by_role("heading", level=4, name=re.compile(r"^Step \S+: "))
                assert steps.count() == result.calls, result.task_id
            # Every embedded picture decodes (lazy ones are made eager: a reader would scroll to them).
            widths = page.evaluate("""() => Promise.all([...document.images].map(img => {
                img.loading = "eager"; return img.decode().then(() => img.naturalWidth, () => 0); }))""")
            assert widths and all(width > 0 for width in widths), widths  # screenshots, frames, views
            assert errors == []
        finally:
            browser.close()
