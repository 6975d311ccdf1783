"""Rendering from Python: the `pixels` and `pixels_gray` representations, `render()` with
`render_mode="rgb_array"`, and Gymnasium's RecordVideo wrapper."""

from __future__ import annotations

import importlib.util

import gymnasium
import numpy as np
import pytest
import touchline
from gymnasium.utils.env_checker import check_env

DRILL = "academy_counterattack_easy"
# Colours of touchline-render's palette (RGB).
LEFT_SHIRT = (214, 48, 40)
RIGHT_SHIRT = (40, 96, 214)
RING = (255, 230, 0)


def count(frame: np.ndarray, rgb: tuple[int, int, int]) -> int:
    return int(np.all(frame == np.array(rgb, dtype=np.uint8), axis=-1).sum())


@pytest.mark.parametrize("representation", ["pixels", "pixels_gray"])
def test_pixels_pass_check_env(representation: str) -> None:
    env = touchline.make(DRILL, representation=representation, seed=0)
    check_env(env, skip_render_check=True)
    channels = 3 if representation == "pixels" else 1
    assert env.observation_space.shape == (72, 96, channels)
    assert env.observation_space.dtype == np.uint8


def test_pixels_show_the_match_in_the_controllers_frame() -> None:
    env = touchline.make(DRILL, representation="pixels", seed=0)
    obs, _ = env.reset(seed=0)
    assert obs.shape == (72, 96, 3) and obs.dtype == np.uint8
    # Own team red, opponents blue, the controlled player ringed in yellow.
    assert count(obs, LEFT_SHIRT) > 0 and count(obs, RIGHT_SHIRT) > 0
    assert np.any(np.all(np.abs(obs.astype(int) - RING) < 40, axis=-1))
    gray, _ = touchline.make(DRILL, representation="pixels_gray", seed=0).reset(seed=0)
    r, g, b = (obs[..., c].astype(np.int64) for c in range(3))
    expected = (4899 * r + 9617 * g + 1868 * b + 8192) >> 14
    np.testing.assert_array_equal(gray[..., 0], expected.astype(np.uint8))
    # A right-team controller sees itself in red too, attacking to the right.
    env = touchline.make(
        "academy_3_vs_1_with_keeper",
        representation="pixels",
        number_of_left_players_agent_controls=1,
        number_of_right_players_agent_controls=1,
        seed=0,
    )
    both, _ = env.reset(seed=0)
    assert both.shape == (2, 72, 96, 3)
    # Three attackers against one defender (goalkeepers wear their own colours): the left
    # controller sees three red shirts and one blue, the right controller the other way round.
    assert count(both[0], LEFT_SHIRT) > count(both[0], RIGHT_SHIRT) > 0
    assert count(both[1], RIGHT_SHIRT) > count(both[1], LEFT_SHIRT) > 0


def test_pixels_stack_and_resize() -> None:
    env = touchline.make(
        DRILL, representation="pixels", stacked=True, channel_dimensions=(160, 120), seed=1
    )
    obs, _ = env.reset()
    assert obs.shape == (120, 160, 12)
    # Reset fills the stack with copies of the first frame (docs/grf-compatibility.md#frame-stacking).
    np.testing.assert_array_equal(obs[..., 0:3], obs[..., 9:12])
    for _ in range(5):
        obs, *_ = env.step(5)
    assert not np.array_equal(obs[..., 0:3], obs[..., 9:12])
    gray = touchline.make(DRILL, representation="pixels_gray", stacked=True, seed=1)
    assert gray.reset()[0].shape == (72, 96, 4)


def test_pixels_are_deterministic() -> None:
    def rollout() -> list[np.ndarray]:
        env = touchline.make(DRILL, representation="pixels", seed=3)
        frames = [env.reset()[0]]
        for a in [5, 5, 12, 0, 3, 3]:
            frames.append(env.step(a)[0])
        return frames

    for a, b in zip(rollout(), rollout()):
        np.testing.assert_array_equal(a, b)


def test_render_rgb_array() -> None:
    env = touchline.make(DRILL, render_mode="rgb_array", seed=0)
    assert env.metadata["render_modes"] == ["rgb_array"] and env.metadata["render_fps"] == 10
    env.reset()
    first = env.render()
    assert first is not None and first.shape == (720, 1280, 3) and first.dtype == np.uint8
    assert count(first, LEFT_SHIRT) > 100 and count(first, RIGHT_SHIRT) > 100
    for _ in range(10):
        env.step(5)
    later = env.render()
    assert later is not None and not np.array_equal(first, later)
    # Gymnasium's checker, render check included.
    check_env(
        gymnasium.make(
            f"touchline/{DRILL}-v0", representation="pixels", render_mode="rgb_array"
        ).unwrapped
    )


def test_render_from_the_extension_and_compat() -> None:
    core = touchline._touchline.Env(DRILL, touchline.EnvOptions())
    assert core.render(320, 240).shape == (240, 320, 3)
    with pytest.raises(ValueError, match="between 1 and 8192"):
        core.render(0, 10)
    from touchline.compat.gfootball import create_environment

    env = create_environment(env_name=DRILL, representation="pixels", render=True)
    assert env.reset().shape == (72, 96, 3)
    assert env.render(mode="rgb_array").shape == (720, 1280, 3)
    with pytest.raises(ValueError, match="rgb_array"):
        env.render()


def test_pettingzoo_render() -> None:
    env = touchline.parallel_env(
        "academy_3_vs_1_with_keeper",
        render_mode="rgb_array",
        number_of_left_players_agent_controls=2,
    )
    env.reset(seed=0)
    frame = env.render()
    assert frame is not None and frame.shape == (720, 1280, 3)


@pytest.mark.skipif(importlib.util.find_spec("moviepy") is None, reason="RecordVideo needs moviepy")
def test_record_video(tmp_path) -> None:
    env = gymnasium.wrappers.RecordVideo(
        touchline.make("academy_empty_goal_close", render_mode="rgb_array", seed=0),
        str(tmp_path / "videos"),
        episode_trigger=lambda episode: True,
        disable_logger=True,
    )
    env.reset(seed=0)
    for _ in range(30):
        _, _, terminated, truncated, _ = env.step(12)
        if terminated or truncated:
            break
    env.close()
    videos = list((tmp_path / "videos").glob("*.mp4"))
    assert videos and videos[0].stat().st_size > 1000
