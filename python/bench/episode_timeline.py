"""One line per episode of a fidelity case: who owned the ball when, the kicks, the restarts, the end.

For tracing a flagged case to its mechanism, side by side with GRF. The episodes are run as the
harness runs them (`fidelity_cases`: the same policies and GRF's end classification), but each
episode gets an env of its own seeded `seed * 1000 + episode`: GRF re-seeds its engine at every
reset, so episodes in a row of one seeded env differ only by the policy's actions.

Events, each `step:what@x,y` (raw observation units):

  * `own T.P` the ball's owner became team T (0 left, 1 right, -1 nobody), player P;
  * `kick V` the ball's horizontal speed jumped by more than 4 m/s to V m/s (a pass, shot,
    clearance or tackle; `z` is its height, `a` the action of that step);
  * `mode M` the game_mode became M (2 goal kick, 3 free kick, 4 corner, 5 throw-in, 6 penalty);
  * `act P` the agent's control passed to player P (the raw observation's `active`).

Closing lines count the episodes in which the agent's team was never seen with the ball, and
their mean length, and split the episodes by which team was first seen with it (`ours`, `theirs`,
`nobody`): how many, how long and how they ended. GRF does not end an episode on a change of
possession before someone had the ball, so the episodes the opponents start with the ball show
what their carriers do against our team.

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/episode_timeline.py SCENARIO POLICY N [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import argparse
import collections
import math

import fidelity_cases as cases

#: A kick: the ball's horizontal speed jumps by more than this (m/s) in a step, to above KICK_SPEED.
KICK_JUMP = cases.KICK_JUMP
KICK_SPEED = cases.KICK_SPEED


def timeline(scenario: str, policy: str, episode: int, seed: int) -> tuple[int, str, list[str]]:
    """Length, end and events of one episode."""
    env = cases.make_env(scenario, seed * 1000 + episode)
    chosen = cases.make_policy(policy, env, seed * 1000 + episode)
    chosen.start()
    first = env.reset()
    obs = first[0] if isinstance(first, list) else first
    tracker = cases.EndTracker()
    events: list[str] = []
    owner: tuple[int, int] | None = None
    mode = 0
    active = int(obs["active"])
    ball = obs["ball"]
    speed = 0.0
    step = 0
    while True:
        action = chosen.act(step, obs)
        result, reward, done, _ = env.step(action)
        step += 1
        obs = result[0] if isinstance(result, list) else result
        end = tracker.classify(obs, reward)
        now = obs["ball"]
        at = f"@{now[0]:.2f},{now[1]:.2f}"
        new_speed = math.hypot(now[0] - ball[0], now[1] - ball[1]) * cases.SPEED_PER_UNIT_STEP
        new_owner = (int(obs["ball_owned_team"]), int(obs["ball_owned_player"]))
        if new_owner != owner:
            events.append(f"{step}:own{new_owner[0]}.{new_owner[1]}{at}")
            owner = new_owner
        if new_speed - speed > KICK_JUMP and new_speed > KICK_SPEED:
            events.append(f"{step}:kick{new_speed:.0f}{at},z{now[2]:.1f} a{action}")
        if int(obs["game_mode"]) != mode:
            mode = int(obs["game_mode"])
            events.append(f"{step}:mode{mode}{at}")
        if int(obs["active"]) != active:
            active = int(obs["active"])
            events.append(f"{step}:act{active}")
        ball, speed = now, new_speed
        if done:
            return step, end, events


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenario")
    parser.add_argument("policy", choices=["random", "idle", "builtin_ai"])
    parser.add_argument("episodes", type=int)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    ends: collections.Counter[str] = collections.Counter()
    lengths = []
    never_owned: list[int] = []
    by_first: list[tuple[str, int, str]] = []
    for episode in range(args.episodes):
        length, end, events = timeline(args.scenario, args.policy, episode, args.seed)
        ends[end] += 1
        lengths.append(length)
        if not any(":own0." in event for event in events):
            never_owned.append(length)
        by_first.append((first_owner(events), length, end))
        print(f"ep{episode} len{length} {end} | " + " ".join(events))
    print(f"mean length {sum(lengths) / len(lengths):.1f}; ends {dict(ends)}")
    print(ownership_line(len(lengths), never_owned))
    for line in first_owner_lines(by_first):
        print(line)


def ownership_line(episodes: int, never_owned: list[int]) -> str:
    """How many episodes never showed the agent's team (left, team 0) with the ball, and how long
    they lasted: with GRF's end on a change of possession, such an episode cannot end that way."""
    share = f"{len(never_owned)} of {episodes} episodes never show our team with the ball"
    if not never_owned:
        return share
    return f"{share} (mean length {sum(never_owned) / len(never_owned):.1f})"


def first_owner(events: list[str]) -> str:
    """Which team an episode's events first show with the ball: `ours` (the agent's, team 0),
    `theirs` (team 1) or `nobody`."""
    for event in events:
        if ":own0." in event:
            return "ours"
        if ":own1." in event:
            return "theirs"
    return "nobody"


def first_owner_lines(rows: list[tuple[str, int, str]]) -> list[str]:
    """One line per first owner (ours, theirs, nobody, those that occur): how many episodes, their
    mean length and how they ended. `rows`: (first owner, length, end) per episode."""
    lines = []
    for who in ("ours", "theirs", "nobody"):
        group = [(length, end) for first, length, end in rows if first == who]
        if not group:
            continue
        ends = collections.Counter(end for _, end in group)
        mean = sum(length for length, _ in group) / len(group)
        lines.append(
            f"first {who}: {len(group)} episodes, mean length {mean:.1f}, ends {dict(ends)}"
        )
    return lines


if __name__ == "__main__":
    main()
