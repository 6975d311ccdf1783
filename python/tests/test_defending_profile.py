"""`python/bench/defending_profile.py`, the harness's view of a side defending against the built-in AI."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import defending_profile  # noqa: E402 (found through BENCH)
from fidelity_cases import METRES_X  # noqa: E402


def observation(carrier_x: float, owner_team: int = 0, mode: int = 0) -> dict[str, object]:
    # Left player 1 on the ball at x = carrier_x; left player 2 sprints along x (0.08 units a step).
    # Right: the keeper, one defender 0.1 units goal-side of the carrier and one 0.1 units behind
    # him running back at 0.005 units a step.
    return {
        "ball_owned_team": owner_team,
        "ball_owned_player": 1,
        "game_mode": mode,
        "left_team": np.array([[-0.9, 0.0], [carrier_x, 0.0], [carrier_x, 0.2]]),
        "left_team_direction": np.array([[0.0, 0.0], [0.01, 0.0], [0.02, 0.0]]),
        "right_team": np.array([[0.9, 0.0], [carrier_x + 0.1, 0.0], [carrier_x - 0.1, 0.0]]),
        "right_team_direction": np.array([[0.0, 0.0], [0.0, 0.0], [0.005, 0.0]]),
    }


def test_defenders_are_split_at_the_carrier_and_timed_from_the_raw_observation() -> None:
    p = defending_profile.DefendingProfile()
    assert defending_profile.observe(observation(0.5), p)
    assert p.goal_side == [1]
    assert math.isclose(p.nearest[0], 0.1 * METRES_X)
    # Both outfield defenders ranked by distance, the keeper left out: two 0.1 units off.
    assert len(p.ranked) == 1 and len(p.ranked[0]) == 2
    assert all(math.isclose(d, 0.1 * METRES_X) for d in p.ranked[0])
    assert p.behind_speed == [p.behind_run_back[0]]
    assert math.isclose(p.behind_run_back[0], 0.005 * METRES_X * 10.0)
    # Only the attacker off the ball counts (not the keeper, not the carrier): 10.9 m/s.
    assert len(p.attacker_speed) == 1 and p.attacker_speed[0] > defending_profile.SPRINTING
    # Outside the attacking 40 %, with the ball loose or the right side's, or out of normal play:
    # nothing is counted.
    for obs in (
        observation(0.1),
        observation(0.5, owner_team=-1),
        observation(0.5, 1),
        observation(0.5, mode=3),
    ):
        assert not defending_profile.observe(obs, p)
    assert len(p.goal_side) == 1


def test_a_side_of_a_keeper_alone_has_no_defender_near() -> None:
    obs = observation(0.5)
    obs["right_team"] = np.array([[0.9, 0.0]])
    obs["right_team_direction"] = np.array([[0.0, 0.0]])
    p = defending_profile.DefendingProfile()
    assert defending_profile.observe(obs, p)
    assert p.goal_side == [0] and p.nearest == [math.inf] and p.ranked == [[]]


def test_the_median_of_an_even_count_is_the_mean_of_the_middle_two() -> None:
    assert defending_profile.median([4.0, 1.0, 3.0, 2.0]) == 2.5
    assert defending_profile.median([3.0, 1.0, 2.0]) == 2.0
    assert math.isnan(defending_profile.median([]))


def test_a_short_match_profiles_the_defence() -> None:
    p = defending_profile.profile("11_vs_11_easy_stochastic", 400, 1)
    # The θ = 1 side reaches the easy side's end within 40 s of play (46 steps counted at seed 1).
    assert p.goal_side and len(p.goal_side) == len(p.nearest)
    assert all(0 <= n <= 10 for n in p.goal_side)
    assert all(d > 0.0 for d in p.nearest)
    # Ten outfield defenders ranked, at most the first six kept, nearest first.
    assert all(len(r) == defending_profile.RANKED and r == sorted(r) for r in p.ranked)
    assert [r[0] for r in p.ranked] == p.nearest
    assert len(p.behind_speed) == len(p.behind_run_back) == 10 * len(p.goal_side) - sum(p.goal_side)
    assert len(p.attacker_speed) == 9 * len(p.goal_side)
    assert 0.0 <= defending_profile.share(p.behind_speed, defending_profile.STANDING, False) <= 1.0
