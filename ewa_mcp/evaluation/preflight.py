"""Checks made before the first episode of an eval, so a missing piece of infrastructure stops the run with the
message that fixes it instead of failing every episode in turn."""

from __future__ import annotations

from ..core.taskmodel import Task
from .outcomes import EvalError


def check_browser(tasks: list[Task]) -> None:
    """Raise EvalError naming the fix when some task needs a browser and no Chromium can be found here (the
    settings' EWA_CHROMIUM / browser options, Playwright's build, the system's)."""
    needing = sum(1 for t in tasks if "browser" in t.environment_names().values())
    if not needing:
        return
    from ..settings import load_settings
    from ..envs.browser.chromium import ChromiumNotFoundError, find_chromium

    settings = load_settings()
    try:
        find_chromium(settings.chromium_path(), settings.browser.headless)
    except ChromiumNotFoundError as exc:
        raise EvalError(f"{needing} of the {len(tasks)} selected tasks need a browser and none can be started: "
                        f"{exc}. Nothing was played") from None
