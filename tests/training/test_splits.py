"""Fresh seeded splits (ewa_mcp/taskgen/splits.py): train and hidden tasks share no instance with the public test
split or with each other, a seed regenerates the same tasks, and bad requests are refused with the fix."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from ewa_mcp.taskgen.splits import (generate_split, instance_key, public_test_tasks, split_of_instance, stream,
                                    write_split)
from ewa_mcp.core.taskmodel import TaskStore
from ewa_mcp.graders import grade_episode

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def navigation_test_keys():
    tasks = public_test_tasks("navigation")
    assert len(tasks) >= 180
    return {instance_key(t) for t in tasks}


@pytest.fixture(scope="module")
def navigation_train():
    return generate_split("navigation", "train", 5)


def test_navigation_train_shares_no_instance_with_the_public_test_split(navigation_train, navigation_test_keys):
    assert len(navigation_train) >= 100
    keys = [instance_key(t) for t in navigation_train]
    assert len(set(keys)) == len(keys)
    assert not set(keys) & navigation_test_keys
    # Not just renamed test tasks: the walks themselves are new.
    starts = {(k[1], k[2]) for k in keys}
    assert len(starts) > len(keys) // 2
    for task in navigation_train:
        assert task.id.startswith("navigation-train5-")
        assert task.metadata["split"] == "train" and task.metadata["split_seed"] == 5
        assert task.oracle and task.embodied_goals and task.web_goals
        assert split_of_instance(instance_key(task)) == "train"


def test_a_seed_regenerates_its_split_and_another_seed_draws_other_tasks(navigation_train):
    again = generate_split("navigation", "train", 5, cities=["boston"])
    boston = [t for t in navigation_train if "-boston-" in t.id]
    assert [t.model_dump() for t in again] == [t.model_dump() for t in boston]
    other = generate_split("navigation", "train", 6, cities=["boston"])
    assert {instance_key(t) for t in other} != {instance_key(t) for t in boston}


def test_hidden_split_is_disjoint_from_every_train_seed_and_the_public_suite(navigation_test_keys):
    hidden = generate_split("navigation", "hidden", 5, cities=["boston"])
    train = generate_split("navigation", "train", 5, cities=["boston"])
    assert hidden and train
    hidden_keys = {instance_key(t) for t in hidden}
    assert not hidden_keys & {instance_key(t) for t in train}
    assert not hidden_keys & navigation_test_keys
    # Membership is a property of the instance, so no train seed can ever draw these.
    assert {split_of_instance(k) for k in hidden_keys} == {"hidden"}


def test_the_train_stream_never_repeats_an_instance():
    drawn = []
    for task in stream("navigation", "train", 0, cities=["pittsburgh"]):
        drawn.append(task)
        if len(drawn) == 40:  # more than one seed gives for this city
            break
    keys = [instance_key(t) for t in drawn]
    assert len(set(keys)) == 40
    assert len({t.metadata["split_seed"] for t in drawn}) >= 2


def test_cooking_train_shares_no_kitchen_recipe_and_missing_ingredients_with_the_test_split(tmp_path):
    test_keys = {instance_key(t) for t in public_test_tasks("cooking")}
    counts = write_split(tmp_path, "train", 2, domains=["cooking"])
    train = TaskStore([tmp_path]).all()
    assert counts == {"cooking": len(train)} and len(train) >= 50
    keys = [instance_key(t) for t in train]
    assert len(set(keys)) == len(keys)
    assert not set(keys) & test_keys
    assert all(t.id.startswith("cooking-train2-") and t.oracle for t in train)


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ewa_mcp", *args], capture_output=True, text=True, timeout=300)


@pytest.mark.parametrize("args, message", [
    (["tasks", "generate", "--split", "train", "--seed", "1", "--domain", "geolocation", "-o", "{out}"],
     "every location is already a public test task"),
    (["tasks", "generate", "--split", "train", "--seed", "1"], "needs -o DIR"),
    (["tasks", "generate", "--split", "test", "--seed", "3", "-o", "{out}"], "--split hidden --seed N"),
    (["tasks", "generate", "--split", "train", "--seed", "-2", "-o", "{out}"], "non-negative"),
])
def test_bad_split_requests_are_refused_with_the_fix_and_write_nothing(tmp_path, args, message):
    out = tmp_path / "out"
    result = _cli(*[a.replace("{out}", str(out)) for a in args])
    assert result.returncode == 2
    assert message in result.stderr
    assert not out.exists() or not any(out.rglob("*.json"))


def test_cli_generates_a_train_split_that_eval_can_play(tmp_path):
    out = tmp_path / "train"
    result = _cli("tasks", "generate", "--split", "train", "--seed", "4", "--domain", "navigation", "-o", str(out))
    assert result.returncode == 0, result.stderr
    count = json.loads(result.stdout.splitlines()[0])["navigation"]
    tasks = TaskStore([out]).all()
    assert len(tasks) == count > 0 and all(t.id.startswith("navigation-train4-") for t in tasks)
    first = min(t.id for t in tasks)
    run = _cli("eval", "--agent", "oracle", "--split", "train", "--seed", "4", "--domain", "navigation",
               "--tasks", first, "--run-dir", str(tmp_path / "run"), "--format", "json", "-q")
    assert run.returncode == 0, run.stderr
    episodes = [p.parent for p in (tmp_path / "run").rglob("task.json")]
    assert len(episodes) == 1
    assert json.loads((episodes[0] / "task.json").read_text())["id"] == first
    assert grade_episode(episodes[0]).overall_success is True


def test_the_gym_draws_only_the_split_it_is_given(tmp_path, navigation_train):
    import gymnasium

    import ewa_mcp.gym  # noqa: F401  (registers the environments)

    env = gymnasium.make("ewa_mcp/navigation-v0", split="train", split_seed=5, run_dir=tmp_path)
    try:
        u = env.unwrapped
        assert u.task_ids == sorted(t.id for t in navigation_train)
        _, info = env.reset(seed=3)
        assert info["task_id"].startswith("navigation-train5-")
    finally:
        env.close()
    with pytest.raises(ValueError, match="the train split exists for cooking, navigation only"):
        gymnasium.make("ewa_mcp/geolocation-v0", split="train", split_seed=1, run_dir=tmp_path)


def test_the_test_split_is_the_shipped_suite_unchanged():
    drawn = generate_split("navigation", "test", 0, cities=["boston"])
    shipped = sorted((t for t in public_test_tasks("navigation") if t.id.startswith(("navigation-boston-",
                                                                                      "navigation-via-boston-"))),
                     key=lambda t: t.id)
    assert len(shipped) == 36 + 8  # PER_CITY and PER_CITY_VIA for Boston
    assert [t.model_dump(mode="json") for t in sorted(drawn, key=lambda t: t.id)] == \
        [t.model_dump(mode="json") for t in shipped]
