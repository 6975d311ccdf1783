"""How a match's kicks look: how far the ball goes, how high, how long it is loose, and who gets it.

For comparing touchline's built-in AI with GRF's, side by side: the same scenario and seed run with
the built-in AI on every player (action set v2, action 19), through `touchline.compat.gfootball`
or, with the measuring folder of `README.md` first on `PYTHONPATH`, through gfootball itself.

A kick is a step on which the loose ball's horizontal speed jumps by more than 4 m/s to above
8 m/s in normal play (the harness's test). It is `after_own` when a player had the ball the step
before (a pass, shot or clearance from the feet) and `first_time` when the ball was already loose
(struck with the first touch, or a deflection). It is followed until someone has the ball, play
stops, or 8 s pass: the distance (m) from where it was struck to where it ends up, the highest the
ball got (m), the steps it was loose, and who ended with it (`same` team or `other` team as the
player who struck it from his feet; `owned` after a first-time kick, whose kicker the observation
does not name; `stop`; `loose`).

Measured here (11_vs_11_stochastic, 3,000 steps, seeds 1 and 3; GRF 2.10.2): GRF strikes about 72
kicks, median distance 12-14 m, a sixth of them above 2 m; touchline (at 07bc74d) about 54, median
17-24 m, a third above 2 m.

Usage (from the repository root):
    PYTHONPATH=python:python/bench python3 python/bench/kick_profile.py 11_vs_11_stochastic --steps 3000 --seed 1
"""

from __future__ import annotations

import collections
import dataclasses
import statistics

import fidelity_cases as cases

#: Steps a kicked ball is followed before it counts as loose for good.
FOLLOW_STEPS = 80


@dataclasses.dataclass
class OpenKick:
    """A kick being followed."""

    kind: str
    step: int
    start: tuple[float, float]
    highest: float
    team: int


def profile(scenario: str, steps: int, seed: int) -> dict[str, list[tuple[float, float, int, str]]]:
    """The kicks of one run: per kind, (distance m, highest m, steps loose, who ended with it)."""
    env = cases.make_env(scenario, seed, builtin_ai=True)
    policy = cases.make_policy("builtin_ai", env, seed)
    policy.start()
    first = env.reset()
    obs = first[0] if isinstance(first, list) else first
    previous = (float(obs["ball"][0]), float(obs["ball"][1]))
    previous_speed = 0.0
    previous_owner = -1
    open_kick: OpenKick | None = None
    kicks: dict[str, list[tuple[float, float, int, str]]] = collections.defaultdict(list)
    for step in range(steps):
        result, _, done, _ = env.step(policy.act(step, obs))
        obs = result[0] if isinstance(result, list) else result
        ball = (float(obs["ball"][0]), float(obs["ball"][1]))
        height = float(obs["ball"][2])
        owner = int(obs["ball_owned_team"])
        mode = int(obs["game_mode"])
        speed = cases.metres(ball, previous) * 10.0
        if open_kick is not None:
            open_kick.highest = max(open_kick.highest, height)
            if owner != -1 or mode != 0 or step - open_kick.step > FOLLOW_STEPS:
                if mode != 0:
                    who = "stop"
                elif owner == -1:
                    who = "loose"
                elif open_kick.team == -1:
                    who = "owned"  # the kicker's team is unknown for a first-time kick
                else:
                    who = "same" if owner == open_kick.team else "other"
                row = (
                    cases.metres(ball, open_kick.start),
                    open_kick.highest,
                    step - open_kick.step,
                    who,
                )
                kicks[open_kick.kind].append(row)
                open_kick = None
        jump = speed - previous_speed > cases.KICK_JUMP and speed > cases.KICK_SPEED
        if open_kick is None and mode == 0 and owner == -1 and jump:
            kind = "after_own" if previous_owner != -1 else "first_time"
            open_kick = OpenKick(kind, step, previous, height, previous_owner)
        previous, previous_speed, previous_owner = ball, speed, owner
        if done:
            break
    return kicks


def main() -> None:
    args = cases.match_arguments(__doc__.split("\n\n")[0], seed=1)
    kicks = profile(args.scenario, args.steps, args.seed)
    for kind in ("after_own", "first_time"):
        rows = kicks.get(kind, [])
        if not rows:
            print(f"{kind}: none")
            continue
        distances = [r[0] for r in rows]
        ends = collections.Counter(r[3] for r in rows)
        print(
            f"{kind}: {len(rows)} kicks; distance median {statistics.median(distances):.1f} m, "
            f"mean {statistics.mean(distances):.1f} m; above 2 m {sum(r[1] > 2.0 for r in rows)}; "
            f"loose {statistics.mean(r[2] for r in rows):.1f} steps; ends {dict(ends)}"
        )


if __name__ == "__main__":
    main()
