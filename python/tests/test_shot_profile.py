"""`python/bench/shot_profile.py`, a tracing tool of the fidelity harness, run as a user runs it."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import shot_profile as profile  # noqa: E402 (found through BENCH)


def observation(ball: tuple[float, float], owner: int, mode: int = 0) -> dict[str, Any]:
    """A raw observation with only what the shot test reads: the ball, its owner, the mode, the
    score and our keeper on his line."""
    left = np.zeros((11, 2))
    left[0] = (-0.99, 0.0)
    return {
        "ball": np.array([ball[0], ball[1], 0.11]),
        "ball_owned_team": owner,
        "game_mode": mode,
        "score": [0, 0],
        "left_team": left,
    }


def test_a_hard_strike_at_our_goal_by_their_carrier_is_a_shot_and_a_pass_away_is_not() -> None:
    before = observation((-0.7, 0.0), owner=1)
    # 0.05 units of x a step: 27 m/s towards our goal, from about 16 m out.
    found = profile.shot(before, observation((-0.75, 0.0), owner=-1))
    assert found is not None
    assert 15.0 < found.distance < 17.0 and 26.0 < found.speed < 28.0
    assert abs(found.keeper_off_line - 0.544) < 1e-6
    assert profile.shot(before, observation((-0.65, 0.0), owner=-1)) is None, "away from goal"
    assert profile.shot(before, observation((-0.71, 0.0), owner=-1)) is None, "a touch, not a shot"
    assert profile.shot(before, observation((-0.75, 0.0), owner=1)) is None, "he still has it"
    assert (
        profile.shot(observation((0.0, 0.0), owner=1), observation((-0.05, 0.0), owner=-1)) is None
    )


def test_distances_fall_into_bands() -> None:
    assert profile.band(3.0) == "0-10 m"
    assert profile.band(15.0) == "15-20 m"
    assert profile.band(31.0) == "25+ m"


def test_a_match_against_an_idle_agent_counts_shots_and_goals() -> None:
    shots, conceded = profile.shots_in_match("11_vs_11_hard_stochastic", "idle", 100, 1500)
    assert conceded >= sum(s.scored for s in shots)
    for s in shots:
        assert 0.0 <= s.distance <= profile.SHOT_RANGE and s.speed >= profile.SHOT_SPEED
    rows = profile.table(shots, 1)
    assert len(rows) == len({profile.band(s.distance) for s in shots})


def test_the_built_in_ai_can_play_the_agents_side() -> None:
    # GRF's built-in action (19) is in the v2 action set only: the env must be made with it.
    shots, conceded = profile.shots_in_match("11_vs_11_stochastic", "builtin_ai", 100, 300)
    assert conceded >= sum(s.scored for s in shots)
