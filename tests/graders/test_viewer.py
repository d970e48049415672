"""The trajectory viewer (ewa-grade --html): a run written by the real MCP server core plus a
crashed episode, rendered to one self-contained page, checked as text and in real Chromium."""

from __future__ import annotations

import base64
import io
import json
import os
import re
from pathlib import Path
from typing import Any

import anyio
import pytest
from grading_builders import EpisodeBuilder, kitchen_task
from mcp import Client
from mcp.server.mcpserver import MCPServer
from PIL import Image

from ewa_mcp.core.environment import EnvError, Environment, Observation
from ewa_mcp.graders import RunReport, grade_run
from ewa_mcp.graders.cli import main
from ewa_mcp.graders.viewer import MAX_IMAGE_SIDE, PAGE_IMAGE_BUDGET_BYTES, render_html, write_html
from ewa_mcp.core.response import env_action
from ewa_mcp.server import ServerConfig, build_server

CHROMIUM = Path("/usr/bin/chromium")
LAUNCH_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
               "--disable-background-networking", "--disable-component-update", "--disable-sync"]

# Text an agent or a web page could put into a run; none of it may become markup.
HOSTILE_INTENT = 'Slice a tomato <img id="intent-pwned" src="x">'
HOSTILE_ARG = '<b id="args-pwned">bold</b>'
HOSTILE_MESSAGE = '"><svg id="message-pwned" onload="document.title=1">'
HOSTILE_ANSWER = ('</pre></q><script>document.title="pwned"</script>'
                  '<img id="answer-pwned" src=x onerror="document.body.dataset.pwned=1">')
OUTSIDE_COLOUR = (7, 201, 99)


def png(width: int, height: int, noise: bool = False, colour: tuple[int, int, int] = (40, 90, 200)) -> bytes:
    image = Image.frombytes("RGB", (width, height), os.urandom(width * height * 3)) if noise \
        else Image.new("RGB", (width, height), colour)
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue()


SCREENSHOT = png(320, 200)
CAMERA = png(960, 720, noise=True)  # a kitchen frame far above the viewer's size and byte thresholds


class Pages(Environment):
    """A web environment whose observations carry a screenshot, like the real browser in vision mode."""

    side = "web"
    name = "browser"

    def __init__(self, episode: Any, services: Any):
        self.page = 0

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        self.page = 0

    async def observe(self) -> Observation:
        return Observation(text=f"recipe page {self.page}", images=[SCREENSHOT])

    async def click(self) -> Observation:
        self.page += 1
        return await self.observe()

    async def final_state(self) -> dict[str, Any]:
        return {"url": f"recipes:/page/{self.page}"}


class Camera(Environment):
    """A kitchen that refuses to slice until the agent has approached, and returns a camera frame."""

    side = "embodied"
    name = "kitchen"

    def __init__(self, episode: Any, services: Any):
        self.near = self.sliced = False

    async def reset(self, task: Any, options: dict[str, Any]) -> None:
        self.near = self.sliced = False

    async def observe(self) -> Observation:
        return Observation(text="a counter with a tomato", images=[CAMERA])

    async def approach(self) -> Observation:
        self.near = True
        return await self.observe()

    async def slice(self, target: str) -> Observation:
        if not self.near:
            raise EnvError(f"{target} is out of reach; call cam_approach first")
        self.sliced = True
        return await self.observe()

    async def final_state(self) -> dict[str, Any]:
        tomato = {"objectId": "Tomato|+1.00|+0.90|-1.00", "objectType": "Tomato", "isSliced": self.sliced,
                  "parentReceptacles": []}
        return {"name": "kitchen", "backend": "sim", "scene": "FloorPlan1", "held": None, "objects": [tomato]}


