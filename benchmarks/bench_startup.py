"""How fast `ewa-mcp serve` (stdio) answers `initialize`: spawn to the first answer, several runs.

Prints the median and the worst time, with the machine's load average (a busy machine is slower;
the target, 0.5 s, is for a quiet one). docs/performance.md records the figure.

    .venv/bin/python benchmarks/bench_startup.py [--runs N]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

INITIALIZE = {
    "jsonrpc": "2.0", "id": 1, "method": "initialize",
    "params": {"protocolVersion": "2025-06-18", "capabilities": {},
               "clientInfo": {"name": "bench_startup", "version": "0"}},
}


def time_initialize(run_dir: str) -> float:
    """Seconds from spawning the server to reading its answer to initialize."""
    started = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "ewa_mcp", "serve", "--run-dir", run_dir],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    try:
        assert proc.stdin is not None and proc.stdout is not None
        proc.stdin.write((json.dumps(INITIALIZE) + "\n").encode())
        proc.stdin.flush()
        line = proc.stdout.readline()
        elapsed = time.perf_counter() - started
        answer = json.loads(line)
        if answer.get("id") != 1 or "result" not in answer:
            raise SystemExit(f"unexpected answer to initialize: {line[:200]!r}")
        return elapsed
    finally:
        proc.stdin.close()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="ewa-bench-startup-") as run_dir:
        time_initialize(run_dir)  # warm the OS file cache and the .pyc files
        times = [time_initialize(run_dir) for _ in range(args.runs)]
    load = os.getloadavg()
    print(f"serve -> initialize answered: median {statistics.median(times):.3f} s, worst {max(times):.3f} s "
          f"over {args.runs} runs; load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
          f"on {os.cpu_count()} CPUs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
