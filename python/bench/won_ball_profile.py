"""What the opponents (right) do with the balls they win from the agent's team (left) in open play:
where they win it, how soon the winner first kicks it, whether a shot at our goal follows, and how
often the player who lost it wins it straight back.

For tracing the harness's full-match goals against (`goals against / match` of the idle and random
agents) side by side with GRF, one step finer than `attack_origin.py`: that tool starts from the
shots, this one from every ball won. Matches are run as `shot_profile.py` runs them
(`fidelity_cases`: the harness's policies, raw observation, one env per match seeded
`seed + match`), and a shot is its shot test (`shot_profile.shot`).

A win is a step in open play on which the right team is the ball's owner while the last owner
before it (loose steps skipped) was the left team. Its spell runs until the left team owns the ball
again (`regain`, `regain_same` when it is the player who lost it), play stops (`stop`), a shot at
our goal is struck (`shot`), or 200 steps pass (`open`). The winner's first kick is the first step
of the spell on which the ball's speed jumps by more than 4 m/s to over 8 m/s (a pass, shot or
clearance; `fidelity_cases.KICK_JUMP` and `KICK_SPEED`). Rows are bands of the ball's x at the win
in metres from halfway (−55 our goal line, GRF's world scale).

Measured here (2026-11-29; GRF 2.10.2 and touchline at f814a51; 11_vs_11_stochastic, idle agent,
`--seed 100`; GRF 6 matches, touchline 20):

| ball x at the win | wins a match GRF / tl | shot follows | first kick, median steps | within 5 steps | lost-it player wins it back |
|---|---|---|---|---|---|
| −55 to −30 | 8.5 / 6.9 | 0.16 / 0.40 | 14 / 8 | 0.16 / 0.37 | 0.57 / 0.15 |
| −30 to −15 | 12.7 / 8.6 | 0.16 / 0.23 | 33 / 8 | 0.04 / 0.38 | 0.53 / 0.25 |
| −15 to 0 | 9.7 / 5.0 | 0.09 / 0.19 | 20.5 / 5 | 0.06 / 0.53 | 0.64 / 0.16 |

GRF's winner keeps the ball a median 14-33 steps before his first kick, touchline's 5-8, and in
GRF our idle player who lost the ball has it back within a second in over half the wins (the
raw observation's owner flips to whoever touches a contested ball), so a ball won near our goal
gives GRF's attack a shot one time in six and touchline's two times in five. Leaving out the
wins won straight back (within 10 steps), the first kick among spells of 10 steps or more still
comes a median 17-33 steps after the win in GRF and 5-8 in touchline (docs/grf-compatibility.md,
"what the opponents do with a ball they win").

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/won_ball_profile.py [--scenario S] [--policy idle]
        [--matches N] [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import collections
import dataclasses
import statistics

import fidelity_cases as cases
import shot_profile

#: Longest spell followed after a win (env steps).
HORIZON = 200
#: Bands of the ball's x at the win (m from halfway, −55 our goal line), as printed.
BANDS = ((-55.0, -30.0), (-30.0, -15.0), (-15.0, 0.0), (0.0, 20.0), (20.0, 55.0))


@dataclasses.dataclass
class Win:
    """One ball the right team won from the left team, and its spell."""

    ball_x: float  # m from halfway at the win, −55 our goal line
    end: str  # "regain", "regain_same", "stop", "shot" or "open"
    steps: int  # length of the spell (env steps)
    first_kick: int | None  # steps from the win to the winner's team's first kick, if any


def kicked(before: cases.Observation, during: cases.Observation, after: cases.Observation) -> bool:
    """Whether the ball was kicked over the step from `during` to `after`: its speed jumped."""
    was = shot_profile.ball_speed(before, during)[0]
    now = shot_profile.ball_speed(during, after)[0]
    return now > cases.KICK_SPEED and now - was > cases.KICK_JUMP


def wins(history: list[cases.Observation]) -> list[Win]:
    """The balls won by the right team in `history` (one observation per env step)."""
    found: list[Win] = []
    last_owner: tuple[int, int] | None = None  # (team, player) of the last owner seen in open play
    k = 0
    while k < len(history):
        o = history[k]
        normal = int(o["game_mode"]) == cases.NORMAL
        team = int(o["ball_owned_team"])
        if not normal:
            last_owner = None
        elif team == 1 and last_owner is not None and last_owner[0] == 0:
            win = follow(history, k, last_owner[1])
            found.append(win)
            k += max(win.steps, 1)
            last_owner = None
            continue
        elif team in (0, 1):
            last_owner = (team, int(o["ball_owned_player"]))
        k += 1
    return found


def follow(history: list[cases.Observation], start: int, loser: int) -> Win:
    """The spell of the win at `history[start]`, the ball lost by the left team's `loser`."""
    first_kick = None
    end = "open"
    k = start + 1
    while k < len(history) and k < start + HORIZON:
        before, after = history[k - 1], history[k]
        if int(after["game_mode"]) != cases.NORMAL:
            end = "stop"
            break
        if int(after["ball_owned_team"]) == 0:
            end = "regain_same" if int(after["ball_owned_player"]) == loser else "regain"
            break
        if first_kick is None and k >= 2 and kicked(history[k - 2], before, after):
            first_kick = k - start
        if shot_profile.shot(before, after) is not None:
            end = "shot"
            break
        k += 1
    ball_x = float(history[start]["ball"][0]) * cases.METRES_X
    return Win(ball_x, end, k - start, first_kick)


def wins_in_match(scenario: str, policy: str, seed: int, steps: int) -> list[Win]:
    """The balls the right team won in one match."""
    return wins(cases.policy_match(scenario, policy, seed, steps))


def table(found: list[Win], matches: int) -> list[str]:
    """The printed rows: per band of the ball's x at the win, wins a match, the share followed by a
    shot, the winner's first kick (median steps, share within 5 steps), and the share the player
    who lost the ball won straight back."""
    rows = []
    for low, high in BANDS:
        band = [w for w in found if low <= w.ball_x < high]
        if not band:
            continue
        ends = collections.Counter(w.end for w in band)
        kicks = [w.first_kick for w in band if w.first_kick is not None]
        kick = (
            f"{statistics.median(kicks):6.1f} {sum(k <= 5 for k in kicks) / len(kicks):6.2f}"
            if kicks
            else " " * 13
        )
        rows.append(
            f"{low:5.0f} to {high:3.0f}  {len(band) / matches:6.2f} {ends['shot'] / len(band):6.2f} {kick}"
            f" {ends['regain_same'] / len(band):6.2f}"
        )
    return rows


def main() -> None:
    args = cases.policy_arguments(__doc__.split("\n\n")[0])
    found: list[Win] = []
    for match in range(args.matches):
        found += wins_in_match(args.scenario, args.policy, args.seed + match, args.steps)
    print(f"{args.scenario}, {args.policy} agent, {args.matches} matches")
    print(f"{'ball x at the win':>16}  {'wins':>6} {'shot':>6} {'kick':>6} {'<=5':>6} {'back':>6}")
    for row in table(found, args.matches):
        print(row)
    print(f"wins {len(found) / args.matches:.2f} a match")


if __name__ == "__main__":
    main()