def register(mcp: MCPServer, episodes: Any) -> None:
    @mcp.tool(description="test tool: click a link")
    async def cam_page_click(episode_id: str, target: str):
        return await env_action(episodes, episode_id, "cam_page_click", {"target": target}, "web",
                                lambda env: env.click())

    @mcp.tool(description="test tool: walk up to the counter")
    async def cam_approach(episode_id: str):
        return await env_action(episodes, episode_id, "cam_approach", {}, "embodied",
                                lambda env: env.approach())

    @mcp.tool(description="test tool: slice an object")
    async def cam_slice(episode_id: str, target: str):
        return await env_action(episodes, episode_id, "cam_slice", {"target": target}, "embodied",
                                lambda env: env.slice(target))


def cooking_task(task_id: str) -> dict[str, Any]:
    return {"id": task_id, "domain": "cooking", "intent": HOSTILE_INTENT,
            "start": {"environment": "web", "web": {"start_url": "recipes:/"},
                      "embodied": {"kind": "kitchen", "scene": "FloorPlan1"}},
            "web_goals": [{"kind": "recipe_completed", "recipe_id": "r-1"}],
            "embodied_goals": [{"kind": "object_state", "object_type": "Tomato", "prop": "isSliced"}],
            "answer": {"kind": "text", "must_include": ["done"]}}


async def play(tmp: Path, run: Path) -> None:
    tasks = tmp / "tasks"
    tasks.mkdir()
    (tasks / "t.json").write_text(json.dumps([cooking_task("cook-good"), cooking_task("cook-bad")]))
    mcp, episodes = build_server(ServerConfig(task_dirs=[tasks], run_dir=run,
                                              environments={"kitchen": Camera, "browser": Pages}))
    register(mcp, episodes)
    async with Client(mcp) as client:
        async def call(tool: str, **args: Any) -> Any:
            return await client.call_tool(tool, args)

        r = await call("start_episode", task_id="cook-good")
        ep = r.structured_content["episode_id"]
        for step in (1, 2):
            assert not (await call("cam_page_click", episode_id=ep, target=f"step {step}")).is_error
            episodes.emit_event(ep, {"site": "recipes", "type": "recipe_step", "recipe_id": "r-1", "step": step,
                                     "of": 2})
        await call("switch_environment", episode_id=ep, target="embodied", message=HOSTILE_MESSAGE)
        await call("cam_approach", episode_id=ep)
        await call("cam_slice", episode_id=ep, target="Tomato")
        await call("finish_episode", episode_id=ep, answer="Done.")

        r = await call("start_episode", task_id="cook-bad")
        ep = r.structured_content["episode_id"]
        await call("cam_page_click", episode_id=ep, target=HOSTILE_ARG)
        await call("switch_environment", episode_id=ep, target="embodied", message="cook now")
        for _ in range(2):
            assert (await call("cam_slice", episode_id=ep, target="Tomato")).is_error
        await call("finish_episode", episode_id=ep, answer=HOSTILE_ANSWER)


def crashed_episode(run: Path) -> Path:
    """An episode that died mid-run: odd trajectory lines, unsafe and missing images, a torn last line."""
    (run.parent / "outside.png").write_bytes(png(8, 8, colour=OUTSIDE_COLOUR))
    ep = EpisodeBuilder(run, kitchen_task("cook-crash", embodied_goals=[
        {"kind": "object_state", "object_type": "Tomato", "prop": "isSliced"}]), episode_id="ep-crashed")
    ep.call("page_open", {"url": "recipes:/r-1"})
    names = ep.recorder.save_images(2, [SCREENSHOT])
    ep.recorder.step(index=2, tool="page_look", args={}, ok=True, error=None, duration_ms=3.0, environment="web",
                     observation="a look", counted=True,
                     images=[*names, "../../outside.png", "images/never-written.png"])
    ep.close()
    with open(ep.directory / "trajectory.jsonl", "a", encoding="utf-8") as fh:
        fh.write(json.dumps({"step": "three", "tool": None, "args": "<i>not a dict</i>", "ok": "yes",
                             "images": "images/also-missing.png", "duration_ms": "slow"}) + "\n")
        fh.write('{"step": 4, "tool": "kitchen_sl')
    return ep.directory


