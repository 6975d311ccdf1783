"""Drills that start from a restart (`start with`, issue 18 item 2), seen from Python as GRF users
see them: GRF's raw `game_mode` at the reset (6 penalty, 4 corner) and GRF's own penalty test."""

from __future__ import annotations

from pathlib import Path

import touchline
from touchline.compat.gfootball import create_environment

SCENARIOS = Path(__file__).resolve().parents[2] / "examples" / "scenarios"
SHORT_PASS, SHOT, SLIDING = 11, 12, 16  # GRF's default action set


def test_the_penalty_drill_starts_in_the_penalty_game_mode() -> None:
    env = touchline.make(str(SCENARIOS / "penalty_kick.tl"))
    env.reset(seed=0)
    raw = env.unwrapped.raw_observations()[0]
    assert raw["game_mode"] == 6
    assert abs(raw["ball"][0] - 0.809) < 0.01 and abs(raw["ball"][1]) < 1e-6
    terminated = truncated = False
    steps = 0
    while not (terminated or truncated):
        _, _reward, terminated, truncated, _ = env.step(SHOT)
        steps += 1
    assert terminated and steps <= 40, (steps, terminated)


def test_grf_penalty_test_through_the_gfootball_compat_layer() -> None:
    # GRF's football_env_test.test_penalty, on tests/penalty started from the penalty kick.
    env = create_environment(env_name=str(SCENARIOS / "penalty_test.tl"), representation="raw")
    o = env.reset()
    assert o[0]["game_mode"] == 6
    done, steps = False, 0
    while not done:
        o, _, done, _ = env.step(SLIDING)
        steps += 1
    assert steps == 31
    assert abs(o[0]["ball"][0] + 0.809) < 0.01 and abs(o[0]["ball"][1]) < 0.01
    assert abs(o[0]["right_team"][0][0] - 1) < 0.1
    assert abs(o[0]["right_team"][1][0] + 0.75) < 0.1
    assert abs(o[0]["left_team"][0][0] + 0.95) < 0.1
    assert abs(o[0]["left_team"][1][0] + 0.70) < 0.1


def test_the_corner_drill_starts_with_a_corner_and_plays_on() -> None:
    env = create_environment(env_name=str(SCENARIOS / "corner_kick.tl"), representation="raw")
    o = env.reset()
    assert o[0]["game_mode"] == 4
    modes = []
    for step in range(15):
        o, _, done, _ = env.step(SHORT_PASS if step < 2 else 0)
        modes.append(o[0]["game_mode"])
        assert not done, f"ended at step {step + 1}: {modes}"
    assert modes[-1] == 0, modes
