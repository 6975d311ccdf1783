"""Gymnasium ids `touchline/<scenario>-v0` for every stdlib scenario.

`import touchline` registers them, so `gymnasium.make("touchline/academy_empty_goal_close-v0",
representation="extracted")` works; keyword arguments are those of `touchline.make`.
`gymnasium.make_vec("touchline/<scenario>-v0", num_envs=N)` builds touchline's own vector env
(`touchline.vector.TouchlineVectorEnv`, matches stepped in Rust threads, autoreset
`AutoresetMode.NEXT_STEP` as Gymnasium's own unless `autoreset_mode=` says otherwise); pass
`vectorization_mode="sync"` for Gymnasium's `SyncVectorEnv` instead.
"""

from __future__ import annotations

from typing import Any

import gymnasium

from ._touchline import scenario_names
from .gymnasium_env import FootballEnv
from .vector import TouchlineVectorEnv

#: Bumped whenever a scenario's dynamics or rewards change (Gymnasium's versioning rule).
VERSION = 0


def env_id(scenario: str) -> str:
    """The Gymnasium id of a stdlib scenario: `touchline/<scenario>-v0`."""
    return f"touchline/{scenario}-v{VERSION}"


def make_env(scenario: str, **kwargs: Any) -> FootballEnv:
    """Gymnasium's entry point for the registered ids; the same as `touchline.make`."""
    return FootballEnv(scenario, **kwargs)


def make_vector_env(scenario: str, num_envs: int, **kwargs: Any) -> TouchlineVectorEnv:
    """Gymnasium's vector entry point for the registered ids; the same as `touchline.vector.make`."""
    return TouchlineVectorEnv(scenario, num_envs, **kwargs)


# Lets gymnasium.make check render modes before building the env.
make_env.metadata = FootballEnv.metadata  # type: ignore[attr-defined]


def register_stdlib() -> None:
    """Registers every stdlib scenario once (importing twice does not re-register)."""
    for name in scenario_names():
        if env_id(name) in gymnasium.registry:
            continue
        gymnasium.register(
            id=env_id(name),
            entry_point="touchline.registration:make_env",
            vector_entry_point="touchline.registration:make_vector_env",
            kwargs={"scenario": name},
            # The env truncates at the scenario's own time limit; no TimeLimit wrapper.
            max_episode_steps=None,
            # Same seed and same actions give the same trajectory, in every scenario.
            nondeterministic=False,
        )
