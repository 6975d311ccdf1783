"""`python/bench/carrier_profile.py`, the fidelity harness's view of the ball carriers."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import carrier_profile  # noqa: E402 (found through BENCH)
from fidelity_cases import METRES_X  # noqa: E402


def observation(owner_team: int, mode: int = 0) -> dict[str, object]:
    # Left player 1 at the centre spot moving 0.01 units along x per step; the right team's nearest
    # player 0.1 units (5.44 m) straight ahead of him.
    left = np.array([[-0.9, 0.0], [0.0, 0.0]])
    right = np.array([[0.9, 0.0], [0.1, 0.0]])
    return {
        "ball_owned_team": owner_team,
        "ball_owned_player": 1,
        "game_mode": mode,
        "left_team": left,
        "right_team": right,
        "left_team_direction": np.array([[0.0, 0.0], [0.01, 0.0]]),
        "right_team_direction": np.zeros((2, 2)),
    }


def test_the_carrier_s_speed_and_nearest_opponent_come_from_the_raw_observation() -> None:
    seen = carrier_profile.carrier(observation(0))
    assert seen is not None
    speed, nearest = seen
    assert abs(speed - 0.01 * METRES_X * 10.0) < 1e-9
    assert abs(nearest - 0.1 * METRES_X) < 1e-9
    # A loose ball, or a ball out of normal play, has no carrier.
    assert carrier_profile.carrier(observation(-1)) is None
    assert carrier_profile.carrier(observation(0, mode=2)) is None


def test_a_short_match_profiles_its_carriers() -> None:
    p = carrier_profile.profile("11_vs_11_stochastic", 300, 3)
    assert p.speeds and len(p.speeds) == len(p.nearest)
    assert all(s >= 0.0 for s in p.speeds) and all(d > 0.0 for d in p.nearest)
    assert abs(sum(p.band_shares()) - 1.0) < 1e-9
    # Every step belongs to at most one spell, and the carrier steps to spells.
    assert sum(p.spells) <= 300 and len(p.speeds) <= sum(p.spells)
