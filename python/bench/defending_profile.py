"""How a side defends while the built-in AI attacks it: how many of its outfield players are
goal-side of the ball carrier, and how those left behind the play run.

For comparing touchline with GRF side by side: the same scenario and seeds run with the built-in AI
on every player (action set v2, action 19), through `touchline.compat.gfootball` or, with the
measuring folder of `README.md` first on `PYTHONPATH`, through gfootball itself.

It counts the normal-play steps on which the left side (the agent's, θ = 1 in the 11-v-11
scenarios) has the ball with its carrier in its attacking 40 % (x ≥ 0.2 in observation units). On
each it takes, for the right side's ten outfield players: who is goal-side of the carrier (further
towards the right goal along x) and who is behind him; each one's speed (m/s, from his
`*_team_direction`, the movement of one 0.1 s step) and his run towards his own goal (m/s along
+x); the nearest one's distance to the carrier (m), and the medians of the first to sixth
nearest ones' distances. Speeds are split as `carrier_profile.py`
splits them: below 1 m/s counts as standing, 6 m/s and above as sprinting. Roles are not used:
GRF's players swap formation places during play while the observation keeps their starting roles.

Measured here (seeds 1-3, 3,000 steps each; GRF 2.10.2 and touchline at f9b2785):

| | GRF easy (θ 0.05) | GRF hard (θ 0.95) | touchline easy | touchline hard |
|---|---|---|---|---|
| steps counted | 2,478 | 1,523 | 1,291 | 885 |
| outfield defenders goal-side of the carrier | 1.78 | 2.08 | 2.95 | 2.83 |
| nearest defender to the carrier, mean m | 4.6 | 3.1 | 2.9 | 2.5 |
| of those behind him: standing | 0.20 | 0.11 | 0.06 | 0.07 |
| of those behind him: sprinting | 0.17 | 0.26 | 0.14 | 0.18 |
| of those behind him: run towards their goal, m/s | 2.13 | 2.81 | 2.93 | 3.07 |
| the attackers off the ball: sprinting | 0.19 | 0.22 | 0.11 | 0.15 |

GRF's θ = 0.05 side leaves more of its players behind the play than its θ = 0.95 side, and they
run back slower; touchline's two sides do not differ, and both have about one defender more
goal-side of the carrier than GRF's (docs/grf-compatibility.md#team-ai).

The first to sixth nearest outfield defenders to the carrier, medians over the same steps of
11_vs_11_easy_stochastic (seeds 1-3, 3,000 steps): GRF 2.10.2 4.7, 7.6, 10.8, 14.3, 16.9 and
19.3 m; touchline at a8faecd 3.0, 6.2, 8.1, 11.0, 13.8 and 17.7 m. touchline's defenders gather
nearer the ball.

Usage (from the repository root):
    PYTHONPATH=python:python/bench python3 python/bench/defending_profile.py 11_vs_11_easy_stochastic --seeds 1 2 3
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import fidelity_cases as cases
from fidelity_cases import Observation

#: The carrier's x (observation units) from which his side is in its attacking 40 %.
ATTACKING_X = 0.2
#: Standing below this speed (m/s); sprinting from the second.
STANDING, SPRINTING = 1.0, 6.0
#: How many of the nearest outfield defenders' distances to the carrier are ranked.
RANKED = 6


@dataclasses.dataclass
class DefendingProfile:
    """Per counted step, the defenders goal-side of the carrier and the nearest one's distance
    (m); per defender-step behind the carrier, his speed and run towards his goal (m/s); per
    attacker-step off the ball, his speed (m/s)."""

    goal_side: list[int] = dataclasses.field(default_factory=list)
    nearest: list[float] = dataclasses.field(default_factory=list)
    ranked: list[list[float]] = dataclasses.field(default_factory=list)
    behind_speed: list[float] = dataclasses.field(default_factory=list)
    behind_run_back: list[float] = dataclasses.field(default_factory=list)
    attacker_speed: list[float] = dataclasses.field(default_factory=list)

    def add(self, other: DefendingProfile) -> None:
        """Appends another run's samples."""
        for field in dataclasses.fields(self):
            getattr(self, field.name).extend(getattr(other, field.name))


