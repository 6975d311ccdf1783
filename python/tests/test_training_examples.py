"""The training examples of examples/python/ run as a user runs them, a few thousand steps each:
they train, log and save, with the real libraries (SB3, torch, SuperSuit). Whether they learn is
shown by the learning curves under docs/, not here.

Skipped where the training libraries are not installed; `.ci/run` installs them.
"""

from __future__ import annotations

import csv
import re
import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "python"


def run(script: str, *args: str, cwd: Path) -> str:
    """Runs an example with this interpreter; returns its stdout, failing with its output."""
    done = subprocess.run(
        [sys.executable, str(EXAMPLES / script), *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, f"{script} failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done.stdout


def event_files(folder: Path) -> list[Path]:
    return list(folder.rglob("events.out.tfevents.*"))


def test_train_sb3_ppo(tmp_path: Path) -> None:
    pytest.importorskip("stable_baselines3")
    pytest.importorskip("tensorboard")
    out = tmp_path / "run"
    stdout = run(
        "train_sb3_ppo.py",
        "--timesteps",
        "2048",
        "--envs",
        "2",
        "--n-steps",
        "256",
        "--eval-every",
        "1024",
        "--eval-episodes",
        "2",
        "--out",
        str(out),
        cwd=tmp_path,
    )
    assert "env steps/s" in stdout and "% in the env" in stdout
    assert (out / "model.zip").is_file() and (out / "best_model.zip").is_file()
    assert event_files(out / "tb")
    with (out / "learning_curve.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert [int(r["steps"]) for r in rows] == [1024, 2048]
    assert all(-1.0 <= float(r["mean_return"]) <= 1.0 for r in rows)


def test_sb3_ppo_trains_10k_steps_through_make_vec_env_with_no_wrapper() -> None:
    # The first training run a new user tries (issue 16): SB3's make_vec_env on the registered id,
    # nothing else. Its Monitor reads info["episode"], which touchline leaves free.
    sb3 = pytest.importorskip("stable_baselines3")
    import touchline  # noqa: F401  (registers the touchline/ ids)
    from stable_baselines3.common.env_util import make_vec_env

    envs = make_vec_env("touchline/academy_empty_goal_close-v0", n_envs=2, seed=0)
    model = sb3.PPO("MlpPolicy", envs, n_steps=512, batch_size=256, seed=0, device="cpu")
    model.learn(total_timesteps=10_000)
    assert model.num_timesteps >= 10_000
    episodes = list(model.ep_info_buffer)
    assert episodes and all({"r", "l", "t"} <= set(e) for e in episodes)
    envs.close()


def test_ppo_vector(tmp_path: Path) -> None:
    pytest.importorskip("torch")
    pytest.importorskip("tensorboard")
    stdout = run(
        "ppo_vector.py",
        "--total-timesteps",
        "2048",
        "--num-envs",
        "4",
        "--num-steps",
        "128",
        "--out",
        str(tmp_path / "runs"),
        cwd=tmp_path,
    )
    assert "2048 steps" in stdout and "env steps/s" in stdout
    assert event_files(tmp_path / "runs")


def test_self_play_pettingzoo(tmp_path: Path) -> None:
    pytest.importorskip("stable_baselines3")
    pytest.importorskip("supersuit")
    out = tmp_path / "run"
    stdout = run(
        "self_play_pettingzoo.py",
        "--timesteps",
        "1024",
        "--matches",
        "2",
        "--n-steps",
        "128",
        "--eval-episodes",
        "1",
        "--out",
        str(out),
        cwd=tmp_path,
    )
    assert "goal difference per match vs builtin" in stdout
    # One policy on both sides: level on average, but one match can end with a goal either way.
    assert re.search(r"goal difference per match vs self: [+-]\d+\.\d\d", stdout), stdout
    assert (out / "model.zip").is_file()


def test_custom_reward(tmp_path: Path) -> None:
    pytest.importorskip("stable_baselines3")
    stdout = run(
        "custom_reward.py",
        "--timesteps",
        "1024",
        "--envs",
        "2",
        "--eval-episodes",
        "1",
        "--out",
        str(tmp_path),
        cwd=tmp_path,
    )
    assert "run_to_score_shaped.tl: goal rate" in stdout
    assert (tmp_path / "model.zip").is_file()


def test_evaluate_plays_the_benchmarks_and_a_league(tmp_path: Path) -> None:
    # `random` and `idle` stand in for model files; SB3 loads these only for a model.
    stdout = run("evaluate.py", "random", "idle", "--episodes", "1", cwd=tmp_path)
    for opponent in ("builtin_easy", "builtin_medium", "builtin_hard"):
        assert f"random vs {opponent}" in stdout and f"idle vs {opponent}" in stdout
    assert "Head to head" in stdout and "Elo (medium built-in AI = 1000)" in stdout
    elo = stdout.split("Elo (medium built-in AI = 1000)")[1]
    ratings = {line.split()[0]: float(line.split()[1]) for line in elo.strip().splitlines()}
    assert set(ratings) == {"random", "idle", "builtin_easy", "builtin_medium", "builtin_hard"}
    assert ratings["builtin_medium"] == 1000.0


def test_elo_is_the_bradley_terry_fit_on_elos_scale(monkeypatch: pytest.MonkeyPatch) -> None:
    import importlib.util

    spec = importlib.util.spec_from_file_location("evaluate", EXAMPLES / "evaluate.py")
    assert spec is not None and spec.loader is not None
    evaluate = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "evaluate", evaluate)  # its dataclass looks itself up there
    spec.loader.exec_module(evaluate)
    results = evaluate.Results()
    # a beats b 3 times in 4 (odds 3:1) over many matches, b and c draw every time.
    results.matches += [("a", "b", 1, 0)] * 300 + [("b", "a", 1, 0)] * 100
    results.matches += [("b", "c", 0, 0)] * 400
    ratings = evaluate.elo(results, anchor="b")
    assert ratings["b"][0] == 1000.0
    # Elo's scale: odds 3:1 are 400·log10(3) ≈ 191 points (the prior shrinks it a little).
    assert 180 < ratings["a"][0] - ratings["b"][0] < 192
    assert abs(ratings["c"][0] - 1000.0) < 5
    assert 0 < ratings["a"][1] < 30
