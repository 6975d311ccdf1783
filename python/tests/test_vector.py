"""The vector env against N single envs, its autoreset, spaces and buffers."""

from __future__ import annotations

import functools
from typing import Any

import gymnasium
import numpy as np
import pytest
import touchline
import touchline.vector
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, SyncVectorEnv

DRILL = "academy_empty_goal_close"  # a short Academy drill: episodes end within 401 steps


def test_spaces_and_metadata() -> None:
    envs = touchline.vector.make(DRILL, num_envs=4, seed=0)
    assert isinstance(envs, gymnasium.vector.VectorEnv)
    assert envs.num_envs == 4
    # Gymnasium's own default, which its vector observation wrappers require.
    assert envs.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP
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


def _sync_envs(n: int, seed: int, mode: AutoresetMode, **kwargs: Any) -> SyncVectorEnv:
    """Gymnasium's reference vector env over `n` single envs, env i seeded with seed + i."""
    return SyncVectorEnv(
        [functools.partial(touchline.make, DRILL, seed=seed + i, **kwargs) for i in range(n)],
        autoreset_mode=mode,
    )


def _assert_infos_match(ours: dict, theirs: dict) -> None:
    """Every key Gymnasium's vector env reports for an env, ours reports with the same value."""
    for key, value in theirs.items():
        if key.startswith("_") or key == "final_obs" or isinstance(value, dict):
            continue
        mask = theirs["_" + key]
        assert (ours["_" + key][mask]).all(), key
        # Gymnasium batches a list-valued key (score) as an object array of lists.
        expected = [np.asarray(v).tolist() for v in np.asarray(value, dtype=object)[mask]]
        assert np.asarray(ours[key])[mask].tolist() == expected, key


@pytest.mark.parametrize("mode", list(AutoresetMode))
@pytest.mark.parametrize("representation", ["simple115v2", "extracted"])
@pytest.mark.parametrize("num_threads", [1, 2])
def test_equals_gymnasiums_sync_vector_env(
    mode: AutoresetMode, representation: str, num_threads: int
) -> None:
    """Step for step, the same observations, rewards, flags and infos as Gymnasium's
    `SyncVectorEnv` over `touchline.make` envs in the same autoreset mode."""
    n, seed, steps = 3, 100, 600
    envs = touchline.vector.make(
        DRILL,
        num_envs=n,
        num_threads=num_threads,
        seed=seed,
        representation=representation,
        autoreset_mode=mode,
    )
    sync = _sync_envs(n, seed, mode, representation=representation)
    obs, infos = envs.reset(seed=seed)
    sync_obs, sync_infos = sync.reset(seed=seed)
    np.testing.assert_array_equal(obs, sync_obs)
    _assert_infos_match(infos, sync_infos)
    rng = np.random.default_rng(0)
    episodes_ended = 0
    for _ in range(steps):
        actions = rng.integers(19, size=n)
        result = envs.step(actions)
        expected = sync.step(actions)
        for ours, theirs in zip(result[:4], expected[:4]):
            np.testing.assert_array_equal(ours, theirs)
        infos, sync_infos = result[4], expected[4]
        _assert_infos_match(infos, sync_infos)
        done = result[2] | result[3]
        episodes_ended += int(done.sum())
        if mode == AutoresetMode.SAME_STEP and done.any():
            # The ended episodes' last observation and info survive the reset.
            np.testing.assert_array_equal(infos["_final_obs"], sync_infos["_final_obs"])
            for i in np.flatnonzero(done):
                np.testing.assert_array_equal(infos["final_obs"][i], sync_infos["final_obs"][i])
            _assert_infos_match(infos["final_info"], sync_infos["final_info"])
        elif mode != AutoresetMode.SAME_STEP:
            assert "final_obs" not in infos and "final_info" not in infos
        if mode == AutoresetMode.DISABLED and done.any():
            # Nothing resets by itself: reset just the ended matches, as a trainer must.
            obs, infos = envs.reset(options={"reset_mask": done})
            sync_obs, sync_infos = sync.reset(options={"reset_mask": done})
            np.testing.assert_array_equal(obs, sync_obs)
            _assert_infos_match(infos, sync_infos)
            assert not infos["_steps"][~done].any()
    assert episodes_ended >= n, "the test should cover autoresets"
    sync.close()


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
            obs, _rewards, _terminated, _truncated, _ = envs.step(rng.integers(19, size=4))
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


@pytest.mark.parametrize("mode", [AutoresetMode.NEXT_STEP, AutoresetMode.SAME_STEP])
def test_record_episode_statistics_around_the_vector_env(mode: AutoresetMode) -> None:
    # CleanRL's scripts wrap their vector env in this: it must find the episodes' ends and leave
    # the env's own per-match keys alone (issue 16, seams 1 to 3).
    envs = gymnasium.wrappers.vector.RecordEpisodeStatistics(
        touchline.vector.make(DRILL, num_envs=2, seed=0, autoreset_mode=mode)
    )
    envs.reset(seed=0)
    finished = 0
    for _ in range(1_000):
        _, _, _, _, infos = envs.step(envs.action_space.sample())
        assert infos["score"].shape == (2, 2)
        if "episode" in infos:
            finished += int(infos["_episode"].sum())
            ended = infos["_episode"]
            # The episode's own info: the step's in NEXT_STEP, final_info in SAME_STEP.
            last = infos if mode == AutoresetMode.NEXT_STEP else infos["final_info"]
            assert (last["steps"][ended] == infos["episode"]["l"][ended]).all()
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


