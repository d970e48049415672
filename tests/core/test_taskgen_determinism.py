"""Task generation is deterministic: the same suites whatever the hash seed of the process."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

SCRIPT = """
import json
from ewa_mcp.envs.street.taskgen import traveling
print(json.dumps([t.model_dump(mode="json") for t in traveling.generate()], sort_keys=True))
"""


# Two whole traveling generations in fresh processes (a minute since the range's-edge draw): run by make test-slow.
@pytest.mark.slow
def test_traveling_generation_does_not_depend_on_hash_seed() -> None:
    runs = []
    for seed in ("1", "4242"):
        env = {k: v for k, v in os.environ.items() if k != "EWA_STREET_DATA"}
        env["PYTHONHASHSEED"] = seed
        runs.append(subprocess.Popen([sys.executable, "-c", SCRIPT], env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True))
    outputs = []
    for proc in runs:
        out, err = proc.communicate(timeout=600)
        assert proc.returncode == 0, err[-2000:]
        outputs.append(out)
    assert outputs[0] == outputs[1]
    assert '"domain": "traveling"' in outputs[0]
