"""`python -m touchline.duel` (issue 19, part 3): policies against each other or the built-in AI,
the result with confidence intervals, and the matches recorded as replays that re-simulate."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import touchline
from touchline.duel import DuelResult, duel, load_policy, main


def test_policy_against_the_builtin_ai_prints_intervals(capsys: pytest.CaptureFixture[str]) -> None:
    assert (
        main(["random", "builtin", "--scenario", "academy_empty_goal_close", "--matches", "3"]) == 0
    )
    out = capsys.readouterr().out
    assert out.count("match ") == 3
    assert "random vs builtin on academy_empty_goal_close" in out
    assert "goal difference" in out and "(95 % CI, n=3)" in out
    assert "points (win 1, draw 1/2)" in out


def test_two_policies_swap_sides_and_record(tmp_path: Path) -> None:
    result = duel(
        load_policy("random", 0), load_policy("idle"), "1_vs_1_easy", 4, seed=2, record=tmp_path
    )
    assert [on_left for _, _, on_left in result.matches] == [True, False, True, False]
    assert result.wins + result.draws + result.losses == 4
    assert [Path(p).name for p in result.replays if p] == [f"duel-{k}.tlreplay" for k in range(4)]
    for k, (mine, theirs, on_left) in enumerate(result.matches):
        replay = touchline.Replay(tmp_path / f"duel-{k}.tlreplay")
        assert replay.controllers == 2
        assert replay.simulate() == replay.frame_hashes
        left, right = replay.scores[-1]
        assert (mine, theirs) == ((left, right) if on_left else (right, left))


def test_intervals_follow_the_matches() -> None:
    result = DuelResult("a", "b", "s", matches=[(2, 0, True), (0, 0, False), (1, 2, True)])
    assert (result.wins, result.draws, result.losses) == (1, 1, 1)
    mean, half = result.goal_difference()
    assert mean == pytest.approx(1 / 3)
    # 1.96 standard errors of (2, 0, -1): sample std 1.5275.
    assert half == pytest.approx(1.96 * 1.527525 / 3**0.5, rel=1e-5)
    assert result.points() == pytest.approx((0.5, 1.96 * 0.5 / 3**0.5))


def test_bad_arguments_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["nothing.zip", "builtin", "--matches", "1"]) == 2
    assert "no policy 'nothing.zip'" in capsys.readouterr().err
    assert main(["builtin", "random"]) == 2
    assert main(["random", "builtin", "--matches", "0"]) == 2
    assert "matches must be 1 or more" in capsys.readouterr().err
    assert main(["random", "builtin", "--scenario", "no_such_scenario", "--matches", "1"]) == 2
    assert "no_such_scenario" in capsys.readouterr().err
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "touchline.duel",
            "idle",
            "builtin",
            "--scenario",
            "academy_empty_goal_close",
            "--matches",
            "1",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0 and "idle vs builtin" in done.stdout, done.stderr


def test_sb3_models_record_their_value_estimates(tmp_path: Path) -> None:
    sb3 = pytest.importorskip("stable_baselines3")
    model = sb3.PPO(
        "MlpPolicy", touchline.make("1_vs_1_easy"), n_steps=64, batch_size=32, device="cpu"
    )
    model.save(tmp_path / "model.zip")
    result = duel(
        load_policy(str(tmp_path / "model.zip")),
        None,
        "academy_empty_goal_close",
        1,
        record=tmp_path / "replays",
    )
    assert result.replays[0] is not None
    replay = touchline.Replay(result.replays[0])
    names = list(replay.values)
    assert names[0] == "model.value" and len(names) == 20
    assert names[1] == "model.probs[idle]" and names[19] == "model.probs[release_dribble]"
    probs = np.stack([replay.values[n] for n in names[1:]])
    np.testing.assert_allclose(probs.sum(axis=0), 1.0, rtol=1e-5)
    assert replay.simulate() == replay.frame_hashes
