"""Envs used from threads other than their creator's, as RLlib's and other threaded runners do
(issue 16, seam 6): it works, and no Rust panic reaches Python."""

from __future__ import annotations

import threading

import numpy as np
import touchline

DRILL = "academy_empty_goal_close"


def test_an_env_made_in_one_thread_steps_in_another() -> None:
    env = touchline.make(DRILL, seed=0)
    env.reset(seed=0)
    errors: list[BaseException] = []
    steps: list[int] = []

    def run() -> None:
        try:
            for _ in range(50):
                _, _, terminated, truncated, _ = env.step(env.action_space.sample())
                steps.append(1)
                if terminated or truncated:
                    env.reset()
        except BaseException as e:  # a PanicException is a BaseException: catch it to report it
            errors.append(e)

    worker = threading.Thread(target=run)
    worker.start()
    worker.join()
    assert not errors, errors
    assert len(steps) == 50
    # And back in the creating thread.
    env.step(env.action_space.sample())


def test_the_same_trajectory_from_any_thread() -> None:
    actions = np.random.default_rng(0).integers(19, size=60)

    def trajectory() -> list[np.ndarray]:
        env = touchline.make(DRILL, seed=3)
        obs, _ = env.reset(seed=3)
        out = [obs]
        for a in actions:
            obs, _, terminated, truncated, _ = env.step(int(a))
            out.append(obs)
            if terminated or truncated:
                obs, _ = env.reset()
        return out

    here = trajectory()
    there: list[list[np.ndarray]] = []
    worker = threading.Thread(target=lambda: there.append(trajectory()))
    worker.start()
    worker.join()
    for a, b in zip(here, there[0]):
        np.testing.assert_array_equal(a, b)


def test_vector_env_from_another_thread() -> None:
    envs = touchline.vector.make(DRILL, num_envs=2, seed=0)
    envs.reset(seed=0)
    errors: list[BaseException] = []

    def run() -> None:
        try:
            for _ in range(20):
                envs.step(envs.action_space.sample())
        except BaseException as e:
            errors.append(e)

    worker = threading.Thread(target=run)
    worker.start()
    worker.join()
    assert not errors, errors
