"""Errors: the exception tree, scenario diagnostics, bad arguments, bad actions, stepping after the end."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
import touchline
import touchline.vector
from touchline.compat.gfootball import create_environment

DRILL = "academy_empty_goal_close"  # a short Academy drill: episodes end within 401 steps
DUEL = "1_vs_1_easy"  # a symmetric 1 + 1 match: one keeper a side, 501 steps


def test_exception_tree_and_exports() -> None:
    assert issubclass(touchline.ScenarioError, touchline.TouchlineError)
    assert issubclass(touchline.TouchlineError, Exception)
    assert isinstance(touchline.__version__, str) and touchline.__version__
    assert DRILL in touchline.scenario_names()
    assert touchline.scenario_names() == sorted(touchline.scenario_names())


def test_unknown_scenario_suggests_the_nearest_name() -> None:
    with pytest.raises(touchline.ScenarioError, match="did you mean") as caught:
        touchline.make("academy_empty_goal_clos")
    assert isinstance(caught.value, touchline.TouchlineError)
    assert "academy_empty_goal_close" in str(caught.value)
    assert isinstance(caught.value.code, str) and caught.value.code


@pytest.mark.parametrize(
    "make",
    [
        lambda name: touchline.parallel_env(name),
        lambda name: touchline.vector.make(name, num_envs=2),
        lambda name: create_environment(env_name=name),
    ],
    ids=["parallel_env", "vector", "gfootball"],
)
def test_unknown_scenario_everywhere(make) -> None:
    with pytest.raises(touchline.ScenarioError, match="did you mean"):
        make("academy_empty_goal_clos")


def test_missing_scenario_file(tmp_path) -> None:
    with pytest.raises(touchline.ScenarioError):
        touchline.make(str(tmp_path / "nowhere.json"))


def test_invalid_scenario_file(tmp_path) -> None:
    path = tmp_path / "broken.json"
    path.write_text('{"name": "broken"')
    with pytest.raises(touchline.ScenarioError):
        touchline.make(path)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"representation": "pixel"}, "unknown representation"),
        ({"representation": "raw"}, "compat"),
        ({"channel_dimensions": (0, 72)}, "channel_dimensions"),
        ({"rewards": "checkpoints"}, "scoring"),
        ({"rewards": "scoring,goals"}, "goals"),
        ({"action_set": "full"}, "full"),
        ({"action_set": "v3"}, "action_set"),
        ({"render_mode": "human"}, "render"),
        ({"seed": -1}, "seed"),
        ({"seed": 1.5}, "seed"),
        ({"channel_dimensions": (96,)}, "channel_dimensions"),
        ({"number_of_left_players_agent_controls": 0}, "at least one"),
        ({"number_of_left_players_agent_controls": -1}, "non-negative"),
    ],
)
def test_bad_arguments(kwargs: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        touchline.make(DRILL, **kwargs)


def test_too_many_controlled_players() -> None:
    with pytest.raises(ValueError):
        touchline.make(DRILL, number_of_left_players_agent_controls=11)


@pytest.mark.parametrize(
    "action", [19, -1, 1.5, True, "shot", [0, 1], np.array([[3]]), np.float32(2)]
)
def test_bad_action_single_player(action) -> None:
    env = touchline.make(DRILL)
    env.reset(seed=0)
    with pytest.raises(ValueError):
        env.step(action)
    env.step(0)  # a bad action leaves the env usable


@pytest.mark.parametrize("action", [np.int64(5), np.int32(5), 5, np.array(5), np.array([5]), [5]])
def test_good_action_forms_single_player(action) -> None:
    env = touchline.make(DRILL)
    env.reset(seed=0)
    env.step(action)


def test_the_extension_reads_action_arrays_in_place_and_any_other_form() -> None:
    # The extension reads a contiguous int64 array in place and falls back to the sequence path
    # for everything else (other dtypes, strided views, lists): every form steps alike.
    core = touchline._touchline.Env(
        "academy_3_vs_1_with_keeper",
        touchline.EnvOptions(number_of_left_players_agent_controls=2),
    )
    forms: list[Any] = [
        np.array([5, 6], dtype=np.int64),
        np.array([5, 6], dtype=np.int32),
        np.array([5, 0, 6, 0], dtype=np.int64)[::2],
        [5, 6],
        (5, 6),
    ]
    observations = []
    for actions in forms:
        core.reset(0)
        observations.append(core.step(actions)[0])
    for observation in observations[1:]:
        np.testing.assert_array_equal(observation, observations[0])
    with pytest.raises(ValueError, match="negative"):
        core.step(np.array([5, -1], dtype=np.int64))
    with pytest.raises(ValueError, match="expected 2 actions"):
        core.step(np.array([5], dtype=np.int64))


@pytest.mark.parametrize("action", [3, [1, 2, 3], [1, 19], [-1, 0], np.array([0.0, 1.0])])
def test_bad_action_several_players(action) -> None:
    env = touchline.make("academy_3_vs_1_with_keeper", number_of_left_players_agent_controls=2)
    env.reset(seed=0)
    with pytest.raises(ValueError):
        env.step(action)
    env.step([0, 0])


def test_step_after_the_end(play_until_done) -> None:
    env = touchline.make(DRILL)
    env.reset(seed=0)
    play_until_done(env)
    with pytest.raises(RuntimeError):
        env.step(0)
    env.reset()
    env.step(0)


def test_parallel_env_errors() -> None:
    env = touchline.parallel_env(DUEL, 1, 1)
    with pytest.raises(RuntimeError):  # before reset there are no agents
        env.step({"left_0": 0, "right_0": 0})
    env.reset(seed=0)
    with pytest.raises(ValueError, match="right_0"):
        env.step({"left_0": 0})
    with pytest.raises(ValueError, match="left_7"):
        env.step({"left_0": 0, "right_0": 0, "left_7": 0})
    with pytest.raises(ValueError, match="right_0"):
        env.step({"left_0": 0, "right_0": 19})
    with pytest.raises(ValueError):
        touchline.parallel_env(DUEL, representation="raw")


def test_vector_env_errors() -> None:
    envs = touchline.vector.make(DRILL, num_envs=3, seed=0)
    envs.reset()
    for actions in ([0, 1], np.zeros((3, 1), np.int64), [0, 1, 19], np.zeros(3, np.float32)):
        with pytest.raises(ValueError):
            envs.step(actions)
    with pytest.raises(ValueError):
        envs.reset(seed=[1, 2, 3])  # type: ignore[arg-type]  # the wrong type is the test
    with pytest.raises(ValueError):
        touchline.vector.make(DRILL, num_envs=0)
    with pytest.raises(ValueError):
        touchline.vector.make(DRILL, num_envs=2, num_threads=-1)
