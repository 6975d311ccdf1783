"""The shots a full match's built-in AI takes against the agent's team (left), by how far out they
are struck: how many, how many go in, how fast, and where our keeper stands.

For tracing the harness's full-match goals against (`goals against / match` of the idle and random
agents) to their mechanism, side by side with GRF. Matches are run as the harness runs them
(`fidelity_cases`: the same policies, raw observation), one env per match seeded `seed + match`.
A shot is read off the raw observation the same way in both engines: on the step before, the right
team had the ball in normal play; now nobody has it, play goes on, and the ball moved towards our
goal (left) faster than `SHOT_SPEED` from within `SHOT_RANGE` of the goal's centre. It goes in when
the right team scores before anyone has the ball again. Distances are at GRF's world scale
(`fidelity_cases.metres`); the keeper's are taken on the step the shot was struck from.

Per distance band it prints shots and goals per match, the share that goes in, the ball's mean
speed (m/s) and the keeper's median distance from the ball and off his goal line (m). The closing
line gives all goals against per match, so the goals that come from no detected shot (a deflection,
a first-time touch, an own goal) show as the difference.

Measured here (2026-11-29; GRF 2.10.2 and touchline at 712a2df; idle agent, `--seed 100`):

| | matches | goals against | shots | from shots | 15-20 m: shots, in | keeper to ball | off line |
|---|---|---|---|---|---|---|---|
| GRF hard | 10 | 3.40 | 7.10 | 2.20 | 5.00, 0.32 | 8.2 m | 6.7 m |
| touchline hard | 40 | 3.73 | 9.22 | 2.20 | 6.22, 0.30 | 16.6 m | 0.2 m |
| GRF medium | 10 | 1.60 | 3.50 | 1.10 | 2.80, 0.29 | 9.3 m | 6.3 m |
| touchline medium | 40 | 3.05 | 8.65 | 2.02 | 5.30, 0.30 | 16.3 m | 0.2 m |

(The keeper's distances are medians over the 15-20 m shots.) Both engines score about 3 in 10 of
these shots. The goals against follow the number of shots, not the finishing: GRF's medium side
takes 3.5 shots a match at an idle agent's team, touchline's 8.7. With the built-in AI on our
controlled player too (`--policy builtin_ai`), GRF's medium side takes 1.0 shot a match (0.5 goals
against, 10 matches) and touchline's 0.7 (0.2, 40 matches). So one idle player lets in 3.5 times
the shots in GRF and 12 times in touchline: touchline's defence leans far more on the one player
the agent controls. touchline's also shoots from 25
m and more (1.1-1.3 a match), which GRF's never does. GRF's keeper meets a shot from 15-20 m about
6.5 m off his line, while touchline's stands on it. That is because touchline's keeper rushes only
at a carrier who has no team-mate of the keeper's within 10 m (`ai/goalkeeper.rs`). Without that
clause (GRF's rush rule alone), he meets a shot from 15-20 m 7.1 m from the ball and 9.1 m off his
line, and more of those shots go in (0.38). The goals do not change (3.62 a match), and harness
seeds 0-7 flag 66 case-runs against 53.

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/shot_profile.py [--scenario S] [--policy idle]
        [--matches N] [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import argparse
import dataclasses
import statistics

import fidelity_cases as cases

#: A shot leaves faster than this (m/s) across the ground.
SHOT_SPEED = 12.0
#: ... towards our goal at this pace at least (m/s along x).
SHOT_TOWARDS = 8.0
#: ... from within this distance (m) of our goal's centre.
SHOT_RANGE = 35.0
#: Upper edges of the distance bands (m); the last band is open.
BANDS = (10.0, 15.0, 20.0, 25.0)
#: Our goal's centre in raw units.
OUR_GOAL = (-1.0, 0.0)


@dataclasses.dataclass
class Shot:
    """One shot at our goal."""

    distance: float
    speed: float
    keeper_to_ball: float
    keeper_off_line: float
    scored: bool = False


def ball_speed(before: cases.Observation, after: cases.Observation) -> tuple[float, float]:
    """The ball's speed across the ground (m/s) and its pace towards our goal (m/s along −x) over
    the step from `before` to `after`."""
    dx = (float(after["ball"][0]) - float(before["ball"][0])) * cases.METRES_X * 10.0
    dy = (float(after["ball"][1]) - float(before["ball"][1])) * cases.METRES_Y * 10.0
    return (dx * dx + dy * dy) ** 0.5, -dx


def shot(before: cases.Observation, after: cases.Observation) -> Shot | None:
    """The shot at our goal struck over the step from `before` to `after`, if there was one."""
    normal = int(before["game_mode"]) == cases.NORMAL and int(after["game_mode"]) == cases.NORMAL
    if not normal or int(before["ball_owned_team"]) != 1 or int(after["ball_owned_team"]) != -1:
        return None
    speed, towards = ball_speed(before, after)
    ball = (float(before["ball"][0]), float(before["ball"][1]))
    distance = cases.metres(ball, OUR_GOAL)
    if speed < SHOT_SPEED or towards < SHOT_TOWARDS or distance > SHOT_RANGE:
        return None
    keeper = (float(before["left_team"][0][0]), float(before["left_team"][0][1]))
    off_line = (keeper[0] - OUR_GOAL[0]) * cases.METRES_X
    return Shot(distance, speed, cases.metres(keeper, ball), off_line)


def band(distance: float) -> str:
    """A distance band as printed, e.g. `10-15 m` or `25+ m`."""
    low = max((edge for edge in (0.0, *BANDS) if distance >= edge), default=0.0)
    higher = [edge for edge in BANDS if edge > low]
    return f"{low:g}-{higher[0]:g} m" if higher else f"{low:g}+ m"


def shots_in_match(scenario: str, policy: str, seed: int, steps: int) -> tuple[list[Shot], int]:
    """The shots at our goal in one match and the goals we conceded."""
    env = cases.make_env(scenario, seed, builtin_ai=policy == "builtin_ai")
    agent = cases.make_policy(policy, env, seed)
    agent.start()
    first = env.reset()
    before = first[0] if isinstance(first, list) else first
    found: list[Shot] = []
    open_shot: Shot | None = None
    try:
        for step in range(steps):
            stepped, _, done, _ = env.step(agent.act(step, before))
            after = stepped[0] if isinstance(stepped, list) else stepped
            if int(after["score"][1]) > int(before["score"][1]) and open_shot is not None:
                open_shot.scored = True
            new = shot(before, after)
            if new is not None:
                found.append(new)
                open_shot = new
            elif int(after["ball_owned_team"]) != -1 or int(after["game_mode"]) != cases.NORMAL:
                open_shot = None
            before = after
            if done:
                break
    finally:
        env.close()
    return found, int(before["score"][1])


def table(shots: list[Shot], matches: int) -> list[str]:
    """The printed rows, one per distance band with shots in it."""
    rows = []
    for name in sorted(
        {band(s.distance) for s in shots}, key=lambda b: float(b.split("-")[0].rstrip("+ m"))
    ):
        group = [s for s in shots if band(s.distance) == name]
        scored = sum(s.scored for s in group)
        rows.append(
            f"{name:>8}  {len(group) / matches:6.2f} {scored / matches:6.2f} {scored / len(group):5.2f}"
            f" {statistics.fmean(s.speed for s in group):6.1f}"
            f" {statistics.median(s.keeper_to_ball for s in group):7.1f}"
            f" {statistics.median(s.keeper_off_line for s in group):6.1f}"
        )
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenario", default="11_vs_11_hard_stochastic")
    parser.add_argument("--policy", default="idle", help="idle, random or builtin_ai")
    parser.add_argument("--matches", type=int, default=10)
    parser.add_argument("--seed", type=int, default=100, help="the first match's seed")
    parser.add_argument("--steps", type=int, default=3001, help="steps per match at most")
    args = parser.parse_args()
    shots: list[Shot] = []
    conceded = 0
    for match in range(args.matches):
        found, goals = shots_in_match(args.scenario, args.policy, args.seed + match, args.steps)
        shots += found
        conceded += goals
    m = args.matches
    print(f"{args.scenario}, {args.policy} agent, {m} matches")
    print(f"{'band':>8}  {'shots':>6} {'goals':>6} {'in':>5} {'speed':>6} {'keeper':>7} {'off':>6}")
    for row in table(shots, m):
        print(row)
    scored = sum(s.scored for s in shots)
    print(
        f"goals against {conceded / m:.2f} a match; shots {len(shots) / m:.2f}, "
        f"goals from them {scored / m:.2f}"
    )


if __name__ == "__main__":
    main()
