"""`ewa-mcp eval --ray [ADDRESS]`: episodes played by Ray actors, each owning a server, a browser and the sites.

Records come back to the driver. An actor records each episode into a private temporary folder on its own node,
and when the episode is over returns the episode's files with its outcome; the driver alone writes the run
directory (into `.incoming-<id>`, then one rename). So a cluster needs no shared file system, and an actor that
dies mid-episode leaves nothing in the run directory: its unfinished episodes are simply played again by
another actor (a new one is started in its place) and land once. The ledger (evaluation/ledger.py) accepts one
outcome per task, so an actor's late answer for a task already taken back is dropped.

Ray is imported only here, and only for --ray (it is an optional extra: `pip install 'ewa-mcp[ray]'`).
"""

from __future__ import annotations

import os
import shutil
import socket
import sys
import tempfile
import time
from dataclasses import asdict
from pathlib import Path
from typing import Any

from ewa_mcp.core.taskmodel import Task
from .ledger import Ledger
from .outcomes import EpisodeOutcome, EvalError, EvalSummary, Progress
from .scale import RayOptions

INCOMING = ".incoming-"
ACTOR_PREFIX = "ewa-episodes-"


def import_ray() -> Any:
    os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")  # nothing leaves the machine
    try:
        import ray
    except ImportError as exc:
        raise EvalError("--ray needs Ray: pip install 'ewa-mcp[ray]' (on the driver and on every node of the "
                        "cluster)") from exc
    return ray


class EpisodeActor:
    """A Ray actor's body: one episode player (server, browser, sites) recording into a private folder."""

    def __init__(self, agent: Any, transport: str, task_dirs: list[str]):
        import logging

        from .player import EpisodePlayer

        logging.basicConfig(level=logging.WARNING, stream=sys.stderr)
        missing = [d for d in task_dirs if not Path(d).is_dir()]
        if missing:
            raise EvalError(f"task directory {missing[0]} does not exist on node {socket.gethostname()}; put the "
                            "tasks at the same path on every node (shared storage) or use the installed suites")
        self.scratch = Path(tempfile.mkdtemp(prefix="ewa-ray-actor-"))
        self.player = EpisodePlayer(agent, transport=transport, task_dirs=[Path(d) for d in task_dirs],
                                    run_dir=self.scratch)

    def where(self) -> tuple[str, int]:
        return socket.gethostname(), os.getpid()

    def play(self, task: Task) -> tuple[dict[str, Any], dict[str, bytes]]:
        """Play one episode; return its outcome and its record's files (relative path -> bytes)."""
        outcome = self.player.play(task)
        files: dict[str, bytes] = {}
        if outcome.episode_id:
            folder = self.scratch / outcome.episode_id
            for path in sorted(folder.rglob("*")):
                if path.is_file() and not path.name.startswith("."):
                    files[path.relative_to(folder).as_posix()] = path.read_bytes()
            shutil.rmtree(folder, ignore_errors=True)
        return asdict(outcome), files

    def close(self) -> None:
        self.player.close()
        shutil.rmtree(self.scratch, ignore_errors=True)


def write_episode(run_dir: Path, episode_id: str, files: dict[str, bytes]) -> None:
    """One episode's record into the run directory, all at once (a reader never sees it half written)."""
    if not files or (run_dir / episode_id).exists():
        return
    incoming = run_dir / f"{INCOMING}{episode_id}"
    shutil.rmtree(incoming, ignore_errors=True)
    for relative, data in files.items():
        target = (incoming / relative).resolve()
        if incoming.resolve() not in target.parents:  # a record names only files inside its folder
            raise EvalError(f"an actor returned a file outside its episode folder: {relative[:200]!r}")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
    os.rename(incoming, run_dir / episode_id)


