"""`python -m touchline.duel`: two saved policies, or a policy and the built-in AI, play N matches.

```sh
python -m touchline.duel runs/a/model.zip builtin --scenario 11_vs_11_easy_stochastic --matches 20
python -m touchline.duel runs/a/model.zip runs/b/model.zip --scenario 1_vs_1_easy --matches 40 --record duels/
```

A policy is a Stable-Baselines3 PPO model file (`.zip`, trained on `simple115v2` observations with
GRF's 19 actions, as `examples/python/train_sb3_ppo.py` saves it), `random` (uniform actions, seeded)
or `idle` (action 0). The second may be `builtin`: the first policy then drives one left player (the
active one, switching, as in GRF's benchmarks) against the scenario's built-in AI. Two policies each
drive one player a side (`touchline.parallel_env`), the first on the left in even matches and on the
right in odd ones. Match k uses seed `--seed + k`.

Printed: each match's score, then from the first policy's side its wins, draws and losses, the mean
goal difference and the mean points (win 1, draw ½, loss 0), each with its 95 % confidence interval
(mean ± 1.96 standard errors; `nan` for one match). With `--record DIR` every match is written as
`DIR/duel-<k>.tlreplay` with, per step, each SB3 policy's value estimate and action probabilities,
named `<policy>.value` and `<policy>.probs[<action>]` (`touchline view DIR` shows them).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ._touchline import TouchlineError
from .make import make, parallel_env
from .record_replay import RecordReplay

__all__ = ["DuelResult", "Policy", "duel", "load_policy", "main"]


@dataclass
class Policy:
    """A named function from one `simple115v2` observation (float32 (115,)) to an action index and
    the numbers to record beside it (`{"value": v, "probs": p}`, p float32 (19,), for SB3 models;
    `{}` otherwise)."""

    name: str
    act: Callable[[np.ndarray], tuple[int, dict[str, Any]]]


def load_policy(spec: str, seed: int = 0) -> Policy:
    """`random`, `idle`, or the path of an SB3 PPO model file.

    Raises:
        ValueError: a path that does not exist (or `builtin`, which is not a policy).
        ImportError: a model file without stable-baselines3 installed.
    """
    if spec == "idle":
        return Policy("idle", lambda observation: (0, {}))
    if spec == "random":
        rng = np.random.default_rng(seed)
        return Policy("random", lambda observation: (int(rng.integers(19)), {}))
    if spec == "builtin":
        raise ValueError("`builtin` is the built-in AI: give it as the second policy only")
    path = Path(spec)
    if not path.is_file():
        raise ValueError(f"no policy {spec!r}: expected an SB3 model file, `random` or `idle`")
    import torch
    from stable_baselines3 import PPO

    model = PPO.load(str(path), device="cpu")

    def act(observation: np.ndarray) -> tuple[int, dict[str, Any]]:
        tensor, _ = model.policy.obs_to_tensor(observation)
        with torch.no_grad():
            probs = model.policy.get_distribution(tensor).distribution.probs[0].cpu().numpy()
            value = float(model.policy.predict_values(tensor)[0, 0])
        # SB3's deterministic prediction of a discrete action: the most probable one.
        action = int(np.argmax(probs))
        return action, {"value": value, "probs": probs}

    return Policy(path.stem, act)


def interval(values: Sequence[float]) -> tuple[float, float]:
    """Mean and the half-width of its 95 % normal confidence interval (nan for one value)."""
    array = np.asarray(values, dtype=float)
    if len(array) < 2:
        return float(array.mean()), float("nan")
    return float(array.mean()), float(1.96 * array.std(ddof=1) / math.sqrt(len(array)))


@dataclass
class DuelResult:
    """The matches of a duel, from the first policy's side."""

    first: str
    second: str
    scenario: str
    #: Per match: (first's goals, second's goals, first played on the left).
    matches: list[tuple[int, int, bool]] = field(default_factory=list)
    #: Per match: its replay, when recorded.
    replays: list[str | None] = field(default_factory=list)

    @property
    def wins(self) -> int:
        return sum(a > b for a, b, _ in self.matches)

    @property
    def draws(self) -> int:
        return sum(a == b for a, b, _ in self.matches)

    @property
    def losses(self) -> int:
        return sum(a < b for a, b, _ in self.matches)

    def goal_difference(self) -> tuple[float, float]:
        """Mean goal difference per match and its 95 % confidence half-width."""
        return interval([a - b for a, b, _ in self.matches])

    def points(self) -> tuple[float, float]:
        """Mean points per match (win 1, draw ½, loss 0) and its 95 % confidence half-width."""
        return interval([1.0 if a > b else 0.5 if a == b else 0.0 for a, b, _ in self.matches])

    def summary(self) -> str:
        """The result in three lines."""
        n = len(self.matches)
        gd, gd_half = self.goal_difference()
        pts, pts_half = self.points()
        goals = np.mean([[a, b] for a, b, _ in self.matches], axis=0) if n else [0.0, 0.0]
        return (
            f"{self.first} vs {self.second} on {self.scenario}: {self.wins} wins, {self.draws} draws, "
            f"{self.losses} losses in {n} matches; goals {goals[0]:.2f} - {goals[1]:.2f} per match\n"
            f"goal difference {gd:+.2f} ± {gd_half:.2f} (95 % CI, n={n})\n"
            f"points (win 1, draw 1/2) {pts:.2f} ± {pts_half:.2f} (95 % CI, n={n})"
        )


