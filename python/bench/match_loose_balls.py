"""Where a full match's loose balls are: how a spell with nobody on the ball starts, how long it
lasts, how often nobody is near the ball, and who has it next.

For tracing the harness's match texture (`loose_share`, `loose_spell`) to its mechanism, side by
side with GRF. Matches are run as the harness runs them (`fidelity_cases.builtin_match`: the
built-in AI on every player, raw observation), one env per match seeded with the match's seed. A
spell is a run of normal-play steps (game_mode 0) on which `ball_owned_team` is -1. It is filed by
how it starts, read off its first step: the ball's speed across the ground (m/s, band) and whether
it is in the air (higher than 0.5 m or rising faster than 2 m/s). A spell ends when someone has the
ball (`same`: the team that had it before the spell, `other`: the other one) or play stops
(`stop`: a restart or the end of the match).

Per band it prints the spells per 1,000 normal-play steps, the share of normal-play steps they
fill (`loose`), the share on which no player stands within `NEAR` m of the ball (`far`), the mean
spell length (steps) and the ends. The closing line gives the totals.

Measured here (11_vs_11_stochastic; GRF 2.10.2 matches 1-2, 5,881 normal-play steps; touchline
at 6686358 matches 1-4, 11,586 steps; distances at GRF's world scale, `fidelity_cases.metres`):

| | loose | far | spells 0-5 / 5-10 m/s on the ground: steps, far | 15-20 m/s in the air: per 1,000, far | 20+ m/s in the air: steps, far |
|---|---|---|---|---|---|
| GRF | 0.428 | 0.071 | 5.4, 0.000 / 7.9, 0.000 | 2.0, 0.003 | 23.5, 0.052 |
| touchline | 0.624 | 0.242 | 12.1, 0.015 / 26.9, 0.037 | 5.9, 0.040 | 37.9, 0.101 |

Most of the loose time touchline has beyond GRF's (0.17 of the 0.20) is time with nobody within
5 m of the ball: its slow balls lie or roll away from every player where GRF's are taken within
about half a second, it plays three times as many balls that fly at 15-20 m/s, and its long balls
come down further from everyone.

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/match_loose_balls.py [--matches N] [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import argparse
import collections
import dataclasses
import math

import fidelity_cases as cases

#: A player within this distance (m) of the ball is near it.
NEAR = 5.0
#: A spell starts in the air when the ball is higher than this (m) ...
AIR_HEIGHT = 0.5
#: ... or rises faster than this (m/s).
AIR_RISE = 2.0
#: Upper edges of the start-speed bands (m/s); the last band is open.
BANDS = (5.0, 10.0, 15.0, 20.0)
ENDS = ("same", "other", "stop")


@dataclasses.dataclass
class Band:
    """The spells of one start band."""

    spells: int = 0
    loose_steps: int = 0
    far_steps: int = 0
    ends: collections.Counter[str] = dataclasses.field(default_factory=collections.Counter)


def band_of(obs: cases.Observation) -> tuple[float, bool]:
    """The start band of a spell whose first step is `obs`: the lower edge of its speed band (m/s)
    and whether the ball is in the air."""
    move = obs["ball_direction"]
    # ball_direction is the ball's movement per step (0.1 s): x and y in raw units, z in metres.
    speed = math.hypot(float(move[0]) * cases.METRES_X, float(move[1]) * cases.METRES_Y) * 10.0
    air = float(obs["ball"][2]) > AIR_HEIGHT or float(move[2]) * 10.0 > AIR_RISE
    return max((edge for edge in (0.0, *BANDS) if speed >= edge), default=0.0), air


def label(band: tuple[float, bool]) -> str:
    """A band as printed, e.g. `5-10 m/s air` or `20+ m/s ground`."""
    low, air = band
    higher = [edge for edge in BANDS if edge > low]
    speeds = f"{low:g}-{higher[0]:g}" if higher else f"{low:g}+"
    return f"{speeds} m/s {'air' if air else 'ground'}"


def nearest(obs: cases.Observation) -> float:
    """Distance (m) from the ball to the nearest player of either team."""
    ball = (float(obs["ball"][0]), float(obs["ball"][1]))
    return min(
        cases.metres(ball, (float(p[0]), float(p[1])))
        for team in ("left_team", "right_team")
        for p in obs[team]
    )


def profile(
    scenario: str, matches: int, seed: int, steps: int
) -> tuple[int, dict[tuple[float, bool], Band]]:
    """The normal-play steps and the spells by start band over `matches` matches."""
    normal = 0
    bands: dict[tuple[float, bool], Band] = collections.defaultdict(Band)
    for match in range(matches):
        spell: Band | None = None
        owner = -1
        for obs in cases.builtin_match(scenario, steps, seed + match):
            if int(obs["game_mode"]) != cases.NORMAL:
                if spell is not None:
                    spell.ends["stop"] += 1
                # A restart's taker shows as the ball's owner: his team had it before the spell.
                spell = None
                owner = int(obs["ball_owned_team"]) if int(obs["ball_owned_team"]) != -1 else owner
                continue
            normal += 1
            now = int(obs["ball_owned_team"])
            if now != -1:
                if spell is not None:
                    spell.ends["same" if now == owner else "other"] += 1
                spell, owner = None, now
                continue
            if spell is None:
                spell = bands[band_of(obs)]
                spell.spells += 1
            spell.loose_steps += 1
            spell.far_steps += nearest(obs) > NEAR
        if spell is not None:
            spell.ends["stop"] += 1
    return normal, bands


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenario", default="11_vs_11_stochastic")
    parser.add_argument("--matches", type=int, default=2)
    parser.add_argument("--seed", type=int, default=1, help="the first match's seed")
    parser.add_argument("--steps", type=int, default=3000, help="steps per match at most")
    args = parser.parse_args()
    normal, bands = profile(args.scenario, args.matches, args.seed, args.steps)
    print(f"{args.scenario}, {args.matches} matches, {normal} normal-play steps")
    print(f"{'start':22} {'per 1000':>8} {'loose':>6} {'far':>6} {'steps':>6}  " + " ".join(ENDS))
    for band in sorted(bands):
        b = bands[band]
        print(
            f"{label(band):22} {1000 * b.spells / normal:8.2f} {b.loose_steps / normal:6.3f} "
            f"{b.far_steps / normal:6.3f} {b.loose_steps / b.spells:6.1f}  "
            + " ".join(f"{b.ends[e]:4d}" for e in ENDS)
        )
    loose = sum(b.loose_steps for b in bands.values()) / normal
    far = sum(b.far_steps for b in bands.values()) / normal
    print(f"loose {loose:.3f} of normal-play steps; nobody within {NEAR:g} m {far:.3f}")


if __name__ == "__main__":
    main()
