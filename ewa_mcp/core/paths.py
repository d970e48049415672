"""Where the project's data lives, overridable by settings (``EWA_TASKS_DIR``, ``EWA_RUNS_DIR``: ewa_mcp/settings.py).

Read-only data ships inside the package: the task suites are installed as ``ewa_mcp/tasks`` (from the
repository's ``tasks/``), so an installed ``ewa-mcp`` sees every task from any directory. In a checkout
(or an editable install) the repository's ``tasks/`` is used directly. Nothing is ever written into the
package: runs go under the working directory (``EWA_RUNS_DIR``), generated tasks to ``-o`` or ``./tasks``.

A server started by an MCP client often runs in a directory it cannot write (``/`` on macOS, a read-only
checkout). When no run directory is set (``--run-dir``, ``EWA_RUN_DIR``, ``EWA_RUNS_DIR``) and ``./runs``
cannot be created, runs go to the per-user data directory (``$XDG_DATA_HOME/ewa-mcp/runs``, by default
``~/.local/share/ewa-mcp/runs``). A directory that *is* set and cannot be written is refused with an error
naming the setting: an explicit choice is honoured or reported, never silently replaced.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from ewa_mcp.settings import Settings, SettingsError, load_settings

PACKAGE_DIR = Path(__file__).resolve().parents[1]  # ewa_mcp/
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


def task_dirs(settings: Settings | None = None) -> list[Path]:
    """The task suites to serve: the tasks_dir setting (--tasks-dir, EWA_TASKS_DIR), else the installed
    package's, else the checkout's tasks/."""
    settings = settings or load_settings()
    if settings.tasks_dir:
        return list(settings.tasks_dir)
    if INSTALLED_TASKS.is_dir():
        return [INSTALLED_TASKS]
    return [REPO_ROOT / "tasks"]


def tasks_dir(settings: Settings | None = None) -> Path:
    """The first directory of ``task_dirs`` (callers that serve one suite)."""
    return task_dirs(settings)[0]


def generated_tasks_dir(settings: Settings | None = None) -> Path:
    """Where ``ewa-mcp tasks generate`` writes without ``-o``: the checkout's tasks/, else ./tasks.

    An installed package is read-only: regenerating into site-packages would be lost on upgrade and
    may not even be writable."""
    settings = settings or load_settings()
    if settings.tasks_dir:
        return settings.tasks_dir[0]
    return REPO_ROOT / "tasks" if in_checkout() else Path.cwd() / "tasks"


def user_data_dir() -> Path:
    """The per-user data directory: $XDG_DATA_HOME/ewa-mcp, by default ~/.local/share/ewa-mcp."""
    return Path(os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share") / "ewa-mcp"


def unwritable_reason(path: Path) -> str | None:
    """Why directory ``path`` cannot be created or written, or None when it can. Probed by creating (and
    removing) a temporary directory in ``path`` or in its nearest existing parent: permission bits alone
    do not tell (root passes them, a read-only mount does not), and the probe leaves nothing behind."""
    probe = path
    while not probe.exists():
        if probe.parent == probe:
            return f"no parent of {path} exists"
        probe = probe.parent
    if not probe.is_dir():
        return f"{probe} is not a directory"
    try:
        tempfile.TemporaryDirectory(dir=probe, prefix=".ewa-write-probe-").cleanup()
    except OSError as exc:
        return f"{probe}: {exc.strerror or exc}"
    return None


def runs_dir(settings: Settings | None = None) -> Path:
    """Where new runs are recorded: the runs_dir setting (EWA_RUNS_DIR), else ./runs when it can be written,
    else the per-user data directory's runs/."""
    settings = settings or load_settings()
    if settings.runs_dir:
        return settings.runs_dir
    local = Path.cwd() / "runs"
    return local if unwritable_reason(local) is None else user_data_dir() / "runs"


def check_run_dir(run_dir: Path, settings: Settings) -> None:
    """Raise SettingsError, naming the setting that chose run_dir and the fix, unless run_dir can be written."""
    reason = unwritable_reason(run_dir)
    if reason is None:
        return
    fix = "set --run-dir DIR (or EWA_RUN_DIR=DIR, or EWA_RUNS_DIR=DIR for a folder of runs) to a writable directory"
    if settings.run_dir is not None:
        where = f"the run directory {run_dir} (--run-dir / EWA_RUN_DIR)"
    elif settings.runs_dir is not None:
        where = f"the run directory {run_dir} under EWA_RUNS_DIR={settings.runs_dir}"
    else:
        where = (f"the run directory {run_dir} (./runs is not writable here, so the per-user data directory "
                 "was tried)")
    raise SettingsError(f"episodes cannot be recorded: {where} cannot be created or written ({reason}); {fix}")


def check_task_dirs(dirs: list[Path]) -> None:
    """Raise TaskStoreMissing unless some directory holds at least one task file (cheap: no parsing)."""
    for d in dirs:
        if d.is_dir() and next(d.rglob("*.json"), None) is not None:
            return
    shown = ", ".join(str(d)[:200] for d in dirs) or "(none given)"
    raise TaskStoreMissing(
        f"no task files in {shown}. Point to a task suite with --tasks-dir DIR (or EWA_TASKS_DIR=DIR), "
        "reinstall the package (`pip install --force-reinstall ewa-mcp`, whose wheel ships the suites), "
        "or write them with `ewa-mcp tasks generate -o DIR`")
