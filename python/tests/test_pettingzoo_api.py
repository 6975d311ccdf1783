"""PettingZoo's API and seed tests on a two-sided match, and per-agent frames."""

from __future__ import annotations

import numpy as np
import pytest
import touchline
from gymnasium import spaces
from pettingzoo.test import (  # type: ignore[import-untyped]
    parallel_api_test,
    parallel_seed_test,
    seed_test,
)
from pettingzoo.utils import parallel_to_aec  # type: ignore[import-untyped]

DUEL = "1_vs_1_easy"  # a symmetric 1 + 1 match: one keeper a side, 501 steps


def test_parallel_api() -> None:
    parallel_api_test(touchline.parallel_env(DUEL, 1, 1, seed=0), num_cycles=1000)


def test_parallel_api_one_team_several_players() -> None:
    env = touchline.parallel_env("academy_3_vs_1_with_keeper", 3, 0, seed=0)
    parallel_api_test(env, num_cycles=500)


def test_parallel_seed() -> None:
    parallel_seed_test(lambda: touchline.parallel_env(DUEL, 1, 1), num_cycles=200)


def test_aec_seed() -> None:
    seed_test(lambda: parallel_to_aec(touchline.parallel_env(DUEL, 1, 1)), num_cycles=200)


def test_agents_and_spaces() -> None:
    env = touchline.parallel_env(
        "academy_3_vs_1_with_keeper", 2, 1, representation="extracted", stacked=True
    )
    assert env.possible_agents == ["left_0", "left_1", "right_0"]
    assert env.agents == []
    for agent in env.possible_agents:
        assert env.observation_space(agent).shape == (72, 96, 16)
        assert env.observation_space(agent).dtype == np.uint8
        assert env.action_space(agent) == spaces.Discrete(19)
    observations, infos = env.reset(seed=0)
    assert env.agents == env.possible_agents
    assert set(observations) == set(infos) == set(env.possible_agents)
    for agent, obs in observations.items():
        assert obs in env.observation_space(agent)


def test_rewards_are_zero_sum_between_sides_and_agents_leave_at_the_end() -> None:
    env = touchline.parallel_env(DUEL, 1, 1)
    env.reset(seed=0)
    for agent in env.agents:
        env.action_space(agent).seed(7)
    while env.agents:
        actions = {agent: env.action_space(agent).sample() for agent in env.agents}
        _, rewards, terminations, truncations, infos = env.step(actions)
        assert rewards["left_0"] == -rewards["right_0"]
        assert rewards["left_0"] == infos["left_0"]["score_reward"]
        assert len(set(terminations.values())) == 1 and len(set(truncations.values())) == 1
    assert truncations["left_0"] or terminations["left_0"]
    with pytest.raises(RuntimeError, match="reset"):
        env.step({"left_0": 0, "right_0": 0})
    observations, _ = env.reset()
    assert env.agents == ["left_0", "right_0"] and set(observations) == set(env.agents)


def test_each_agent_observes_in_its_own_frame() -> None:
    """1_vs_1_easy is symmetric: one keeper a side, each at (-1, 0) in its own frame."""
    env = touchline.parallel_env(DUEL, 1, 1, representation="simple115v2")
    observations, _ = env.reset(seed=0)
    left, right = observations["left_0"], observations["right_0"]
    np.testing.assert_allclose(left[0:2], [-1.0, 0.0], atol=0.02)  # own keeper, own frame
    np.testing.assert_allclose(right[0:2], [-1.0, 0.0], atol=0.02)
    np.testing.assert_allclose(left[44:46], [1.0, 0.0], atol=0.02)  # the opponent's keeper
    np.testing.assert_allclose(right[44:46], [1.0, 0.0], atol=0.02)
    raw = env.raw_observations()
    np.testing.assert_allclose(raw["left_0"]["ball"][:2], -raw["right_0"]["ball"][:2], atol=1e-6)
