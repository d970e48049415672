"""The built wheel works as a new user installs it: in a fresh virtual environment, from a directory
outside the checkout, `ewa-mcp` sees every task, plays one, Inspect finds the ewa_mcp tasks, `inspect eval
ewa_mcp/navigation --model mockllm/model --limit 2` runs offline and writes a scored log, and `inspect view`
serves that log's episodes.

To stay cheap the wheel is installed with --no-deps into a venv that borrows this environment's
installed dependencies (a .pth line: the checkout's editable finder is not activated by it, so only the
wheel's ewa_mcp can be imported)."""

from __future__ import annotations

import json
import os
import site
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path

import pytest

from ewa_mcp.core.paths import REPO_ROOT, in_checkout

pytestmark = pytest.mark.slow


# Nothing listens on port 9 of loopback: any HTTPS download (tiktoken's encoding files, for one) fails at
# once, on a machine with network too. The harness's own traffic (MCP, the local websites) is plain HTTP.
OFFLINE = {"HTTPS_PROXY": "http://127.0.0.1:9", "https_proxy": "http://127.0.0.1:9"}


def _env(extra: dict[str, str] | None = None) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EWA_")}
    return env | (extra or {})


def _run(cmd: list[str], cwd: Path, env: dict[str, str] | None = None, **kw) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, env=_env(env), capture_output=True, text=True, timeout=300, **kw)


@pytest.fixture(scope="module")
def venv(tmp_path_factory) -> Path:
    if not in_checkout():
        pytest.skip("builds the wheel from a checkout")
    root = tmp_path_factory.mktemp("wheel")
    built = _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(root / "dist"),
                  str(REPO_ROOT)], cwd=root)
    assert built.returncode == 0, built.stderr[-2000:]
    [wheel] = (root / "dist").glob("ewa_mcp-*.whl")
    venv = root / "venv"
    made = _run([sys.executable, "-m", "venv", "--without-pip", str(venv)], cwd=root)
    assert made.returncode == 0, made.stderr
    [target] = venv.glob("lib/python*/site-packages")
    (target / "borrowed-deps.pth").write_text("\n".join(site.getsitepackages()) + "\n")
    installed = _run([sys.executable, "-m", "pip", "--python", str(venv / "bin" / "python"), "install", "-q",
                      "--no-deps", str(wheel)], cwd=root)
    assert installed.returncode == 0, installed.stderr[-2000:]
    # The `inspect` command as pip writes it for inspect-ai (borrowed above, so not installed in this venv).
    (venv / "bin" / "inspect").write_text(f"#!{venv / 'bin' / 'python'}\nimport sys\n"
                                          "from inspect_ai._cli.main import main\nsys.exit(main())\n")
    (venv / "bin" / "inspect").chmod(0o755)
    return venv


def test_installed_command_sees_every_task_and_plays_one(venv, tmp_path):
    where = _run([str(venv / "bin" / "python"), "-c", "import ewa_mcp.core.paths as p; print(p.tasks_dir()); "
                  "print(p.generated_tasks_dir())"], cwd=tmp_path)
    tasks_dir, generated = where.stdout.split()
    assert str(venv) in tasks_dir, where  # the wheel's own suites, not the checkout's
    assert generated == str(tmp_path / "tasks")  # never site-packages
    listed = _run([str(venv / "bin" / "ewa-mcp"), "tasks", "list"], cwd=tmp_path)
    assert listed.returncode == 0, listed.stderr
    domains = {line.split("\t")[1] for line in listed.stdout.splitlines()}
    assert {"cooking", "navigation", "shopping", "traveling", "geolocation"} <= domains
    assert len(listed.stdout.splitlines()) > 1000
    played = _run([str(venv / "bin" / "ewa-mcp"), "eval", "--agent", "oracle", "--domain", "geolocation",
                   "--sample", "1", "--format", "json", "-q"], cwd=tmp_path)
    assert played.returncode == 0, played.stderr[-2000:]
    assert len(list((tmp_path / "runs").glob("*/*/final_state.json"))) == 1  # recorded under the cwd
    # The same command into that run directory resumes it: the task already played is not played again.
    run_dir = next((tmp_path / "runs").glob("*/*/final_state.json")).parent.parent
    again = _run([str(venv / "bin" / "ewa-mcp"), "eval", "--agent", "oracle", "--domain", "geolocation",
                  "--sample", "1", "--run-dir", str(run_dir), "--format", "json", "-q"], cwd=tmp_path)
    assert again.returncode == 0, again.stderr[-2000:]
    assert len(list(run_dir.glob("*/final_state.json"))) == 1


