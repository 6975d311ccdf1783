"""Evaluate saved policies: against the built-in AI at GRF's three difficulties, and against each other.

    python examples/python/evaluate.py runs/a/model.zip runs/b/model.zip random --episodes 20

Each policy is an SB3 model file (`PPO.load`; simple115v2 observations, GRF's 19 actions, as the
training examples save), or `random` / `idle` (action 0) as baselines. A policy drives one player
of the left team (GRF's default: the active player, switching), the other ten play as the built-in
AI does.

1. **Against the built-in AI**: `--episodes` full matches of `11_vs_11_easy_stochastic`,
   `11_vs_11_stochastic` and `11_vs_11_hard_stochastic` (GRF's benchmarks: opponent difficulty
   0.05, 0.6 and 0.95), seeds `--seed + k`. Printed: goals for and against per match and the goal
   difference with its 95 % confidence interval (mean ± 1.96 standard errors).
2. **A league**: every pair of policies plays `--episodes` matches of `--league-scenario` with one
   controlled player a side (`touchline.parallel_env`), each policy on the left half of the time.
   The built-in AI at the three difficulties joins the table through the matches of part 1. The Elo
   table is the maximum-likelihood Bradley–Terry fit of every match (win 1, draw ½, loss 0) on
   Elo's scale (400 points = 10:1 odds), anchored so the medium built-in AI has 1000, with each
   rating's standard error (of its difference from the anchor) from the fit's curvature.
"""

from __future__ import annotations

import argparse
import itertools
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import touchline

#: GRF's 11 v 11 benchmarks by the opponent's difficulty (GRF's scenario table).
BENCHMARKS = {
    "builtin_easy": "11_vs_11_easy_stochastic",
    "builtin_medium": "11_vs_11_stochastic",
    "builtin_hard": "11_vs_11_hard_stochastic",
}

Policy = Callable[[np.ndarray], int]


def load_policy(spec: str, seed: int) -> Policy:
    """A function from one simple115v2 observation to an action index."""
    if spec == "idle":
        return lambda observation: 0
    if spec == "random":
        rng = np.random.default_rng(seed)
        return lambda observation: int(rng.integers(19))
    from stable_baselines3 import PPO

    model = PPO.load(spec, device="cpu")
    return lambda observation: int(model.predict(observation, deterministic=True)[0])


@dataclass
class Results:
    """Every match played: (left name, right name, left goals, right goals)."""

    matches: list[tuple[str, str, int, int]] = field(default_factory=list)

    def goal_differences(self, left: str, right: str) -> np.ndarray:
        return np.array(
            [a - b for home, away, a, b in self.matches if (home, away) == (left, right)], float
        )


def against_builtin(name: str, policy: Policy, episodes: int, seed: int, results: Results) -> None:
    for opponent, scenario in BENCHMARKS.items():
        env = touchline.make(scenario)
        goals = []
        for k in range(episodes):
            observation, _ = env.reset(seed=seed + k)
            done = False
            while not done:
                observation, _, terminated, truncated, info = env.step(policy(observation))
                done = terminated or truncated
            goals.append(info["score"])
            results.matches.append((name, opponent, *info["score"]))
        goals_for, goals_against = np.mean(goals, axis=0)
        mean, half = interval(results.goal_differences(name, opponent))
        print(
            f"{name:>24} vs {opponent:<15} {goals_for:5.2f} – {goals_against:<5.2f} "
            f"goal difference {mean:+.2f} ± {half:.2f} (95 %, n={episodes})"
        )


def head_to_head(
    names: tuple[str, str],
    policies: tuple[Policy, Policy],
    scenario: str,
    episodes: int,
    seed: int,
    results: Results,
) -> None:
    """`episodes` matches, the first policy on the left in the even ones, on the right in the odd."""
    env = touchline.parallel_env(
        scenario, number_of_left_players_agent_controls=1, number_of_right_players_agent_controls=1
    )
    for k in range(episodes):
        left, right = (0, 1) if k % 2 == 0 else (1, 0)
        observations, infos = env.reset(seed=seed + k)
        while env.agents:
            actions = {
                "left_0": policies[left](observations["left_0"]),
                "right_0": policies[right](observations["right_0"]),
            }
            observations, _, _, _, infos = env.step(actions)
        left_goals, right_goals = infos["left_0"]["score"]
        results.matches.append((names[left], names[right], left_goals, right_goals))


