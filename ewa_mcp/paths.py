"""Where the project's data lives, overridable by environment variables."""

from __future__ import annotations

import os
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
# In a checkout (or editable install) the repository root holds tasks/; EWA_TASKS_DIR overrides.
REPO_ROOT = PACKAGE_DIR.parent


def tasks_dir() -> Path:
    return Path(os.environ.get("EWA_TASKS_DIR", REPO_ROOT / "tasks"))


def runs_dir() -> Path:
    return Path(os.environ.get("EWA_RUNS_DIR", Path.cwd() / "runs"))
