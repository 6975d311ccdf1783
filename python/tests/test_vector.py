"""The vector env against N single envs, its autoreset, spaces and buffers."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest
import touchline
import touchline.vector
from gymnasium import spaces

DRILL = "academy_empty_goal_close"  # a short Academy drill: episodes end within 401 steps


def test_spaces_and_metadata() -> None:
    envs = touchline.vector.make(DRILL, num_envs=4, seed=0)
    assert isinstance(envs, gymnasium.vector.VectorEnv)
    assert envs.num_envs == 4
    assert envs.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.SAME_STEP
    assert envs.single_observation_space.shape == (115,)
    assert envs.single_action_space == spaces.Discrete(19)
    assert envs.observation_space.shape == (4, 115)
    assert envs.action_space == spaces.MultiDiscrete([19] * 4)
    obs, infos = envs.reset(seed=0)
    assert obs.shape == (4, 115) and obs.dtype == np.float32 and obs in envs.observation_space
    assert isinstance(infos, dict)
    obs, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())
    assert rewards.shape == (4,) and rewards.dtype == np.float32
    assert terminated.shape == truncated.shape == (4,) and terminated.dtype == np.bool_


@pytest.mark.parametrize("representation", ["simple115v2", "extracted"])
@pytest.mark.parametrize("num_threads", [1, 2])
def test_equals_single_envs_with_autoreset(representation: str, num_threads: int) -> None:
    """Env i of the vector env is `touchline.make(seed=seed + i)` reset with `reset()` at each end."""
    n, seed, steps = 3, 100, 600
    envs = touchline.vector.make(
        DRILL, num_envs=n, num_threads=num_threads, seed=seed, representation=representation
    )
    singles = [
        touchline.make(DRILL, seed=seed + i, representation=representation) for i in range(n)
    ]
    obs, _ = envs.reset(seed=seed)
    for i, env in enumerate(singles):
        first, _ = env.reset(seed=seed + i)
        np.testing.assert_array_equal(obs[i], first)
    rng = np.random.default_rng(0)
    episodes_ended = 0
    for _ in range(steps):
        actions = rng.integers(19, size=n)
        obs, rewards, terminated, truncated, infos = envs.step(actions)
        for i, env in enumerate(singles):
            single_obs, reward, term, trunc, single_info = env.step(int(actions[i]))
            assert (terminated[i], truncated[i]) == (term, trunc)
            assert rewards[i] == np.float32(reward)
            if term or trunc:
                # Gymnasium's same-step autoreset keys carry the episode's last observation and
                # info: its final score survives the reset.
                assert infos["_final_obs"][i] and infos["_final_info"][i]
                np.testing.assert_array_equal(infos["final_obs"][i], single_obs)
                final = infos["final_info"]
                assert final["_score"][i] and list(final["score"][i]) == single_info["score"]
                assert final["steps"][i] == single_info["steps"]
                assert final["score_reward"][i] == np.float32(single_info["score_reward"])
                episodes_ended += 1
                # The vector env has already reset: same first observation and info.
                single_obs, single_info = env.reset()
            else:
                assert "_final_obs" not in infos or not infos["_final_obs"][i]
            np.testing.assert_array_equal(obs[i], single_obs)
            # The same info as the single env's (a reset's info has fewer keys than a step's).
            for key in ("steps_left", "game_mode", "steps", "episode_index"):
                if key in single_info:
                    assert infos["_" + key][i] and infos[key][i] == single_info[key], key
    assert episodes_ended >= n, "the test should cover autoresets"


def test_reset_without_seed_continues_with_the_next_episodes() -> None:
    envs = touchline.vector.make(DRILL, num_envs=2, seed=5)
    singles = [touchline.make(DRILL, seed=5 + i) for i in range(2)]
    envs.reset()
    for env in singles:
        env.reset()
    actions = np.array([5, 5])
    for _ in range(3):
        envs.step(actions)
        for env in singles:
            env.step(5)
    obs, _ = envs.reset()
    for i, env in enumerate(singles):
        np.testing.assert_array_equal(obs[i], env.reset()[0])


def test_copy_false_reuses_the_buffers_and_copy_true_does_not() -> None:
    fast = touchline.vector.make(DRILL, num_envs=2, seed=0, copy=False)
    obs_a, _ = fast.reset()
    obs_b, rew_b, *_ = fast.step(np.array([0, 0]))
    obs_c, rew_c, *_ = fast.step(np.array([0, 0]))
    assert obs_a is obs_b is obs_c and rew_b is rew_c
    safe = touchline.vector.make(DRILL, num_envs=2, seed=0)
    obs_a, _ = safe.reset()
    obs_b, rew_b, *_ = safe.step(np.array([0, 0]))
    obs_c, rew_c, *_ = safe.step(np.array([0, 0]))
    assert not np.shares_memory(obs_b, obs_c) and not np.shares_memory(rew_b, rew_c)
    assert not np.shares_memory(obs_a, obs_b)


def test_thread_counts_agree() -> None:
    results = []
    # 3 and 7 threads for 4 matches: uneven runs, and more threads than matches.
    for threads in (1, 2, 0, 3, 7):
        envs = touchline.vector.make("11_vs_11_stochastic", num_envs=4, num_threads=threads, seed=9)
        envs.reset()
        rng = np.random.default_rng(1)
        trace = []
        for _ in range(50):
            obs, rewards, terminated, truncated, _ = envs.step(rng.integers(19, size=4))
            trace.append(obs.copy())
        results.append(np.stack(trace))
    for other in results[1:]:
        np.testing.assert_array_equal(results[0], other)


def test_close() -> None:
    envs = touchline.vector.make(DRILL, num_envs=2)
    envs.close()
    envs.close()
    assert envs.closed


def test_gymnasium_make_vec_uses_the_rust_vector_env() -> None:
    envs = gymnasium.make_vec(f"touchline/{DRILL}-v0", num_envs=3, seed=4, num_threads=2)
    assert isinstance(envs.unwrapped, touchline.vector.TouchlineVectorEnv)
    obs, _ = envs.reset(seed=4)
    assert obs.shape == (3, 115)
    sync = gymnasium.make_vec(f"touchline/{DRILL}-v0", num_envs=3, vectorization_mode="sync")
    sync_obs, _ = sync.reset(seed=4)
    np.testing.assert_array_equal(obs, sync_obs)  # Gymnasium seeds sub-env i with seed + i too
    sync.close()


def test_record_episode_statistics_around_the_vector_env() -> None:
    # CleanRL's scripts wrap their vector env in this: it must find the episodes' ends and leave
    # the env's own per-match keys alone (issue 16, seams 1 and 2).
    import gymnasium

    envs = gymnasium.wrappers.vector.RecordEpisodeStatistics(
        touchline.vector.make(DRILL, num_envs=2, seed=0)
    )
    envs.reset(seed=0)
    finished = 0
    for _ in range(400):
        _, _, _, _, infos = envs.step(envs.action_space.sample())
        assert infos["score"].shape == (2, 2)
        if "episode" in infos:
            finished += int(infos["_episode"].sum())
            ended = infos["_episode"]
            assert (infos["final_info"]["steps"][ended] == infos["episode"]["l"][ended]).all()
        if finished >= 2:
            break
    assert finished >= 2


@pytest.mark.parametrize("num_threads", [3, 8])
def test_more_threads_than_matches_is_the_same_game(num_threads: int) -> None:
    # More threads than matches run one per match (the others are not started), and a worker's
    # step taken over by the calling thread changes nothing: the trajectories are the same.
    rng = np.random.default_rng(1)
    actions = rng.integers(19, size=(150, 3))
    results = []
    for threads in (1, num_threads):
        envs = touchline.vector.make(DRILL, num_envs=3, num_threads=threads, seed=2)
        obs, _ = envs.reset(seed=2)
        trace = [obs]
        for a in actions:
            obs, rewards, terminated, truncated, _ = envs.step(a)
            trace += [obs, rewards, terminated, truncated]
        results.append(trace)
    for x, y in zip(*results):
        np.testing.assert_array_equal(x, y)
