"""`touchline.make` and `touchline.parallel_env`: the two ways in for most users."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from .gymnasium_env import FootballEnv
from .options import EnvOptions

if TYPE_CHECKING:
    from .pettingzoo_env import FootballParallelEnv


def make(
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
) -> FootballEnv:
    """A `gymnasium.Env` playing `scenario` (a stdlib name, or the path of a `.tl` or compiled `.json`
    scenario file).

    Args:
        scenario: stdlib name (`touchline.scenario_names()`), or the path of a scenario in
            touchline's language (`.tl`, compiled on load) or compiled by `touchline compile`
            (`.json`).
        representation: "simple115v2" (float32 (115,)), "simple115" (GRF's legacy layout) or
            "extracted" (SMM, uint8 (72, 96, 4)); see `FootballEnv` for every index.
        rewards: "scoring" or "scoring,checkpoints" (GRF's reward names, comma-separated).
        stacked: stack the last 4 observations along the last axis.
        number_of_left_players_agent_controls: players the agent controls on the left team.
        number_of_right_players_agent_controls: players the agent controls on the right team.
        seed: seed of the first episode; None draws a random one.
        channel_dimensions: (width, height) of SMM observations.
        action_set: "default" (19 actions) or "v2" (20, adds builtin_ai).
        render_mode: None or "rgb_array": `render()` returns the match drawn from above, a
            (720, 1280, 3) uint8 RGB frame.
        watch: hot reload. The scenario file (`.tl` or `.json`), its imports and its scripts are
            watched; a change is compiled in the background and the env plays it from its next
            `reset()` (never mid-episode). A change that does not load keeps the last good
            version and warns once (`UserWarning` at the next `reset()`, with the rendered
            diagnostic). `info["scenario_version"]` says which version an episode plays: 1 for
            the file as first loaded, then the count of changes that loaded (0 without watch).
        options: all of the above but `seed` and `render_mode` as one `touchline.EnvOptions`;
            when given, it is used instead of those keyword arguments.

    Raises:
        touchline.ScenarioError: the scenario cannot be found or loaded (with `watch=True` too:
            the first version must load), or `watch=True` names a stdlib scenario (no file to
            watch); the message is the rendered diagnostic, with the nearest names for a
            misspelt one.
        ValueError: a bad argument.
    """
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
    return FootballEnv(scenario, seed=seed, render_mode=render_mode, options=options)


def parallel_env(
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
) -> FootballParallelEnv:
    """A PettingZoo `ParallelEnv` with one agent per controlled player, on one or both teams.

    Agents are `left_0 …` and `right_0 …`, each observing in its own frame; controlling players on
    both sides is self-play. The arguments are those of `make` (`watch=True` included: every
    agent's info carries `scenario_version`); see `FootballParallelEnv`.
    Needs the `pettingzoo` package.
    """
    from .pettingzoo_env import FootballParallelEnv

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
    return FootballParallelEnv(scenario, seed=seed, render_mode=render_mode, options=options)
