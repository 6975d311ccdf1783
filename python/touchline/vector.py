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
from .options import EnvOptions

__all__ = ["TouchlineVectorEnv", "make"]


class TouchlineVectorEnv(gymnasium.vector.VectorEnv[np.ndarray, np.ndarray, np.ndarray]):
    """Independent matches stepped in Rust threads, each controlled player one entry of the batch.

    A match gives the agent `number_of_left_players_agent_controls` players on the left and
    `number_of_right_players_agent_controls` on the right (self-play when both are set; a
    `control_all_players` scenario may give more). Each controlled player is one entry of the
    batch, so `num_envs` here is matches × players per match (`num_matches` ×
    `agents_per_match`); entry `k` is player `k % agents_per_match` (its side in
    `controller_sides`) of match `k // agents_per_match`. Every player observes in its own frame
    and gets its own side's reward, so one shared policy trains on both teams (self-play)
    with any single-agent trainer. With one player per match the batch is simply the matches.

    Each step releases the GIL, steps every match on `num_threads` threads (0: one per core) and
    writes observations `(num_envs, *shape)`, rewards `(num_envs,)` float32 and the terminated and
    truncated flags `(num_envs,)` bool (the same for every player of a match) into numpy arrays
    allocated once.

    A match that ends is reset as `autoreset_mode` says (Gymnasium's `AutoresetMode`,
    https://farama.org/Vector-Autoreset-Mode; `metadata["autoreset_mode"]` holds it):
    - `NEXT_STEP` (the default, as Gymnasium's own vector envs and their observation and
      normalisation wrappers expect): the step that ends an episode returns its last observation
      and info; on the next step the match's actions are ignored, it is reset, and its reward is
      0 and both flags are False.
    - `SAME_STEP`: the match is reset within the step that ends it; the observation and info
      returned are the next episode's first, the ended episode's are in `final_obs` (object
      array, None where no match ended) and `final_info` (a dict of the batched info keys), with
      masks `_final_obs` / `_final_info`.
    - `DISABLED`: the match stays ended; `reset(options={"reset_mask": mask})` resets the masked
      entries (all players of a match together). Stepping an ended match raises ValueError.

    Match `i` plays with seed `seed + i`: its trajectory is that of `touchline.make(scenario,
    seed=seed + i)` given the same actions, resetting with `reset()` after each episode.

    Args:
        scenario: a stdlib name, or the path of a `.tl` scenario or a compiled `.json` one.
        num_envs: number of matches.
        num_threads: threads stepping the matches, the calling one included, at most one per
            match (more are not started); 0 uses one per core. A step whose worker has not
            started yet, its core busy elsewhere, is done by the calling thread, so threads do
            not make a loaded machine slower than one thread.
        autoreset_mode: an `AutoresetMode` or its value ("NextStep", "SameStep", "Disabled").
        copy: True (the default, as Gymnasium's own vector envs) returns fresh arrays from every
            `reset` and `step`; False returns the preallocated buffers themselves, which the next
            call overwrites — faster, but copy whatever you keep.
        number_of_left_players_agent_controls, number_of_right_players_agent_controls,
        representation, rewards, stacked, seed, channel_dimensions, action_set: as in
            `touchline.make`. `seed=None` draws a random seed.
        watch: hot reload, as in `touchline.make`: every match follows the scenario file and
            takes a change that loads at its next reset (its own, or an autoreset); a change
            that does not load warns once, at the next `reset` or `step`.
        options: those options (all but `seed`) as one `touchline.EnvOptions`, used instead of
            the keyword arguments when given; kept in the `options` attribute either way.

    Raises:
        ValueError: a bad argument, the raw representation (it has no array form) or a
            `render_mode` (render one env with `touchline.make`).

    `infos` follows Gymnasium 1.x's vector layout: every key of a single env's info (`score`
    int64 (num_envs, 2) from the left team's view, `steps_left`, `game_mode`, `score_reward`,
    `checkpoint_reward`, `event_reward`, `script_reward`, `script_errors`, `steps`,
    `episode_index`, `lesson`, `scenario_version`; one row per entry, repeated across a match's players) with its
    mask `_key`.
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
        autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP,
        number_of_left_players_agent_controls: int = 1,
        number_of_right_players_agent_controls: int = 0,
        watch: bool = False,
        *,
        options: EnvOptions | None = None,
    ) -> None:
        if render_mode is not None:
            raise ValueError(
                f"render_mode={render_mode!r} is not available for vector envs; render one env "
                "with touchline.make(..., render_mode='rgb_array')"
            )
        if options is None:
            options = EnvOptions(
                representation=representation,
                rewards=rewards,
                stacked=stacked,
                number_of_left_players_agent_controls=number_of_left_players_agent_controls,
                number_of_right_players_agent_controls=number_of_right_players_agent_controls,
                channel_dimensions=channel_dimensions,
                action_set=action_set,
                watch=watch,
            )
        options.array_only()
        #: The options the env was made with (its keyword arguments, checked).
        self.options = options
        # Kept to rebuild the env when it is unpickled.
        self._init_args: dict[str, Any] = {
            "scenario": scenario,
            "num_envs": num_envs,
            "num_threads": num_threads,
            "seed": seed,
            "copy": copy,
            "autoreset_mode": autoreset_mode,
            "options": options,
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
        self.autoreset_mode = _autoreset_argument(autoreset_mode)
        self._core = _CoreVectorEnv(
            _arguments.scenario_argument(scenario),
            int(num_envs),
            options,
            num_threads=int(num_threads),
            seed=_arguments.seed_argument(seed),
            autoreset_mode=self.autoreset_mode.value,
        )
        #: Matches played side by side.
        self.num_matches = int(num_envs)
        #: Controlled players per match: entries of the batch per match.
        self.agents_per_match: int = self._core.num_controllers
        #: "left" or "right" for each player of a match, in batch order.
        self.controller_sides: list[str] = list(self._core.controller_sides)
        m = self.agents_per_match
        n = self.num_matches
        self.num_envs = n * m
        self.copy = bool(copy)
        self.render_mode = render_mode
        self.representation = options.representation
        self.metadata = {"autoreset_mode": self.autoreset_mode, "render_modes": []}
        shape = tuple(self._core.observation_shape)
        self.single_observation_space = _arguments.observation_box(
            shape, self._core.observation_dtype
        )
        self.single_action_space = spaces.Discrete(self._core.action_count)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._action_count: int = self._core.action_count

        dtype = self.single_observation_space.dtype
        self._observations = np.zeros((n * m, *shape), dtype=dtype)
        self._rewards = np.zeros(n * m, dtype=np.float32)
        self._terminated = np.zeros(n, dtype=np.bool_)
        self._truncated = np.zeros(n, dtype=np.bool_)
        self._actions = np.zeros(n * m, dtype=np.int64)
        self._final_observations = np.zeros((n * m, *shape), dtype=dtype)
        self._info_rows = np.zeros((n, _INFO_COLUMNS), dtype=np.float64)
        self._final_info_rows = np.zeros((n, _INFO_COLUMNS), dtype=np.float64)
        self._every_env = np.ones(n * m, dtype=np.bool_)
        # The extension's layout is (matches, players, ...): views of the flat batch, no copies.
        self._observations_m = self._observations.reshape(n, m, *shape)
        self._final_observations_m = self._final_observations.reshape(n, m, *shape)
        self._rewards_m = self._rewards.reshape(n, m)
        self._actions_m = self._actions.reshape(n, m)

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """Resets every match; with `seed`, match i is reseeded with `seed + i`.

        `options={"reset_mask": mask}` (bool `(num_envs,)`, Gymnasium's key) resets only the
        masked entries; a match's players must be masked together. The infos then carry only the
        reset entries (their `_key` masks). No other option is defined.

        Raises:
            ValueError: a list of seeds, a mask of the wrong shape or dtype, or one that splits
                a match.
        """
        if isinstance(seed, (list, tuple)):
            raise ValueError(
                "pass one integer seed (match i gets seed + i) or None, not a list of seeds"
            )
        super().reset(seed=seed)
        checked = None if seed is None else _arguments.checked_seed(seed)
        mask = None if options is None else options.get("reset_mask")
        if mask is None:
            self._core.reset(self._observations_m, checked)
            entries = self._every_env
        else:
            matches = self._match_mask(mask)
            self._core.reset(self._observations_m, checked, matches.tolist())
            entries = np.repeat(matches, self.agents_per_match)
        observations = self._observations.copy() if self.copy else self._observations
        self._core.infos(self._info_rows, self._final_info_rows)
        _arguments.show_watch_messages(self._core)
        return observations, self._info_dict(self._info_rows, entries)

    def _match_mask(self, mask: Any) -> np.ndarray:
        """The per-match mask of a `reset_mask` over the batch entries."""
        if not isinstance(mask, np.ndarray) or mask.dtype != np.bool_:
            raise ValueError("options['reset_mask'] must be a numpy bool array")
        if mask.shape != (self.num_envs,):
            raise ValueError(
                f"options['reset_mask'] must have shape ({self.num_envs},), got {mask.shape}"
            )
        per_match = mask.reshape(self.num_matches, self.agents_per_match)
        if not (per_match.all(axis=1) | ~per_match.any(axis=1)).all():
            raise ValueError(
                "options['reset_mask'] must mask all players of a match or none "
                f"({self.agents_per_match} consecutive entries per match)"
            )
        return per_match[:, 0].copy()

    def step(
        self, actions: Any
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """Steps every match with `actions` (num_envs,) integer indices.

        Raises:
            ValueError: actions of another shape, not integers, or outside the action set; a
                match stepped after it ended with autoreset DISABLED.
        """
        array = np.asarray(actions)
        if array.shape != (self.num_envs,):
            raise ValueError(
                f"expected actions of shape ({self.num_envs},) (one per controlled player), "
                f"got shape {array.shape}"
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
            self._final_observations_m,
        )
        infos = self._step_infos()
        # Matches reset within steps (autoreset): a change that does not load is told here.
        _arguments.show_watch_messages(self._core)
        terminated, truncated = self._terminated, self._truncated
        if self.agents_per_match > 1:
            terminated = np.repeat(terminated, self.agents_per_match)
            truncated = np.repeat(truncated, self.agents_per_match)
        elif self.copy:
            terminated, truncated = terminated.copy(), truncated.copy()
        if self.copy:
            return self._observations.copy(), self._rewards.copy(), terminated, truncated, infos
        return self._observations, self._rewards, terminated, truncated, infos

    def _step_infos(self) -> dict[str, Any]:
        """Every entry's info and, in SAME_STEP, Gymnasium's keys for the matches that ended."""
        self._core.infos(self._info_rows, self._final_info_rows)
        infos = self._info_dict(self._info_rows, self._every_env)
        if self.autoreset_mode != AutoresetMode.SAME_STEP:
            return infos
        done = np.repeat(self._terminated | self._truncated, self.agents_per_match)
        if not done.any():
            return infos
        final_obs = np.full(self.num_envs, None, dtype=object)
        for i in np.flatnonzero(done):
            final_obs[i] = self._final_observations[i].copy()
        rows = np.where((self._terminated | self._truncated)[:, None], self._final_info_rows, 0.0)
        infos["final_obs"] = final_obs
        infos["_final_obs"] = done.copy()
        infos["final_info"] = self._info_dict(rows, done)
        infos["_final_info"] = done.copy()
        return infos

    def _info_dict(self, rows: np.ndarray, mask: np.ndarray) -> dict[str, Any]:
        """Gymnasium 1.x's vector info layout: each key batched over the entries (a match's
        row repeated for its players), `_key` its mask."""
        if self.agents_per_match > 1:
            rows = np.repeat(rows, self.agents_per_match, axis=0)
        infos: dict[str, Any] = {"score": rows[:, 0:2].astype(np.int64), "_score": mask.copy()}
        for column, (key, dtype) in enumerate(_INFO_SCALARS, start=2):
            infos[key] = rows[:, column].astype(dtype)
            infos["_" + key] = mask.copy()
        return infos

    def __getstate__(self) -> dict[str, Any]:
        """Pickling keeps the constructor arguments, every match's state (and whether it waits
        for its reset) and the current observations, so the copy goes on where this env is
        (SuperSuit's and RLlib's workers)."""
        return {
            "args": self._init_args,
            "states": self._core.get_states(),
            "ended": self._core.ended(),
            "observations": self._observations.copy(),
        }

    def __setstate__(self, saved: dict[str, Any]) -> None:
        self.__init__(**saved["args"])  # type: ignore[misc]
        self._core.set_states(saved["states"], saved.get("ended"))
        self._observations[:] = saved["observations"]

    def close_extras(self, **kwargs: Any) -> None:
        """Nothing to release: the matches are freed with the object."""


def _autoreset_argument(mode: Any) -> AutoresetMode:
    """An `AutoresetMode` from the mode or its value."""
    if isinstance(mode, AutoresetMode):
        return mode
    try:
        return AutoresetMode(mode)
    except ValueError:
        choices = ", ".join(repr(m.value) for m in AutoresetMode)
        raise ValueError(
            f"autoreset_mode must be a gymnasium.vector.AutoresetMode or one of {choices}, "
            f"got {mode!r}"
        ) from None


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
    ("scenario_version", np.int64),
)
_INFO_COLUMNS = 2 + len(_INFO_SCALARS)


def make(
    scenario: str | os.PathLike[str],
    num_envs: int,
    num_threads: int = 0,
    **kwargs: Any,
) -> TouchlineVectorEnv:
    """`num_envs` matches of `scenario` stepped in Rust threads; see `TouchlineVectorEnv` for the
    keyword arguments (autoreset mode, players per side for batched self-play)."""
    return TouchlineVectorEnv(scenario, num_envs, num_threads=num_threads, **kwargs)
