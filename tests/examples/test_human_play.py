"""Human play driven by a scripted stdin: the same tools, recorded like an agent's episode."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from ewa_mcp.evaluation.human import parse_command

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow


def test_parse_command():
    assert parse_command('kitchen_put object=Tomato receptacle="Plate"') == (
        "kitchen_put", {"object": "Tomato", "receptacle": "Plate"})
    assert parse_command("browser_type element=12 text='two words' press_enter=true") == (
        "browser_type", {"element": 12, "text": "two words", "press_enter": True})
    for bad in ['x "open', "tool novalue", ""]:
        with pytest.raises(ValueError):
            parse_command(bad)


def test_play_records_an_episode(tmp_path):
    script = "tools\nbogus\nget_observation\nfinish_episode answer=hello\n"
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "play", "demo-hello", "--run-dir", str(tmp_path)],
                       input=script, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "unknown tool 'bogus'" in r.stdout
    (episode,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    tools = [json.loads(x)["tool"] for x in (episode / "trajectory.jsonl").read_text().splitlines()]
    assert tools == ["start_episode", "get_observation", "finish_episode"]
    assert json.loads((episode / "final_state.json").read_text())["answer"] == "hello"


def test_play_end_of_input_finishes_the_episode(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "play", "demo-hello", "--run-dir", str(tmp_path)],
                       input="", capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    (episode,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    final = json.loads((episode / "final_state.json").read_text())
    assert final["status"] == "finished" and final["answer"] is None


def test_play_unknown_task(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ewa_mcp", "play", "nope"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "unknown task id" in r.stderr
