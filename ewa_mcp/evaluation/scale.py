"""Where the episodes of one eval run: this process, N worker processes, or Ray actors (docs/scaling.md)."""

from __future__ import annotations

import argparse

from dataclasses import dataclass
from typing import Any

from .outcomes import EvalError


@dataclass
class RayOptions:
    address: str | None = None  # None: RAY_ADDRESS, else the cluster started here, else a new local one
    actors: int | None = None  # None: the cluster's CPUs // num_cpus
    num_cpus: float = 1.0  # what each actor declares: its server, browser and sites
    memory: int | None = None  # bytes each actor declares (None: nothing), so Ray packs actors by memory too
    max_attempts: int = 3  # plays of one task before it is recorded as failed (its actor died each time)


@dataclass
class ScaleOptions:
    workers: int = 1
    concurrency: int = 1
    ray: RayOptions | None = None

    def describe(self) -> str:
        where = (f"Ray actors at {self.ray.address or 'the default cluster'}" if self.ray else
                 f"{self.workers} worker process(es)" if self.workers > 1 else "1 process")
        return f"{where}, {self.concurrency} episode(s) at once in each"


def scale_options(args: Any) -> ScaleOptions:
    """The options of --workers / --concurrency / --ray*, checked (EvalError names the fix)."""
    workers = args.workers
    concurrency = args.concurrency if args.concurrency is not None else 1
    if workers < 1:
        raise EvalError(f"--workers must be at least 1 (got {workers})")
    if concurrency < 1:
        raise EvalError(f"--concurrency must be at least 1 (got {concurrency})")
    ray = None
    if args.ray is not None:
        if workers > 1:
            raise EvalError("--ray and --workers do not combine: with Ray, size the run with --ray-actors "
                            "(and --ray-num-cpus)")
        if args.ray_actors is not None and args.ray_actors < 1:
            raise EvalError(f"--ray-actors must be at least 1 (got {args.ray_actors})")
        if args.ray_num_cpus <= 0:
            raise EvalError(f"--ray-num-cpus must be positive (got {args.ray_num_cpus})")
        ray = RayOptions(address=args.ray or None, actors=args.ray_actors, num_cpus=args.ray_num_cpus)
    elif args.ray_actors is not None:
        raise EvalError("--ray-actors needs --ray")
    return ScaleOptions(workers=workers, concurrency=concurrency, ray=ray)


def add_scale_arguments(p: argparse.ArgumentParser) -> None:
    """--workers, --concurrency and --ray (shared with the LLM agent examples)."""
    g = p.add_argument_group("scale", "where episodes run (docs/scaling.md)")
    g.add_argument("--workers", type=int, default=1, metavar="N",
                   help="processes, each with its own server, browser and sites (default 1: this process)")
    g.add_argument("--concurrency", type=int, default=None, metavar="K",
                   help="episodes at once in each process or Ray actor (default 1; LLM agents waiting on a "
                   "model want more)")
    g.add_argument("--ray", nargs="?", const="", default=None, metavar="ADDRESS",
                   help="play on Ray actors. ADDRESS: a cluster's (host:6379 on a cluster node, ray://host:10001 "
                   "from outside), 'auto' (the cluster `ray start` made here) or 'local' (a new one-machine "
                   "cluster); without it RAY_ADDRESS, else the cluster started here, else a new local one. "
                   "Needs `pip install 'ewa-mcp[ray]'`")
    g.add_argument("--ray-actors", type=int, default=None, metavar="N",
                   help="Ray actors to start (default: the cluster's CPUs / --ray-num-cpus)")
    g.add_argument("--ray-num-cpus", type=float, default=1.0, metavar="C",
                   help="CPUs each Ray actor declares (its server, browser and sites; default 1)")
