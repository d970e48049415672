"""`ewa-mcp eval --workers N`: episodes spread over N processes, each with its own server, browser and sites.

One process drives: it hands tasks to the workers (`concurrency` playing and one waiting each), collects their
outcomes and owns the run directory. A worker's server records into a staging folder of its own
(`<run>/.staging/w<k>/`); when the driver accepts an episode's outcome it renames the episode's folder into the
run directory (an atomic move on one file system). So the run directory only ever holds episodes the driver
accepted, each once: if a worker dies, its unfinished episodes are deleted from its staging folder and played
again by another worker (a new one is started in its place).

Nothing outlives the driver (lifeline.py): a SIGTERM or SIGHUP to the driver stops the run (``EvalInterrupted``)
after its workers are stopped and the staging folder removed; each worker dies with the driver even when the
driver is SIGKILLed (the kernel's parent-death signal), killing its Playwright driver, browser and renderers and
removing its staging folder first.

Each worker reports on a pipe of its own, never on a queue shared with the others: a process that dies in the
middle of a write (os._exit, SIGKILL, the OOM killer) can leave a shared queue's write lock held forever, and
every other worker, and so the whole run, would hang behind it. A torn pipe only ends its own worker's reports.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import pickle
import shutil
import signal
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from multiprocessing.connection import Connection, wait
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from ewa_mcp.core.taskmodel import Task
from .ledger import Ledger
from .outcomes import EpisodeOutcome, EvalError, EvalSummary, Progress

STAGING = ".staging"


class RecordStop(Exception):
    """A worker's episode record could not be written: the run stops (play() reports it in one line)."""


class EvalInterrupted(Exception):
    """The driver was asked to stop by a signal; its workers are stopped and nothing is left behind."""

    def __init__(self, signum: int):
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


def check_picklable(agent: Any, where: str) -> bytes:
    try:
        return pickle.dumps(agent)
    except Exception as exc:
        raise EvalError(f"agent {getattr(agent, 'name', type(agent).__name__)!r} cannot be sent to {where} "
                        f"({type(exc).__name__}: {str(exc)[:200]}); give it picklable parts (a module-level "
                        "class or functools.partial instead of a lambda or a local function), or run it in "
                        "this process (--workers 1)") from exc


class _Reports:
    """A worker's end of its pipe to the driver; its episode threads take turns to write."""

    def __init__(self, conn: Connection):
        self.conn = conn
        self.lock = threading.Lock()

    def put(self, message: tuple) -> None:
        with self.lock:
            self.conn.send(message)


def _worker_main(wid: int, agent_blob: bytes, transport: str, task_dirs: list[Path], staging: Path,
                 concurrency: int, inbox: Any, report_end: Connection, parent_pid: int | None = None) -> None:
    """A worker process: one episode player, up to `concurrency` episodes at once, until it gets None."""
    import logging

    outbox = _Reports(report_end)

    from .lifeline import bind_to_parent
    from .player import EpisodePlayer

    if parent_pid is not None:
        bind_to_parent(staging, parent_pid)  # before any browser or driver is started
    # A tool error is part of the episode's record; the SDK's INFO line for each would interleave N streams.
    logging.basicConfig(level=logging.WARNING, stream=sys.stderr)
    try:
        agent = pickle.loads(agent_blob)
        player = EpisodePlayer(agent, transport=transport, task_dirs=task_dirs, run_dir=staging)
    except BaseException as exc:  # noqa: BLE001 - reported to the driver, which stops the run
        outbox.put(("fatal", wid, f"{type(exc).__name__}: {str(exc)[:500]}"))
        return
    outbox.put(("ready", wid))

    def run(slot: int, task: Task) -> None:
        try:
            outcome = player.play(task, on_start=lambda episode_id: outbox.put(("start", wid, slot, episode_id)))
        except BaseException as exc:  # noqa: BLE001 - the driver must hear about every slot it handed out
            outcome = EpisodeOutcome(task_id=task.id, domain=task.domain, episode_id=None,
                                     failure=f"{type(exc).__name__}: {str(exc)[:300]}")
        outbox.put(("done", wid, slot, asdict(outcome)))

    try:
        with ThreadPoolExecutor(max_workers=concurrency, thread_name_prefix=f"ewa-w{wid}") as pool:
            while (item := inbox.get()) is not None:
                pool.submit(run, *item)
    finally:
        player.close()  # aborts (and records) whatever is still running


