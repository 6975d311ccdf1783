"""`python/bench/loose_ball_profile.py`, a tracing tool of the fidelity harness, run as a user runs it."""

from __future__ import annotations

import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import loose_ball_profile as profile  # noqa: E402 (found through BENCH)


def test_a_spell_ends_as_grf_ends_an_episode_goal_first_then_the_stoppage_then_the_owner() -> None:
    assert profile.spell_end(owner=-1, mode=0, reward=0.0, done=False) is None
    assert profile.spell_end(owner=1, mode=0, reward=0.0, done=False) == "theirs"
    assert profile.spell_end(owner=0, mode=0, reward=0.0, done=True) == "ours"
    assert profile.spell_end(owner=-1, mode=0, reward=0.0, done=True) == "time limit"
    # A goal restarts with a kickoff (game_mode 1) on the step it is scored: the goal counts.
    assert profile.spell_end(owner=-1, mode=1, reward=1.0, done=True) == "goal for"
    assert profile.spell_end(owner=-1, mode=1, reward=-1.0, done=False) == "goal against"
    assert profile.spell_end(owner=-1, mode=2, reward=0.0, done=True) == "out: goal kick"
    assert profile.spell_end(owner=1, mode=5, reward=0.0, done=False) == "out: throw-in"


def test_the_table_groups_spells_by_button_then_end() -> None:
    spells = [
        profile.Spell("shot", 10, 20.0, 1.0, "theirs"),
        profile.Spell("long", 30, 10.0, 3.0, "out: corner"),
        profile.Spell("long", 10, 30.0, 1.0, "out: corner"),
        profile.Spell("long", 5, 2.0, 0.5, "ours"),
    ]
    lines = profile.table(spells)
    assert [line.split()[:4] for line in lines] == [
        ["long", "->", "ours", "1"],
        ["long", "->", "out:", "corner"],
        ["shot", "->", "theirs", "1"],
    ]
    assert "2 spells,  20.0 steps (median 20),  20.0 m, highest 2.00 m" in lines[1]


def test_a_random_agent_in_a_drill_loses_the_ball_and_every_spell_ends() -> None:
    found = [
        s
        for episode in range(3)
        for s in profile.spells("academy_3_vs_1_with_keeper", "random", episode, 0)
    ]
    assert found, "a random agent never lost the ball in three episodes"
    for spell in found:
        assert spell.end in profile.ENDS
        assert spell.button in (*profile.BUTTONS.values(), "none")
        assert spell.steps >= 0 and spell.distance >= 0.0 and spell.highest >= 0.0


def test_an_idle_carrier_never_lets_the_ball_go_loose_by_a_button() -> None:
    # academy_run_to_score: the idle carrier keeps the ball to the time limit (GRF: 80 % of episodes).
    assert all(s.button == "none" for s in profile.spells("academy_run_to_score", "idle", 0, 0))
