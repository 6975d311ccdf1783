"""How long a shot pressed by our ball carrier takes to leave his foot, and whether it leaves at all.

For comparing touchline's kick timing with GRF's, side by side: each episode our player runs with
the ball (one direction held, or a new random direction every step), presses shot once after he
has been seen with it for k steps, and runs on; the script reports, for each k, how many of the
presses struck the ball within 8 steps and how many steps after the press the ball left (its
horizontal speed above 12 m/s). Run it in touchline and, with the measuring folder of `README.md`
first on `PYTHONPATH`, in GRF.

Measured here (academy_empty_goal_close, 12 episodes per k, k in 0, 1, 2, 3, 4, 6, 8, seed 11;
GRF 2.10.2, touchline at dc1f13c):
  * running right (`--moves 5`): every press struck in both; GRF 2-4 steps after the press (mean
    2.7; the same in every episode of a k), touchline 2-3 (mean 2.4);
  * a new random direction every step (`--moves random`): GRF struck 82 of 84 presses, after 2-8
    steps (mean 5.0); touchline all 84, after 2-5 (mean 3.8).
GRF keeps a pressed shot until its carrier's current animation ends, and its turning animations
run long, so under a random agent its kicks come later and more spread than touchline's; it
dropped none but two (the ball still at his feet 8 steps on).

Usage (from the repository root):
    PYTHONPATH=python:python/bench python3 python/bench/kick_delay.py academy_empty_goal_close --moves random
"""

from __future__ import annotations

import argparse
import collections
import math
import random
import statistics

import fidelity_cases as cases
from fidelity_cases import Observation
from touchline.compat.gfootball import FootballEnv

#: GRF's default action set (docs/grf-compatibility.md#actions): the eight directions and shot.
DIRECTIONS = range(1, 9)
SHOT = 12
#: The ball has left his foot once it runs faster than this (m/s).
STRUCK_SPEED = 12.0
#: A press whose ball has not left within this many steps counts as not struck.
WAIT_STEPS = 8
#: Steps an episode may last before the press (the carrier must have had the ball k steps by then).
MAX_STEPS = 40


def ball_speed(obs: Observation) -> float:
    """The ball's horizontal speed (m/s) from the raw observation's per-step displacement."""
    dx, dy = float(obs["ball_direction"][0]), float(obs["ball_direction"][1])
    return math.hypot(dx * cases.METRES_X, dy * cases.METRES_Y) * 10.0


def probe(env: FootballEnv, owned_steps: int, moves: str, rng: random.Random) -> int | None:
    """One episode: steps from the press to the strike, or `None` if the ball never left."""
    env.reset()
    owned = 0
    pressed_at: int | None = None
    for step in range(1, MAX_STEPS + WAIT_STEPS + 1):
        if pressed_at is None and owned > owned_steps:
            action, pressed_at = SHOT, step
        elif moves == "random":
            action = rng.choice(DIRECTIONS)
        else:
            action = int(moves)
        observations, _, done, _ = env.step([action])
        obs = observations[0]
        if cases.owns_ball(obs):
            owned += 1
        if pressed_at is not None and ball_speed(obs) > STRUCK_SPEED:
            return step - pressed_at
        if done or (pressed_at is not None and step - pressed_at >= WAIT_STEPS):
            return None
    return None


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("scenario", nargs="?", default="academy_empty_goal_close")
    parser.add_argument(
        "--moves", default="random", help="'random' or a direction action index (1-8)"
    )
    parser.add_argument("--episodes", type=int, default=12, help="episodes per k")
    parser.add_argument(
        "--seed", type=int, default=11, help="the engine seed (and the random directions')"
    )
    args = parser.parse_args()
    if args.moves != "random" and (not args.moves.isdigit() or int(args.moves) not in DIRECTIONS):
        parser.error(f"--moves must be 'random' or a direction 1-8, got {args.moves!r}")
    env = cases.make_env(args.scenario, args.seed)
    rng = random.Random(args.seed)
    for k in (0, 1, 2, 3, 4, 6, 8):
        delays = [probe(env, k, args.moves, rng) for _ in range(args.episodes)]
        struck = [d for d in delays if d is not None]
        spread = sorted(collections.Counter(struck).items())
        mean = f"{statistics.mean(struck):.1f}" if struck else "-"
        print(
            f"shot after {k} steps on the ball: struck {len(struck)}/{len(delays)}, mean {mean} steps, {spread}"
        )


if __name__ == "__main__":
    main()
