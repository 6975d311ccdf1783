"""get_state / set_state and pickling (issue 10): restoring and replaying the same actions gives
identical observations, rewards and flags; bad bytes raise ValueError."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import touchline
from touchline.compat.gfootball import create_environment


def _play(env, actions):
    seen = []
    for a in actions:
        obs, reward, terminated, truncated, _ = env.step(int(a))
        seen.append((obs.copy(), reward, terminated, truncated))
        if terminated or truncated:
            env.reset()
    return seen


def _assert_same(a, b):
    assert len(a) == len(b)
    for (o1, r1, t1, u1), (o2, r2, t2, u2) in zip(a, b):
        np.testing.assert_array_equal(o1, o2)
        assert (r1, t1, u1) == (r2, t2, u2)


@pytest.mark.parametrize(
    ("scenario", "representation", "stacked"),
    [
        ("11_vs_11_stochastic", "simple115v2", False),
        ("academy_3_vs_1_with_keeper", "extracted", True),
        ("academy_counterattack_hard", "simple115", True),
    ],
)
def test_restore_replays_bit_for_bit(scenario: str, representation: str, stacked: bool) -> None:
    env = touchline.make(scenario, representation=representation, stacked=stacked, seed=3)
    env.reset(seed=3)
    rng = np.random.default_rng(0)
    _play(env, rng.integers(19, size=50))
    state = env.unwrapped.get_state()
    assert isinstance(state, bytes)
    if not stacked:
        # Stacked frames travel with the state (4 SMM frames are 110 KB); the match itself is small.
        assert len(state) < 16 * 1024
    actions = rng.integers(19, size=200)
    first = _play(env, actions)
    env.unwrapped.set_state(state)
    _assert_same(_play(env, actions), first)


def test_pickled_env_continues_identically() -> None:
    env = touchline.make("academy_run_to_score_with_keeper", seed=1)
    env.reset(seed=1)
    _play(env, [5] * 10)
    clone = pickle.loads(pickle.dumps(env))
    actions = np.random.default_rng(2).integers(19, size=100)
    _assert_same(_play(clone, actions), _play(env, actions))


def test_bad_state_bytes_raise_value_error() -> None:
    env = touchline.make("academy_corner", seed=0)
    env.reset(seed=0)
    state = env.unwrapped.get_state()
    for bad in (
        b"",
        b"nonsense",
        state[: len(state) // 2],
        state[:40] + bytes([state[40] ^ 1]) + state[41:],
    ):
        with pytest.raises(ValueError):
            env.unwrapped.set_state(bad)
    other = touchline.make("academy_empty_goal", seed=0)
    other.reset(seed=0)
    with pytest.raises(ValueError, match="another scenario"):
        other.unwrapped.set_state(state)


def test_compat_get_state_round_trip() -> None:
    env = create_environment(env_name="academy_empty_goal", representation="simple115v2")
    env.reset()
    state = env.get_state()
    first = [env.step(5) for _ in range(20)]
    env.set_state(state)
    again = [env.step(5) for _ in range(20)]
    for (o1, r1, d1, _), (o2, r2, d2, _) in zip(first, again):
        np.testing.assert_array_equal(o1, o2)
        assert (r1, d1) == (r2, d2)