def test_missing_task_store_is_an_error_naming_the_fix(venv, tmp_path):
    env_dir = tmp_path / "empty"
    env_dir.mkdir()
    for args in (["tasks", "list"], ["eval", "--agent", "noop"], ["serve"]):
        out = _run([str(venv / "bin" / "ewa-mcp"), *args, "--tasks" if args[0] != "eval" else "--tasks-dir",
                    str(env_dir)], cwd=tmp_path, stdin=subprocess.DEVNULL)
        assert out.returncode == 2, (args, out.stderr)
        assert "no task files" in out.stderr and "EWA_TASKS_DIR" in out.stderr, out.stderr


def test_inspect_finds_the_installed_tasks(venv, tmp_path):
    pytest.importorskip("inspect_ai")
    script = ("from inspect_ai._util.registry import registry_lookup, registry_find, registry_info\n"
              "from inspect_ai._util.entrypoints import ensure_entry_points\n"
              "ensure_entry_points()\n"
              "names = sorted(registry_info(t).name for t in registry_find(lambda i: i.type == 'task'))\n"
              "print(' '.join(names))\n")
    found = _run([str(venv / "bin" / "python"), "-c", script], cwd=tmp_path)
    assert found.returncode == 0, found.stderr[-2000:]
    names = set(found.stdout.split())
    assert {"ewa_mcp/cooking", "ewa_mcp/navigation", "ewa_mcp/suite", "ewa_mcp/geolocation"} <= names, names


@pytest.fixture(scope="module")
def inspect_eval_dir(venv, tmp_path_factory) -> Path:
    """The "done when" command of the Inspect tasks, as written, from a directory outside the checkout,
    with no HTTPS reachable; its log lands in ./logs, its episodes in ./runs."""
    pytest.importorskip("inspect_ai")
    cwd = tmp_path_factory.mktemp("inspect-eval")
    out = _run([str(venv / "bin" / "inspect"), "eval", "ewa_mcp/navigation", "--model", "mockllm/model",
                "--limit", "2"], cwd=cwd, env=OFFLINE, stdin=subprocess.DEVNULL)
    assert out.returncode == 0, (out.stdout[-2000:], out.stderr[-3000:])
    return cwd


@pytest.mark.browser
def test_inspect_eval_with_a_mock_model_runs_offline_and_scores_zero(inspect_eval_dir):
    from inspect_ai.log import read_eval_log

    [log_file] = (inspect_eval_dir / "logs").glob("*.eval")
    log = read_eval_log(str(log_file))
    assert log.status == "success", log.error
    assert log.eval.task == "ewa_mcp/navigation"
    assert [str(s.id).split("-")[0] for s in log.samples] == ["navigation", "navigation"]
    for sample in log.samples:  # mockllm's default output only talks: every episode fails
        score = sample.scores["ewa_grader"]
        assert score.value["overall"] == 0.0 and score.value["completion"] == 0.0, score
        assert "conditions met" in score.explanation
    metrics = log.results.scores[0].metrics
    assert metrics["overall"].value == 0.0 and metrics["completion"].value == 0.0
    # Both episodes were recorded under the working directory, not site-packages.
    assert len(list((inspect_eval_dir / "runs").glob("inspect-*/*/final_state.json"))) == 2


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _get_json(url: str) -> object:
    with urllib.request.urlopen(url, timeout=10) as answer:
        return json.loads(answer.read())


