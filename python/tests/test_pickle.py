"""Every env pickles and goes on where it was (issue 16, seam 5): SuperSuit's
`concat_vec_envs_v1`, RLlib and multiprocessing send envs to other processes by pickling them."""

from __future__ import annotations

import pickle

import numpy as np
import touchline
from touchline.compat.gfootball import create_environment

DRILL = "academy_3_vs_1_with_keeper"


def test_the_extension_env_pickles_with_its_episode() -> None:
    env = touchline.make(DRILL, seed=4)
    env.reset(seed=4)
    for a in (5, 5, 13, 5):
        env.step(a)
    copy = pickle.loads(pickle.dumps(env))
    for a in (5, 12, 0, 0, 3):
        np.testing.assert_array_equal(env.step(a)[0], copy.step(a)[0])


def test_the_pettingzoo_env_pickles() -> None:
    env = touchline.parallel_env(DRILL, seed=1)
    env.reset(seed=1)
    actions = dict.fromkeys(env.agents, 5)
    env.step(actions)
    copy = pickle.loads(pickle.dumps(env))
    assert copy.agents == env.agents
    a = env.step(actions)
    b = copy.step(actions)
    for agent in env.agents:
        np.testing.assert_array_equal(a[0][agent], b[0][agent])
        assert a[1][agent] == b[1][agent]


def test_the_gfootball_compat_env_pickles() -> None:
    env = create_environment(env_name=DRILL, representation="simple115v2")
    env.reset()
    env.step(5)
    copy = pickle.loads(pickle.dumps(env))
    np.testing.assert_array_equal(env.step(5)[0], copy.step(5)[0])


def test_the_vector_env_pickles_with_its_matches() -> None:
    envs = touchline.vector.make(DRILL, num_envs=3, seed=2)
    envs.reset(seed=2)
    rng = np.random.default_rng(0)
    for _ in range(20):
        envs.step(rng.integers(19, size=3))
    copy = pickle.loads(pickle.dumps(envs))
    for _ in range(30):
        actions = rng.integers(19, size=3)
        a, b = envs.step(actions), copy.step(actions)
        for x, y in zip(a[:4], b[:4]):
            np.testing.assert_array_equal(x, y)


def test_a_vector_env_waiting_for_its_next_step_reset_pickles_so() -> None:
    # In NEXT_STEP a match that just ended resets on the next step; the copy must too.
    envs = touchline.vector.make("academy_empty_goal_close", num_envs=2, seed=3)
    envs.reset(seed=3)
    rng = np.random.default_rng(1)
    for _ in range(500):
        *_, terminated, truncated, _ = envs.step(rng.integers(19, size=2))
        if (terminated | truncated).any():
            break
    assert (terminated | truncated).any()
    copy = pickle.loads(pickle.dumps(envs))
    actions = rng.integers(19, size=2)
    a, b = envs.step(actions), copy.step(actions)
    for x, y in zip(a[:4], b[:4]):
        np.testing.assert_array_equal(x, y)
    ended = terminated | truncated
    assert (a[1][ended] == 0).all() and not (a[2] | a[3])[ended].any()
