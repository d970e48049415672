"""The Gymnasium environments: check_env, the oracle earns 1.0, noop and random earn 0, seeded resets repeat."""

from __future__ import annotations

import gymnasium
import pytest
from gymnasium.utils.env_checker import check_env

import ewa_mcp.gym
from ewa_mcp.graders import grade_episode

from .helpers import ONE_PER_DOMAIN

pytestmark = pytest.mark.browser


def play(env, actions):
    total, last = 0.0, None
    for step in actions:
        obs, reward, terminated, truncated, info = env.step(step)
        assert isinstance(obs, str) and obs in env.observation_space
        total += reward
        last = (terminated, truncated, info)
        if terminated or truncated:
            break
    return total, last


def oracle_actions(env, task_id):
    task = env.unwrapped._runtime.episodes.tasks.get(task_id)
    return [{"tool": s.tool, "arguments": dict(s.args)} for s in task.oracle]


def test_every_domain_and_the_suite_are_registered():
    assert set(ewa_mcp.gym.ENV_IDS) == {f"ewa_mcp/{d}-v0" for d in [*ONE_PER_DOMAIN, "suite"]}
    assert all(env_id in gymnasium.registry for env_id in ewa_mcp.gym.ENV_IDS)


@pytest.mark.parametrize("domain", ["geolocation", "navigation"])
def test_check_env_passes(domain, tmp_path):
    env = gymnasium.make(f"ewa_mcp/{domain}-v0", run_dir=tmp_path)
    try:
        check_env(env.unwrapped)
    finally:
        env.close()


@pytest.mark.parametrize("domain", list(ONE_PER_DOMAIN))
def test_oracle_earns_one_noop_and_random_earn_zero(domain, tmp_path):
    task_id = ONE_PER_DOMAIN[domain]
    env = gymnasium.make(f"ewa_mcp/{domain}-v0", run_dir=tmp_path)
    try:
        obs, info = env.reset(seed=0, options={"task_id": task_id})
        assert info["task_id"] == task_id and "Task:" in obs
        total, (terminated, truncated, info) = play(env, oracle_actions(env, task_id))
        assert total == 1.0 and terminated and not truncated
        assert info["grade"]["overall_success"] is True and info["completion"] == 1.0
        assert "episode_id" not in info  # info repeats across identical runs: no fresh ids in it

        # noop: ends the episode at once (the eval runner's noop agent does the same).
        env.reset(options={"task_id": task_id})
        end = "submit_location" if domain == "geolocation" else "finish_episode"
        args = {"lat": 0.0, "lng": 0.0} if domain == "geolocation" else {}
        total, (terminated, _, info) = play(env, [{"tool": end, "arguments": args}])
        assert total == 0.0 and terminated and info["grade"]["overall_success"] is False

        # random: sampled tool calls until the episode ends (step limit or a finishing call)
        env.reset(options={"task_id": task_id})
        env.action_space.seed(1)
        total, (terminated, truncated, info) = play(env, iter(env.action_space.sample, None))
        assert total == 0.0 and (terminated or truncated) and info["grade"]["overall_success"] is not True
    finally:
        env.close()


def test_same_seed_same_first_observation_and_task(tmp_path):
    env = gymnasium.make("ewa_mcp/suite-v0", run_dir=tmp_path)
    try:
        first = [env.reset(seed=seed) for seed in (3, 4, 3)]
        assert first[0] == first[2]
        assert first[0][1]["task_id"] != first[1][1]["task_id"]
    finally:
        env.close()


def test_reset_aborts_the_running_episode_and_bad_input_is_refused(tmp_path):
    env = gymnasium.make("ewa_mcp/geolocation-v0", run_dir=tmp_path)
    try:
        u = env.unwrapped
        with pytest.raises(gymnasium.error.ResetNeeded):
            env.step({"tool": "geo_look", "arguments": {}})
        env.reset(options={"task_id": "geo-0018-baseline"})
        first = u.episode_id
        with pytest.raises(ValueError, match="unknown task id"):
            env.reset(options={"task_id": "no-such-task"})
        assert u.episode.status == "running" and u.episode_id == first  # a refused reset changes nothing
        with pytest.raises(ValueError, match="an action is"):
            env.step("geo_look")
        with pytest.raises(ValueError, match="unknown reset option"):
            env.reset(options={"task": "geo-0018-baseline"})
        obs, reward, terminated, truncated, info = env.step({"tool": "no_such_tool", "arguments": {}})
        assert info["ok"] is False and info["steps"] == 1 and "no_such_tool" in obs  # refused, a step as over MCP
        env.reset(options={"task_id": "geo-0018-baseline"})
        assert grade_episode(u.run_dir / first).status == "aborted"
    finally:
        env.close()
