"""How a match's ball carriers play: how fast they run with the ball, how near the nearest opponent
is, and how long one player keeps it.

For comparing touchline's built-in AI with GRF's, side by side: the same scenario and seed run with
the built-in AI on every player (action set v2, action 19), through `touchline.compat.gfootball`
or, with the measuring folder of `README.md` first on `PYTHONPATH`, through gfootball itself.

On every normal-play step on which a player has the ball, it takes his speed (m/s, from his
`*_team_direction`, the movement of one 0.1 s step) and the distance (m) to the nearest opponent;
a spell is a run of steps with the same owner (a loose ball ends it). Speeds are split at GRF's
gait switches (1.8, 4.2 and 6 m/s: standing, dribbling, walking, sprinting; below 1 m/s counts as
standing here, since a carrier who means to stand still drifts a little).

Measured here (3,000 steps, seed 3; GRF 2.10.2 and touchline at 28dbfb6):

| | GRF 11_vs_11_stochastic | GRF 11_vs_11_easy | touchline 11_vs_11_stochastic | touchline 11_vs_11_easy |
|---|---|---|---|---|
| carrier speed, median m/s (quartiles) | 4.8 (2.8-7.0) | 4.5 (2.8-6.4) | 3.5 (3.3-4.9) | 4.9 (3.5-5.0) |
| share of carrier steps at 6 m/s or more | 0.37 | 0.28 | 0.06 | 0.07 |
| nearest opponent, median m (quartiles) | 3.7 (2.4-5.3) | 4.1 (2.4-5.5) | 1.3 (0.7-2.4) | 2.4 (1.6-3.7) |
| spells: count, median, longest (steps) | 106, 7, 104 | 97, 9, 72 | 67, 9, 109 | 79, 8, 124 |

GRF's carriers run at a walk or a sprint with the nearest opponent a few metres off; touchline's
dribble at 3.5 m/s with an opponent at their side (docs/grf-compatibility.md#team-ai).

Usage (from the repository root):
    PYTHONPATH=python:python/bench python3 python/bench/carrier_profile.py 11_vs_11_stochastic --seed 3
"""

from __future__ import annotations

import dataclasses
import math
import statistics

import fidelity_cases as cases
from fidelity_cases import Observation

#: Speed bands (m/s): GRF's gait switches, with standing below 1 m/s.
BANDS = (1.0, 4.2, 6.0)


@dataclasses.dataclass
class CarrierProfile:
    """The carriers of one run: per owned normal-play step, speed (m/s) and nearest opponent (m);
    and the length (steps) of each spell of one player on the ball."""

    speeds: list[float] = dataclasses.field(default_factory=list)
    nearest: list[float] = dataclasses.field(default_factory=list)
    spells: list[int] = dataclasses.field(default_factory=list)

    def band_shares(self) -> list[float]:
        """Share of carrier steps in each speed band: below 1, 1-4.2, 4.2-6, 6 m/s and above."""
        edges = (-math.inf, *BANDS, math.inf)
        n = max(len(self.speeds), 1)
        return [sum(lo <= s < hi for s in self.speeds) / n for lo, hi in zip(edges, edges[1:])]


def carrier(obs: Observation) -> tuple[float, float] | None:
    """The ball carrier's (speed m/s, nearest opponent m) in normal play, or None."""
    team = int(obs["ball_owned_team"])
    if team < 0 or int(obs["game_mode"]) != 0:
        return None
    own, other = ("left_team", "right_team") if team == 0 else ("right_team", "left_team")
    player = int(obs["ball_owned_player"])
    at = obs[own][player]
    step = obs[own + "_direction"][player]
    speed = math.hypot(float(step[0]) * cases.METRES_X, float(step[1]) * cases.METRES_Y) * 10.0
    nearest = min(
        math.hypot(float(o[0] - at[0]) * cases.METRES_X, float(o[1] - at[1]) * cases.METRES_Y)
        for o in obs[other]
    )
    return speed, nearest


def profile(scenario: str, steps: int, seed: int) -> CarrierProfile:
    """The carriers of one run of `steps` steps with the built-in AI on every player."""
    result = CarrierProfile()
    owner: tuple[int, int] | None = None
    spell = 0
    for obs in cases.builtin_match(scenario, steps, seed):
        seen = carrier(obs)
        if seen is not None:
            result.speeds.append(seen[0])
            result.nearest.append(seen[1])
        team = int(obs["ball_owned_team"])
        now = (team, int(obs["ball_owned_player"])) if team >= 0 else None
        if now != owner:
            if owner is not None:
                result.spells.append(spell)
            owner, spell = now, 0
        spell += 1
    if owner is not None:
        result.spells.append(spell)
    return result


def quartiles(values: list[float]) -> str:
    """Median and quartiles, as `median (q1-q3)`."""
    if len(values) < 2:
        return "n/a"
    q1, q2, q3 = statistics.quantiles(values, n=4)
    return f"{q2:.1f} ({q1:.1f}-{q3:.1f})"


def main() -> None:
    args = cases.match_arguments(__doc__.split("\n\n")[0], seed=3)
    p = profile(args.scenario, args.steps, args.seed)
    shares = ", ".join(f"{s:.2f}" for s in p.band_shares())
    print(f"carrier steps {len(p.speeds)}; speed m/s {quartiles(p.speeds)}")
    print(f"speed bands <1 / 1-4.2 / 4.2-6 / >=6 m/s: {shares}")
    print(f"nearest opponent m {quartiles(p.nearest)}")
    if p.spells:
        print(
            f"spells {len(p.spells)}, median {statistics.median(p.spells)}, longest {max(p.spells)} steps"
        )


if __name__ == "__main__":
    main()
