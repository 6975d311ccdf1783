"""Same seed and same actions give the same trajectory, seen from Python; other seeds differ."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
import touchline
from gymnasium.utils.env_checker import data_equivalence

SCENARIOS = touchline.scenario_names()


def rollout(env, seed: int, steps: int, action_seed: int = 0) -> list:
    """(observation, reward, terminated, truncated, info) of up to `steps` steps, over episodes."""
    obs, info = env.reset(seed=seed)
    trace: list[tuple[Any, ...]] = [(obs.copy(), info)]
    env.action_space.seed(action_seed)
    for _ in range(steps):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        trace.append((obs.copy(), reward, terminated, truncated, info))
        if terminated or truncated:
            obs, info = env.reset()
            trace.append((obs.copy(), info))
    return trace


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_same_seed_same_trajectory(scenario: str) -> None:
    first = rollout(touchline.make(scenario), seed=42, steps=120)
    second = rollout(touchline.make(scenario), seed=42, steps=120)
    assert data_equivalence(first, second, exact=True)


def test_same_seed_same_trajectory_extracted_stacked_two_sides() -> None:
    def make():
        return touchline.make(
            "academy_3_vs_1_with_keeper",
            representation="extracted",
            stacked=True,
            number_of_left_players_agent_controls=3,
            number_of_right_players_agent_controls=1,
            rewards="scoring,checkpoints",
        )

    assert data_equivalence(rollout(make(), 7, 200), rollout(make(), 7, 200), exact=True)


def test_seed_at_construction_equals_seed_at_reset() -> None:
    constructed = touchline.make("11_vs_11_stochastic", seed=3)
    reseeded = touchline.make("11_vs_11_stochastic", seed=999)
    obs_a, _ = constructed.reset()
    obs_b, _ = reseeded.reset(seed=3)
    np.testing.assert_array_equal(obs_a, obs_b)
    for _ in range(50):
        obs_a, *_ = constructed.step(5)
        obs_b, *_ = reseeded.step(5)
    np.testing.assert_array_equal(obs_a, obs_b)


def test_reseeding_replays_the_episode() -> None:
    env = touchline.make("11_vs_11_stochastic")
    first = rollout(env, seed=11, steps=80)
    rollout(env, seed=12, steps=30)
    assert data_equivalence(first, rollout(env, seed=11, steps=80), exact=True)


def test_different_seeds_differ_on_a_stochastic_match() -> None:
    env = touchline.make("11_vs_11_stochastic")
    a = rollout(env, seed=1, steps=300)
    b = rollout(env, seed=2, steps=300)
    assert any(not np.array_equal(x[0], y[0]) for x, y in zip(a, b))
