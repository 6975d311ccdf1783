"""Batched matches stepped in Rust threads: `touchline.vector.make(scenario, num_envs=N)`.

```python
import touchline
envs = touchline.vector.make("academy_empty_goal_close", num_envs=8, seed=0)
observations, infos = envs.reset(seed=0)
observations, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())
```
"""

from __future__ import annotations

import os
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode
from gymnasium.vector.utils import batch_space

from . import _arguments
from ._touchline import VectorEnv as _CoreVectorEnv

__all__ = ["TouchlineVectorEnv", "make"]


class TouchlineVectorEnv(gymnasium.vector.VectorEnv[np.ndarray, np.ndarray, np.ndarray]):
    """`num_envs` independent matches, one controlled left player each, stepped in Rust threads.

    Each step releases the GIL, steps every match on `num_threads` threads (0: one per core) and
    writes observations `(num_envs, *shape)`, rewards `(num_envs,)` float32 and the terminated and
    truncated flags `(num_envs,)` bool into numpy arrays allocated once. A match that ends is reset
    in the same step (`metadata["autoreset_mode"]` is `AutoresetMode.SAME_STEP`): the observation
    returned for it is the first one of its next episode, and its reward, terminated and truncated
    are those of the step that ended the previous one.

    Env `i` plays with seed `seed + i`: its trajectory is that of `touchline.make(scenario,
    seed=seed + i)` given the same actions, resetting with `reset()` after each episode.

    Args:
        scenario: a stdlib name or the path of a compiled `.json` scenario.
        num_envs: number of matches.
        num_threads: threads stepping the matches, the calling one included, at most one per
            match (more are not started); 0 uses one per core. A step whose worker has not
            started yet, its core busy elsewhere, is done by the calling thread, so threads do
            not make a loaded machine slower than one thread.
        copy: True (the default, as Gymnasium's own vector envs) returns fresh arrays from every
            `reset` and `step`; False returns the preallocated buffers themselves, which the next
            call overwrites — faster, but copy whatever you keep.
        representation, rewards, stacked, seed, channel_dimensions, action_set, render_mode: as
            in `touchline.make`. `seed=None` draws a random seed.

    `infos` follows Gymnasium 1.x's vector layout: every key of a single env's info (`score`
    int64 (num_envs, 2), `steps_left`, `game_mode`, `score_reward`, `checkpoint_reward`,
    `event_reward`, `script_reward`, `script_errors`, `steps`, `episode_index`, `lesson`; one entry
    per match) with its mask `_key`. For a match that just ended these describe its next episode;
    the finished one is in Gymnasium's same-step keys: `final_obs` (object array, the last
    observation of each match that ended, None elsewhere), `final_info` (a dict of the same
    batched keys, zero where no match ended, with their masks) and `_final_obs` / `_final_info`.
    """

    def __init__(
        self,
        scenario: str | os.PathLike[str],
        num_envs: int,
        num_threads: int = 0,
        representation: str = "simple115v2",
        rewards: str = "scoring",
        stacked: bool = False,
        seed: int | None = None,
        channel_dimensions: tuple[int, int] = (96, 72),
        action_set: str = "default",
        render_mode: str | None = None,
        copy: bool = True,
    ) -> None:
        if render_mode is not None:
            raise ValueError(
                f"render_mode={render_mode!r} is not available for vector envs; render one env "
                "with touchline.make(..., render_mode='rgb_array')"
            )
        # Kept to rebuild the env when it is unpickled.
        self._init_args: dict[str, Any] = {
            "scenario": scenario,
            "num_envs": num_envs,
            "num_threads": num_threads,
            "representation": representation,
            "rewards": rewards,
            "stacked": stacked,
            "seed": seed,
            "channel_dimensions": channel_dimensions,
            "action_set": action_set,
            "copy": copy,
        }
        if (
            isinstance(num_envs, bool)
            or not isinstance(num_envs, (int, np.integer))
            or num_envs < 1
        ):
            raise ValueError(f"num_envs must be a positive integer, got {num_envs!r}")
        if (
            isinstance(num_threads, bool)
            or not isinstance(num_threads, (int, np.integer))
            or num_threads < 0
        ):
            raise ValueError(
                f"num_threads must be a non-negative integer (0: one per core), got {num_threads!r}"
            )
        self._core = _CoreVectorEnv(
            _arguments.scenario_argument(scenario),
            int(num_envs),
            num_threads=int(num_threads),
            representation=_arguments.representation_argument(representation, allow_raw=False),
            left_agents=1,
            right_agents=0,
            rewards=_arguments.rewards_argument(rewards),
            action_set=_arguments.action_set_argument(action_set),
            seed=_arguments.seed_argument(seed),
            stacked=bool(stacked),
            channel_dimensions=_arguments.channel_dimensions_argument(channel_dimensions),
        )
        if self._core.num_controllers != 1:
            raise ValueError(
                f"the vector env drives one player per match, but this scenario gives the agent "
                f"{self._core.num_controllers} (control_all_players); use touchline.make or "
                "touchline.parallel_env"
            )
        self.num_envs = int(num_envs)
        self.copy = bool(copy)
        self.render_mode = render_mode
        self.representation = representation
        self.metadata = {"autoreset_mode": AutoresetMode.SAME_STEP, "render_modes": []}
        shape = tuple(self._core.observation_shape)
        self.single_observation_space = _arguments.observation_box(
            shape, self._core.observation_dtype
        )
        self.single_action_space = spaces.Discrete(self._core.action_count)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._action_count: int = self._core.action_count

        n = self.num_envs
        dtype = self.single_observation_space.dtype
        self._observations = np.zeros((n, *shape), dtype=dtype)
        self._rewards = np.zeros(n, dtype=np.float32)
        self._terminated = np.zeros(n, dtype=np.bool_)
        self._truncated = np.zeros(n, dtype=np.bool_)
        self._actions = np.zeros(n, dtype=np.int64)
        self._final_observations = np.zeros((n, *shape), dtype=dtype)
        self._info_rows = np.zeros((n, _INFO_COLUMNS), dtype=np.float64)
        self._final_info_rows = np.zeros((n, _INFO_COLUMNS), dtype=np.float64)
        self._every_env = np.ones(n, dtype=np.bool_)
        # The extension's layout has a controller axis of size 1: views, no copies.
        self._observations_m = self._observations.reshape(n, 1, *shape)
        self._rewards_m = self._rewards.reshape(n, 1)
        self._actions_m = self._actions.reshape(n, 1)

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """Resets every match; with `seed`, match i is reseeded with `seed + i`.

        `options` is accepted for Gymnasium's API; touchline defines no reset options yet.
        """
        if isinstance(seed, (list, tuple)):
            raise ValueError(
                "pass one integer seed (match i gets seed + i) or None, not a list of seeds"
            )
        super().reset(seed=seed)
        if seed is None:
            self._core.reset(self._observations_m)
        else:
            self._core.reset(self._observations_m, _arguments.checked_seed(seed))
        observations = self._observations.copy() if self.copy else self._observations
        self._core.infos(self._info_rows, self._final_info_rows)
        return observations, _info_dict(self._info_rows, self._every_env)

    def step(
        self, actions: Any
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """Steps every match with `actions` (num_envs,) integer indices.

        Raises:
            ValueError: actions of another shape, not integers, or outside the action set.
        """
        array = np.asarray(actions)
        if array.shape != (self.num_envs,):
            raise ValueError(
                f"expected actions of shape ({self.num_envs},) (one per match), got shape {array.shape}"
            )
        if array.dtype.kind not in "iu":
            raise ValueError(f"actions must be integer indices, got dtype {array.dtype}")
        # The range is checked in Rust (a ValueError naming the bad index), once.
        self._actions[:] = array
        self._core.step(
            self._actions_m,
            self._observations_m,
            self._rewards_m,
            self._terminated,
            self._truncated,
            self._final_observations.reshape(self.num_envs, 1, *self._final_observations.shape[1:]),
        )
        infos = self._final_infos()
        if self.copy:
            return (
                self._observations.copy(),
                self._rewards.copy(),
                self._terminated.copy(),
                self._truncated.copy(),
                infos,
            )
        return self._observations, self._rewards, self._terminated, self._truncated, infos

    def _final_infos(self) -> dict[str, Any]:
        """Every match's info, and Gymnasium's same-step autoreset keys for those that ended."""
        self._core.infos(self._info_rows, self._final_info_rows)
        infos = _info_dict(self._info_rows, self._every_env)
        done = self._terminated | self._truncated
        if not done.any():
            return infos
        final_obs = np.full(self.num_envs, None, dtype=object)
        for i in np.flatnonzero(done):
            final_obs[i] = self._final_observations[i].copy()
        rows = np.where(done[:, None], self._final_info_rows, 0.0)
        infos["final_obs"] = final_obs
        infos["_final_obs"] = done.copy()
        infos["final_info"] = _info_dict(rows, done)
        infos["_final_info"] = done.copy()
        return infos

    def __getstate__(self) -> dict[str, Any]:
        """Pickling keeps the constructor arguments, every match's state and the current
        observations, so the copy goes on where this env is (SuperSuit's and RLlib's workers)."""
        return {
            "args": self._init_args,
            "states": self._core.get_states(),
            "observations": self._observations.copy(),
        }

    def __setstate__(self, saved: dict[str, Any]) -> None:
        self.__init__(**saved["args"])  # type: ignore[misc]
        self._core.set_states(saved["states"])
        self._observations[:] = saved["observations"]

    def close_extras(self, **kwargs: Any) -> None:
        """Nothing to release: the matches are freed with the object."""


#: The per-match info keys after `score`, in the extension's column order, with their dtypes.
_INFO_SCALARS = (
    ("steps_left", np.int64),
    ("game_mode", np.int64),
    ("score_reward", np.float32),
    ("checkpoint_reward", np.float32),
    ("event_reward", np.float32),
    ("script_reward", np.float32),
    ("script_errors", np.int64),
    ("steps", np.int64),
    ("episode_index", np.int64),
    ("lesson", np.int64),
)
_INFO_COLUMNS = 2 + len(_INFO_SCALARS)


def _info_dict(rows: np.ndarray, mask: np.ndarray) -> dict[str, Any]:
    """Gymnasium 1.x's vector info layout: each key batched over the matches, `_key` its mask."""
    infos: dict[str, Any] = {"score": rows[:, 0:2].astype(np.int64), "_score": mask.copy()}
    for column, (key, dtype) in enumerate(_INFO_SCALARS, start=2):
        infos[key] = rows[:, column].astype(dtype)
        infos["_" + key] = mask.copy()
    return infos


def make(
    scenario: str | os.PathLike[str],
    num_envs: int,
    num_threads: int = 0,
    **kwargs: Any,
) -> TouchlineVectorEnv:
    """`num_envs` matches of `scenario` stepped in Rust threads; see `TouchlineVectorEnv`."""
    return TouchlineVectorEnv(scenario, num_envs, num_threads=num_threads, **kwargs)
