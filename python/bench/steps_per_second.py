"""Steps per second of touchline's Python environments: measured and printed, never asserted.

For each representation it times
  * `_touchline.Env.step` called directly (the Rust step plus the binding),
  * `FootballEnv.step` (the Gymnasium env), and reports its overhead per step over the former,
  * `TouchlineVectorEnv.step` (copy=False) for each thread count, with its speed-up over one thread.

Usage (from the repository root, with the package installed):
    python3 python/bench/steps_per_second.py [--scenario NAME] [--steps N] [--num-envs N] [--threads 1,2]
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from typing import Any

import numpy as np
import touchline
import touchline.vector
from touchline._touchline import Env as CoreEnv

REPRESENTATIONS = ("simple115v2", "simple115", "extracted")


def time_core(scenario: str, representation: str, actions: list[int]) -> float:
    """Seconds for len(actions) steps of the extension's Env, resetting at each episode end."""
    env = CoreEnv(scenario, touchline.EnvOptions(representation=representation), seed=0)
    env.reset()
    step, reset = env.step, env.reset
    start = time.perf_counter()
    for action in actions:
        _, _, terminated, truncated, _ = step(action)
        if terminated or truncated:
            reset()
    return time.perf_counter() - start


def time_gymnasium(scenario: str, representation: str, actions: list[int]) -> float:
    """Seconds for len(actions) steps of the Gymnasium env, resetting at each episode end."""
    env = touchline.make(scenario, representation=representation, seed=0)
    env.reset()
    step, reset = env.step, env.reset
    start = time.perf_counter()
    for action in actions:
        _, _, terminated, truncated, _ = step(action)
        if terminated or truncated:
            reset()
    return time.perf_counter() - start


def time_vector(
    scenario: str, representation: str, num_envs: int, threads: int, actions: np.ndarray
) -> float:
    """Seconds for len(actions) steps of a vector env of num_envs matches on `threads` threads."""
    envs = touchline.vector.make(
        scenario, num_envs, num_threads=threads, representation=representation, seed=0, copy=False
    )
    envs.reset()
    step = envs.step
    start = time.perf_counter()
    for batch in actions:
        step(batch)
    return time.perf_counter() - start


def best_of(repeats: int, run: Callable[..., float], *args: Any) -> float:
    """The fastest of `repeats` runs (the least disturbed by other work on the machine)."""
    return min(run(*args) for _ in range(repeats))


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--scenario", default="academy_empty_goal_close")
    parser.add_argument("--steps", type=int, default=20_000, help="single-env steps per run")
    parser.add_argument("--num-envs", type=int, default=16)
    parser.add_argument("--vector-steps", type=int, default=1_000, help="vector steps per run")
    parser.add_argument("--threads", default="1,2", help="comma-separated thread counts")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--representations", default=",".join(REPRESENTATIONS))
    args = parser.parse_args()

    rng = np.random.default_rng(0)
    actions = [int(a) for a in rng.integers(19, size=args.steps)]
    batches = rng.integers(19, size=(args.vector_steps, args.num_envs))
    threads = [int(t) for t in args.threads.split(",")]
    representations = args.representations.split(",")

    print(
        f"scenario {args.scenario}; best of {args.repeats} runs; touchline {touchline.__version__}"
    )
    print()
    print(
        f"{'representation':<14} {'extension steps/s':>18} {'gymnasium steps/s':>18} {'overhead µs/step':>17}"
    )
    for representation in representations:
        core = best_of(args.repeats, time_core, args.scenario, representation, actions)
        gym = best_of(args.repeats, time_gymnasium, args.scenario, representation, actions)
        overhead = (gym - core) / args.steps * 1e6
        print(
            f"{representation:<14} {args.steps / core:>18,.0f} {args.steps / gym:>18,.0f} {overhead:>17.2f}"
        )
    print()
    print(f"vector env, {args.num_envs} matches, copy=False")
    print(f"{'representation':<14} {'threads':>7} {'steps/s':>12} {'speed-up':>9}")
    for representation in representations:
        baseline = None
        for count in threads:
            seconds = best_of(
                args.repeats,
                time_vector,
                args.scenario,
                representation,
                args.num_envs,
                count,
                batches,
            )
            rate = args.vector_steps * args.num_envs / seconds
            baseline = baseline or rate
            print(f"{representation:<14} {count:>7} {rate:>12,.0f} {rate / baseline:>8.2f}x")


if __name__ == "__main__":
    main()
