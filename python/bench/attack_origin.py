"""Where the attacks that end in shots against the agent's team (left) begin: after one of our
players had the ball (and where the ball was then), or straight from one of our restarts with no
touch of ours between (and which restart).

For tracing the harness's full-match goals against (`goals against / match` of the idle and random
agents) side by side with GRF. Matches are run as `shot_profile.py` runs them (`fidelity_cases`:
the harness's policies, raw observation, one env per match seeded `seed + match`), and a shot is
its shot test (`shot_profile.shot`). From each shot the tool walks back step by step: the attack
began at the last step on which our team was the ball's owner (`from_us`), or at the last step of
a restart (`restart`, with GRF's game mode: 2 goal kick, 3 free kick, 4 corner, 5 throw-in), or at
the episode's start. The ball's x is given at that step in metres from halfway (−55 our goal
line, GRF's world scale).

Measured here (2026-11-29; GRF 2.10.2 and touchline at 83d06ed, before its goal-kick places;
11_vs_11_stochastic, idle agent, `--seed 100`):

| | matches | shots a match | from our possession | from our restarts |
|---|---|---|---|---|
| GRF | 6 | 4.33 | 4.33 (ball a median 21 m into our half) | 0 |
| touchline | 20 | 7.25 | 4.60 (17 m) | 2.65 (2.05 from our goal kicks) |

GRF's opponents stand back round halfway at our goal kicks, touchline's stood where the ball had
gone out, inside our half (docs/grf-compatibility.md#formations). With GRF's goal-kick places
(touchline at 7c0a4e3, 20 matches) our restarts give 0.75 shots a match (0.60 from goal kicks)
and our possession 6.60: 7.35 in all. So touchline's attack still gets a shot from about one in
four of the balls it wins off our idle player, GRF's from one in seven (29.8 and 29.6 spells of
our idle player on the ball a match, nearly all lost).

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/attack_origin.py [--scenario S] [--policy idle]
        [--matches N] [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import collections
import dataclasses
import statistics

import fidelity_cases as cases
import shot_profile

#: GRF's names of its game modes, for the restarts printed.
MODES = {
    cases.KICK_OFF: "kickoff",
    cases.GOAL_KICK: "goal kick",
    cases.FREE_KICK: "free kick",
    cases.CORNER: "corner",
    cases.THROW_IN: "throw-in",
    cases.PENALTY: "penalty",
}


@dataclasses.dataclass
class Origin:
    """Where the attack that ended in one shot began."""

    kind: str  # "from_us", "restart" or "start"
    steps: int  # env steps from its start to the shot
    ball_x: float  # m from halfway, −55 at our goal line
    mode: int  # the restart's game mode (NORMAL unless kind is "restart")


def origin(history: list[cases.Observation], shot_at: int) -> Origin:
    """Where the attack that ended in the shot struck between `history[shot_at]` and the step after
    it began: the last step before it with our team on the ball or play stopped."""
    for k in range(shot_at, -1, -1):
        o = history[k]
        mode = int(o["game_mode"])
        if mode != cases.NORMAL or int(o["ball_owned_team"]) == 0:
            kind = "from_us" if mode == cases.NORMAL else "restart"
            return Origin(kind, shot_at - k, float(o["ball"][0]) * cases.METRES_X, mode)
    return Origin("start", shot_at, float(history[0]["ball"][0]) * cases.METRES_X, cases.NORMAL)


def origins_in_match(scenario: str, policy: str, seed: int, steps: int) -> list[Origin]:
    """The origins of the shots at our goal in one match."""
    history = cases.policy_match(scenario, policy, seed, steps)
    return [
        origin(history, k - 1)
        for k in range(1, len(history))
        if shot_profile.shot(history[k - 1], history[k]) is not None
    ]


def table(found: list[Origin], matches: int) -> list[str]:
    """The printed rows: per kind of origin (and per restart), shots a match, the median steps to
    the shot and the median ball x where the attack began."""
    rows = []
    groups: dict[str, list[Origin]] = collections.defaultdict(list)
    for o in found:
        name = o.kind if o.kind != "restart" else f"restart: {MODES.get(o.mode, str(o.mode))}"
        groups[name].append(o)
    for name in sorted(groups):
        group = groups[name]
        rows.append(
            f"{name:>20}  {len(group) / matches:6.2f} {statistics.median(o.steps for o in group):6.0f}"
            f" {statistics.median(o.ball_x for o in group):7.1f}"
        )
    return rows


def main() -> None:
    args = cases.policy_arguments(__doc__.split("\n\n")[0])
    found: list[Origin] = []
    for match in range(args.matches):
        found += origins_in_match(args.scenario, args.policy, args.seed + match, args.steps)
    print(f"{args.scenario}, {args.policy} agent, {args.matches} matches")
    print(f"{'began':>20}  {'shots':>6} {'steps':>6} {'ball x':>7}")
    for row in table(found, args.matches):
        print(row)
    print(f"shots {len(found) / args.matches:.2f} a match")


if __name__ == "__main__":
    main()
