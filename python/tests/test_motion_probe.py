"""`python/bench/motion_probe.py`, the probe of how a player starts, stops and turns."""

from __future__ import annotations

import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import motion_probe  # noqa: E402 (found through BENCH)


def test_a_sprinter_reaches_his_top_speed_and_turns_back(tmp_path: Path) -> None:
    env = motion_probe.make_env(False, 1.0, False, tmp_path)
    actions = motion_probe.SEQUENCES["reverse"]
    rows = motion_probe.velocities(env, actions)
    assert len(rows) == len(actions)
    # He stands while idle, then sprints right at GRF's 8·(0.9 + 0.1·speed) m/s at most.
    assert all(abs(vx) < 1e-6 and abs(vy) < 1e-6 for vx, vy in rows[:5])
    top = max(vx for vx, _ in rows)
    assert 7.0 < top <= 8.0, top
    # Held left, he runs the other way by the end.
    assert rows[-1][0] < -5.0, rows[-1]


def test_the_grf_and_touchline_scenarios_place_the_same_players() -> None:
    for carry in (False, True):
        grf = motion_probe.scenario_text(motion_probe.GRF_SCENARIO, 0.6, carry)
        tl = motion_probe.scenario_text(motion_probe.TL_SCENARIO, 0.6, carry)
        for x, y in (motion_probe.KEEPER, motion_probe.RUNNER):
            assert f"{x}, {y}" in grf and f"({x}, {y})" in tl
        assert "difficulty = 0.6" in grf and "difficulty 0.6" in tl
