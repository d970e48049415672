"""`ewa-mcp eval --workers` killed with SIGTERM or SIGKILL leaves nothing behind: no worker, no Playwright
driver, no Chromium, no `.staging/` folder (ewa_mcp/evaluation/lifeline.py)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from ewa_mcp.evaluation.lifeline import _alive, descendants
from ewa_mcp.evaluation.workers import STAGING

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = [pytest.mark.browser, pytest.mark.skipif(not sys.platform.startswith("linux"),
                                                      reason="the process tree is read from /proc"), pytest.mark.slow]


@pytest.fixture(scope="module")
def chromium_path() -> str:
    from ewa_mcp.envs.browser.chromium import ChromiumNotFoundError, find_chromium

    try:
        return find_chromium().path
    except ChromiumNotFoundError as exc:
        pytest.skip(f"no Chromium on this machine: {exc}")


def _comm(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/comm", encoding="utf-8") as f:
            return f.read().strip()
    except OSError:
        return "?"


def _describe(pid: int) -> str:
    """The command line and parent of a process, to tell which part of the tree outlived the driver."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            cmdline = f.read().replace(b"\0", b" ").decode(errors="replace").strip()
        with open(f"/proc/{pid}/stat", encoding="utf-8", errors="replace") as f:
            ppid = f.read().rsplit(")", 1)[-1].split()[1]
    except (OSError, IndexError):
        return _comm(pid)
    return f"(parent {ppid}) {cmdline[:300]}"


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["SIGTERM", "SIGKILL"])
def test_a_killed_eval_leaves_no_process_and_no_staging(tmp_path, chromium_path, sig):
    run = tmp_path / "run"
    driver = subprocess.Popen(
        [sys.executable, "-m", "ewa_mcp", "eval", "--agent", "oracle", "--domain", "navigation", "--sample", "6",
         "--workers", "2", "--run-dir", str(run), "-q"],
        env={**os.environ, "EWA_RUNS_DIR": str(tmp_path / "runs"), "EWA_CHROMIUM": chromium_path},
        stderr=subprocess.PIPE, text=True, start_new_session=True)
    tree: list[int] = []
    try:
        # Until both workers' browsers are up and episodes are being recorded into the staging folder.
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline and driver.poll() is None:
            tree = descendants(driver.pid)
            browsers = [p for p in tree if _comm(p).startswith("chrom")]
            drivers = [p for p in tree if _comm(p).startswith("node")]
            if len(drivers) >= 2 and len(browsers) >= 4 and (run / STAGING).is_dir():
                break
            time.sleep(0.2)
        else:
            pytest.fail(f"the eval did not get its browsers up: {driver.stderr.read() if driver.poll() else ''}")
        tree = descendants(driver.pid)
        assert {_comm(p)[:4] for p in tree} >= {"pyth", "node", "chro"}

        os.kill(driver.pid, sig)
        driver.wait(timeout=60)
        deadline = time.monotonic() + 60
        # (the staging folder goes a moment after its worker: lifeline.py's helper removes it)
        while time.monotonic() < deadline and (any(_alive(p) for p in tree) or (run / STAGING).exists()):
            time.sleep(0.1)
        left = [f"{p} {_describe(p)}" for p in tree if _alive(p)]
        assert left == [], f"left behind after {sig.name}: {left}"
        assert not (run / STAGING).exists()
        for episode in run.glob("ep-*"):  # only whole, accepted episodes (eval.json beside them names the agent)
            assert (episode / "final_state.json").is_file(), episode
        err = driver.stderr.read()
        assert "Traceback" not in err, err[-3000:]
        if sig == signal.SIGTERM:
            assert driver.returncode == 128 + signal.SIGTERM
            assert "eval: stopped by SIGTERM" in err
    finally:
        for pid in [driver.pid, *tree]:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        driver.wait(timeout=30)