@dataclass
class _Worker:
    wid: int
    process: Any
    inbox: Any
    reports: Connection  # the driver's (reading) end of the worker's pipe
    staging: Path
    ready: bool = False
    stopping: bool = False
    # Accepted episodes whose record is still open (an agent broke off mid-episode): moved once the
    # worker has stopped and its server has recorded their end.
    deferred: list[str] = field(default_factory=list)


class _Driver:
    def __init__(self, tasks: list[Task], agent: Any, *, workers: int, concurrency: int, run_dir: Path,
                 task_dirs: list[Path], transport: str, progress: bool, max_attempts: int = 3):
        self.tasks, self.run_dir, self.task_dirs, self.transport = tasks, run_dir, task_dirs, transport
        self.size, self.concurrency = workers, max(1, concurrency)
        self.agent_blob = check_picklable(agent, "worker processes")
        self.ctx = mp.get_context("spawn")  # a fork of a process with threads (the sites, Playwright) is unsafe
        self.ledger = Ledger(tasks, max_attempts=max_attempts)
        self.workers: dict[int, _Worker] = {}
        self.started = 0
        self.replacements_left = 2 * workers
        self.summary = EvalSummary(run_dir=run_dir, agent=agent.name, transport=transport)
        self.bar = Progress(len(tasks), progress)
        self.staging_root = run_dir / STAGING

    # ------------------------------------------------------------ workers
    def spawn(self) -> None:
        wid = self.started
        self.started += 1
        staging = self.staging_root / f"w{wid}"
        inbox = self.ctx.Queue()
        reports, report_end = self.ctx.Pipe(duplex=False)
        process = self.ctx.Process(target=_worker_main, name=f"ewa-eval-w{wid}", daemon=True,
                                   args=(wid, self.agent_blob, self.transport, self.task_dirs, staging,
                                         self.concurrency, inbox, report_end, os.getpid()))
        process.start()
        report_end.close()  # the worker holds the only writing end: its death reads as the end of the pipe
        self.workers[wid] = _Worker(wid, process, inbox, reports, staging)

    def feed(self, worker: _Worker) -> None:
        # One task more than the worker plays at once waits in its queue, so a worker that finishes an episode
        # starts the next at once instead of waiting for the driver to be scheduled and answer.
        while worker.ready and not worker.stopping and self.ledger.held(worker.wid) < self.concurrency + 1:
            slot = self.ledger.take(worker.wid)
            if slot is None:
                return
            worker.inbox.put((slot, self.tasks[slot]))

    def record(self, outcome: EpisodeOutcome) -> None:
        self.summary.outcomes.append(outcome)
        self.bar.tick(outcome)

    # ------------------------------------------------------------ messages
    def handle(self, message: tuple) -> None:
        kind, wid = message[0], message[1]
        worker = self.workers.get(wid)
        if worker is None:  # from a worker already declared lost
            return
        if kind == "ready":
            worker.ready = True
            for w in self.workers.values():
                self.feed(w)
        elif kind == "fatal":
            raise EvalError(f"an eval worker could not start: {message[2]}")
        elif kind == "done":
            slot, outcome = message[2], EpisodeOutcome(**message[3])
            if outcome.record_problem is not None:  # a full disk: every episode after it would fail the same way
                self.summary.record_problem = outcome.record_problem
                raise RecordStop()
            if self.ledger.finish(wid, slot, outcome):
                self.land(worker, outcome)
                self.record(outcome)
            elif outcome.episode_id:
                shutil.rmtree(worker.staging / outcome.episode_id, ignore_errors=True)
            self.feed(worker)
        # "start" needs nothing: a lost worker's staging folder is deleted whole.

    def land(self, worker: _Worker, outcome: EpisodeOutcome) -> None:
        if not outcome.episode_id:
            return
        source = worker.staging / outcome.episode_id
        if (source / "final_state.json").exists():
            os.rename(source, self.run_dir / outcome.episode_id)
        elif source.exists():
            worker.deferred.append(outcome.episode_id)

    def land_deferred(self, worker: _Worker) -> None:
        for episode_id in worker.deferred:
            source = worker.staging / episode_id
            if source.exists():
                os.rename(source, self.run_dir / episode_id)
        worker.deferred.clear()

    def receive(self, timeout: float) -> None:
        """Handle what the workers sent within timeout seconds."""
        live = {w.reports: w for w in self.workers.values() if not w.reports.closed}
        if not live:  # every pipe has ended: only check_deaths has news
            time.sleep(timeout)
            return
        for conn in wait(list(live), timeout=timeout):
            self.read(live[conn])  # type: ignore[index]

    def read(self, worker: _Worker) -> None:
        """One report from worker; a pipe whose writer is gone (or that broke mid-report) is closed."""
        try:
            message = worker.reports.recv()
        except (EOFError, OSError, pickle.UnpicklingError):
            worker.reports.close()
            return
        self.handle(message)

    def drain(self, worker: _Worker) -> None:
        """Everything worker sent before it died."""
        while not worker.reports.closed and worker.reports.poll():
            self.read(worker)

    def check_deaths(self) -> None:
        dead = [w for w in self.workers.values() if not w.stopping and w.process.exitcode is not None]
        if not dead:
            return
        for worker in dead:
            self.drain(worker)  # what a worker sent before it died counts
        for worker in dead:
            code = worker.process.exitcode
            reason = f"worker process {worker.process.pid} exited with code {code}"
            del self.workers[worker.wid]
            if not worker.reports.closed:
                worker.reports.close()
            self.land_deferred(worker)  # accepted outcomes keep their (unfinished) records
            shutil.rmtree(worker.staging, ignore_errors=True)  # the unfinished episodes: played again
            for outcome in self.ledger.lost(worker.wid, reason):
                self.record(outcome)
            if not worker.ready:
                raise EvalError(f"an eval worker died while starting ({reason}); run with --workers 1 to "
                                "see the error")
            sys.stderr.write(f"\n{reason}; its unfinished episodes go to another worker\n")
            if self.replacements_left > 0 and not self.ledger.complete:
                self.replacements_left -= 1
                self.spawn()
        if not self.workers and not self.ledger.complete:
            for outcome in self.ledger.abandon("no eval worker left: every worker process died"):
                self.record(outcome)

    # ------------------------------------------------------------ the run
    def run(self) -> EvalSummary:
        self.run_dir.mkdir(parents=True, exist_ok=True)
        t0 = time.monotonic()
        previous: dict[int, Any] = {}
        if threading.current_thread() is threading.main_thread():
            def interrupted(signum: int, _frame: Any) -> None:
                raise EvalInterrupted(signum)

            for sig in (signal.SIGTERM, signal.SIGHUP):
                previous[sig] = signal.signal(sig, interrupted)
        try:
            for _ in range(min(self.size, len(self.tasks)) or 1):
                self.spawn()
            while not self.ledger.complete:
                self.receive(timeout=0.5)
                self.check_deaths()
            self.stop()
        except RecordStop:
            pass  # the workers are stopped below; the summary carries the problem
        finally:
            for signum in previous:  # a second signal now would cut the cleanup short
                signal.signal(signum, signal.SIG_IGN)
            for worker in self.workers.values():
                if worker.process.is_alive():
                    worker.process.terminate()  # the worker kills its browser tree (lifeline.py)
            for worker in self.workers.values():
                worker.process.join(timeout=10)
                if worker.process.is_alive():
                    worker.process.kill()
                    worker.process.join(timeout=5)
            # What is left there was never accepted (an interrupted run): the run directory stays accepted-only.
            shutil.rmtree(self.staging_root, ignore_errors=True)
            for signum, handler in previous.items():
                signal.signal(signum, handler)
        self.summary.seconds = time.monotonic() - t0
        return self.summary

    def stop(self) -> None:
        for worker in self.workers.values():
            worker.stopping = True
            worker.inbox.put(None)
        deadline = time.monotonic() + 60
        for worker in self.workers.values():
            worker.process.join(timeout=max(0.1, deadline - time.monotonic()))
            self.land_deferred(worker)


def play_in_processes(tasks: list[Task], agent: Any, *, workers: int, concurrency: int = 1, run_dir: Path,
                      task_dirs: list[Path], transport: str = "inprocess", progress: bool = True) -> EvalSummary:
    """Play tasks over `workers` processes (blocking); one run directory, each task recorded once."""
    return _Driver(tasks, agent, workers=workers, concurrency=concurrency, run_dir=run_dir, task_dirs=task_dirs,
                   transport=transport, progress=progress).run()
