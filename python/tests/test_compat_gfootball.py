"""`touchline.compat.gfootball`: GRF scripts run unchanged and see GRF-shaped data."""

from __future__ import annotations

from pathlib import Path

import gymnasium
import numpy as np
import pytest
import touchline
from touchline.compat.gfootball import create_environment

#: GRF's EXPOSED_OBSERVATIONS plus the per-controller keys (docs/grf-compatibility.md#raw-observation).
GRF_RAW_KEYS = {
    "ball",
    "ball_direction",
    "ball_rotation",
    "ball_owned_team",
    "ball_owned_player",
    "left_team",
    "left_team_direction",
    "left_team_tired_factor",
    "left_team_yellow_card",
    "left_team_active",
    "left_team_roles",
    "right_team",
    "right_team_direction",
    "right_team_tired_factor",
    "right_team_yellow_card",
    "right_team_active",
    "right_team_roles",
    "score",
    "steps_left",
    "game_mode",
    "active",
    "designated",
    "sticky_actions",
}


def test_grf_random_agent_script() -> None:
    """The random agent of GRF's README, with only the import changed."""
    from touchline.compat.gfootball import create_environment

    env = create_environment(env_name="academy_empty_goal_close", representation="simple115v2")
    obs = env.reset()
    done = False
    steps = 0
    while not done:
        obs, reward, done, info = env.step(env.action_space.sample())
        steps += 1
    assert obs.shape == (115,) and obs.dtype == np.float32
    assert isinstance(reward, float) and isinstance(done, bool)
    assert "score_reward" in info
    assert 1 <= steps <= 401
    env.close()


def test_default_representation_is_smm() -> None:
    env = create_environment(env_name="academy_empty_goal_close")
    obs = env.reset()
    assert obs.shape == (72, 96, 4) and obs.dtype == np.uint8
    assert env.observation_space is not None
    assert env.observation_space.shape == (72, 96, 4)
    assert obs.max() == 255  # marked pixels are 255 (docs/grf-compatibility.md#smm)
    obs, *_ = env.step(0)
    assert obs.shape == (72, 96, 4)


def test_stacked_smm() -> None:
    env = create_environment(env_name="academy_empty_goal_close", stacked=True)
    obs = env.reset()
    assert obs.shape == (72, 96, 16)
    # Reset replicates the first frame 4 times (docs/grf-compatibility.md#frame-stacking).
    for k in range(1, 4):
        np.testing.assert_array_equal(obs[..., 4 * k : 4 * k + 4], obs[..., 0:4])


def test_raw_is_a_list_of_dicts_with_grf_keys() -> None:
    env = create_environment(env_name="academy_empty_goal_close", representation="raw")
    obs = env.reset()
    assert isinstance(obs, list) and len(obs) == 1
    assert set(obs[0]) >= GRF_RAW_KEYS
    assert obs[0]["ball"].shape == (3,)
    assert obs[0]["left_team"].shape == (2, 2)  # 2 left players in this drill
    assert obs[0]["sticky_actions"].shape == (10,)
    assert obs[0]["steps_left"] == 401
    obs, _reward, _done, _info = env.step(5)
    assert isinstance(obs, list) and set(obs[0]) >= GRF_RAW_KEYS
    assert env.unwrapped.observation()[0].keys() == obs[0].keys()


def test_several_players_keep_the_leading_axis() -> None:
    env = create_environment(
        env_name="academy_3_vs_1_with_keeper",
        representation="simple115v2",
        number_of_left_players_agent_controls=2,
        number_of_right_players_agent_controls=1,
    )
    obs = env.reset()
    assert obs.shape == (3, 115)
    assert env.action_space.shape == (3,)
    obs, reward, _done, _info = env.step([0, 0, 0])
    assert reward.shape == (3,) and reward.dtype == np.float32
    assert reward[0] == -reward[2]
    raw = create_environment(
        env_name="academy_3_vs_1_with_keeper",
        representation="raw",
        number_of_left_players_agent_controls=2,
    ).reset()
    assert len(raw) == 2


def test_fixed_engine_seed_is_reproducible() -> None:
    def trace() -> list[np.ndarray]:
        env = create_environment(
            env_name="11_vs_11_stochastic",
            representation="simple115v2",
            other_config_options={"game_engine_random_seed": 17},
        )
        env.action_space.seed(0)
        observations = [env.reset()]
        for _ in range(100):
            observations.append(env.step(env.action_space.sample())[0])
        return observations

    np.testing.assert_array_equal(np.stack(trace()), np.stack(trace()))


