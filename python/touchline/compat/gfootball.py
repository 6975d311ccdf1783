"""GRF's `gfootball.env.create_environment`, for code written against Google Research Football.

```python
from touchline.compat.gfootball import create_environment  # was: from gfootball.env import ...
env = create_environment(env_name="academy_empty_goal_close", representation="simple115v2")
obs = env.reset()
obs, reward, done, info = env.step(env.action_space.sample())
```

The returned env speaks the old gym API that GRF pins (gym 0.21): `reset()` returns the observation
only and `step(action)` returns `(observation, reward, done, info)`, `done` being terminated or
truncated. Observations are shaped as in GRF (docs/grf-compatibility.md#representations,
#multi-agent): one controlled player gives `(115,)` or `(72, 96, 4)`, M players add a leading axis
of size M, and `raw` is always a list of M dicts. The reward is a float for one player and a float32
array (M,) for several.

`pixels` and `pixels_gray` are touchline's CPU-drawn top view (docs/grf-compatibility.md#pixels;
`render=True` is accepted and changes nothing, since touchline draws on demand without a display), and
`env.render(mode="rgb_array")` returns a 1280 × 720 RGB frame (GRF returns BGR there).

GRF's dumps and videos (`write_full_episode_dumps`, `write_goal_dumps`, `write_video`,
`dump_frequency`, `logdir`) are written as touchline replays (`.tlreplay`, with `.gif` videos
beside them): see `touchline.compat.dumps`. As in GRF, `info["dumps"]` lists the dumps a step
finished.

Not available yet (a `ValueError` says so when asked for): `extra_players` and `action_set="full"`. GRF's `control_all_players`
reduction (`MultiAgentToSingleAgent`) is not applied: in such a scenario the env returns every
controllable player.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces

from .. import _arguments
from .._touchline import Env as _CoreEnv
from ..options import EnvOptions
from .dumps import DumpWriter

__all__ = ["FootballEnv", "create_environment"]

#: `other_config_options` keys that change nothing here (video, display, wall-clock pacing).
_COSMETIC_OPTIONS = frozenset(
    {
        "custom_display_stats",
        "display_game_stats",
        "real_time",
        "render_resolution_x",
        "render_resolution_y",
        "video_format",
        "video_quality_level",
    }
)
#: `other_config_options` keys honoured as flags that must stay off.
_OFF_OPTIONS = frozenset({"render"})
#: `other_config_options` keys of the dumps (GRF's Config names), overriding the arguments.
_DUMP_OPTIONS = frozenset({"dump_full_episodes", "dump_scores", "write_video", "tracesdir"})
#: GRF's seed when the user gives none is random per episode; these keys set it.
_SEED_OPTION = "game_engine_random_seed"


class FootballEnv:
    """What `create_environment` returns: one match behind GRF's old gym API.

    Attributes:
        observation_space: a Gymnasium `Box` shaped like the observations (`None` for `raw`,
            whose list of dicts has no Box, as in GRF).
        action_space: `Discrete(19)` for one player, `MultiDiscrete([19] * M)` for M players.
    """

    metadata: dict[str, Any] = {"render.modes": []}  # noqa: RUF012 (the base class declares it so)
    reward_range = (-float("inf"), float("inf"))
    spec = None

    def __init__(
        self, core: _CoreEnv, representation: str, dumps: DumpWriter | None = None
    ) -> None:
        self._core = core
        self._dumps = dumps
        self._representation = representation
        self._count: int = core.num_controllers
        self._single = self._count == 1 and representation != "raw"
        self._action_count: int = core.action_count
        self._actions = np.zeros(self._count, dtype=np.int64)
        self._next_seed: int | None = None
        self.observation_space: spaces.Space[Any] | None
        if representation == "raw":
            self.observation_space = None
        else:
            shape = tuple(core.observation_shape)
            self.observation_space = _arguments.observation_box(
                shape if self._single else (self._count, *shape), core.observation_dtype
            )
        self.action_space: spaces.Space[Any] = (
            spaces.Discrete(self._action_count)
            if self._count == 1
            else spaces.MultiDiscrete([self._action_count] * self._count)
        )

    @property
    def unwrapped(self) -> FootballEnv:
        """This env (GRF's wrappers are folded into it)."""
        return self

    def seed(self, seed: int | None = None) -> list[int]:
        """Old gym's seeding: the next `reset()` starts episode 0 of `seed`."""
        self._next_seed = _arguments.seed_argument(seed)
        return [self._next_seed]

    def reset(self) -> Any:
        """Starts the next episode and returns its first observation."""
        if self._next_seed is not None:
            observation = self._core.reset(self._next_seed)
            self._next_seed = None
        else:
            observation = self._core.reset()
        if self._dumps is not None:
            self._dumps.reset()
        return self._shape(observation)

    def step(self, action: Any) -> tuple[Any, Any, bool, dict[str, Any]]:
        """One step; returns `(observation, reward, done, info)`.

        Accepts an integer (one player) or a list/array of M integers, left players first.

        With dumps on, `info["dumps"]` lists the dumps this step finished, each
        `{"name": "episode_done" | "score" | "lost_score", "replay": path, "video": path or None}`.

        Raises:
            ValueError: a wrong number of actions or an index outside the action set.
            RuntimeError: the episode is done; call `reset()`.
            OSError: a dump cannot be written.
        """
        _arguments.write_actions(action, self._actions, self._action_count)
        observation, rewards, terminated, truncated, info = self._core.step(self._actions)
        reward: Any = float(rewards[0]) if self._count == 1 else rewards
        done = bool(terminated or truncated)
        if self._dumps is not None:
            dumps = self._dumps.step(info, done)
            if dumps:
                info["dumps"] = dumps
        return self._shape(observation), reward, done, info

    def observation(self) -> list[dict[str, Any]]:
        """GRF's `env.unwrapped.observation()`: the raw observation of each controlled player."""
        return self._core.raw_observations()

    def render(self, mode: str = "human") -> Any:
        """GRF's `render(mode="rgb_array")`: the match drawn from above, `(720, 1280, 3)` uint8 RGB.

        Raises:
            ValueError: another mode ("human" needs a window, which touchline does not open).
        """
        if mode != "rgb_array":
            raise ValueError(
                f"render(mode={mode!r}) is not available: touchline draws without a window; "
                "use render(mode='rgb_array') or `touchline view` on recorded replays"
            )
        return self._core.render()

    def close(self) -> None:
        """Nothing to release."""

    def get_state(self, to_pickle: Any = None) -> bytes:
        """The whole state of the match as bytes (GRF's `get_state`; `to_pickle` is ignored)."""
        return self._core.get_state()

    def set_state(self, state: bytes) -> None:
        """Restores a state from `get_state` of an env created with the same arguments."""
        self._core.set_state(bytes(state))

    def _shape(self, observation: Any) -> Any:
        if self._single:
            return observation[0]
        return observation

    def __repr__(self) -> str:
        return (
            f"<touchline.compat.gfootball.FootballEnv {self._core.scenario_name} "
            f"{self._representation} x{self._count}>"
        )


def create_environment(
    env_name: str = "",
    stacked: bool = False,
    representation: str = "extracted",
    rewards: str = "scoring",
    write_goal_dumps: bool = False,
    write_full_episode_dumps: bool = False,
    render: bool = False,
    write_video: bool = False,
    dump_frequency: int = 1,
    logdir: str = "",
    extra_players: list[str] | None = None,
    number_of_left_players_agent_controls: int = 1,
    number_of_right_players_agent_controls: int = 0,
    channel_dimensions: tuple[int, int] = (96, 72),
    other_config_options: dict[str, Any] | None = None,
) -> FootballEnv:
    """GRF's `create_environment` (docs/grf-compatibility.md#create-environment), with the same
    arguments and defaults.

    Args:
        env_name: a stdlib scenario name (GRF's scenario module name) or the path of a `.tl` or
            compiled `.json` scenario.
        stacked: stack the last 4 observations along the last axis.
        representation: "raw", "extracted" (SMM), "simple115" or "simple115v2".
        rewards: comma-separated; must contain "scoring"; "checkpoints" adds the checkpoint reward.
        write_goal_dumps: write a replay round each goal (the 100 steps before it and 1 after),
            `score_<time>.tlreplay` for a goal the agent's team scores, `lost_score_<time>` for one
            it concedes.
        write_full_episode_dumps: write each episode whole, `episode_done_<time>.tlreplay`.
        render: must be False (touchline draws on demand, without a display).
        write_video: with a dump, also write its video, `<dump>.gif` (800 × 450, 10 frames per
            second, drawn on the CPU; GRF writes `.avi`). Without dumps it writes nothing, as in GRF.
        dump_frequency: with N > 1, dumps only for every Nth episode (the 0th, Nth, ...); 0 and 1
            dump every episode.
        logdir: the folder of the dumps (made if missing); must be set when dumps are on.
        extra_players: must be empty for now (no scripted or checkpoint players).
        number_of_left_players_agent_controls, number_of_right_players_agent_controls: players the
            agent controls on each side.
        channel_dimensions: (width, height) of SMM observations.
        other_config_options: GRF Config overrides; `action_set` ("default", "v2"),
            `game_engine_random_seed` and `level` are honoured, display and video settings ignored.

    Raises:
        ValueError: a bad or not-yet-supported argument (GRF asserts in some of these cases).
        touchline.ScenarioError: the scenario cannot be found or loaded.
    """
    options = dict(other_config_options or {})
    level = options.pop("level", env_name)
    if not level:
        raise ValueError("env_name must name a scenario, e.g. env_name='academy_empty_goal_close'")
    if representation not in _arguments.REPRESENTATIONS:
        raise ValueError(f"Unsupported representation: {representation}")
    if stacked and representation == "raw":
        raise ValueError("stacked=True needs an array representation, not 'raw'")
    write_full_episode_dumps = bool(options.pop("dump_full_episodes", write_full_episode_dumps))
    write_goal_dumps = bool(options.pop("dump_scores", write_goal_dumps))
    write_video = bool(options.pop("write_video", write_video))
    logdir = str(options.pop("tracesdir", logdir))
    if (write_goal_dumps or write_full_episode_dumps) and not logdir:
        raise ValueError(
            "dumps are on (write_full_episode_dumps or write_goal_dumps) but logdir is empty: "
            "pass the folder to write them in, e.g. logdir='/tmp/dumps'"
        )
    if (
        isinstance(dump_frequency, bool)
        or not isinstance(dump_frequency, int)
        or dump_frequency < 0
    ):
        raise ValueError(f"dump_frequency must be a non-negative integer, got {dump_frequency!r}")
    if extra_players:
        raise ValueError(
            f"extra_players={extra_players!r} is not supported yet: touchline has no scripted or "
            "checkpoint players; the built-in AI drives every player the agent does not control"
        )
    action_set = options.pop("action_set", "default")
    seed = options.pop(_SEED_OPTION, None)
    physics_steps = options.pop("physics_steps_per_frame", 10)
    if physics_steps != 10:
        raise ValueError(
            f"physics_steps_per_frame={physics_steps!r} is not supported: a step is always 10 ticks"
        )
    for key in sorted(options):
        if key in _COSMETIC_OPTIONS:
            continue
        if key in _OFF_OPTIONS and not options[key]:
            continue
        if key in _OFF_OPTIONS:
            raise ValueError(f"other_config_options[{key!r}] is not available yet in touchline")
        raise ValueError(
            f"other_config_options[{key!r}] is not supported; supported keys are 'action_set', "
            f"'{_SEED_OPTION}', 'level', 'physics_steps_per_frame' (10), the dump settings "
            f"({', '.join(sorted(_DUMP_OPTIONS))}) and the display settings "
            f"({', '.join(sorted(_COSMETIC_OPTIONS))})"
        )
    env_options = EnvOptions(
        representation=representation,
        rewards=rewards,
        stacked=stacked,
        number_of_left_players_agent_controls=number_of_left_players_agent_controls,
        number_of_right_players_agent_controls=number_of_right_players_agent_controls,
        channel_dimensions=channel_dimensions,
        action_set=action_set,
    )
    core = _arguments.core_env(level, env_options, seed)
    dumps = DumpWriter(
        core,
        logdir,
        full_episodes=write_full_episode_dumps,
        goals=write_goal_dumps,
        video=write_video,
        dump_frequency=dump_frequency,
    )
    return FootballEnv(core, representation, dumps if dumps.active else None)
