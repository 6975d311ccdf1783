"""`touchline.EnvOptions` (issue 20, part 4): the envs' shared keyword arguments as one value,
checked once; every env still takes the keyword arguments themselves."""

from __future__ import annotations

import dataclasses
import pickle

import numpy as np
import pytest
import touchline
import touchline.vector
from touchline._touchline import Env as CoreEnv
from touchline._touchline import VectorEnv as CoreVectorEnv

DRILL = "academy_empty_goal_close"


def test_defaults_are_grf_s_and_touchline_s() -> None:
    options = touchline.EnvOptions()
    assert options.representation == "simple115v2"
    assert options.rewards == "scoring"
    assert options.stacked is False
    assert (options.left_agents, options.right_agents) == (1, 0)
    assert options.channel_dimensions == (96, 72)
    assert options.action_set == "default"
    assert options.watch is False


def test_values_are_normalised_once() -> None:
    options = touchline.EnvOptions(
        rewards=" checkpoints , scoring ",
        channel_dimensions=[np.int64(48), 36],  # type: ignore[arg-type]
        number_of_left_players_agent_controls=np.int32(2),  # type: ignore[arg-type]
    )
    assert options.rewards == "scoring,checkpoints"
    assert options.channel_dimensions == (48, 36)
    assert type(options.left_agents) is int and options.left_agents == 2
    with pytest.raises(dataclasses.FrozenInstanceError):
        options.stacked = True  # type: ignore[misc]


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"representation": "pixelz"}, "unknown representation 'pixelz'"),
        ({"rewards": "checkpoints"}, "must contain 'scoring'"),
        ({"rewards": "scoring,goals"}, "unknown reward term 'goals'"),
        ({"action_set": "full"}, "action_set='full'"),
        ({"channel_dimensions": (0, 72)}, "channel_dimensions must be positive"),
        ({"channel_dimensions": 96}, r"channel_dimensions must be \(width, height\)"),
        ({"number_of_left_players_agent_controls": -1}, "non-negative integer"),
        ({"number_of_left_players_agent_controls": 0}, "at least one player"),
        ({"watch": "yes"}, "watch must be True or False"),
        ({"representation": "raw", "stacked": True}, "stacked=True needs an array"),
    ],
)
def test_bad_values_raise_value_error_with_what_is_accepted(
    changes: dict[str, object], message: str
) -> None:
    with pytest.raises(ValueError, match=message):
        touchline.EnvOptions(**changes)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=message):
        touchline.EnvOptions().replace(**changes)


def test_every_env_takes_options_or_the_keyword_arguments() -> None:
    options = touchline.EnvOptions(representation="extracted", channel_dimensions=(48, 36))
    by_keywords = touchline.make(DRILL, representation="extracted", channel_dimensions=(48, 36))
    by_options = touchline.make(DRILL, options=options)
    assert by_keywords.options == by_options.options == options
    assert by_options.observation_space.shape == (36, 48, 4)
    np.testing.assert_array_equal(by_keywords.reset(seed=1)[0], by_options.reset(seed=1)[0])
    assert touchline.parallel_env(DRILL, options=options).options == options
    vector = touchline.vector.make(DRILL, num_envs=2, options=options)
    assert vector.options == options and vector.single_observation_space.shape == (36, 48, 4)


def test_raw_is_refused_where_there_is_no_space() -> None:
    raw = touchline.EnvOptions(representation="raw")
    with pytest.raises(ValueError, match="list of dicts"):
        touchline.make(DRILL, options=raw)
    with pytest.raises(ValueError, match="list of dicts"):
        touchline.vector.make(DRILL, num_envs=2, options=raw)
    core = CoreEnv(DRILL, raw, seed=0)
    assert core.observation_dtype == "raw"


def test_the_extension_reads_any_object_with_the_fields_and_checks_them_again() -> None:
    fields = dataclasses.asdict(touchline.EnvOptions())
    fields["representation"] = "smm3d"
    lookalike = type("Lookalike", (), fields)()
    with pytest.raises(ValueError, match="unknown representation"):
        CoreEnv(DRILL, lookalike)
    with pytest.raises(TypeError, match=r"options must be a touchline\.EnvOptions.*got dict"):
        CoreEnv(DRILL, {"representation": "simple115v2"})  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"options must be a touchline\.EnvOptions"):
        CoreVectorEnv(DRILL, 2, object())  # type: ignore[arg-type]


def test_envs_pickle_with_their_options() -> None:
    options = touchline.EnvOptions(representation="simple115", stacked=True)
    env = touchline.make(DRILL, seed=3, options=options)
    env.reset(seed=3)
    env.step(5)
    copy = pickle.loads(pickle.dumps(env))
    assert copy.options == options
    np.testing.assert_array_equal(env.step(5)[0], copy.step(5)[0])
    core = CoreEnv(DRILL, options, seed=2)
    core_copy = pickle.loads(pickle.dumps(core))
    assert core_copy.observation_shape == core.observation_shape == (460,)
