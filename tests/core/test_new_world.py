"""docs/extending.md, "Add a world", done literally: a copy of the checkout gets the lamp world
(tests/core/lamp_domain/, whose files are exactly the ones the page lists) as ``ewa_mcp/envs/lamp/``, one line in
``ewa_mcp/envs/__init__.py`` and, once the packaging check names them, its package lines in pyproject.toml, and
nothing else. Then lint, the import contracts and the type checker pass on it, and the copy serves the lamp's
tools, validates its tasks and passes ``check_environment``."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
LAMP = Path(__file__).resolve().parent / "lamp_domain"
BIN = Path(sys.executable).parent

pytestmark = pytest.mark.slow


def documented_files() -> list[str]:
    """The world-files block of docs/extending.md: the files every world package has."""
    text = (ROOT / "docs" / "extending.md").read_text(encoding="utf-8")
    block = text.split("<!-- world-files")[1].split("<!-- /world-files -->")[0]
    lines = block.split("```")[1].strip().splitlines()[1:]  # below the "ewa_mcp/envs/<world>/" line
    return sorted(line.split()[0] for line in lines)


def package_problems(repo: Path) -> list[str]:
    """tests/core/test_packaging.py's check, on another checkout: packages missing from pyproject.toml."""
    config = tomllib.loads((repo / "pyproject.toml").read_text())
    listed = set(config["tool"]["setuptools"]["packages"])
    found = set()
    for name, folder in config["tool"]["setuptools"]["package-dir"].items():
        for init in (repo / folder).rglob("__init__.py"):
            rel = init.parent.relative_to(repo / folder)
            if not any(part.startswith(".") or part == "__pycache__" for part in rel.parts):
                found.add(".".join([name, *rel.parts]))
    return sorted(found - listed)


def run(cmd: list[str], cwd: Path, **env: str) -> subprocess.CompletedProcess:
    environ = {**os.environ, **env}
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600, env=environ)


def test_the_documented_files_are_the_lamp_worlds():
    on_disk = sorted(str(p.relative_to(LAMP)) for p in LAMP.rglob("*") if p.is_file() and "__pycache__" not in p.parts)
    documented = sorted(f.replace("<domain>", "lighting") for f in documented_files())
    assert on_disk == documented


@pytest.fixture(scope="module")
def repo(tmp_path_factory) -> Path:
    """A copy of the checkout's code (no task suites, no site data) with the lamp world added as docs say."""
    out = tmp_path_factory.mktemp("checkout")
    tracked = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=ROOT, capture_output=True,
                             text=True, check=True).stdout.splitlines()
    for name in tracked:
        src = ROOT / name
        if src.suffix in (".py", ".toml", ".pyi", ".typed") or name in ("Makefile",):
            if name.startswith("tests/") or not src.is_file():
                continue
            dst = out / name
            dst.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dst)
    world = out / "ewa_mcp" / "envs" / "lamp"
    shutil.copytree(LAMP, world, ignore=shutil.ignore_patterns("__pycache__"))
    registry_file = out / "ewa_mcp" / "envs" / "__init__.py"
    text = registry_file.read_text()
    assert text.count('    "ewa_mcp.envs.browser:DOMAINS",\n') == 1
    registry_file.write_text(text.replace('    "ewa_mcp.envs.browser:DOMAINS",\n',
                                          '    "ewa_mcp.envs.browser:DOMAINS",\n    "ewa_mcp.envs.lamp:DOMAINS",\n'))
    return out


def test_the_packaging_check_names_the_missing_package_lines_then_passes(repo):
    assert package_problems(repo) == ["ewa_mcp.envs.lamp", "ewa_mcp.envs.lamp.taskgen"]
    pyproject = repo / "pyproject.toml"
    text = pyproject.read_text()
    pyproject.write_text(text.replace('    "ewa_mcp.envs.geo", "ewa_mcp.envs.geo.taskgen",\n',
                                      '    "ewa_mcp.envs.geo", "ewa_mcp.envs.geo.taskgen",\n'
                                      '    "ewa_mcp.envs.lamp", "ewa_mcp.envs.lamp.taskgen",\n'))
    assert package_problems(repo) == []


def test_lint_contracts_and_types_pass_with_no_other_edit(repo):
    ruff = run([str(BIN / "ruff"), "check", "--quiet", "."], repo)
    assert ruff.returncode == 0, ruff.stdout + ruff.stderr
    layout = run([sys.executable, "scripts/installed_layout.py", ".lint"], repo)
    assert layout.returncode == 0, layout.stderr
    contracts = run([str(BIN / "lint-imports"), "--config", "../pyproject.toml", "--no-cache"], repo / ".lint",
                    PYTHONPATH=str(repo / ".lint"))
    assert contracts.returncode == 0, contracts.stdout[-3000:]
    assert "ewa_mcp.envs.lamp" not in contracts.stdout  # no contract broken by the new world
    cache = repo / ".mypy_cache"
    if (ROOT / ".mypy_cache").is_dir():  # a warm cache makes this seconds instead of a minute
        shutil.copytree(ROOT / ".mypy_cache", cache)
    types = run([str(BIN / "mypy"), "--config-file", "../pyproject.toml", "--cache-dir", str(cache), "ewa_mcp"],
                repo / ".lint")
    assert types.returncode == 0, types.stdout[-3000:]


PLAY = r"""
import json, sys
import anyio
from ewa_mcp.core import registry
from ewa_mcp.core.conformance import check_environment
from ewa_mcp.server import build_server, ServerConfig
from ewa_mcp.taskgen import generate_all
from ewa_mcp.core.taskmodel import TaskStore
from pathlib import Path

out = Path(sys.argv[1])
counts = generate_all(out / "tasks", ["lighting"])
store = TaskStore([out / "tasks"])
task = store.all("lighting")[0]

async def main():
    from mcp import Client
    mcp, _ = build_server(ServerConfig(task_dirs=[out / "tasks"], run_dir=out / "run"))
    async with Client(mcp) as client:
        names = [t.name for t in (await client.list_tools()).tools]
    problems = await check_environment(registry.environments()["lamp"], task)
    return names, problems

names, problems = anyio.run(main)
print(json.dumps({"domains": registry.domain_names(), "counts": counts, "tools": names, "problems": problems,
                  "instructions_ok": True}))
"""


def test_the_copy_serves_generates_and_conforms(repo, tmp_path):
    out = run([sys.executable, "-c", PLAY, str(tmp_path)], repo, PYTHONPATH=str(repo),
              EWA_RUNS_DIR=str(tmp_path / "runs"))
    assert out.returncode == 0, out.stderr[-3000:]
    result = json.loads(out.stdout.strip().splitlines()[-1])
    assert result["domains"][-1] == "lighting" and result["counts"] == {"lighting": 2}
    assert "lamp_switch" in result["tools"] and result["problems"] == []
    assert re.search(r"^list_tasks$", "\n".join(result["tools"]), re.M)
