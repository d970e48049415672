"""`uvx --from <the built wheel> ewa-mcp ...` works as the README's one-line install does: uv makes its own tool
environment from the wheel, outside the checkout, and the `ewa-mcp` command there answers `--version`, lists every
task and serves MCP over stdio (initialize, tools, a prompt per domain), the form the client snippets use.

Offline and cheap: uv installs the wheel alone (``--offline --no-index``; each of the wheel's dependencies is
overridden by a requirement whose marker never holds), and the tool environment borrows this environment's
installed dependencies through PYTHONPATH. Resolving the dependencies from PyPI is not exercised here (it needs
the network); the wheel, its console script, its package data and uv's handling of it are."""

from __future__ import annotations

import email.parser
import json
import os
import shutil
import site
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

import pytest
from packaging.requirements import Requirement

from ewa_mcp.core.paths import REPO_ROOT, in_checkout

pytestmark = pytest.mark.slow


def _uvx() -> str:
    found = Path(sys.executable).with_name("uvx")
    if found.exists():
        return str(found)
    which = shutil.which("uvx")
    if which is None:
        pytest.skip("no uvx: install the test extra (pip install -c requirements.lock -e '.[test]'), which has uv")
    return which


@pytest.fixture(scope="module")
def uvx_from_wheel(tmp_path_factory) -> tuple[list[str], dict[str, str]]:
    """The command prefix that runs a command of the wheel's tool environment, and the environment to run it in."""
    if not in_checkout():
        pytest.skip("builds the wheel from a checkout")
    root = tmp_path_factory.mktemp("uvx")
    built = subprocess.run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(root / "dist"),
                            str(REPO_ROOT)], capture_output=True, text=True, timeout=300)
    assert built.returncode == 0, built.stderr[-2000:]
    [wheel] = (root / "dist").glob("ewa_mcp-*.whl")
    with zipfile.ZipFile(wheel) as z:
        [meta] = [n for n in z.namelist() if n.endswith(".dist-info/METADATA")]
        metadata = email.parser.Parser().parsestr(z.read(meta).decode("utf-8"))
    needed = sorted({Requirement(r).name for r in metadata.get_all("Requires-Dist") or []
                     if Requirement(r).marker is None})
    assert "mcp" in needed and "playwright" in needed
    (root / "overrides.txt").write_text("".join(f"{name}; sys_platform == 'never'\n" for name in needed))
    env = {k: v for k, v in os.environ.items() if not k.startswith(("EWA_", "UV_")) and k != "VIRTUAL_ENV"}
    env |= {"PYTHONPATH": os.pathsep.join(site.getsitepackages()), "UV_CACHE_DIR": str(root / "uv-cache"),
            "UV_TOOL_DIR": str(root / "uv-tools"), "UV_PYTHON_DOWNLOADS": "never"}
    prefix = [_uvx(), "--offline", "--no-index", "--python", sys.executable,
              "--overrides", str(root / "overrides.txt"), "--from", str(wheel)]
    return prefix, env


def _run(cmd: list[str], env: dict[str, str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, env=env, cwd=cwd, capture_output=True, text=True, timeout=300)


def test_uvx_from_the_wheel_runs_ewa_mcp_from_its_own_environment(uvx_from_wheel, tmp_path):
    prefix, env = uvx_from_wheel
    version = tomllib.loads((REPO_ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]
    shown = _run([*prefix, "ewa-mcp", "--version"], env, tmp_path)
    assert shown.returncode == 0, shown.stderr[-2000:]
    assert shown.stdout.split() == ["ewa-mcp", version]
    where = _run([*prefix, "python", "-c", "import ewa_mcp.core.paths as p; print(p.__file__); print(p.tasks_dir())"],
                 env, tmp_path)
    assert where.returncode == 0, where.stderr[-2000:]
    module, tasks = where.stdout.split()
    assert module.startswith(env["UV_CACHE_DIR"]), module  # uv's environment, not the checkout or this venv
    assert tasks.startswith(env["UV_CACHE_DIR"]), tasks  # the task suites shipped in the wheel
    listed = _run([*prefix, "ewa-mcp", "tasks", "list"], env, tmp_path)
    assert listed.returncode == 0, listed.stderr[-2000:]
    assert len(listed.stdout.splitlines()) > 1000
    assert {line.split("\t")[1] for line in listed.stdout.splitlines()} >= {
        "cooking", "navigation", "shopping", "traveling", "geolocation"}


def test_uvx_from_the_wheel_serves_mcp_over_stdio(uvx_from_wheel, tmp_path):
    prefix, env = uvx_from_wheel
    script = r'''
import asyncio, json, os, sys
from mcp import Client, StdioServerParameters

async def main():
    # The whole environment: the SDK passes a server only a few variables unless told otherwise.
    params = StdioServerParameters(command=sys.argv[1], args=[*sys.argv[2:], "ewa-mcp", "serve"], env=dict(os.environ))
    async with Client(params) as client:
        tools = [t.name for t in (await client.list_tools()).tools]
        prompts = [p.name for p in (await client.list_prompts()).prompts]
        started = await client.call_tool("start_episode", {"task_id": "geo-0001-baseline"})
        episode = ("error: " + started.content[0].text) if started.is_error else started.structured_content["episode_id"]
    print(json.dumps({"tools": tools, "prompts": prompts, "episode": episode}))

asyncio.run(main())
'''
    served = _run([sys.executable, "-c", script, *prefix], env | {"EWA_RUNS_DIR": str(tmp_path / "runs")}, tmp_path)
    assert served.returncode == 0, served.stderr[-3000:]
    got = json.loads(served.stdout.strip().splitlines()[-1])
    assert {"start_episode", "finish_episode", "browser_click", "geo_look"} <= set(got["tools"])
    assert {"cooking", "navigation", "shopping", "traveling", "geolocation"} <= set(got["prompts"])
    assert got["episode"].startswith("ep-"), got["episode"]
    assert any(p.name.startswith("ep-") for p in (tmp_path / "runs").rglob("*") if p.is_dir()), \
        "the episode was not recorded in EWA_RUNS_DIR"
