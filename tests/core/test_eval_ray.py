"""`ewa-mcp eval --ray`: episodes played by Ray actors on a small local cluster the test starts; each task lands
once in the driver's run directory and grades as a one-process run does, including when an actor is killed
(`ray.kill`) in the middle of an episode."""

from __future__ import annotations

import sys
from collections import Counter

import pytest

ray = pytest.importorskip("ray", reason="Ray is the optional extra ewa-mcp[ray] (in the test extra)")

from ewa_mcp.evaluation.ray_eval import ACTOR_PREFIX, INCOMING, play_on_ray  # noqa: E402
from ewa_mcp.evaluation.runner import select_tasks  # noqa: E402
from ewa_mcp.evaluation.scale import RayOptions  # noqa: E402
from ewa_mcp.core.paths import tasks_dir  # noqa: E402
from ewa_mcp.core.taskmodel import TaskStore  # noqa: E402

from .test_eval_workers import StallOnce, drive_until_stalled, grades, grades_in_one_process, landed  # noqa: E402

# End to end (minutes of the suite's time): `make test-slow`, which CI runs after `make test`.
pytestmark = pytest.mark.slow


def ray_tasks():
    store = TaskStore([tasks_dir()])
    # Quick episodes, one of them (geo-0027-embodied) with a browser.
    return select_tasks(store, None, 4, ["geolocation"]) + select_tasks(store, ["demo-*"], None)


@pytest.fixture(scope="module")
def cluster():
    ray.init(num_cpus=2, include_dashboard=False, configure_logging=False, log_to_driver=False,
             runtime_env={"env_vars": {"RAY_USAGE_STATS_ENABLED": "0"}})
    # The test's agent class lives in this package, which the actors' processes cannot import: send it by value.
    ray.cloudpickle.register_pickle_by_value(sys.modules[StallOnce.__module__])
    yield
    ray.shutdown()


@pytest.fixture(scope="module")
def one_process_grades(tmp_path_factory):
    return grades_in_one_process(ray_tasks(), tmp_path_factory.mktemp("one-process"))


def test_ray_actor_killed_mid_episode_its_episode_lands_once(cluster, one_process_grades, tmp_path):
    tasks = ray_tasks()
    target = tasks[2].id
    marker = tmp_path / "stalled.pid"
    run_dir = tmp_path / "run"
    driver, result, pid = drive_until_stalled(
        lambda: play_on_ray(tasks, StallOnce(target, marker), RayOptions(actors=2, num_cpus=1), run_dir=run_dir,
                            task_dirs=[tasks_dir()], progress=False), marker)
    stalled = [h for h in map(ray.get_actor, [n for n in ray.util.list_named_actors() if n.startswith(ACTOR_PREFIX)])
               if ray.get(h.where.remote())[1] == pid]
    assert len(stalled) == 1
    ray.kill(stalled[0])
    driver.join(timeout=120)
    assert not driver.is_alive()
    summary = result["summary"]
    assert not [o.failure for o in summary.outcomes if o.failure]
    assert sorted(o.task_id for o in summary.outcomes) == sorted(t.id for t in tasks)
    assert landed(run_dir) == Counter(t.id for t in tasks)
    assert not list(run_dir.glob(f"{INCOMING}*"))
    assert grades(run_dir) == one_process_grades
