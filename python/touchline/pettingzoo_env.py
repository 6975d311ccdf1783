"""`FootballParallelEnv`: one touchline match with several agents, as a PettingZoo `ParallelEnv`."""

from __future__ import annotations

import os
from typing import Any

import numpy as np
from gymnasium import spaces
from pettingzoo import ParallelEnv  # type: ignore[import-untyped]

from . import _arguments
from .gymnasium_env import reset_info
from .options import EnvOptions
from .recording import ReplayRecording


class FootballParallelEnv(ReplayRecording, ParallelEnv[str, np.ndarray, int]):  # type: ignore[misc]
    """Several controlled players, on one team or both (self-play), each an agent.

    Agents are named `left_0 … left_{L-1}` then `right_0 … right_{R-1}`. Every agent observes the
    match in its own frame — a right-team agent sees itself as the "left" team attacking +x
    (docs/grf-compatibility.md#coordinates) — so one policy can play either side; its directional
    actions are read in that frame too. Each agent's observation space is the single-player space of
    `touchline.make` (`Box` (115,) float32 for `simple115v2`, (72, 96, 4) uint8 for `extracted`, ×4
    on the last axis when stacked) and its action space is `Discrete(19)` (20 with `action_set="v2"`).

    Rewards follow GRF (docs/grf-compatibility.md#scoring-reward): every left agent gets the left
    team's scoring reward r, every right agent gets −r; checkpoint rewards go to the agent that owns
    the ball. All agents end together: `terminated` on the scenario's end conditions, `truncated` at
    the time limit, after which `agents` is empty. `infos[agent]` carries `score` ([left, right], in
    the left team's frame as in GRF's info), `steps_left`, `game_mode`, `score_reward` (left
    team's), `checkpoint_reward`, `event_reward` (the scenario's `reward on …` terms), `steps` and
    `episode`.

    Build it with `touchline.parallel_env(...)`; the arguments are those of `touchline.make`
    (`options=` included; the `options` attribute holds them).
    """

    metadata: dict[str, Any] = {  # noqa: RUF012 (the base class declares it so)
        "render_modes": ["rgb_array"],
        "render_fps": 10,
        "name": "touchline_v0",
        "is_parallelizable": True,
    }

    def __init__(
        self,
        scenario: str | os.PathLike[str],
        number_of_left_players_agent_controls: int = 1,
        number_of_right_players_agent_controls: int = 1,
        representation: str = "simple115v2",
        rewards: str = "scoring",
        stacked: bool = False,
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
        self.render_mode = render_mode
        self._core = _arguments.core_env(scenario, options, seed)
        self.representation = options.representation
        sides = list(self._core.controller_sides)
        counts = {"left": 0, "right": 0}
        names = []
        for side in sides:
            names.append(f"{side}_{counts[side]}")
            counts[side] += 1
        self.possible_agents: list[str] = names
        self.agents: list[str] = []
        self._index = {agent: i for i, agent in enumerate(names)}
        self._action_count: int = self._core.action_count
        self._actions = np.zeros(len(names), dtype=np.int64)
        observation_space = _arguments.observation_box(
            tuple(self._core.observation_shape), self._core.observation_dtype
        )
        # One space object per agent, returned every time (PettingZoo's API test checks identity),
        # so that seeding an agent's action space sticks.
        self.observation_spaces: dict[str, spaces.Space[Any]] = {
            agent: (observation_space if i == 0 else _copy_box(observation_space))
            for i, agent in enumerate(names)
        }
        self.action_spaces: dict[str, spaces.Space[Any]] = {
            agent: spaces.Discrete(self._action_count) for agent in names
        }

    def observation_space(self, agent: str) -> spaces.Space[Any]:
        """The observation space of `agent` (the same object on every call)."""
        return self.observation_spaces[agent]

    def action_space(self, agent: str) -> spaces.Space[Any]:
        """The action space of `agent` (the same object on every call)."""
        return self.action_spaces[agent]

    def reset(
        self, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, np.ndarray], dict[str, dict[str, Any]]]:
        """Starts an episode: reseeds when `seed` is given, else plays the current seed's next episode.

        `options` is accepted for PettingZoo's API; touchline defines no reset options yet.
        """
        if seed is None:
            observation = self._core.reset()
        else:
            observation = self._core.reset(_arguments.checked_seed(seed))
        _arguments.show_watch_messages(self._core)
        self.agents = list(self.possible_agents)
        info = reset_info(self._core)
        observations = {agent: observation[i] for i, agent in enumerate(self.agents)}
        infos = {agent: dict(info) for agent in self.agents}
        return observations, infos

    def step(
        self, actions: dict[str, Any]
    ) -> tuple[
        dict[str, np.ndarray],
        dict[str, float],
        dict[str, bool],
        dict[str, bool],
        dict[str, dict[str, Any]],
    ]:
        """One step with an action for every agent.

        Raises:
            ValueError: an agent is missing or unknown, or an action is not an index in the set.
            RuntimeError: the episode has ended (`agents` is empty); call `reset`.
        """
        if not self.agents:
            raise RuntimeError(
                "step() called after the episode ended (agents is empty); call reset()"
            )
        missing = [agent for agent in self.agents if agent not in actions]
        if missing:
            raise ValueError(f"no action given for agent(s) {', '.join(missing)}")
        unknown = [agent for agent in actions if agent not in self._index]
        if unknown:
            raise ValueError(
                f"unknown agent(s) {', '.join(map(repr, unknown))}; the agents are {', '.join(self.agents)}"
            )
        for agent in self.agents:
            action = actions[agent]
            try:
                _arguments.write_actions(
                    action, self._actions[self._index[agent] :][:1], self._action_count
                )
            except ValueError as error:
                raise ValueError(f"agent {agent}: {error}") from None
        observation, rewards, terminated, truncated, info = self._core.step(self._actions)
        agents = self.agents
        observations = {agent: observation[i] for i, agent in enumerate(agents)}
        reward_dict = {agent: float(rewards[i]) for i, agent in enumerate(agents)}
        terminations = dict.fromkeys(agents, bool(terminated))
        truncations = dict.fromkeys(agents, bool(truncated))
        infos = {agent: dict(info) for agent in agents}
        if terminated or truncated:
            self.agents = []
        return observations, reward_dict, terminations, truncations, infos

    def render(self) -> np.ndarray | None:
        """With `render_mode="rgb_array"`: the match drawn from above, a (720, 1280, 3) uint8 RGB
        frame. With None: nothing."""
        if self.render_mode == "rgb_array":
            frame: np.ndarray = self._core.render()
            return frame
        return None

    def close(self) -> None:
        """Nothing to release: the match is freed with the object."""

    def raw_observations(self) -> dict[str, dict[str, Any]]:
        """GRF's raw observation of each agent (a dict of numpy arrays in its frame,
        docs/grf-compatibility.md#raw-observation)."""
        raw = self._core.raw_observations()
        return {agent: raw[i] for i, agent in enumerate(self.possible_agents)}


def _copy_box(box: spaces.Box) -> spaces.Box:
    return spaces.Box(box.low, box.high, box.shape, box.dtype)