def _values(prefix: str, values: dict[str, Any]) -> dict[str, Any]:
    return {f"{prefix}{name}": value for name, value in values.items()}


def duel(
    first: Policy,
    second: Policy | None,
    scenario: str,
    matches: int,
    seed: int = 0,
    record: str | Path | None = None,
    report: Callable[[str], None] | None = None,
) -> DuelResult:
    """Plays `matches` matches of `scenario`: `first` against `second`, or against the built-in
    AI when `second` is None (see the module documentation); `report` gets one line per match.

    Raises:
        ValueError: `matches` below 1, or a scenario without a controllable player a side for two
            policies.
        touchline.ScenarioError: the scenario cannot be loaded.
    """
    if matches < 1:
        raise ValueError(f"matches must be 1 or more, got {matches}")
    result = DuelResult(first.name, "builtin" if second is None else second.name, scenario)
    if second is None:
        env: Any = make(scenario, representation="simple115v2", seed=seed)
    else:
        env = parallel_env(
            scenario,
            number_of_left_players_agent_controls=1,
            number_of_right_players_agent_controls=1,
            representation="simple115v2",
            seed=seed,
        )
    if record is not None:
        env = RecordReplay(env, record, name_prefix="duel")
    for k in range(matches):
        replay = None
        if second is None:
            observation, _ = env.reset(seed=seed + k)
            done = False
            while not done:
                action, values = first.act(observation)
                if record is not None and values:
                    env.record_values(_values(f"{first.name}.", values))
                observation, _, terminated, truncated, info = env.step(action)
                done = terminated or truncated
            mine, theirs = info["score"]
            on_left = True
            replay = info.get("replay_path")
        else:
            on_left = k % 2 == 0
            players = (
                {"left_0": first, "right_0": second}
                if on_left
                else {"left_0": second, "right_0": first}
            )
            observations, infos = env.reset(seed=seed + k)
            while env.agents:
                actions = {}
                shown: dict[str, Any] = {}
                for agent, policy in players.items():
                    actions[agent], values = policy.act(observations[agent])
                    shown.update(_values(f"{policy.name}.", values))
                if record is not None and shown:
                    env.record_values(shown)
                observations, _, _, _, infos = env.step(actions)
            left, right = infos["left_0"]["score"]
            mine, theirs = (left, right) if on_left else (right, left)
            replay = infos["left_0"].get("replay_path")
        result.matches.append((int(mine), int(theirs), on_left))
        result.replays.append(replay)
        if report is not None:
            side = "left" if on_left else "right"
            where = f"  replay {replay}" if replay else ""
            report(
                f"match {k + 1:>3}: {result.first} ({side}) {mine} - {theirs} {result.second}{where}"
            )
    env.close()
    return result


def main(argv: Sequence[str] | None = None) -> int:
    """The command line (`python -m touchline.duel --help`); returns the exit status."""
    parser = argparse.ArgumentParser(
        prog="python -m touchline.duel", description=(__doc__ or "").split("\n")[0]
    )
    parser.add_argument("first", help="an SB3 model file, `random` or `idle`")
    parser.add_argument("second", help="an SB3 model file, `random`, `idle` or `builtin`")
    parser.add_argument("--scenario", default="11_vs_11_easy_stochastic")
    parser.add_argument("--matches", type=int, default=20)
    parser.add_argument("--seed", type=int, default=0, help="match k plays seed SEED + k")
    parser.add_argument("--record", metavar="DIR", help="write each match as DIR/duel-<k>.tlreplay")
    args = parser.parse_args(argv)
    try:
        first = load_policy(args.first, args.seed)
        second = None if args.second == "builtin" else load_policy(args.second, args.seed + 1)
        if second is not None and second.name == first.name:
            second.name = f"{second.name}#2"
        result = duel(first, second, args.scenario, args.matches, args.seed, args.record, print)
    except (ValueError, ImportError, OSError, TouchlineError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(result.summary())
    return 0


if __name__ == "__main__":
    sys.exit(main())
