"""`python/bench/won_ball_profile.py`, a tracing tool of the fidelity harness, run as a user runs it."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import fidelity_cases as cases  # noqa: E402
import won_ball_profile  # noqa: E402 (found through BENCH)


def observation(ball_x: float, team: int, player: int = 0, mode: int = 0) -> dict[str, Any]:
    """A raw observation with only what the tool reads: the ball, its owner and the mode."""
    return {
        "ball": np.array([ball_x, 0.0, 0.11]),
        "ball_owned_team": team,
        "ball_owned_player": player,
        "game_mode": mode,
    }


def test_a_win_is_followed_to_its_end() -> None:
    # Our player 4 has it, it runs loose, their player 2 has it for two steps, then our 4 again.
    history = [
        observation(-0.5, 0, 4),
        observation(-0.5, -1),
        observation(-0.51, 1, 2),
        observation(-0.52, 1, 2),
        observation(-0.52, 0, 4),
    ]
    (win,) = won_ball_profile.wins(history)
    assert (win.end, win.steps, win.first_kick) == ("regain_same", 2, None)
    assert abs(win.ball_x + 0.51 * cases.METRES_X) < 1e-4
    # Won, carried, then kicked away at 20 m/s (0.2 units a step along x is about 109 m/s, so
    # 0.04 is about 22 m/s), then our goal kick: the spell ends on the stop.
    history = [
        observation(0.0, 0, 3),
        observation(0.0, 1, 5),
        observation(0.01, 1, 5),
        observation(0.05, -1),
        observation(0.09, -1),
        observation(-0.9, -1, mode=cases.GOAL_KICK),
    ]
    (win,) = won_ball_profile.wins(history)
    assert (win.end, win.first_kick) == ("stop", 2)
    # A restart between our touch and theirs is no win.
    history = [
        observation(0.0, 0, 3),
        observation(0.0, -1, mode=cases.THROW_IN),
        observation(0.0, 1, 5),
    ]
    assert won_ball_profile.wins(history) == []


def test_a_match_against_an_idle_agent_gives_rows_per_band() -> None:
    found = won_ball_profile.wins_in_match("11_vs_11_hard_stochastic", "idle", 100, 1500)
    assert found, "the hard side wins the ball off an idle agent"
    for w in found:
        assert w.end in ("regain", "regain_same", "stop", "shot", "open")
        assert 0 < w.steps <= won_ball_profile.HORIZON and -56.0 < w.ball_x < 56.0
        assert w.first_kick is None or 0 < w.first_kick <= w.steps
    rows = won_ball_profile.table(found, 1)
    assert 1 <= len(rows) <= len(won_ball_profile.BANDS)