def trajectory_tools(episode_dir: Path) -> list[str]:
    """The tools of every complete trajectory line, read independently of the viewer."""
    tools = []
    for line in (episode_dir / "trajectory.jsonl").read_text(encoding="utf-8").splitlines():
        try:
            record = json.loads(line)
        except json.JSONDecodeError:
            continue
        tools.append(record["tool"] if record.get("tool") is not None else "(no tool recorded)")
    return tools


@pytest.fixture(scope="module")
def graded(tmp_path_factory: pytest.TempPathFactory) -> tuple[RunReport, Path, str]:
    tmp = tmp_path_factory.mktemp("viewer")
    run = tmp / "runs" / "model-a"
    anyio.run(play, tmp, run)
    crashed_episode(run)
    report = grade_run(run)
    page = write_html([report], tmp / "viewer")[0]
    return report, page, page.read_text(encoding="utf-8")


def by_task(report: RunReport) -> dict[str | None, Any]:
    return {e.task_id: e for e in report.episodes}


def data_images(page: str) -> list[bytes]:
    return [base64.b64decode(m) for m in re.findall(r'src="data:image/[a-z]+;base64,([A-Za-z0-9+/=]+)"', page)]


# ------------------------------------------------------------------ the page as text
def test_the_fixture_run_has_the_intended_outcomes(graded: tuple[RunReport, Path, str]) -> None:
    report, page_path, _ = graded
    episodes = by_task(report)
    assert episodes["cook-good"].overall_success is True
    assert episodes["cook-bad"].overall_success is False
    assert episodes["cook-bad"].error is not None and episodes["cook-bad"].error.category == "failed_to_reach_object"
    # a trajectory line that breaks the record format makes the crashed episode an invalid record (a failure)
    assert episodes["cook-crash"].overall_success is False and episodes["cook-crash"].status == "incomplete"
    assert episodes["cook-crash"].error is not None and episodes["cook-crash"].error.category == "invalid_record"
    assert page_path.name == "model-a.html"


def test_page_is_self_contained_and_inert(graded: tuple[RunReport, Path, str]) -> None:
    _, _, page = graded
    assert "<script" not in page.lower()  # the hostile answer's script tag arrives escaped
    references = re.findall(r'\b(?:src|href|action|srcset|poster)\s*=\s*"([^"]*)"', page, flags=re.IGNORECASE)
    assert references, "the page should reference its images"
    assert all(ref.startswith(("data:image/", "#")) for ref in references), \
        [r[:40] for r in references if not r.startswith(("data:", "#"))]
    assert "url(" not in page.split("<style>")[1].split("</style>")[0].replace("url(#", "")
    assert 'http-equiv="Content-Security-Policy"' in page and "default-src 'none'; img-src data:;" in page
    for hostile in (HOSTILE_INTENT, HOSTILE_ARG, HOSTILE_MESSAGE, HOSTILE_ANSWER):
        assert hostile not in page
    assert "&lt;script&gt;document.title=&quot;pwned&quot;&lt;/script&gt;" in page


def test_large_images_are_downscaled_small_ones_kept(graded: tuple[RunReport, Path, str]) -> None:
    _, _, page = graded
    embedded = data_images(page)
    assert SCREENSHOT in embedded  # small enough: embedded byte for byte
    camera_frames = [Image.open(io.BytesIO(data)) for data in embedded if data != SCREENSHOT]
    assert camera_frames, "the kitchen frames should be on the page"
    for frame in camera_frames:
        assert max(frame.size) == MAX_IMAGE_SIDE and frame.size[0] / frame.size[1] == pytest.approx(960 / 720)
    assert max(len(d) for d in embedded) < len(CAMERA) / 4
    assert f"960×720, shown at {MAX_IMAGE_SIDE}×{MAX_IMAGE_SIDE * 3 // 4}" in page


def test_unsafe_and_missing_images_are_reported_not_read(graded: tuple[RunReport, Path, str]) -> None:
    _, _, page = graded
    outside = png(8, 8, colour=OUTSIDE_COLOUR)
    assert outside not in data_images(page)
    assert "../../outside.png: outside the episode directory; not read" in page
    assert "images/never-written.png: file missing" in page
    assert "images/also-missing.png: file missing" in page