class _RayDriver:
    def __init__(self, ray: Any, tasks: list[Task], agent: Any, options: RayOptions, *, run_dir: Path,
                 task_dirs: list[Path], transport: str, concurrency: int, progress: bool):
        self.ray, self.tasks, self.agent, self.options = ray, tasks, agent, options
        self.run_dir, self.transport, self.concurrency = run_dir, transport, max(1, concurrency)
        self.task_dirs = [str(Path(d).resolve()) for d in task_dirs]
        self.ledger = Ledger(tasks, max_attempts=options.max_attempts)
        self.summary = EvalSummary(run_dir=run_dir, agent=agent.name, transport=f"ray:{transport}")
        self.bar = Progress(len(tasks), progress)
        self.actor_class = ray.remote(EpisodeActor)
        self.actors: dict[int, Any] = {}
        self.calls: dict[Any, tuple[int, int]] = {}  # object ref -> (actor number, slot)
        self.made = 0
        self.replacements_left = 0
        self.token = os.urandom(3).hex()

    def make_actor(self) -> int:
        number = self.made
        self.made += 1
        resources: dict[str, Any] = {"num_cpus": self.options.num_cpus}
        if self.options.memory:
            resources["memory"] = self.options.memory
        # One extra slot of concurrency so that where()/close() answer while episodes run.
        # Named (ewa-episodes-<run>-<n>) so that an operator, or a test, can find and stop one.
        handle = self.actor_class.options(name=f"{ACTOR_PREFIX}{self.token}-{number}",
                                          max_concurrency=self.concurrency + 1, max_restarts=0,
                                          max_task_retries=0, **resources).remote(
            self.agent, self.transport, self.task_dirs)
        self.actors[number] = handle
        return number

    def feed(self, number: int) -> None:
        handle = self.actors[number]
        while self.ledger.held(number) < self.concurrency:
            slot = self.ledger.take(number)
            if slot is None:
                return
            self.calls[handle.play.remote(self.tasks[slot])] = (number, slot)

    def record(self, outcome: EpisodeOutcome) -> None:
        self.summary.outcomes.append(outcome)
        self.bar.tick(outcome)

    def lose(self, number: int, error: BaseException) -> None:
        handle = self.actors.pop(number, None)
        if handle is None:
            return
        self.calls = {ref: v for ref, v in self.calls.items() if v[0] != number}
        reason = f"{type(error).__name__}: {str(error).strip().splitlines()[0][:200] if str(error).strip() else ''}"
        for outcome in self.ledger.lost(number, reason):
            self.record(outcome)
        sys.stderr.write(f"\nRay actor {number} died ({reason}); its unfinished episodes go to another actor\n")
        try:
            self.ray.kill(handle)
        except Exception:  # already gone
            pass
        if self.replacements_left > 0 and not self.ledger.complete:
            self.replacements_left -= 1
            self.feed(self.make_actor())
        if not self.actors and not self.ledger.complete:
            for outcome in self.ledger.abandon(f"no Ray actor left (last died of {reason})"):
                self.record(outcome)

    def start(self) -> None:
        ray = self.ray
        count = self.options.actors
        if count is None:
            cpus = ray.cluster_resources().get("CPU", 1)
            count = max(1, int(cpus // self.options.num_cpus))
        count = max(1, min(count, len(self.tasks)))
        self.replacements_left = 2 * count
        for _ in range(count):
            self.make_actor()
        # Every actor must start (a node without ewa-mcp or Chromium fails here, with its reason).
        try:
            places = ray.get([h.where.remote() for h in self.actors.values()], timeout=600)
        except ray.exceptions.GetTimeoutError as exc:
            raise EvalError(f"{count} Ray actors of {self.options.num_cpus} CPU each did not start within "
                            "10 minutes: the cluster lacks the resources; lower --ray-actors or "
                            "--ray-num-cpus") from exc
        except ray.exceptions.RayActorError as exc:
            raise EvalError(f"a Ray actor could not start: {str(exc).strip()[-600:]}") from exc
        sys.stderr.write(f"{count} Ray actors on {len({host for host, _ in places})} node(s)\n")

    def run(self) -> EvalSummary:
        ray = self.ray
        self.run_dir.mkdir(parents=True, exist_ok=True)
        t0 = time.monotonic()
        try:
            self.start()
            for number in list(self.actors):
                self.feed(number)
            while not self.ledger.complete:
                if not self.calls:  # nothing in flight and tasks left: no actor can take them
                    for outcome in self.ledger.abandon("no Ray actor left to play it"):
                        self.record(outcome)
                    break
                ready, _ = ray.wait(list(self.calls), num_returns=1, timeout=5)
                for ref in ready:
                    if ref not in self.calls:
                        continue
                    number, slot = self.calls.pop(ref)
                    try:
                        outcome_fields, files = ray.get(ref)
                    except ray.exceptions.RayActorError as exc:
                        self.lose(number, exc)
                        continue
                    except ray.exceptions.RayError as exc:  # the call failed, the actor lives: one failed episode
                        task = self.tasks[slot]
                        outcome_fields = {"task_id": task.id, "domain": task.domain, "episode_id": None,
                                          "failure": f"{type(exc).__name__}: {str(exc).strip()[-300:]}"}
                        files = {}
                    outcome = EpisodeOutcome(**outcome_fields)
                    if self.ledger.finish(number, slot, outcome):
                        if outcome.episode_id:
                            write_episode(self.run_dir, outcome.episode_id, files)
                        self.record(outcome)
                    if number in self.actors:
                        self.feed(number)
        finally:
            self.stop()
        self.summary.seconds = time.monotonic() - t0
        return self.summary

    def stop(self) -> None:
        ray = self.ray
        closing = []
        for handle in self.actors.values():
            try:
                closing.append(handle.close.remote())
            except Exception:
                pass
        try:
            ray.wait(closing, num_returns=len(closing), timeout=60)
        except Exception:
            pass
        for handle in self.actors.values():
            try:
                ray.kill(handle)
            except Exception:
                pass
        self.actors.clear()
        for leftover in self.run_dir.glob(f"{INCOMING}*"):
            shutil.rmtree(leftover, ignore_errors=True)


def play_on_ray(tasks: list[Task], agent: Any, options: RayOptions, *, run_dir: Path, task_dirs: list[Path],
                transport: str = "inprocess", concurrency: int = 1, progress: bool = True) -> EvalSummary:
    """Play tasks on Ray actors (blocking); one run directory on the driver, each task recorded once.

    Connects with ray.init(options.address) unless Ray is already initialised (a test's local cluster)."""
    ray = import_ray()
    if not ray.is_initialized():
        try:
            ray.init(address=options.address, include_dashboard=False, configure_logging=False,
                     log_to_driver=False)
        except (ConnectionError, ValueError, RuntimeError) as exc:
            raise EvalError(f"could not reach the Ray cluster at {options.address or 'the default address'} "
                            f"({str(exc)[:200]}); start one with `ray start --head` or pass its address") from exc
    return _RayDriver(ray, tasks, agent, options, run_dir=run_dir, task_dirs=task_dirs, transport=transport,
                      concurrency=concurrency, progress=progress).run()
