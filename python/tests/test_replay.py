"""Replays written from Python (issue 19): `touchline.RecordReplay` and `save_replay` write the
`.tlreplay` form of `touchline run --record`, and the Rust reader (`touchline.Replay`) re-opens
and re-simulates them with the same state hashes, scripted scenarios included."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import touchline

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def play_recorded(env: Any, seed: int) -> tuple[list[int], list[float], dict[str, Any]]:
    """Plays one episode through a RecordReplay-wrapped Gymnasium env with seeded random actions
    and a made-up value estimate per step; returns the live state hash after reset and after
    every step, the values given, and the last info."""
    env.reset(seed=seed)
    env.action_space.seed(seed)
    hashes = [env.unwrapped.state_hash()]
    values: list[float] = []
    done = False
    info: dict[str, Any] = {}
    while not done:
        value = 0.01 * len(values)
        env.record_values({"value": value})
        values.append(value)
        _, _, terminated, truncated, info = env.step(env.action_space.sample())
        hashes.append(env.unwrapped.state_hash())
        done = terminated or truncated
    return hashes, values, info


@pytest.mark.parametrize(
    "scenario",
    [
        "academy_3_vs_1_with_keeper",
        # A reward script (`reward script "../rewards/distance_to_goal.rhai"`).
        str(EXAMPLES / "scenarios" / "run_to_score_shaped.tl"),
    ],
    ids=["stdlib", "reward_script"],
)
def test_recorded_episode_resimulates_with_matching_state_hashes(
    scenario: str, tmp_path: Path
) -> None:
    env = touchline.RecordReplay(touchline.make(scenario), tmp_path / "replays")
    hashes, values, info = play_recorded(env, seed=5)
    env.close()
    path = Path(info["replay_path"])
    assert path == tmp_path / "replays" / "episode-0.tlreplay"

    replay = touchline.Replay(path)
    assert replay.steps == len(hashes) - 1 > 0
    assert replay.frame_hashes == hashes
    assert replay.simulate() == hashes
    np.testing.assert_array_equal(replay.values["value"], np.array(values, dtype=np.float32))
    assert len(replay.actions) == replay.steps and all(len(a) == 1 for a in replay.actions)
    if scenario.endswith(".tl"):
        assert replay.script_paths == ["../rewards/distance_to_goal.rhai"]


def test_scripted_replay_resimulates_without_the_script_file(tmp_path: Path) -> None:
    (tmp_path / "scenarios").mkdir()
    (tmp_path / "rewards").mkdir()
    scenario = tmp_path / "scenarios" / "run_to_score_shaped.tl"
    shutil.copy(EXAMPLES / "scenarios" / "run_to_score_shaped.tl", scenario)
    script = tmp_path / "rewards" / "distance_to_goal.rhai"
    shutil.copy(EXAMPLES / "rewards" / "distance_to_goal.rhai", script)
    env = touchline.make(str(scenario), seed=2)
    env.reset(seed=2)
    env.unwrapped.start_recording()
    for _ in range(20):
        _, _, terminated, truncated, _ = env.step(5)
        if terminated or truncated:
            break
    live = env.unwrapped.state_hash()
    env.unwrapped.save_replay(tmp_path / "ep.tlreplay")
    script.unlink()
    replay = touchline.Replay(tmp_path / "ep.tlreplay")
    assert replay.simulate()[-1] == live


def test_parallel_env_episodes_record_for_both_teams(tmp_path: Path) -> None:
    env = touchline.RecordReplay(
        touchline.parallel_env(
            "academy_3_vs_1_with_keeper",
            number_of_left_players_agent_controls=2,
            number_of_right_players_agent_controls=1,
        ),
        tmp_path,
        name_prefix="selfplay",
    )
    assert isinstance(env, touchline.ParallelRecordReplay)
    env.reset(seed=1)
    rng = np.random.default_rng(0)
    infos: dict[str, Any] = {}
    while env.agents:
        env.record_values({"value_left": 0.5})
        actions = {agent: int(rng.integers(19)) for agent in env.agents}
        _, _, _, _, infos = env.step(actions)
    path = Path(infos["left_0"]["replay_path"])
    assert path.name == "selfplay-0.tlreplay"
    replay = touchline.Replay(path)
    assert replay.controllers == 3
    assert replay.simulate() == replay.frame_hashes


def test_episode_trigger_and_mid_episode_start(tmp_path: Path) -> None:
    env = touchline.RecordReplay(
        touchline.make("academy_empty_goal_close"), tmp_path, episode_trigger=lambda e: e % 2 == 1
    )
    for episode in range(3):
        env.reset(seed=episode)
        done = False
        while not done:
            _, _, terminated, truncated, info = env.step(0)
            done = terminated or truncated
        assert ("replay_path" in info) == (episode % 2 == 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["episode-1.tlreplay"]

    # Started mid-episode, the replay begins from a snapshot of the state there.
    base = touchline.make("academy_empty_goal_close")
    base.reset(seed=0)
    for _ in range(3):
        base.step(5)
    base.start_recording()
    for _ in range(4):
        base.step(5)
    base.save_replay(tmp_path / "mid.tlreplay")
    replay = touchline.Replay(tmp_path / "mid.tlreplay")
    assert (replay.first_step, replay.steps) == (3, 4)
    assert replay.simulate()[-1] == base.state_hash()


def test_recording_errors_are_clear(tmp_path: Path) -> None:
    env = touchline.make("academy_empty_goal_close")
    env.reset(seed=0)
    with pytest.raises(RuntimeError, match="recording is off"):
        env.save_replay(tmp_path / "x.tlreplay")
    with pytest.raises(RuntimeError, match="recording is off"):
        env.record_values({"value": 1.0})
    env.start_recording()
    with pytest.raises(ValueError, match="real number"):
        env.record_values({"value": "high"})  # type: ignore[dict-item]
    with pytest.raises(ValueError, match="1 to 64 characters"):
        env.record_values({"": 1.0})
    with pytest.raises(OSError, match="cannot write the replay"):
        env.save_replay(tmp_path / "missing-folder" / "x.tlreplay")
    assert not (tmp_path / "missing-folder").exists()
    with pytest.raises(ValueError, match="touchline env"):
        touchline.RecordReplay(object(), tmp_path)  # type: ignore[arg-type]

    bad = tmp_path / "bad.tlreplay"
    bad.write_bytes(b"TLREPLAY" + b"\x00" * 4)
    with pytest.raises(touchline.ReplayError, match="truncated"):
        touchline.Replay(bad)
    with pytest.raises(OSError):
        touchline.Replay(tmp_path / "nothing.tlreplay")
    assert issubclass(touchline.ReplayError, touchline.TouchlineError)


def test_episodes_cut_short_are_saved_as_they_stand(tmp_path: Path) -> None:
    env = touchline.RecordReplay(touchline.make("academy_empty_goal_close"), tmp_path)
    env.reset(seed=0)
    for _ in range(3):
        env.step(5)
    env.reset(seed=1)
    for _ in range(2):
        env.step(5)
    env.close()
    assert touchline.Replay(tmp_path / "episode-0.tlreplay").steps == 3
    assert touchline.Replay(tmp_path / "episode-1.tlreplay").steps == 2


def test_replays_draw_into_gif_and_png_frames(tmp_path: Path) -> None:
    env = touchline.make("academy_empty_goal_close")
    env.reset(seed=0)
    env.start_recording()
    for _ in range(6):
        env.step(5)
    env.save_replay(tmp_path / "ep.tlreplay")
    replay = touchline.Replay(tmp_path / "ep.tlreplay")
    assert replay.write_video(tmp_path / "ep.gif", width=64, height=36) == 7
    assert (tmp_path / "ep.gif").read_bytes()[:6] == b"GIF89a"
    assert replay.write_video(tmp_path / "frames", width=32, height=18, every=3) == 3
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [
        "frame_00000.png",
        "frame_00001.png",
        "frame_00002.png",
    ]
    with pytest.raises(ValueError, match="16 to 8192"):
        replay.write_video(tmp_path / "x.gif", width=8)
    with pytest.raises(OSError, match="unknown video type"):
        replay.write_video(tmp_path / "x.avi")


def test_arrays_of_values_are_stored_per_element_in_order(tmp_path: Path) -> None:
    env = touchline.make("academy_empty_goal_close")
    env.reset(seed=0)
    env.start_recording()
    probs = np.linspace(0.0, 1.0, 19, dtype=np.float32)
    env.record_values({"value": 0.25, "probs": probs, "aux": [1.5, -2.0]})
    env.step(5)
    env.record_values({"value": 0.5})
    env.step(5)
    env.save_replay(tmp_path / "ep.tlreplay")
    values = touchline.Replay(tmp_path / "ep.tlreplay").values
    names = list(values)
    assert names[:3] == ["value", "probs[idle]", "probs[left]"]
    assert names[19:] == ["probs[release_dribble]", "aux[0]", "aux[1]"]
    np.testing.assert_array_equal(values["value"], [0.25, 0.5])
    assert values["probs[release_dribble]"][0] == 1.0 and np.isnan(values["probs[idle]"][1])
    np.testing.assert_array_equal(values["aux[1]"][:1], [-2.0])
    with pytest.raises(ValueError, match="1-D sequence"):
        env.record_values({"grid": np.zeros((2, 2))})
    with pytest.raises(ValueError, match="infinite"):
        env.record_values({"probs": [0.5, float("inf")]})


def test_two_recorders_sharing_a_folder_never_overwrite_each_other(tmp_path: Path) -> None:
    # Two envs of a vector env (or two runs) recording into one folder with the default prefix:
    # the second keeps the first's files and writes `_1` names, with one warning.
    first = touchline.RecordReplay(touchline.make("academy_empty_goal_close"), tmp_path)
    second = touchline.RecordReplay(touchline.make("academy_empty_goal_close"), tmp_path)
    first_hashes, _, first_info = play_recorded(first, seed=1)
    with pytest.warns(UserWarning, match="already exists"):
        second_hashes, _, second_info = play_recorded(second, seed=2)
    assert Path(first_info["replay_path"]) == tmp_path / "episode-0.tlreplay"
    assert Path(second_info["replay_path"]) == tmp_path / "episode-0_1.tlreplay"
    assert touchline.Replay(first_info["replay_path"]).frame_hashes == first_hashes
    assert touchline.Replay(second_info["replay_path"]).frame_hashes == second_hashes
    first.close()
    second.close()
