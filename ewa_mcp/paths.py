"""Where the project's data lives, overridable by environment variables.

Read-only data ships inside the package: the task suites are installed as ``ewa_mcp/tasks`` (from the
repository's ``tasks/``), so an installed ``ewa-mcp`` sees every task from any directory. In a checkout
(or an editable install) the repository's ``tasks/`` is used directly. Nothing is ever written into the
package: runs go under the working directory (``EWA_RUNS_DIR``), generated tasks to ``-o`` or ``./tasks``.
"""

from __future__ import annotations

import os
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
# The checkout's root when running from one; in an installed wheel this is site-packages (never written).
REPO_ROOT = PACKAGE_DIR.parent
# The task suites inside an installed wheel (setuptools maps the repository's tasks/ there).
INSTALLED_TASKS = PACKAGE_DIR / "tasks"


class TaskStoreMissing(RuntimeError):
    """No task suite where one was expected; the message names the fix."""


def in_checkout() -> bool:
    """True when running from the source tree (plain or editable install), not from an installed wheel."""
    pyproject = REPO_ROOT / "pyproject.toml"
    return pyproject.is_file() and 'name = "ewa-mcp"' in pyproject.read_text(encoding="utf-8", errors="replace")


def tasks_dir() -> Path:
    """The task suites to serve: EWA_TASKS_DIR, else the installed package's, else the checkout's tasks/."""
    if os.environ.get("EWA_TASKS_DIR"):
        return Path(os.environ["EWA_TASKS_DIR"])
    if INSTALLED_TASKS.is_dir():
        return INSTALLED_TASKS
    return REPO_ROOT / "tasks"


def generated_tasks_dir() -> Path:
    """Where ``ewa-mcp tasks generate`` writes without ``-o``: the checkout's tasks/, else ./tasks.

    An installed package is read-only: regenerating into site-packages would be lost on upgrade and
    may not even be writable."""
    if os.environ.get("EWA_TASKS_DIR"):
        return Path(os.environ["EWA_TASKS_DIR"])
    return REPO_ROOT / "tasks" if in_checkout() else Path.cwd() / "tasks"


def runs_dir() -> Path:
    return Path(os.environ.get("EWA_RUNS_DIR", Path.cwd() / "runs"))


def check_task_dirs(dirs: list[Path]) -> None:
    """Raise TaskStoreMissing unless some directory holds at least one task file (cheap: no parsing)."""
    for d in dirs:
        if d.is_dir() and next(d.rglob("*.json"), None) is not None:
            return
    shown = ", ".join(str(d)[:200] for d in dirs) or "(none given)"
    raise TaskStoreMissing(
        f"no task files in {shown}. Point to a task suite with --tasks DIR (or EWA_TASKS_DIR=DIR), "
        "reinstall the package (`pip install --force-reinstall ewa-mcp`, whose wheel ships the suites), "
        "or write them with `ewa-mcp tasks generate -o DIR`")
