"""What becomes of the ball once the agent's team loses it in an Academy drill: how long it stays
loose, how far it goes, and who or what ends that spell, by the button the agent pressed.

For tracing the harness's random-agent cases to their mechanism, side by side with GRF. A spell
starts on a step where nobody has the ball after a step where the agent's team (left, team 0) had
it, and lasts until someone has it again or the episode ends. It is filed under the kick button the
agent pressed on one of the last `KICK_WINDOW` steps of his team's possession (`long`, `high`,
`short`, `shot`; `none` when he pressed none: a tackle, a knock or a lost touch) and under its end:

  * `ours` / `theirs`: a player of that team has the ball;
  * `out: corner`, `out: goal kick`, `out: throw-in`, `out: free kick`, `out: penalty`: play
    stopped with no goal, for that restart (game_mode left 0; `out: other` for any other mode);
  * `goal for` / `goal against`: the scoring reward;
  * `time limit`: the episode ran out with the ball loose.

A spell that ends on the step it began (a goal off a first-time touch) lasts 0 steps.

Per (button, end) it prints the spells' count, their mean and median length (steps), how far the
ball ended from where the spell began (m) and how high it got (m). Episodes are run as the harness
runs them (`fidelity_cases`: the same policies, raw observation, scoring reward), each with an env
of its own seeded `seed * 1000 + episode`, as `episode_timeline.py` does.

Measured here (academy_3_vs_1_with_keeper, random agent, 150 episodes, seed 0; GRF 2.10.2 and
touchline at 0da7081):

| | spells | ours | theirs | out | after a long pass, ours: spells, mean steps |
|---|---|---|---|---|---|
| GRF | 284 | 145 | 89 | 43 | 19, 46.0 |
| touchline | 402 | 260 | 117 | 19 | 60, 19.7 |

GRF's ball, once the agent's team loses it, goes out of play twice as often and stays loose longer
before his team has it back: touchline's team gets it back sooner and more often, so its episodes
hold more, shorter spells. Of GRF's 43 outs, 24 gave the opponents a goal kick: the agent's
passes and shots going over their goal line, 2-5 m high on average; touchline's, 12 of 19.

Usage (from the repository root, with the package installed):
    PYTHONPATH=python/bench python3 python/bench/loose_ball_profile.py SCENARIO N [--seed S]

In GRF, with the measuring folder of `README.md` (beside this file) first on PYTHONPATH.
"""

from __future__ import annotations

import argparse
import collections
import dataclasses
import statistics

import fidelity_cases as cases

#: The kick buttons of GRF's default action set (docs/grf-compatibility.md#actions).
BUTTONS = {
    cases.LONG_PASS: "long",
    cases.HIGH_PASS: "high",
    cases.SHORT_PASS: "short",
    cases.SHOT: "shot",
}
#: A button counts for a spell when pressed on one of this many steps before it began (a pass
#: pressed on the ball leaves the foot 3-5 steps later in both engines).
KICK_WINDOW = 8
#: The restart a ball out of play gives, by game_mode (GRF's raw observation).
OUTS = {
    cases.GOAL_KICK: "out: goal kick",
    cases.FREE_KICK: "out: free kick",
    cases.CORNER: "out: corner",
    cases.THROW_IN: "out: throw-in",
    cases.PENALTY: "out: penalty",
}
ENDS = ("ours", "theirs", *OUTS.values(), "out: other", "goal for", "goal against", "time limit")


@dataclasses.dataclass
class Spell:
    """One loose-ball spell after the agent's team had the ball."""

    button: str
    steps: int
    distance: float
    highest: float
    end: str


def spells(scenario: str, policy: str, episode: int, seed: int) -> list[Spell]:
    """The loose-ball spells of one episode, in order."""
    env = cases.make_env(scenario, seed * 1000 + episode)
    chosen = cases.make_policy(policy, env, seed * 1000 + episode)
    chosen.start()
    first = env.reset()
    obs = first[0] if isinstance(first, list) else first
    found: list[Spell] = []
    owner = int(obs["ball_owned_team"])
    last_kick: tuple[int, str] | None = None
    start: tuple[int, tuple[float, float], str] | None = None
    highest = 0.0
    step = 0
    while True:
        action = chosen.act(step, obs)
        if owner == 0 and action in BUTTONS:
            last_kick = (step, BUTTONS[action])
        result, reward, done, _ = env.step(action)
        step += 1
        obs = result[0] if isinstance(result, list) else result
        now = int(obs["ball_owned_team"])
        ball = (float(obs["ball"][0]), float(obs["ball"][1]))
        if start is None and owner == 0 and now == -1:
            button = last_kick[1] if last_kick and step - last_kick[0] <= KICK_WINDOW else "none"
            start, highest = (step, ball, button), 0.0
        if start is not None:
            highest = max(highest, float(obs["ball"][2]))
            end = spell_end(now, int(obs["game_mode"]), reward, done)
            if end is not None:
                found.append(
                    Spell(start[2], step - start[0], cases.metres(ball, start[1]), highest, end)
                )
                start = None
        owner = now
        if done:
            env.close()
            return found


def spell_end(owner: int, mode: int, reward: float, done: bool) -> str | None:
    """How a loose spell ends on this step, or None while it goes on (GRF's order: the goal, then
    play stopping, then the ball owned, then the time limit)."""
    if reward > 0:
        return "goal for"
    if reward < 0:
        return "goal against"
    if mode != cases.NORMAL:
        return OUTS.get(mode, "out: other")
    if owner != -1:
        return "ours" if owner == 0 else "theirs"
    if done:
        return "time limit"
    return None


def table(found: list[Spell]) -> list[str]:
    """One line per (button, end) with spells: count, mean and median steps, mean distance (m),
    mean highest (m)."""
    groups: dict[tuple[str, str], list[Spell]] = collections.defaultdict(list)
    for spell in found:
        groups[(spell.button, spell.end)].append(spell)
    order = [*BUTTONS.values(), "none"]
    lines = []
    for key in sorted(groups, key=lambda k: (order.index(k[0]), ENDS.index(k[1]))):
        group = groups[key]
        steps = [s.steps for s in group]
        lines.append(
            f"{key[0]:>5} -> {key[1]:<14} {len(group):4d} spells, {statistics.mean(steps):5.1f} steps "
            f"(median {statistics.median(steps):g}), {statistics.mean(s.distance for s in group):5.1f} m, "
            f"highest {statistics.mean(s.highest for s in group):.2f} m"
        )
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenario")
    parser.add_argument("episodes", type=int)
    parser.add_argument("--policy", choices=["random", "idle", "builtin_ai"], default="random")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    found = [
        s for e in range(args.episodes) for s in spells(args.scenario, args.policy, e, args.seed)
    ]
    for line in table(found):
        print(line)
    ended = collections.Counter(s.end for s in found)
    print(f"{len(found)} spells in {args.episodes} episodes; ends {dict(ended)}")


if __name__ == "__main__":
    main()