def interval(values: np.ndarray) -> tuple[float, float]:
    """Mean and the half-width of its 95 % normal confidence interval (nan for one value)."""
    if len(values) < 2:
        return float(values.mean()), float("nan")
    return float(values.mean()), float(1.96 * values.std(ddof=1) / np.sqrt(len(values)))


def elo(results: Results, anchor: str = "builtin_medium") -> dict[str, tuple[float, float]]:
    """Bradley–Terry ratings on Elo's scale by Newton's method, with standard errors.

    A draw counts as half a win for each side. A small prior (one draw against a virtual player
    rated as the mean) keeps unbeaten or winless players finite.
    """
    players = sorted({p for home, away, _, _ in results.matches for p in (home, away)})
    index = {p: i for i, p in enumerate(players)}
    n = len(players)
    scale = 400.0 / np.log(10.0)
    theta = np.zeros(n)
    for _ in range(100):
        gradient = np.zeros(n)
        hessian = np.zeros((n, n))
        for left, right, a, b in results.matches:
            i, j = index[left], index[right]
            expected = 1.0 / (1.0 + np.exp(theta[j] - theta[i]))
            score = 1.0 if a > b else 0.5 if a == b else 0.0
            gradient[i] += score - expected
            gradient[j] -= score - expected
            w = expected * (1.0 - expected)
            hessian[i, i] -= w
            hessian[j, j] -= w
            hessian[i, j] += w
            hessian[j, i] += w
        # The prior: a draw against a virtual player at 0 (a tie to the mean).
        expected = 1.0 / (1.0 + np.exp(-theta))
        gradient += 0.5 - expected
        hessian[np.diag_indices(n)] -= expected * (1.0 - expected)
        step = np.linalg.solve(hessian, -gradient)
        theta += step
        if np.abs(step).max() < 1e-9:
            break
    covariance = np.linalg.inv(-hessian)
    # Ratings are differences from the anchor (or the mean), and so are their errors: the common
    # level is set only by the weak prior, and must not blur them.
    origin = np.zeros(n)
    if anchor in index:
        origin[index[anchor]] = 1.0
    else:
        origin[:] = 1.0 / n
    ratings = {}
    for p, i in index.items():
        contrast = -origin.copy()
        contrast[i] += 1.0
        variance = max(float(contrast @ covariance @ contrast), 0.0)
        ratings[p] = (1000.0 + scale * float(contrast @ theta), scale * np.sqrt(variance))
    return ratings


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("policies", nargs="+", help="SB3 model files, `random` or `idle`")
    parser.add_argument("--episodes", type=int, default=20, help="matches per pairing")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--league-scenario", default="11_vs_11_stochastic")
    args = parser.parse_args()

    names = [Path(p).stem if p not in ("random", "idle") else p for p in args.policies]
    # Two files called model.zip: name them by their folder.
    names = [
        f"{Path(p).parent.name}/{n}" if names.count(n) > 1 else n
        for p, n in zip(args.policies, names)
    ]
    policies = [load_policy(p, args.seed + i) for i, p in enumerate(args.policies)]
    results = Results()
    print("Against the built-in AI")
    for name, policy in zip(names, policies):
        against_builtin(name, policy, args.episodes, args.seed, results)
    if len(policies) > 1:
        print(f"\nHead to head on {args.league_scenario} (first named on the left half the time)")
        for (a, pa), (b, pb) in itertools.combinations(zip(names, policies), 2):
            head_to_head((a, b), (pa, pb), args.league_scenario, args.episodes, args.seed, results)
            mean, half = interval(
                np.concatenate([results.goal_differences(a, b), -results.goal_differences(b, a)])
            )
            print(f"{a:>24} vs {b:<24} goal difference {mean:+.2f} ± {half:.2f} (95 %)")
    print("\nElo (medium built-in AI = 1000)")
    for name, (rating, se) in sorted(elo(results).items(), key=lambda item: -item[1][0]):
        print(f"{name:>24} {rating:7.0f} ± {se:.0f}")


if __name__ == "__main__":
    main()
