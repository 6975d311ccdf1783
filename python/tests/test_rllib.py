"""touchline.rllib: the env names Ray workers build, and PPO training through them.

Skipped where `ray[rllib]` is not installed. `.ci/run` runs this file in a venv of its own that
has it (RLlib pins its own Gymnasium), and the example `examples/python/rllib_ppo.py` for two
iterations with env runners.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("ray.rllib")

import ray
from ray.rllib.env.env_context import EnvContext
from touchline import rllib


def test_single_agent_env_is_touchline_make() -> None:
    env = rllib.single_agent_env({"scenario": "academy_empty_goal_close", "seed": 3})
    observation, _ = env.reset()
    assert observation.shape == (115,)
    import touchline

    np.testing.assert_array_equal(
        observation, touchline.make("academy_empty_goal_close", seed=3).reset()[0]
    )


def test_each_worker_and_slot_plays_its_own_seed() -> None:
    # A match starts the same every time; its stochastic play then differs by seed (within 400
    # steps: the kickoff and the first seconds can play out the same, as the AI draws no dice there).
    config = {"scenario": "11_vs_11_stochastic", "seed": 5}

    def trajectory(worker: int, slot: int) -> bytes:
        env = rllib.single_agent_env(EnvContext(config, worker_index=worker, vector_index=slot))
        env.reset()
        return b"".join(env.step(0)[0].tobytes() for _ in range(400))

    trajectories = {trajectory(w, v) for w in (0, 1, 2) for v in (0, 1)}
    assert len(trajectories) == 6
    assert trajectory(1, 1) == trajectory(1, 1)


def test_multi_agent_env_has_an_agent_a_side() -> None:
    env = rllib.multi_agent_env(
        {
            "scenario": "1_vs_1_easy",
            "number_of_left_players_agent_controls": 1,
            "number_of_right_players_agent_controls": 1,
        }
    )
    observations, _ = env.reset(seed=0)
    assert set(observations) == {"left_0", "right_0"}
    _, rewards, terminated, truncated, _ = env.step({"left_0": 0, "right_0": 0})
    assert set(rewards) == {"left_0", "right_0"}
    assert "__all__" in terminated and "__all__" in truncated


def test_an_env_config_without_a_scenario_is_a_value_error() -> None:
    with pytest.raises(ValueError, match="scenario"):
        rllib.single_agent_env({"seed": 1})


@pytest.mark.parametrize("multi_agent", [False, True])
def test_ppo_trains_an_iteration(multi_agent: bool) -> None:
    ray.init(num_cpus=1, include_dashboard=False, ignore_reinit_error=True)
    try:
        scenario = "1_vs_1_easy" if multi_agent else "academy_empty_goal_close"
        config = rllib.ppo_config(
            scenario, multi_agent=multi_agent, num_env_runners=0, env_config={"seed": 0}
        ).training(train_batch_size_per_learner=256, minibatch_size=64, num_epochs=1)
        algorithm = config.build_algo()
        result = algorithm.train()
        assert result["env_runners"]["num_env_steps_sampled_lifetime"] >= 256
        algorithm.stop()
    finally:
        ray.shutdown()
