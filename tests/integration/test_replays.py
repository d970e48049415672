"""The example replays play through `ewa-mcp eval --agent replay` and grade to their documented outcomes."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pytest

from ewa_mcp.graders import grade_run
from ewa_mcp.core.paths import REPO_ROOT

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow

REPLAYS = REPO_ROOT / "examples" / "replays"
EXPECTED = json.loads((REPLAYS / "expected.json").read_text())


@pytest.mark.skipif(not shutil.which("chromium"), reason="no Chromium: apt-get install chromium")
def test_replays_grade_as_documented(tmp_path):
    outcomes = {}
    for domain in EXPECTED:
        run = tmp_path / domain
        r = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "replay",
                            str(REPLAYS / f"{domain}.jsonl"), "--run-dir", str(run), "-q", "--format", "json"],
                           capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, r.stderr[-2000:]
        (episode,) = grade_run(run).episodes
        outcomes[domain] = episode
    for domain, want in EXPECTED.items():
        got = outcomes[domain]
        for key in ("overall_success", "web_success", "embodied_success", "answer_correct"):
            if want[key] is not None:
                assert getattr(got, key) == want[key], (domain, key, got.conditions)
        for level, value in want.get("geolocation", {}).items():
            assert got.geolocation[level] == value, (domain, level)


def test_replays_are_current():
    """The committed replays match their generator (tasks regenerate deterministically)."""
    before = {p.name: p.read_text() for p in REPLAYS.glob("*.jsonl")}
    r = subprocess.run([sys.executable, str(REPLAYS / "make_replays.py")], capture_output=True, text=True,
                       timeout=120)
    try:
        assert r.returncode == 0, r.stderr
        after = {p.name: p.read_text() for p in REPLAYS.glob("*.jsonl")}
        assert after == before, "run examples/replays/make_replays.py and commit the replays"
    finally:
        for name, text in before.items():
            (REPLAYS / name).write_text(text)


def test_malformed_replay_is_refused(tmp_path):
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"task_id": "demo-hello", "tool": "get_observation"}\nnot json\n')
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "replay", str(bad)],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "bad.jsonl:2" in r.stderr and "not JSON" in r.stderr
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "eval", "--agent", "oracle", "--tasks", "no-such-*"],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "no task id matches" in r.stderr
