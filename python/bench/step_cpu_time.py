"""CPU time per `env.step` of a full match, for the side-by-side speed figure against GRF.

Runs GRF's own call, `create_environment('11_vs_11_stochastic', representation='raw',
other_config_options={'action_set': 'v2'})` then `env.step([19])` (every player on the built-in
AI), in touchline (`touchline.compat.gfootball`) or, with `--grf`, in gfootball itself (run it with
GRF's Python; `README.md` beside this file says how to build GRF). Prints microseconds of CPU
time (`time.process_time`) per step; measures, asserts nothing.

  * touchline: the process's CPU time over loops of `--steps` steps, resets included (timing each
    step alone would add the timer's own cost, about 0.6 µs, to a 20 µs step);
  * GRF: CPU time around each `env.step` alone (its reset takes seconds and is not a step).

This VM's speed drifts by up to 2× within minutes, so run the two at the same time, one core each:

    ~/grf-venv/bin/python python/bench/step_cpu_time.py --grf --steps 1500 &
    python3 python/bench/step_cpu_time.py --steps 30000; wait
"""

from __future__ import annotations

import argparse
import statistics
import time
from typing import Any


def make(grf: bool, representation: str) -> Any:
    """The env, through gfootball or touchline's compat layer."""
    options = {"action_set": "v2"}
    if grf:
        from gfootball.env import create_environment  # type: ignore[import-not-found]
    else:
        from touchline.compat.gfootball import create_environment
    return create_environment(
        env_name="11_vs_11_stochastic", representation=representation, other_config_options=options
    )


def touchline_loops(env: Any, steps: int, loops: int) -> list[float]:
    """µs of CPU time per step over each of `loops` loops of `steps` steps."""
    env.reset()
    per_step = []
    for _ in range(loops):
        start = time.process_time()
        for _ in range(steps):
            if env.step([19])[2]:
                env.reset()
        per_step.append((time.process_time() - start) / steps * 1e6)
    return per_step


def grf_steps(env: Any, steps: int) -> float:
    """µs of CPU time per step, timed around each `env.step` alone."""
    env.reset()
    total = 0.0
    for _ in range(steps):
        start = time.process_time()
        done = env.step([19])[2]
        total += time.process_time() - start
        if done:
            env.reset()
    return total / steps * 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--grf", action="store_true", help="time gfootball instead of touchline")
    parser.add_argument("--steps", type=int, default=30_000, help="steps per loop (GRF: in all)")
    parser.add_argument("--loops", type=int, default=5, help="touchline: loops, median printed")
    parser.add_argument("--representation", default="raw", help="raw, simple115v2, extracted, ...")
    args = parser.parse_args()
    env = make(args.grf, args.representation)
    if args.grf:
        print(
            f"GRF {args.representation}: {grf_steps(env, args.steps):.0f} µs of CPU time per step"
        )
    else:
        loops = touchline_loops(env, args.steps, args.loops)
        print(
            f"touchline {args.representation}: median {statistics.median(loops):.1f} µs of CPU time "
            f"per step (loops: {', '.join(f'{x:.1f}' for x in loops)})"
        )


if __name__ == "__main__":
    main()
