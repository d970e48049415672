"""A worker process that dies with its driver and takes its whole process tree with it (Linux).

`eval --workers` starts worker processes; each starts a Playwright driver (node), which starts Chromium (in a
process group of its own) and its renderers. When the driver is killed (SIGTERM, or SIGKILL, which no handler
sees), multiprocessing's daemon flag does nothing: the workers, their Playwright drivers and browsers would live
on, and the staging folder with them. So each worker:

* asks the kernel for a signal when its parent dies (``PR_SET_PDEATHSIG``: SIGTERM), and checks it was not
  orphaned before asking;
* becomes a child subreaper (``PR_SET_CHILD_SUBREAPER``), so that a grandchild whose parent dies (Chromium after
  its node driver) is re-parented to the worker, not to init, and is still found among its descendants;
* on SIGTERM, SIGHUP or SIGINT kills every descendant (SIGKILL, until none is left) and exits at once (no
  interpreter shutdown that could wait on a stuck episode thread); a helper forked at that moment deletes its
  staging folder, and the run's ``.staging`` folder once it is empty, as soon as the worker is gone;
* does that from a watchdog thread, never from a Python signal handler. Python runs handlers in the main thread
  alone, and only once it executes bytecode again; the kernel may hand the signal to any thread, and a main
  thread blocked in a semaphore wait (the worker waiting on its task queue) is then never interrupted, so a
  handler never ran and the worker outlived its driver (with it, multiprocessing's resource tracker, which waits
  for every holder of its pipe). The watchdog reads the signal numbers the C-level handler writes to the wakeup
  fd, whichever thread received them, and also sees the parent go by polling ``getppid``. It is the only path
  that ends the worker: a second signal arriving while a handler was ending it (inside its fork) deadlocked.

Elsewhere than Linux the worker keeps the default handlers (the driver's own cleanup still runs on SIGTERM).
"""

from __future__ import annotations

import ctypes
import os
import shutil
import select
import signal
import sys
import threading
import time
from pathlib import Path
from typing import Any

PR_SET_PDEATHSIG = 1
PR_SET_CHILD_SUBREAPER = 36


def _prctl(option: int, value: int) -> bool:
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return int(libc.prctl(option, value, 0, 0, 0)) == 0
    except (OSError, AttributeError):
        return False


def children_map() -> dict[int, list[int]]:
    """parent pid -> child pids, from /proc (empty where there is no /proc)."""
    tree: dict[int, list[int]] = {}
    try:
        entries = os.listdir("/proc")
    except OSError:
        return tree
    for entry in entries:
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="utf-8", errors="replace") as f:
                stat = f.read()
        except OSError:
            continue
        # The command name (field 2) may hold spaces and parentheses: the parent pid follows its last ')'.
        fields = stat[stat.rfind(")") + 2:].split()
        if len(fields) > 1:
            tree.setdefault(int(fields[1]), []).append(int(entry))
    return tree


def descendants(root: int) -> list[int]:
    """Every process below ``root`` (not ``root`` itself)."""
    tree = children_map()
    found: list[int] = []
    todo = list(tree.get(root, []))
    while todo:
        pid = todo.pop()
        found.append(pid)
        todo.extend(tree.get(pid, []))
    return found


def kill_descendants(rounds: int = 50) -> None:
    """SIGKILL every descendant of this process, again while new ones appear (a browser starting a renderer)."""
    me = os.getpid()
    for _ in range(rounds):
        pids = descendants(me)
        if not pids:
            return
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        # Reap what are now our (subreaper) children, so that /proc no longer lists them.
        deadline = time.monotonic() + 1.0
        while time.monotonic() < deadline:
            try:
                pid, _ = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                break
            if pid == 0:
                if not any(os.path.exists(f"/proc/{p}") and _alive(p) for p in pids):
                    break
                time.sleep(0.01)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", encoding="utf-8", errors="replace") as f:
            state = f.read().rsplit(")", 1)[-1].split()[0]
    except (OSError, IndexError):
        return False
    return state not in ("Z", "X")


def remove_staging(staging: Path) -> None:
    shutil.rmtree(staging, ignore_errors=True)
    try:
        staging.parent.rmdir()  # the run's .staging folder, once the last worker's folder is gone
    except OSError:
        pass


def bind_to_parent(staging: Path, parent_pid: int) -> None:
    """Make this worker die with its parent and leave nothing behind (see the module docstring). Called from
    the worker's main thread, before it starts any other thread."""
    if not sys.platform.startswith("linux"):
        return

    def die(signum: int) -> None:
        # The episodes under way fail as their browser goes: their tracebacks would bury the driver's one line.
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), 2)
        except OSError:
            pass
        kill_descendants()
        # The worker's episode threads may still write into the staging folder (an episode failing as its browser
        # went, the agent starting the next) until the process ends, and only os._exit stops them. So a forked
        # helper, which has none of those threads, removes the folder once this process is gone, then exits.
        worker = os.getpid()
        try:
            helper = os.fork()
        except OSError:
            helper = -1
        if helper == 0:
            deadline = time.monotonic() + 10
            while os.getppid() == worker and time.monotonic() < deadline:
                time.sleep(0.005)
            remove_staging(staging)
            os._exit(0)
        if helper < 0:
            remove_staging(staging)
        os._exit(128 + signum)

    # The watchdog alone ends the worker, once: the Python-level handlers only keep these signals from killing
    # the process outright (their C-level half writes the signal's number to the wakeup fd, from whichever thread
    # the kernel chose). Ending the worker from a handler too raced with the watchdog, and a second signal ran
    # the handler again inside the first one's fork.
    wake_r, wake_w = os.pipe()
    os.set_blocking(wake_w, False)
    signal.set_wakeup_fd(wake_w, warn_on_full_buffer=False)
    for sig in WATCHED:
        signal.signal(sig, _noted)
    _prctl(PR_SET_CHILD_SUBREAPER, 1)
    _prctl(PR_SET_PDEATHSIG, int(signal.SIGTERM))
    # Its first look at the parent also catches a parent that died before the death signal was asked for.
    threading.Thread(target=_watch, args=(wake_r, parent_pid, die), name="ewa-lifeline", daemon=True).start()


WATCHED = (signal.SIGTERM, signal.SIGHUP, signal.SIGINT)


def _noted(_signum: int, _frame: Any) -> None:
    """The Python-level handler of the watched signals: nothing to do, the watchdog thread acts on them."""


def _watch(wake_fd: int, parent_pid: int, die: Any, interval: float = 0.1) -> None:
    """The watchdog thread: ends the worker on a watched signal (its number read from the wakeup fd) or when
    the parent is gone, whatever the main thread is blocked in."""
    watched = {int(s) for s in WATCHED}
    while True:
        if os.getppid() != parent_pid:
            die(int(signal.SIGTERM))
        try:
            ready, _, _ = select.select([wake_fd], [], [], interval)
            received = os.read(wake_fd, 64) if ready else b""
        except OSError:
            received = b""
        for signum in received:
            if signum in watched:
                die(signum)