def test_gymnasiums_vector_observation_wrappers_accept_it() -> None:
    # NormalizeObservation refuses a vector env whose metadata is not NEXT_STEP; the others
    # transform observations in the layout Gymnasium's own vector envs give.
    from gymnasium.wrappers.vector import (
        DtypeObservation,
        FlattenObservation,
        NormalizeObservation,
        NormalizeReward,
    )

    envs = touchline.vector.make(DRILL, num_envs=2, seed=0, representation="extracted")
    wrapped = NormalizeReward(
        NormalizeObservation(DtypeObservation(FlattenObservation(envs), np.float64))
    )
    obs, _ = wrapped.reset(seed=0)
    assert obs.shape == (2, 72 * 96 * 4)
    for _ in range(5):
        obs, rewards, *_ = wrapped.step(wrapped.action_space.sample())
    assert np.isfinite(obs).all() and np.isfinite(rewards).all()


def test_disabled_autoreset_needs_a_reset_of_the_ended_matches() -> None:
    envs = touchline.vector.make(DRILL, num_envs=2, seed=0, autoreset_mode="Disabled")
    assert envs.metadata["autoreset_mode"] == AutoresetMode.DISABLED
    envs.reset(seed=0)
    rng = np.random.default_rng(0)
    for _ in range(500):
        *_, terminated, truncated, _ = envs.step(rng.integers(19, size=2))
        if (terminated | truncated).any():
            break
    done = terminated | truncated
    assert done.any()
    with pytest.raises(ValueError, match="reset"):
        envs.step(np.zeros(2, dtype=np.int64))
    envs.reset(options={"reset_mask": done})
    envs.step(np.zeros(2, dtype=np.int64))


@pytest.mark.parametrize(
    "mask, message",
    [
        ([True, False], "numpy bool array"),
        (np.array([1, 0]), "numpy bool array"),
        (np.array([True, False, True]), "shape"),
    ],
)
def test_a_bad_reset_mask_is_a_value_error(mask: object, message: str) -> None:
    envs = touchline.vector.make(DRILL, num_envs=2, seed=0)
    with pytest.raises(ValueError, match=message):
        envs.reset(options={"reset_mask": mask})


def test_a_bad_autoreset_mode_is_a_value_error() -> None:
    with pytest.raises(ValueError, match="autoreset_mode"):
        touchline.vector.make(DRILL, num_envs=2, autoreset_mode="Eventually")


SELF_PLAY = "academy_3_vs_1_with_keeper"


@pytest.mark.parametrize("mode", [AutoresetMode.NEXT_STEP, AutoresetMode.SAME_STEP])
def test_self_play_batch_is_pettingzoos_parallel_env_per_match(mode: AutoresetMode) -> None:
    """With players on both sides, entry 2i is match i's left player and 2i + 1 its right one:
    each the same observation and reward as that agent of `touchline.parallel_env`."""
    n, seed = 2, 7
    envs = touchline.vector.make(
        SELF_PLAY,
        num_envs=n,
        seed=seed,
        autoreset_mode=mode,
        number_of_left_players_agent_controls=1,
        number_of_right_players_agent_controls=1,
    )
    assert (envs.num_envs, envs.num_matches, envs.agents_per_match) == (2 * n, n, 2)
    assert envs.controller_sides == ["left", "right"]
    assert envs.observation_space.shape == (2 * n, 115)
    matches = [touchline.parallel_env(SELF_PLAY, seed=seed + i) for i in range(n)]
    obs, _ = envs.reset(seed=seed)
    for i, match in enumerate(matches):
        first, _ = match.reset(seed=seed + i)
        np.testing.assert_array_equal(obs[2 * i], first["left_0"])
        np.testing.assert_array_equal(obs[2 * i + 1], first["right_0"])
    rng = np.random.default_rng(3)
    waiting = [False] * n  # NEXT_STEP: the match resets on this step
    ended = 0
    for _ in range(300):
        actions = rng.integers(19, size=2 * n)
        obs, rewards, terminated, truncated, infos = envs.step(actions)
        for i, match in enumerate(matches):
            left, right = 2 * i, 2 * i + 1
            assert terminated[left] == terminated[right] and truncated[left] == truncated[right]
            if waiting[i]:
                expected, _ = match.reset()
                assert rewards[left] == rewards[right] == 0 and not terminated[left]
                waiting[i] = False
            else:
                step = {"left_0": int(actions[left]), "right_0": int(actions[right])}
                expected, reward, term, trunc, _ = match.step(step)
                assert rewards[left] == np.float32(reward["left_0"])
                assert rewards[right] == np.float32(reward["right_0"])
                assert (terminated[left], truncated[left]) == (term["left_0"], trunc["left_0"])
                if term["left_0"] or trunc["left_0"]:
                    ended += 1
                    if mode == AutoresetMode.SAME_STEP:
                        np.testing.assert_array_equal(
                            infos["final_obs"][right], expected["right_0"]
                        )
                        expected, _ = match.reset()
                    else:
                        waiting[i] = True
            np.testing.assert_array_equal(obs[left], expected["left_0"])
            np.testing.assert_array_equal(obs[right], expected["right_0"])
    assert ended >= 1, "the test should cover an episode's end"


def test_a_reset_mask_must_not_split_a_match() -> None:
    envs = touchline.vector.make(
        SELF_PLAY, num_envs=2, seed=0, number_of_right_players_agent_controls=1
    )
    with pytest.raises(ValueError, match="all players of a match"):
        envs.reset(options={"reset_mask": np.array([True, False, False, False])})
    envs.reset(options={"reset_mask": np.array([False, False, True, True])})