@pytest.mark.browser
def test_inspect_view_serves_the_episodes(venv, inspect_eval_dir):
    """`inspect view` over that log: its API (what the viewer's pages read) lists the log and serves every
    sample with its messages and the grader's score."""
    port = _free_port()
    view = subprocess.Popen([str(venv / "bin" / "inspect"), "view", "--log-dir", "logs", "--port", str(port)],
                            cwd=inspect_eval_dir, env=_env(OFFLINE), stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        base = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 120
        while True:
            try:
                listing = _get_json(base + "/api/logs")
                break
            except (urllib.error.URLError, ConnectionError):
                assert view.poll() is None, view.stderr.read()[-2000:]
                assert time.monotonic() < deadline, "inspect view did not answer in 120 s"
                time.sleep(0.3)
        [entry] = listing["files"]
        assert entry["task"] == "navigation"
        log = _get_json(base + "/api/logs/" + urllib.parse.quote(entry["name"], safe=""))
        assert log["status"] == "success"
        samples = log["samples"]
        assert len(samples) == 2
        for sample in samples:
            assert sample["id"].startswith("navigation-")
            assert sample["scores"]["ewa_grader"]["value"]["overall"] == 0.0
            roles = [m["role"] for m in sample["messages"]]
            assert roles[:2] == ["system", "user"] and "assistant" in roles
            assert "Task id: " + sample["id"] in json.dumps(sample["messages"][1]["content"])
        with urllib.request.urlopen(base + "/", timeout=10) as page:  # the viewer's own page
            assert page.status == 200 and b"<html" in page.read().lower()
    finally:
        view.terminate()
        try:
            view.wait(timeout=20)
        except subprocess.TimeoutExpired:
            view.kill()


def test_the_installed_server_offers_a_prompt_per_domain_and_ships_its_fonts(venv, tmp_path):
    """What `uvx ewa-mcp serve` runs (the wheel's `ewa-mcp serve`, outside the checkout): its MCP prompts carry the
    agent instructions of each domain, and the sign fonts come from the wheel, not the system."""
    script = r'''
import asyncio, json, sys
from mcp import Client, StdioServerParameters

async def main():
    params = StdioServerParameters(command=sys.argv[1], args=["serve"])
    async with Client(params) as client:
        prompts = {p.name: [a.name for a in p.arguments or []] for p in (await client.list_prompts()).prompts}
        cooking = (await client.get_prompt("cooking", {"task_id": "cooking-cook-0001"})).messages[0].content.text
        geo = (await client.get_prompt("geolocation", {})).messages[0].content.text
    print(json.dumps({"prompts": prompts, "cooking": cooking, "geo": geo}))

asyncio.run(main())
'''
    out = _run([str(venv / "bin" / "python"), "-c", script, str(venv / "bin" / "ewa-mcp")], cwd=tmp_path,
               env={"EWA_RUNS_DIR": str(tmp_path / "runs")})
    assert out.returncode == 0, out.stderr[-2000:]
    got = json.loads(out.stdout.strip().splitlines()[-1])
    assert {"cooking", "navigation", "shopping", "traveling", "geolocation"} <= set(got["prompts"])
    assert all(args == ["task_id"] for args in got["prompts"].values())
    assert 'start_episode(task_id="cooking-cook-0001")' in got["cooking"] and "kitchen_* tools" in got["cooking"]
    assert "switch_environment" in got["cooking"] and "submit_location" in got["geo"]
    fonts = _run([str(venv / "bin" / "python"), "-c", "from ewa_mcp.street_drawing import fonts; "
                  "print(fonts.font_file('japanese')[0]); print(fonts.font_file('thai')[0])"], cwd=tmp_path)
    assert fonts.returncode == 0, fonts.stderr[-2000:]
    for path in fonts.stdout.split():
        assert path.startswith(str(venv)) and "street_drawing/fonts/" in path, path
