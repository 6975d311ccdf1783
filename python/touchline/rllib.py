"""touchline for RLlib (needs `ray[rllib]`): env names every Ray worker finds, and PPO configs.

```python
import ray
from touchline.rllib import ppo_config

ray.init()  # or ray.init(address="auto") on a cluster started with `ray start`
algorithm = ppo_config("academy_empty_goal_close", num_env_runners=2).build_algo()
result = algorithm.train()
```

`register()` (which `ppo_config` calls) registers two env names with Ray's registry, which ships
them to every worker process, local or on other machines, so no worker needs Gymnasium's
`touchline:` import-prefix or `import touchline` of its own (touchline must be installed there):

- `"touchline"`: one `FootballEnv` (`touchline.make`), single-agent.
- `"touchline_multi_agent"`: the PettingZoo `touchline.parallel_env` as an RLlib
  `MultiAgentEnv` (RLlib's own `ParallelPettingZooEnv` wrapper), agents `left_0 …`, `right_0 …`.

Their `env_config` is `{"scenario": name or path, **keyword arguments of touchline.make or
touchline.parallel_env}`. A `seed` in it is the base seed: the env of worker w, vector slot v
plays seed `seed + 1000·w + v`, so no two workers play the same matches.
"""

from __future__ import annotations

from typing import Any

from ray.rllib.algorithms.ppo import PPOConfig
from ray.rllib.core.rl_module.multi_rl_module import MultiRLModuleSpec
from ray.rllib.core.rl_module.rl_module import RLModuleSpec
from ray.rllib.env.wrappers.pettingzoo_env import ParallelPettingZooEnv
from ray.tune.registry import register_env

from .gymnasium_env import FootballEnv
from .make import parallel_env

__all__ = [
    "MULTI_AGENT",
    "SINGLE_AGENT",
    "multi_agent_env",
    "ppo_config",
    "register",
    "single_agent_env",
]

#: Ray registry name of the single-agent env.
SINGLE_AGENT = "touchline"
#: Ray registry name of the multi-agent env.
MULTI_AGENT = "touchline_multi_agent"


def _arguments(config: Any) -> tuple[str, dict[str, Any]]:
    """The scenario and keyword arguments of an `env_config` (a dict or RLlib's `EnvContext`)."""
    kwargs = dict(config)
    if "scenario" not in kwargs:
        raise ValueError(
            "env_config needs a 'scenario': a stdlib name such as 'academy_empty_goal_close' "
            "or the path of a .tl or .json scenario"
        )
    scenario = kwargs.pop("scenario")
    if kwargs.get("seed") is not None:
        # EnvContext knows which worker and vector slot builds this env; a plain dict is worker 0.
        worker = getattr(config, "worker_index", 0)
        slot = getattr(config, "vector_index", 0)
        kwargs["seed"] = int(kwargs["seed"]) + 1000 * worker + slot
    return scenario, kwargs


def single_agent_env(config: Any) -> FootballEnv:
    """The env of `"touchline"`: `touchline.make(**env_config)`."""
    scenario, kwargs = _arguments(config)
    return FootballEnv(scenario, **kwargs)


def multi_agent_env(config: Any) -> ParallelPettingZooEnv:
    """The env of `"touchline_multi_agent"`: `touchline.parallel_env(**env_config)` for RLlib."""
    scenario, kwargs = _arguments(config)
    return ParallelPettingZooEnv(parallel_env(scenario, **kwargs))


def register() -> None:
    """Registers `"touchline"` and `"touchline_multi_agent"` with Ray (again is harmless)."""
    register_env(SINGLE_AGENT, single_agent_env)
    register_env(MULTI_AGENT, multi_agent_env)


def ppo_config(
    scenario: str,
    *,
    multi_agent: bool = False,
    self_play: bool = True,
    num_env_runners: int = 2,
    env_config: dict[str, Any] | None = None,
) -> PPOConfig:
    """A PPO config (RLlib's new API stack, torch) on `scenario`, ready for `.build_algo()`.

    Args:
        scenario: a stdlib name or the path of a `.tl` or `.json` scenario.
        multi_agent: one agent per side (`"touchline_multi_agent"`, one controlled player each
            unless `env_config` says otherwise); False: one agent on the left (`"touchline"`).
        self_play: with `multi_agent`, both sides map to one policy `"shared"` (each agent
            observes in its own frame, so one policy plays either side); False gives each side
            its own, `"left"` and `"right"`.
        num_env_runners: Ray actors collecting experience (0: the driver collects). On a cluster
            they spread over its machines.
        env_config: more keyword arguments of `touchline.make` / `touchline.parallel_env`
            (`representation`, `rewards`, `seed`, …).

    Change the rest with RLlib's own methods (`.training(lr=…)`, `.env_runners(…)`).
    """
    register()
    config = {"scenario": scenario, **(env_config or {})}
    ppo = (
        PPOConfig()
        .environment(MULTI_AGENT if multi_agent else SINGLE_AGENT, env_config=config)
        .env_runners(num_env_runners=num_env_runners)
        .training(gamma=0.993, lambda_=0.95, lr=3e-4, entropy_coeff=0.01)
    )
    if not multi_agent:
        return ppo
    if self_play:
        return ppo.multi_agent(
            policies={"shared"}, policy_mapping_fn=lambda agent_id, episode, **kwargs: "shared"
        ).rl_module(rl_module_spec=MultiRLModuleSpec(rl_module_specs={"shared": RLModuleSpec()}))
    return ppo.multi_agent(
        policies={"left", "right"},
        policy_mapping_fn=lambda agent_id, episode, **kwargs: agent_id.split("_")[0],
    ).rl_module(
        rl_module_spec=MultiRLModuleSpec(
            rl_module_specs={"left": RLModuleSpec(), "right": RLModuleSpec()}
        )
    )
