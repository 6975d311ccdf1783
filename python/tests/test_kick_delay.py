"""`python/bench/kick_delay.py`, the probe of when a carrier's pressed shot leaves his foot."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import fidelity_cases as cases  # noqa: E402 (found through BENCH)
import kick_delay  # noqa: E402
from fidelity_cases import METRES_X  # noqa: E402


def test_the_ball_s_speed_comes_from_its_displacement_per_step() -> None:
    obs = {"ball_direction": np.array([0.02, 0.0, 0.0])}
    assert abs(kick_delay.ball_speed(obs) - 0.02 * METRES_X * 10.0) < 1e-9
    obs = {"ball_direction": np.array([0.0, -0.01, 0.3])}
    assert abs(kick_delay.ball_speed(obs) - 0.01 * cases.METRES_Y * 10.0) < 1e-9


def test_a_shot_pressed_on_the_run_leaves_his_foot_a_few_steps_later() -> None:
    env = cases.make_env("academy_empty_goal_close", 11)
    rng = random.Random(11)
    for owned_steps, moves in [(0, "5"), (3, "5"), (2, "random")]:
        delay = kick_delay.probe(env, owned_steps, moves, rng)
        # The wind-up and the turn to goal take at least a step; touchline never drops the press.
        assert delay is not None and 1 <= delay <= kick_delay.WAIT_STEPS, (
            owned_steps,
            moves,
            delay,
        )
