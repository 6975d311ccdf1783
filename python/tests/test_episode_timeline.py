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


def test_episodes_are_split_by_the_team_first_seen_with_the_ball() -> None:
    events = ["3:own-1.-1@0.02,0.00", "11:own1.3@-0.05,-0.01", "40:own0.1@-0.2,0.0"]
    assert episode_timeline.first_owner(events) == "theirs"
    assert episode_timeline.first_owner(["5:own0.1@0.02,0.00"]) == "ours"
    assert episode_timeline.first_owner(["9:kick20@0.1,0.0,z0.3 a12"]) == "nobody"
    rows = [("ours", 80, "possession"), ("theirs", 200, "out_of_play"), ("theirs", 100, "goal")]
    assert episode_timeline.first_owner_lines(rows) == [
        "first ours: 1 episodes, mean length 80.0, ends {'possession': 1}",
        "first theirs: 2 episodes, mean length 150.0, ends {'out_of_play': 1, 'goal': 1}",
    ]
