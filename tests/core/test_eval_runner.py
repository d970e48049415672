"""The eval runner over each transport: the same episode recorded and graded whatever the wire."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest


@pytest.mark.parametrize("transport", ["inprocess", "stdio", "http"])
def test_eval_over_each_transport(transport, tmp_path):
    run = tmp_path / transport
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "oracle", "--tasks", "demo-*",
                        "--transport", transport, "--run-dir", str(run), "-q", "--format", "json"],
                       capture_output=True, text=True, timeout=180)
    assert r.returncode == 0, r.stderr[-2000:]
    (episode,) = [p for p in run.iterdir() if p.is_dir()]
    final = json.loads((episode / "final_state.json").read_text())
    assert final["status"] == "finished" and final["answer"] == "hello"
    assert '"overall_success": true' in r.stdout


def test_noop_agent_fails_the_demo(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "noop", "--tasks", "demo-*",
                        "--run-dir", str(tmp_path), "-q", "--format", "json"], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr[-2000:]
    assert '"overall_success": false' in r.stdout