def test_crashed_episode_renders_as_far_as_the_data_goes(graded: tuple[RunReport, Path, str]) -> None:
    report, _, page = graded
    crashed = page.split("Episode ep-crashed: cook-crash", 1)[1]
    assert "trajectory.jsonl: last line is not complete JSON" in crashed
    assert "final_state.json missing" in crashed
    assert "Steps (3)" in crashed  # two recorded steps and the odd line; the torn one is skipped
    assert "&lt;i&gt;not a dict&lt;/i&gt;" in crashed and "outcome not recorded" in crashed
    assert by_task(report)["cook-crash"].episode_id == "ep-crashed"


def test_page_renders_without_the_run_directory(graded: tuple[RunReport, Path, str]) -> None:
    report, _, _ = graded
    moved = report.model_copy(update={"run_dir": str(Path(report.run_dir) / "gone")})
    page = render_html(moved)
    assert page.count("The episode directory is gone") == 3
    assert "Failed to reach interactable object" in page


# ------------------------------------------------------------------ the CLI
def test_cli_writes_pages_and_keeps_the_table(graded: tuple[RunReport, Path, str], tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    report, _, _ = graded
    run = Path(report.run_dir)
    assert main([str(run), "--html", str(tmp_path / "out")]) == 0
    captured = capsys.readouterr()
    assert "Results by domain" in captured.out
    assert (tmp_path / "out" / "model-a.html").exists() and "html: " in captured.err
    single = tmp_path / "one" / "page.html"
    assert main([str(run), "--format", "json", "--html", str(single)]) == 0
    assert json.loads(capsys.readouterr().out)["label"] == "model-a"
    assert "Trajectories of run model-a" in single.read_text(encoding="utf-8")


def test_cli_compare_writes_one_page_per_run(graded: tuple[RunReport, Path, str], tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    report, _, _ = graded
    run = Path(report.run_dir)
    copies = []
    for parent in ("x", "y"):
        copy = tmp_path / parent / "run"
        copy.mkdir(parents=True)
        for episode in run.iterdir():
            (copy / episode.name).mkdir()
            for item in episode.rglob("*"):
                target = copy / episode.name / item.relative_to(episode)
                target.mkdir(exist_ok=True) if item.is_dir() else target.write_bytes(item.read_bytes())
        copies.append(copy)
    assert main([str(copies[0]), "--compare", str(copies[1]), "--html", str(tmp_path / "pages")]) == 0
    capsys.readouterr()
    assert sorted(p.name for p in (tmp_path / "pages").iterdir()) == ["x_run.html", "y_run.html"]
    assert "Trajectories of run y/run" in (tmp_path / "pages" / "y_run.html").read_text(encoding="utf-8")


def test_cli_refuses_a_bad_out_before_doing_anything(graded: tuple[RunReport, Path, str], tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    report, _, _ = graded
    run = Path(report.run_dir)
    assert main([str(run), "--compare", str(run), "--html", str(tmp_path / "both.html")]) == 2
    captured = capsys.readouterr()
    assert "names one file but 2 runs were given; pass a directory" in captured.err and captured.out == ""
    assert not (tmp_path / "both.html").exists()
    (tmp_path / "notes.txt").write_text("keep me")
    assert main([str(run), "--html", str(tmp_path / "notes.txt")]) == 2
    assert "is an existing file" in capsys.readouterr().err
    assert (tmp_path / "notes.txt").read_text() == "keep me"
    with pytest.raises(SystemExit):
        main(["--help"])
    assert "--html OUT" in capsys.readouterr().out


# ------------------------------------------------------------------ in real Chromium
@pytest.mark.browser
@pytest.mark.skipif(not CHROMIUM.exists(), reason="no Chromium at /usr/bin/chromium (apt-get install chromium)")
def test_viewer_in_chromium(graded: tuple[RunReport, Path, str]) -> None:
    playwright_api = pytest.importorskip("playwright.sync_api")
    report, page_path, _ = graded
    run = Path(report.run_dir)
    with playwright_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=str(CHROMIUM), headless=True, args=LAUNCH_ARGS)
        try:
            page = browser.new_page()
            fetched: list[str] = []
            page.on("request", lambda request: fetched.append(request.url))
            page.goto(page_path.as_uri())
            page.wait_for_load_state("load")
            assert all(url.startswith(("file:", "data:")) for url in fetched), fetched

            for result in report.episodes:
                section = page.get_by_role("region", name=f"Episode {result.episode_id}: {result.task_id}")
                expected = trajectory_tools(run / result.episode_id)
                steps = section.get_by_role("heading", level=4, name=re.compile(r"^Step \S+: "))
                assert steps.count() == len(expected), result.task_id
                assert [re.sub(r"^Step \S+: ", "", t) for t in steps.all_inner_texts()] == expected
                outcome = section.get_by_role("row", name=re.compile("^Overall")).inner_text()
                assert {True: "pass", False: "fail", None: "not gradable"}[result.overall_success] in outcome

            bad = page.get_by_role("region", name=re.compile(": cook-bad$"))
            assert "Failed to reach interactable object" in bad.get_by_role("row", name=re.compile(
                "^Error category")).inner_text()
            good = page.get_by_role("region", name=re.compile(": cook-good$"))
            assert good.get_by_role("note").filter(has_text="Switch web → embodied").count() == 1

            summary = page.get_by_role("region", name="Run summary")
            overall = summary.get_by_role("row", name=re.compile("Overall Accuracy")).first.inner_text()
            assert overall.split()[2] == "33.3"  # 1 of the 3 cooking episodes succeeded

            images = page.get_by_role("img")
            assert images.count() >= 4
            widths = []
            for k in range(images.count()):  # lazy images load once scrolled to, as a reader would
                images.nth(k).scroll_into_view_if_needed()
                widths.append(images.nth(k).evaluate("e => e.decode().then(() => e.naturalWidth, () => 0)"))
            assert all(width > 0 for width in widths), widths
            assert max(widths) == MAX_IMAGE_SIDE

            # Hostile text is shown as text, and none of it became an element or ran.
            for selector in ("#intent-pwned", "#args-pwned", "#message-pwned", "#answer-pwned", "script", "svg"):
                assert page.locator(selector).count() == 0, selector
            assert page.title() == "ewa-grade trajectories: model-a"
            assert page.evaluate("document.body.dataset.pwned") is None
            assert bad.get_by_text(HOSTILE_ANSWER, exact=False).first.is_visible()
            click = bad.get_by_role("article", name=re.compile(r"^Step \S+: cam_page_click$"))
            assert json.loads(click.locator("pre.args").inner_text()) == {"target": HOSTILE_ARG}
            assert HOSTILE_INTENT in bad.get_by_role("row", name=re.compile("^Intent")).inner_text()
        finally:
            browser.close()


@pytest.mark.parametrize("alpha", [255, 128])
def test_downscaling_keeps_transparency_only_where_there_is_some(tmp_path: Path, alpha: int) -> None:
    from ewa_mcp.graders.viewer import ImageBudget, embed_image

    (tmp_path / "images").mkdir()
    palette = Image.new("RGBA", (1000, 500), (10, 200, 30, alpha)).quantize(colors=4)  # a P-mode screenshot
    palette.save(tmp_path / "images" / "shot.png")
    budget = ImageBudget()
    shown = embed_image(tmp_path, "images/shot.png", budget)
    assert shown.data_uri is not None and shown.caption.endswith(f"(1000×500, shown at {MAX_IMAGE_SIDE}×"
                                                                 f"{MAX_IMAGE_SIDE // 2})")
    mime, data = shown.data_uri.removeprefix("data:").split(";base64,")
    image = Image.open(io.BytesIO(base64.b64decode(data)))
    assert image.size == (MAX_IMAGE_SIDE, MAX_IMAGE_SIDE // 2)
    if alpha == 255:
        assert mime == "image/jpeg"
    else:
        assert mime == "image/png" and image.convert("RGBA").getpixel((5, 5))[3] < 255
    assert budget.remaining == PAGE_IMAGE_BUDGET_BYTES - len(base64.b64decode(data))
