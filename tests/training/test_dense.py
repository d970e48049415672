"""The dense reward: the change in the grader's completion on the live state; an episode's rewards sum to its
final completion. Checked over the oracle of a sample of tasks per domain (the whole suite: the lead's run)."""

from __future__ import annotations

import gymnasium
import pytest

import ewa_mcp.gym  # noqa: F401  (registers the environments)
from ewa_mcp.graders import grade_episode

pytestmark = pytest.mark.browser
SAMPLE = 2  # tasks per domain, spread over the domain's id order


@pytest.mark.parametrize("domain", ["navigation", "cooking", "shopping", "traveling", "geolocation"])
def test_dense_rewards_of_the_oracle_sum_to_the_final_completion(domain, tmp_path):
    env = gymnasium.make(f"ewa_mcp/{domain}-v0", run_dir=tmp_path, reward="dense")
    u = env.unwrapped
    try:
        ids = u.task_ids
        for task_id in [ids[k * len(ids) // SAMPLE] for k in range(SAMPLE)]:
            env.reset(options={"task_id": task_id})
            rewards = []
            for step in u._runtime.episodes.tasks.get(task_id).oracle:
                _, reward, terminated, truncated, info = env.step({"tool": step.tool, "arguments": dict(step.args)})
                rewards.append(reward)
                if terminated or truncated:
                    break
            final = grade_episode(u.run_dir / u.episode_id)
            assert final.overall_success is True, task_id
            assert sum(rewards) == pytest.approx(final.completion, abs=1e-9), (task_id, rewards)
            assert info["completion"] == final.completion
            if final.conditions_total > 1 and domain != "geolocation":
                # Progress is paid as it is made: some reward arrives before the finishing step.
                assert any(r > 0 for r in rewards[:-1]), (task_id, rewards)
    finally:
        env.close()


def test_dense_reward_pays_each_condition_when_the_live_state_meets_it(tmp_path):
    """navigation-boston-000: directions shown on the map site (one of two conditions) on the first step, the walk's
    end within the destination's radius on the move that enters it; walking away takes it back."""
    env = gymnasium.make("ewa_mcp/navigation-v0", run_dir=tmp_path, reward="dense")
    u = env.unwrapped
    try:
        env.reset(options={"task_id": "navigation-boston-000"})
        oracle = [{"tool": s.tool, "arguments": dict(s.args)} for s in
                  u._runtime.episodes.tasks.get("navigation-boston-000").oracle]
        rewards = [env.step(action)[1] for action in oracle[:-2]]  # up to the last move, before stop and finish
        assert rewards[0] == pytest.approx(0.5)  # browser_goto: the directions page
        walk = rewards[1:]
        assert sum(walk) == pytest.approx(0.5) and [r for r in walk if r] == [pytest.approx(0.5)]  # arriving
        moves = [a["arguments"]["neighbour"] for a in oracle if a["tool"] == "street_move"]
        away = [env.step({"tool": "street_move", "arguments": {"neighbour": node}})[1] for node in moves[-2:-5:-1]]
        assert sum(away) == pytest.approx(-0.5)  # walking three nodes back leaves the destination: taken back
        *_, info = env.step({"tool": "finish_episode", "arguments": {}})
        assert info["grade"]["completion"] == pytest.approx(0.5)
    finally:
        env.close()
