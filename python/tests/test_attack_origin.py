"""`python/bench/attack_origin.py`, a tracing tool of the fidelity harness, run as a user runs it."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import attack_origin  # noqa: E402 (found through BENCH)
import fidelity_cases as cases  # noqa: E402


def observation(ball_x: float, owner: int, mode: int = 0) -> dict[str, Any]:
    """A raw observation with only what the walk back reads: the ball, its owner and the mode."""
    return {"ball": np.array([ball_x, 0.0, 0.11]), "ball_owned_team": owner, "game_mode": mode}


def test_an_attack_begins_where_we_last_had_the_ball_or_at_our_restart() -> None:
    # We had it at x = -0.5, then they did for three steps and shot.
    history = [
        observation(-0.5, 0),
        observation(-0.6, 1),
        observation(-0.6, -1),
        observation(-0.7, 1),
    ]
    found = attack_origin.origin(history, 3)
    assert (found.kind, found.steps, found.mode) == ("from_us", 3, cases.NORMAL)
    assert abs(found.ball_x + 0.5 * cases.METRES_X) < 1e-4
    # Our goal kick, then straight to them.
    history = [observation(-0.92, -1, cases.GOAL_KICK), observation(-0.4, 1), observation(-0.6, 1)]
    found = attack_origin.origin(history, 2)
    assert (found.kind, found.steps, found.mode) == ("restart", 2, cases.GOAL_KICK)
    # Theirs from the first step.
    found = attack_origin.origin([observation(0.0, 1), observation(-0.5, 1)], 1)
    assert (found.kind, found.steps) == ("start", 1)


def test_a_match_against_an_idle_agent_gives_each_shot_an_origin() -> None:
    found = attack_origin.origins_in_match("11_vs_11_hard_stochastic", "idle", 100, 1500)
    for o in found:
        assert o.kind in ("from_us", "restart", "start") and 0 <= o.steps < 1500
        assert -56.0 < o.ball_x < 56.0
    rows = attack_origin.table(found, 1)
    assert len(rows) == len({(o.kind, o.mode) for o in found})
