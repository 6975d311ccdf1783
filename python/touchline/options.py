"""`EnvOptions`: how an environment is made, as one checked value.

Every touchline environment (`touchline.make`, `touchline.parallel_env`, `touchline.vector.make`,
the GRF-compatible `create_environment`) takes the same keyword arguments. They are gathered here
once, checked once, and handed to the extension as one value (`touchline._touchline.Env(scenario,
options, seed=...)` reads its fields), instead of being passed along one by one.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from . import _arguments


@dataclass(frozen=True)
class EnvOptions:
    """The options of an environment, each checked when the value is made.

    Attributes:
        representation: "simple115v2" (float32 (115,)), "simple115" (GRF's legacy layout),
            "extracted" (Super Mini Map, uint8 (height, width, 4)), "pixels" (uint8 (height,
            width, 3)), "pixels_gray" (uint8 (height, width, 1)) or "raw" (GRF's list of dicts;
            only the GRF-compatible env and the extension's `Env` accept it).
        rewards: "scoring" or "scoring,checkpoints" (GRF's reward names, comma-separated; kept in
            that normal form).
        stacked: stack the last 4 observations along the last axis (not with "raw").
        number_of_left_players_agent_controls: players the agent controls on the left team, ≥ 0.
        number_of_right_players_agent_controls: players the agent controls on the right team,
            ≥ 0; at least one player in all.
        channel_dimensions: (width, height) in pixels of image observations, 1 to 4096 each;
            default GRF's (96, 72).
        action_set: "default" (19 actions) or "v2" (20, adds builtin_ai).
        watch: hot reload of a scenario file (see `touchline.make`).

    Raises:
        ValueError: a bad value, with what is accepted (`TypeError` for a scenario that is not
            a string or path is raised by the envs, which take the scenario separately).
    """

    representation: str = "simple115v2"
    rewards: str = "scoring"
    stacked: bool = False
    number_of_left_players_agent_controls: int = 1
    number_of_right_players_agent_controls: int = 0
    channel_dimensions: tuple[int, int] = (96, 72)
    action_set: str = "default"
    watch: bool = False

    def __post_init__(self) -> None:
        left, right = _arguments.controls_argument(
            self.number_of_left_players_agent_controls,
            self.number_of_right_players_agent_controls,
        )
        checked: dict[str, Any] = {
            "representation": _arguments.representation_argument(
                self.representation, allow_raw=True
            ),
            "rewards": _arguments.rewards_argument(self.rewards),
            "stacked": bool(self.stacked),
            "number_of_left_players_agent_controls": left,
            "number_of_right_players_agent_controls": right,
            "channel_dimensions": _arguments.channel_dimensions_argument(self.channel_dimensions),
            "action_set": _arguments.action_set_argument(self.action_set),
            "watch": _arguments.watch_argument(self.watch),
        }
        if checked["representation"] == "raw" and checked["stacked"]:
            raise ValueError("stacked=True needs an array representation, not 'raw'")
        # Frozen: the checked, normalised values replace what was given, once.
        for name, value in checked.items():
            object.__setattr__(self, name, value)

    @property
    def left_agents(self) -> int:
        """Players the agent controls on the left team (the extension's name)."""
        return self.number_of_left_players_agent_controls

    @property
    def right_agents(self) -> int:
        """Players the agent controls on the right team (the extension's name)."""
        return self.number_of_right_players_agent_controls

    def replace(self, **changes: Any) -> EnvOptions:
        """A copy with some fields changed, checked again."""
        return dataclasses.replace(self, **changes)

    def array_only(self) -> EnvOptions:
        """These options, or ValueError when the representation is "raw" (a list of dicts has no
        Gymnasium space)."""
        _arguments.representation_argument(self.representation, allow_raw=False)
        return self
