"""`python/bench/episode_timeline.py`, the tracing tool of the fidelity harness, run as a user runs it."""

from __future__ import annotations

import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import episode_timeline  # noqa: E402 (found through BENCH)


def test_an_idle_carrier_is_seen_with_the_ball_and_plays_out_the_time() -> None:
    # academy_run_to_score: the defenders run past an idle carrier who keeps the ball (GRF: 80 % of
    # episodes reach the 401-step limit).
    length, end, events = episode_timeline.timeline("academy_run_to_score", "idle", 0, 0)
    assert (length, end) == (401, "time_limit")
    assert any(":own0.1" in event for event in events), events


def test_the_closing_line_counts_episodes_our_team_never_had_the_ball() -> None:
    assert (
        episode_timeline.ownership_line(3, [])
        == "0 of 3 episodes never show our team with the ball"
    )
    line = episode_timeline.ownership_line(4, [100, 201])
    assert line == "2 of 4 episodes never show our team with the ball (mean length 150.5)"
