"""A worker bound to its parent (ewa_mcp/evaluation/lifeline.py) ends, with its children and its staging folder,
even while its main thread cannot run a Python signal handler: the case that left an `eval --workers` worker (and
multiprocessing's resource tracker with it) alive after its driver was SIGKILLed, whenever the kernel handed the
parent-death signal to another thread while the main thread waited on its task queue. No browser needed."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from ewa_mcp.evaluation.lifeline import _alive

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the lifeline is Linux-only")

# The worker: bound to its parent, with a child of its own and a second thread, then its main thread blocks the
# watched signals and waits on a lock nobody releases (as a worker waits on its task queue). A signal can then only
# land on the other thread, where Python runs no handler.
WORKER = r"""
import os, signal, subprocess, sys, threading, time
from pathlib import Path
from ewa_mcp.evaluation.lifeline import bind_to_parent

staging = Path(sys.argv[1])
(staging / "ep-unfinished").mkdir(parents=True)
bind_to_parent(staging, os.getppid())
threading.Thread(target=time.sleep, args=(600,), daemon=True).start()
child = subprocess.Popen(["sleep", "600"])
signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGHUP, signal.SIGINT})
Path(sys.argv[2]).write_text(f"{os.getpid()} {child.pid}")
lock = threading.Lock()
lock.acquire()
lock.acquire()
"""

# The driver: starts the worker and waits.
DRIVER = "import subprocess, sys, time; subprocess.Popen([sys.executable, '-c', *sys.argv[1:]]); time.sleep(600)"


@pytest.mark.parametrize("how", ["driver SIGKILLed", "worker sent SIGTERM"])
def test_a_worker_whose_main_thread_is_blocked_still_dies_with_its_children_and_staging(tmp_path, how):
    staging = tmp_path / ".staging" / "w0"
    ready = tmp_path / "ready"
    driver = subprocess.Popen([sys.executable, "-c", DRIVER, WORKER, str(staging), str(ready)],
                              start_new_session=True)
    pids: list[int] = []
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not (ready.exists() and ready.read_text()):
            assert driver.poll() is None, "the driver ended before its worker was ready"
            time.sleep(0.05)
        pids = [int(p) for p in ready.read_text().split()]
        worker, child = pids
        assert _alive(worker) and _alive(child)

        if how == "driver SIGKILLed":
            os.kill(driver.pid, signal.SIGKILL)
        else:
            os.kill(worker, signal.SIGTERM)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and (_alive(worker) or _alive(child) or staging.parent.exists()):
            time.sleep(0.05)
        assert not _alive(worker), f"the worker outlived ({how}) with its main thread blocked"
        assert not _alive(child), "the worker's child was left behind"
        assert not staging.parent.exists(), "the staging folder was left behind"
    finally:
        for pid in [driver.pid, *pids]:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        driver.wait(timeout=30)