def test_other_config_options() -> None:
    env = create_environment(
        env_name="ignored",
        other_config_options={"level": "academy_empty_goal", "action_set": "v2", "real_time": True},
    )
    assert isinstance(env.action_space, gymnasium.spaces.Discrete)
    assert env.action_space.n == 20
    with pytest.raises(ValueError, match="physics_steps_per_frame"):
        create_environment(
            env_name="academy_empty_goal", other_config_options={"physics_steps_per_frame": 5}
        )
    with pytest.raises(ValueError, match="not supported"):
        create_environment(env_name="academy_empty_goal", other_config_options={"players": ["bot"]})


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"env_name": ""}, "env_name"),
        ({"representation": "smm"}, "Unsupported representation: smm"),
        ({"rewards": "checkpoints"}, "scoring"),
        ({"write_goal_dumps": True}, "logdir is empty"),
        ({"write_full_episode_dumps": True}, "logdir is empty"),
        (
            {"write_full_episode_dumps": True, "logdir": "/tmp", "dump_frequency": -1},
            "dump_frequency",
        ),
        ({"extra_players": ["bot:right_players=1"]}, "extra_players"),
        ({"representation": "raw", "stacked": True}, "stacked"),
    ],
)
def test_grf_argument_errors(kwargs: dict, message: str) -> None:
    kwargs.setdefault("env_name", "academy_empty_goal_close")
    with pytest.raises(ValueError, match=message):
        create_environment(**kwargs)


def test_unknown_scenario() -> None:
    with pytest.raises(touchline.ScenarioError, match="did you mean"):
        create_environment(env_name="academy_empty_goal_clos")


def test_step_after_done() -> None:
    env = create_environment(env_name="academy_empty_goal_close", representation="simple115v2")
    env.reset()
    env.action_space.seed(0)
    done = False
    while not done:
        _, _, done, _ = env.step(env.action_space.sample())
    with pytest.raises(RuntimeError):
        env.step(0)


def test_full_episode_and_goal_dumps_are_replays_with_videos(tmp_path: Path) -> None:
    """GRF's dumps as touchline replays (issue 19): every second episode (dump_frequency=2) is
    written whole and round its goal, with a GIF beside each; each replay re-simulates."""
    env = create_environment(
        env_name="academy_empty_goal_close",
        representation="simple115v2",
        write_full_episode_dumps=True,
        write_goal_dumps=True,
        write_video=True,
        dump_frequency=2,
        logdir=str(tmp_path / "dumps"),
        other_config_options={"game_engine_random_seed": 3},
    )
    written: list[list[dict]] = []
    for _ in range(3):
        env.reset()
        done = False
        dumps: list[dict] = []
        steps = 0
        while not done:
            # Run right and shoot: the empty goal is scored in about 30 steps.
            _, _, done, info = env.step(12 if steps > 25 else 5)
            steps += 1
            dumps += info.get("dumps", [])
        written.append(dumps)
    assert written[1] == []
    for episode in (0, 2):
        names = sorted(d["name"] for d in written[episode])
        assert names == ["episode_done", "score"], written[episode]
        for d in written[episode]:
            replay = touchline.Replay(d["replay"])
            assert replay.simulate() == replay.frame_hashes
            assert Path(d["video"]).read_bytes()[:6] == b"GIF89a"
        full = next(d for d in written[episode] if d["name"] == "episode_done")
        goal = next(d for d in written[episode] if d["name"] == "score")
        whole, clip = touchline.Replay(full["replay"]), touchline.Replay(goal["replay"])
        # The episode ends on the goal, so the clip holds the (< 100) steps before it.
        assert clip.frame_hashes == whole.frame_hashes[-len(clip.frame_hashes) :]
        assert whole.scores[-1] == [1, 0]
    assert len(list((tmp_path / "dumps").glob("*.tlreplay"))) == 4


def test_write_video_without_dumps_writes_nothing(tmp_path: Path) -> None:
    env = create_environment(
        env_name="academy_empty_goal_close", write_video=True, logdir=str(tmp_path)
    )
    env.reset()
    _, _, _, info = env.step(0)
    assert "dumps" not in info
    assert list(tmp_path.iterdir()) == []
