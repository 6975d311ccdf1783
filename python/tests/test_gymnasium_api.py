"""Gymnasium's own checker on every stdlib scenario and representation, and the registered ids."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest
import touchline
from gymnasium import spaces
from gymnasium.utils.env_checker import check_env

DRILL = "academy_empty_goal_close"  # a short Academy drill: episodes end within 401 steps

SCENARIOS = touchline.scenario_names()
REPRESENTATIONS = ["simple115v2", "simple115", "extracted"]

# check_env warns that Box(-inf, inf) is "probably too low/high"; simple115's space is unbounded on
# purpose (GRF's space, docs/grf-compatibility.md#simple115: ball z and directions have no hard bound).
unbounded_box = pytest.mark.filterwarnings(
    r"ignore:.*A Box observation space (minimum|maximum) value is -?infinity:UserWarning"
)


@unbounded_box
@pytest.mark.parametrize("representation", REPRESENTATIONS)
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_check_env(scenario: str, representation: str) -> None:
    env = touchline.make(scenario, representation=representation, seed=0)
    check_env(env, skip_render_check=True)


@unbounded_box
@pytest.mark.parametrize("representation", REPRESENTATIONS)
def test_check_env_stacked_and_several_players(representation: str) -> None:
    env = touchline.make(
        "academy_3_vs_1_with_keeper",
        representation=representation,
        stacked=True,
        number_of_left_players_agent_controls=2,
        number_of_right_players_agent_controls=1,
        seed=0,
    )
    check_env(env, skip_render_check=True)


@unbounded_box
def test_registered_ids_make_and_pass_check_env() -> None:
    for name in SCENARIOS:
        assert f"touchline/{name}-v0" in gymnasium.registry
    env = gymnasium.make("touchline/academy_empty_goal-v0")
    obs, _info = env.reset(seed=0)
    assert obs.shape == (115,) and obs.dtype == np.float32
    obs, reward, _terminated, _truncated, _info = env.step(env.action_space.sample())
    assert isinstance(reward, float)
    check_env(env.unwrapped, skip_render_check=True)
    env.close()


def test_registered_id_passes_arguments() -> None:
    env = gymnasium.make(f"touchline/{DRILL}-v0", representation="extracted", stacked=True)
    obs, _ = env.reset(seed=1)
    assert obs.shape == (72, 96, 16) and obs.dtype == np.uint8


def test_spaces_single_player() -> None:
    env = touchline.make(DRILL)
    assert env.action_space == spaces.Discrete(19)
    assert env.observation_space.shape == (115,)
    assert env.observation_space.dtype == np.float32
    assert touchline.make(DRILL, action_set="v2").action_space == spaces.Discrete(20)


@pytest.mark.parametrize(
    ("representation", "stacked", "dimensions", "shape"),
    [
        ("simple115v2", False, (96, 72), (115,)),
        ("simple115v2", True, (96, 72), (460,)),
        ("simple115", True, (96, 72), (460,)),
        ("extracted", False, (96, 72), (72, 96, 4)),
        ("extracted", True, (96, 72), (72, 96, 16)),
        ("extracted", False, (48, 36), (36, 48, 4)),
    ],
)
def test_observation_shapes(
    representation: str, stacked: bool, dimensions: tuple[int, int], shape: tuple[int, ...]
) -> None:
    env = touchline.make(
        DRILL, representation=representation, stacked=stacked, channel_dimensions=dimensions
    )
    assert env.observation_space.shape == shape
    obs, _ = env.reset(seed=0)
    assert obs.shape == shape
    obs, *_ = env.step(0)
    assert obs.shape == shape and obs in env.observation_space


def test_several_players_reward_is_the_mean_and_info_has_the_vector() -> None:
    env = touchline.make(
        "academy_3_vs_1_with_keeper",
        number_of_left_players_agent_controls=2,
        number_of_right_players_agent_controls=1,
        rewards="scoring,checkpoints",
    )
    assert env.action_space == spaces.MultiDiscrete([19, 19, 19])
    assert env.observation_space.shape == (3, 115)
    assert env.controller_sides == ["left", "left", "right"]
    obs, _ = env.reset(seed=3)
    assert obs.shape == (3, 115)
    env.action_space.seed(0)
    done = False
    while not done:
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        rewards = info["rewards"]
        assert rewards.shape == (3,) and rewards.dtype == np.float32
        assert reward == pytest.approx(float(rewards.mean()))
        done = terminated or truncated


def test_info_and_episode_end(play_until_done) -> None:
    env = touchline.make(DRILL)
    _obs, info = env.reset(seed=0)
    assert info["score"] == [0, 0]
    assert info["steps_left"] == env.game_duration + 1
    assert info["game_mode"] in range(7)
    for seed in range(5):
        env.reset(seed=seed)
        steps, terminated, truncated, info = play_until_done(env, seed=seed)
        assert terminated != truncated
        for key in (
            "score",
            "steps_left",
            "game_mode",
            "score_reward",
            "checkpoint_reward",
            "event_reward",
        ):
            assert key in info
        assert info["steps_left"] == env.game_duration + 1 - steps
        if truncated:
            assert steps == env.game_duration + 1 and info["steps_left"] == 0


def test_time_limit_truncates() -> None:
    """A full match that runs out of time is truncated, never terminated (Gymnasium's rule)."""
    env = touchline.make("1_vs_1_easy", seed=0)
    env.reset()
    steps = 0
    terminated = truncated = False
    while not (terminated or truncated):
        _, _, terminated, truncated, info = env.step(0)
        steps += 1
    assert truncated and not terminated
    assert steps == env.game_duration + 1
    assert info["steps_left"] == 0


def test_raw_observations_next_to_an_array_representation() -> None:
    env = touchline.make(DRILL, representation="extracted")
    env.reset(seed=0)
    (raw,) = env.raw_observations()
    assert raw["left_team"].shape[1] == 2 and raw["steps_left"] == env.game_duration + 1


def test_render_mode_none_renders_nothing() -> None:
    env = touchline.make(DRILL)
    assert env.render_mode is None and env.metadata["render_modes"] == ["rgb_array"]
    assert env.render() is None
    env.close()
    env.close()


def test_record_episode_statistics_wraps_the_env_unchanged() -> None:
    # Every CleanRL script and Stable-Baselines3's Monitor put their episode statistics under
    # info["episode"]; the env must leave that key to them (issue 16, seam 1).
    env = gymnasium.wrappers.RecordEpisodeStatistics(gymnasium.make(f"touchline/{DRILL}-v0"))
    env.reset(seed=0)
    for _ in range(2):
        done, steps = False, 0
        while not done:
            _, _, terminated, truncated, info = env.step(env.action_space.sample())
            steps += 1
            done = terminated or truncated
        assert info["episode"]["l"] == steps
        assert "episode_index" in info
        env.reset()


def test_record_episode_statistics_around_a_gymnasium_vector_env() -> None:
    envs = gymnasium.make_vec(f"touchline/{DRILL}-v0", num_envs=2, vectorization_mode="sync")
    envs = gymnasium.wrappers.vector.RecordEpisodeStatistics(envs)
    envs.reset(seed=0)
    # Seeded actions, and room for two drill episodes of up to 401 steps each in either env.
    envs.action_space.seed(0)
    finished = 0
    for _ in range(1000):
        _, _, _terminated, _truncated, infos = envs.step(envs.action_space.sample())
        if "episode" in infos:
            finished += int(infos["_episode"].sum())
        if finished >= 2:
            break
    assert finished >= 2