def speed(step: object) -> float:
    """Speed (m/s) of one observed `*_direction` row (the movement of one 0.1 s step)."""
    dx, dy = float(step[0]), float(step[1])  # type: ignore[index]
    return math.hypot(dx * cases.METRES_X, dy * cases.METRES_Y) * 10.0


def observe(obs: Observation, into: DefendingProfile) -> bool:
    """Adds one observation's samples when the left side has the ball in its attacking 40 % in
    normal play; returns whether it counted."""
    if int(obs["ball_owned_team"]) != 0 or int(obs["game_mode"]) != 0:
        return False
    owner = int(obs["ball_owned_player"])
    carrier = obs["left_team"][owner]
    if float(carrier[0]) < ATTACKING_X:
        return False
    ahead = 0
    distances = []
    for at, step in zip(obs["right_team"][1:], obs["right_team_direction"][1:]):
        dx, dy = float(at[0] - carrier[0]), float(at[1] - carrier[1])
        distances.append(math.hypot(dx * cases.METRES_X, dy * cases.METRES_Y))
        if dx > 0.0:
            ahead += 1
        else:
            into.behind_speed.append(speed(step))
            into.behind_run_back.append(float(step[0]) * cases.METRES_X * 10.0)
    distances.sort()
    into.goal_side.append(ahead)
    # A side of a keeper alone (the empty-goal drills) has no outfield defender: none is near.
    into.nearest.append(distances[0] if distances else math.inf)
    into.ranked.append(distances[:RANKED])
    for i, step in enumerate(obs["left_team_direction"]):
        if i != 0 and i != owner:
            into.attacker_speed.append(speed(step))
    return True


def profile(scenario: str, steps: int, seed: int) -> DefendingProfile:
    """One run of `steps` steps with the built-in AI on every player."""
    result = DefendingProfile()
    for obs in cases.builtin_match(scenario, steps, seed):
        observe(obs, result)
    return result


def share(values: list[float], test: float, above: bool) -> float:
    """Share of `values` at or above `test` (`above`) or below it."""
    if not values:
        return math.nan
    return sum((v >= test) == above for v in values) / len(values)


def median(values: list[float]) -> float:
    """Median, or NaN for no values."""
    if not values:
        return math.nan
    ordered = sorted(values)
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else (ordered[middle - 1] + ordered[middle]) / 2


def mean(values: list[float] | list[int]) -> float:
    """Mean, or NaN for no values."""
    return sum(values) / len(values) if values else math.nan


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenario")
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    args = parser.parse_args()
    total = DefendingProfile()
    for seed in args.seeds:
        total.add(profile(args.scenario, args.steps, seed))
    print(f"steps counted {len(total.goal_side)} ({args.scenario}, seeds {args.seeds})")
    print(f"outfield defenders goal-side of the carrier: mean {mean(total.goal_side):.2f}")
    print(f"nearest defender to the carrier: mean {mean(total.nearest):.1f} m")
    ranked = [median([r[k] for r in total.ranked if len(r) > k]) for k in range(RANKED)]
    print(
        "first to sixth nearest outfield defenders, median m: "
        + " ".join(f"{d:.1f}" for d in ranked)
    )
    print(
        f"behind him: standing {share(total.behind_speed, STANDING, False):.2f}, "
        f"sprinting {share(total.behind_speed, SPRINTING, True):.2f}, "
        f"run towards their goal {mean(total.behind_run_back):.2f} m/s"
    )
    print(f"attackers off the ball: sprinting {share(total.attacker_speed, SPRINTING, True):.2f}")


if __name__ == "__main__":
    main()
