"""The built wheel works as a new user installs it: in a fresh virtual environment, from a directory
outside the checkout, `ewa-mcp` sees every task, plays one, and Inspect finds the ewa_mcp tasks.

To stay cheap the wheel is installed with --no-deps into a venv that borrows this environment's
installed dependencies (a .pth line: the checkout's editable finder is not activated by it, so only the
wheel's ewa_mcp can be imported)."""

from __future__ import annotations

import os
import site
import subprocess
import sys
from pathlib import Path

import pytest

from ewa_mcp.paths import REPO_ROOT, in_checkout

pytestmark = pytest.mark.slow


def _run(cmd: list[str], cwd: Path, **kw) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EWA_")}
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=300, **kw)


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
    return venv


def test_installed_command_sees_every_task_and_plays_one(venv, tmp_path):
    where = _run([str(venv / "bin" / "python"), "-c", "import ewa_mcp.paths as p; print(p.tasks_dir()); "
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
