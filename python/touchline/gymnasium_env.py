"""`FootballEnv`: one touchline match as a `gymnasium.Env`."""

from __future__ import annotations

import os
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from . import _arguments
from ._touchline import Env as _CoreEnv
from .options import EnvOptions
from .recording import ReplayRecording


def reset_info(core: _CoreEnv) -> dict[str, Any]:
    """The info of a reset: `score`, `steps_left`, `game_mode`, `lesson` (with a curriculum also
    `lesson_name`) and `scenario_version`, as in the info of a step."""
    raw = core.raw_observations()[0]
    info: dict[str, Any] = {
        "score": [int(goals) for goals in raw["score"]],
        "steps_left": int(raw["steps_left"]),
        "game_mode": int(raw["game_mode"]),
        "lesson": 0,
        "scenario_version": core.scenario_version,
    }
    lesson = core.lesson
    if lesson is not None:
        info["lesson"], info["lesson_name"] = lesson
    return info


class FootballEnv(ReplayRecording, gymnasium.Env[np.ndarray, Any]):
    """A football match against touchline's built-in AI, with Google Research Football's conventions.

    ## Description

    One scenario of the stdlib (`touchline.scenario_names()`: the Academy drills and the 11 v 11
    matches of GRF), a `.tl` scenario or a compiled `.json` one. The agent controls one or more players of the
    left team (and optionally of the right team); every other player is driven by the built-in AI.
    One step is 0.1 s of game time (10 engine ticks); a full match is 3000 steps.

    ## Action Space

    GRF's action set (docs/grf-compatibility.md#action-sets). `action_set="default"`: `Discrete(19)` —
    0 idle, 1 left, 2 top_left, 3 top, 4 top_right, 5 right, 6 bottom_right, 7 bottom, 8 bottom_left,
    9 long_pass, 10 high_pass, 11 short_pass, 12 shot, 13 sprint, 14 release_direction,
    15 release_sprint, 16 sliding, 17 dribble, 18 release_dribble. `action_set="v2"` adds
    19 builtin_ai (`Discrete(20)`). Directions and sprint/dribble are sticky
    (docs/grf-compatibility.md#sticky-actions). With M > 1 controlled players the space is
    `MultiDiscrete([n] * M)`, left controllers first; a right-team player's directions are in its
    own (rotated) frame.

    ## Observation Space

    Positions are GRF-normalised pitch coordinates (x in [-1, 1] towards the opponent goal,
    y in [-0.42, 0.42], y down), directions are displacements per step in the same units, ball z is
    in metres. Each controller sees the match in its own frame (a right-team player sees itself as
    "left", attacking +x).

    | representation | shape, dtype | content |
    |---|---|---|
    | `simple115v2` | (115,) float32 | 0–21 left positions (x, y per player, padded with −1 to 11 players), 22–43 left directions, 44–65 right positions, 66–87 right directions, 88–90 ball x, y, z, 91–93 ball direction, 94–96 ball owner one-hot (nobody, left, right), 97–107 active player one-hot, 108–114 game mode one-hot (docs/grf-compatibility.md#simple115) |
    | `simple115` | (115,) float32 | the same blocks, the four player blocks back to back and padded only at the end (GRF's legacy layout) |
    | `extracted` | (72, 96, 4) uint8 | Super Mini Map: channels left team, right team, ball, active player; 255 where marked (docs/grf-compatibility.md#smm); (height, width) from `channel_dimensions=(width, height)` |
    | `pixels` | (72, 96, 3) uint8 | the match drawn from above on the CPU, RGB 0–255: own team red attacking right, opponents blue, controlled player ringed in yellow, ball with its shadow (docs/grf-compatibility.md#pixels); size from `channel_dimensions` |
    | `pixels_gray` | (72, 96, 1) uint8 | the same frame in grey, 0.299 R + 0.587 G + 0.114 B |

    `stacked=True` stacks the last 4 observations along the last axis (115 → 460 floats, 4 → 16
    channels, 3 → 12 for `pixels`; docs/grf-compatibility.md#frame-stacking). With M > 1 controlled
    players observations gain a leading axis of size M. The space is `Box(-inf, inf)` for
    `simple115*` (as in GRF) and `Box(0, 255)` for `extracted` and `pixels*`. `representation="raw"`
    is not accepted here (a list of dicts has no Box); use `raw_observations()`,
    `touchline.compat.gfootball` or `touchline._touchline.Env`.

    ## Rewards

    `rewards="scoring"`: +1 when the left team scores, −1 when it concedes (a right-team controller
    gets the opposite). `"scoring,checkpoints"` adds GRF's checkpoint reward: 0.1 for each of 10
    distance rings around the opponent goal, collected while the controlled player owns the ball,
    all paid at once on scoring (docs/grf-compatibility.md#rewards). With M > 1 controlled players,
    GRF returns one reward per player; Gymnasium needs a float, so `reward` is the **mean** of the
    controllers' rewards and `info["rewards"]` holds the float32 vector (M,). For self-play use
    `touchline.parallel_env`.

    ## Starting State

    The scenario's positions (GRF's tables, docs/grf-compatibility.md#scenario-players), drawn again
    at every reset where the scenario randomises them. The first observation has
    `steps_left = game_duration + 1`.

    ## Episode End

    * `terminated`: the scenario's end conditions — a goal, the ball going out of play, or a
      change of possession in the Academy drills (docs/grf-compatibility.md#episode-length).
    * `truncated`: the time limit, after `game_duration + 1` steps (401 for Academy drills, 3001 for
      full matches). Calling `step` after either raises `RuntimeError`; call `reset`.

    `info` carries `score` ([left, right] goals), `steps_left`, `game_mode` (0 normal, 1 kickoff,
    2 goal kick, 3 free kick, 4 corner, 5 throw-in, 6 penalty), `score_reward` (the left team's
    scoring reward this step), `checkpoint_reward`, `event_reward` (the scenario's `reward on …`
    terms), `steps`, `episode`, and with M > 1 `rewards`.

    ## Arguments

    ```python
    touchline.make(scenario, representation="simple115v2", rewards="scoring", stacked=False,
                   number_of_left_players_agent_controls=1, number_of_right_players_agent_controls=0,
                   seed=None, channel_dimensions=(96, 72), action_set="default", render_mode=None)
    gymnasium.make("touchline/academy_empty_goal_close-v0", representation="extracted")
    ```

    * `scenario`: a stdlib name, or the path of a `.tl` or compiled `.json` scenario.
    * `seed`: seed of the first episode; None draws a random one. `reset(seed=s)` reseeds, and
      `reset()` continues with the next episode of the current seed. Same seed and same actions
      give the same trajectory.
    * `render_mode`: None or `"rgb_array"`: `render()` then returns the match drawn from above,
      a (720, 1280, 3) uint8 RGB frame with the scoreboard, made on the CPU (no display needed;
      Gymnasium's `RecordVideo` works with it).
    * `options`: every argument but `scenario`, `seed` and `render_mode` as one
      `touchline.EnvOptions`, used instead of those keyword arguments when given; the env's
      `options` attribute holds the options it was made with, either way.

    ## Version History

    * v0: first version.
    """

    metadata: dict[str, Any] = {"render_modes": ["rgb_array"], "render_fps": 10}  # noqa: RUF012 (the base class declares it so)

    def __init__(
        self,
        scenario: str | os.PathLike[str],
        representation: str = "simple115v2",
        rewards: str = "scoring",
        stacked: bool = False,
        number_of_left_players_agent_controls: int = 1,
        number_of_right_players_agent_controls: int = 0,
        seed: int | None = None,
        channel_dimensions: tuple[int, int] = (96, 72),
        action_set: str = "default",
        render_mode: str | None = None,
        watch: bool = False,
        *,
        options: EnvOptions | None = None,
    ) -> None:
        _arguments.render_mode_argument(render_mode)
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
            "seed": seed,
            "render_mode": render_mode,
            "options": options,
        }
        self.render_mode = render_mode
        self._core = _arguments.core_env(scenario, options, seed)
        self.representation = options.representation
        # A scenario with control_all_players may give the agent more players than asked for.
        self.num_controllers: int = self._core.num_controllers
        self._single = self.num_controllers == 1
        self._action_count: int = self._core.action_count
        self._actions = np.zeros(self.num_controllers, dtype=np.int64)
        shape = tuple(self._core.observation_shape)
        if not self._single:
            shape = (self.num_controllers, *shape)
        self.observation_space = _arguments.observation_box(shape, self._core.observation_dtype)
        self.action_space = (
            spaces.Discrete(self._action_count)
            if self._single
            else spaces.MultiDiscrete([self._action_count] * self.num_controllers)
        )

    def get_state(self) -> bytes:
        """The whole state of the episode as bytes (GRF's `get_state`,
        docs/grf-compatibility.md#determinism).

        The match (physics, players, referee, AI, random stream), sticky actions, reward and
        end-condition bookkeeping, episode counters and stacked frames: restoring it with
        `set_state` and replaying the same actions repeats the trajectory bit for bit. A few KiB
        (GRF: up to 10 MB). The bytes are one checksummed engine snapshot with the stacked frames
        inside it, so a scenario's `start from "FILE"` can start from them too.
        """
        return self._core.get_state()

    def set_state(self, state: bytes) -> None:
        """Restores a state from `get_state` of an env made with the same arguments.

        Raises:
            ValueError: bytes that are not a state of this scenario and representation
                (corrupted, truncated, another scenario or another touchline format version), or
                whose contents are out of range (a position that is not finite, an index past
                its list).
        """
        self._core.set_state(bytes(state))

    def __getstate__(self) -> dict[str, Any]:
        """Pickling keeps the constructor arguments and the episode state."""
        return {"args": self._init_args, "state": self._core.get_state()}

    def __setstate__(self, saved: dict[str, Any]) -> None:
        self.__init__(**saved["args"])  # type: ignore[misc]
        self._core.set_state(saved["state"])

    @property
    def unwrapped(self) -> FootballEnv:
        """This env: it wraps nothing. Typed as `FootballEnv`, so that
        `gymnasium.make("touchline/...").unwrapped.get_state()` type-checks."""
        return self

    @property
    def scenario_name(self) -> str:
        """Name of the scenario being played."""
        return self._core.scenario_name

    @property
    def controller_sides(self) -> list[str]:
        """ "left" or "right" for each controlled player, left controllers first."""
        return self._core.controller_sides

    @property
    def game_duration(self) -> int:
        """The scenario's time limit in steps (the episode truncates after `game_duration + 1`)."""
        return self._core.game_duration

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """Starts an episode: reseeds when `seed` is given, else plays the current seed's next episode.

        `options` is accepted for Gymnasium's API; touchline defines no reset options yet.
        Returns `(observation, info)`; info has `score`, `steps_left`, `game_mode`,
        `scenario_version` and the episode's starting counters. With `watch=True` the env takes
        the newest version of its scenario file that loads here, and warns (`UserWarning`, once
        per failed change) about a change that does not load.
        """
        super().reset(seed=seed)
        if seed is None:
            observation = self._core.reset()
        else:
            observation = self._core.reset(_arguments.checked_seed(seed))
        _arguments.show_watch_messages(self._core)
        return (observation[0] if self._single else observation), reset_info(self._core)

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """One step (0.1 s of game time) with one action index per controlled player.

        Raises:
            ValueError: the action is not an integer index in the action set, or (M > 1) not an
                array of shape (M,).
            RuntimeError: the episode has ended; call `reset`.
        """
        if self._single:
            observation, rewards, terminated, truncated, info = self._core.step(
                _arguments.single_action(action, self._action_count)
            )
            return observation[0], float(rewards[0]), terminated, truncated, info
        _arguments.write_actions(action, self._actions, self._action_count)
        observation, rewards, terminated, truncated, info = self._core.step(self._actions)
        info["rewards"] = rewards
        return observation, float(rewards.mean()), terminated, truncated, info

    def raw_observations(self) -> list[dict[str, Any]]:
        """GRF's raw observation of each controlled player (a dict of numpy arrays,
        docs/grf-compatibility.md#raw-observation)."""
        return self._core.raw_observations()

    def render(self) -> np.ndarray | None:
        """With `render_mode="rgb_array"`: the match drawn from above, a (720, 1280, 3) uint8 RGB
        frame (scoreboard on top, controlled players ringed in yellow). With None: nothing."""
        if self.render_mode == "rgb_array":
            frame: np.ndarray = self._core.render()
            return frame
        return None
