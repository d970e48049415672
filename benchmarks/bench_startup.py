"""How fast `ewa-mcp serve` (stdio) answers `initialize`: spawn to the first answer, several runs; and
spawn to the answer of the first `tools/list` that follows (the first answer a client can act on).

Prints the medians and the worst times, with the machine's load average (a busy machine is slower;
the target, 0.5 s to `initialize`, is for a quiet one). docs/performance.md records the figures.

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


INITIALIZED = {"jsonrpc": "2.0", "method": "notifications/initialized"}
TOOLS_LIST = {"jsonrpc": "2.0", "id": 2, "method": "tools/list"}


def _answer(proc: subprocess.Popen, request_id: int, what: str) -> dict:
    assert proc.stdout is not None
    line = proc.stdout.readline()
    answer = json.loads(line) if line else {}
    if answer.get("id") != request_id or "result" not in answer:
        raise SystemExit(f"unexpected answer to {what}: {line[:200]!r}")
    return answer


def _send(proc: subprocess.Popen, message: dict) -> None:
    assert proc.stdin is not None
    proc.stdin.write((json.dumps(message) + "\n").encode())
    proc.stdin.flush()


def time_initialize(run_dir: str) -> tuple[float, float]:
    """Seconds from spawning the server to reading its answer to initialize, and to its tool list."""
    started = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "ewa_mcp", "serve", "--run-dir", run_dir],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    try:
        _send(proc, INITIALIZE)
        _answer(proc, 1, "initialize")
        initialized = time.perf_counter() - started
        _send(proc, INITIALIZED)
        _send(proc, TOOLS_LIST)
        tools = _answer(proc, 2, "tools/list")["result"]["tools"]
        if not tools:
            raise SystemExit("the server listed no tools")
        return initialized, time.perf_counter() - started
    finally:
        assert proc.stdin is not None
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
        runs = [time_initialize(run_dir) for _ in range(args.runs)]
    load = os.getloadavg()
    init, listed = [r[0] for r in runs], [r[1] for r in runs]
    print(f"serve -> initialize answered: median {statistics.median(init):.3f} s, worst {max(init):.3f} s; "
          f"tools/list answered: median {statistics.median(listed):.3f} s, worst {max(listed):.3f} s; "
          f"over {args.runs} runs; load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
          f"on {os.cpu_count()} CPUs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
