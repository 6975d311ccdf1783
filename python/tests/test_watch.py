"""Issue 18, item 4: hot reload from Python.

`touchline.make(path, watch=True)` (and the vector and PettingZoo envs) follow the scenario file:
an edit is played from the next `reset()`, `info["scenario_version"]` says which version an
episode plays, and an edit that does not load keeps the last good version and warns once.

The watcher runs on its own thread (debounced, 100 ms), so each test resets until the change
shows, for at most `PATIENCE` seconds: a bound on waiting, not a timing assertion.
"""

from __future__ import annotations

import pathlib
import time
import warnings
from typing import Any, Callable

import numpy as np
import pytest
import touchline

PATIENCE = 20.0

DRILL = """/// The ball where the test says.
scenario moving_ball {{
  extends academy_empty_goal_close
  ball at ({x}, {y})
}}
"""


def _write(path: pathlib.Path, x: float, y: float) -> None:
    path.write_text(DRILL.format(x=x, y=y))


def _until(reset: Callable[[], Any], done: Callable[[Any], bool]) -> Any:
    """Calls `reset` until `done(result)`, for at most PATIENCE seconds."""
    deadline = time.monotonic() + PATIENCE
    while True:
        result = reset()
        if done(result):
            return result
        assert time.monotonic() < deadline, "the watcher did not pick up the change"
        time.sleep(0.05)


def _ball(env: Any) -> np.ndarray:
    return np.asarray(env.raw_observations()[0]["ball"])


def test_an_edit_is_played_from_the_next_reset_and_a_broken_one_keeps_the_last_good(
    tmp_path: pathlib.Path,
) -> None:
    path = tmp_path / "drill.tl"
    _write(path, 0.5, 0.0)
    env = touchline.make(path, watch=True, seed=0)
    _, info = env.reset()
    assert info["scenario_version"] == 1
    assert _ball(env)[:2] == pytest.approx([0.5, 0.0], abs=1e-3)
    env.step(0)

    _write(path, -0.3, 0.1)
    _, info = _until(env.reset, lambda r: r[1]["scenario_version"] == 2)
    assert _ball(env)[:2] == pytest.approx([-0.3, 0.1], abs=1e-3)
    _, _, _, _, step_info = env.step(0)
    assert step_info["scenario_version"] == 2

    # Broken: the env keeps version 2 (same ball) and warns once, with the diagnostic.
    path.write_text("scenario moving_ball {\n  extends academy_empty_goal_close\n  ball at (\n}\n")
    caught: list[warnings.WarningMessage] = []

    def reset_recording() -> Any:
        with warnings.catch_warnings(record=True) as record:
            warnings.simplefilter("always")
            result = env.reset()
        caught.extend(record)
        return result

    _until(reset_recording, lambda _: bool(caught))
    for _ in range(5):
        time.sleep(0.05)
        reset_recording()
        env.step(0)
    _, info = reset_recording()
    assert len(caught) == 1, [str(w.message) for w in caught]
    assert issubclass(caught[0].category, UserWarning)
    message = str(caught[0].message)
    assert "keeps the last good version" in message and "tl::E100" in message, message
    assert info["scenario_version"] == 2
    assert _ball(env)[:2] == pytest.approx([-0.3, 0.1], abs=1e-3)

    # Fixed again: played, version 3.
    _write(path, 0.2, -0.1)
    _until(reset_recording, lambda r: r[1]["scenario_version"] == 3)
    assert _ball(env)[:2] == pytest.approx([0.2, -0.1], abs=1e-3)
    assert len(caught) == 1


def test_without_watch_the_version_is_0_and_edits_are_not_seen(tmp_path: pathlib.Path) -> None:
    path = tmp_path / "drill.tl"
    _write(path, 0.5, 0.0)
    env = touchline.make(path, seed=0)
    _, info = env.reset()
    assert info["scenario_version"] == 0
    _write(path, -0.3, 0.1)
    time.sleep(0.3)
    env.reset()
    assert _ball(env)[:2] == pytest.approx([0.5, 0.0], abs=1e-3)


def test_the_vector_env_follows_the_file(tmp_path: pathlib.Path) -> None:
    path = tmp_path / "drill.tl"
    _write(path, 0.5, 0.0)
    env = touchline.vector.make(path, 3, num_threads=2, watch=True, seed=0)
    _, infos = env.reset()
    assert infos["scenario_version"].tolist() == [1, 1, 1]
    _write(path, -0.3, 0.1)
    _, infos = _until(env.reset, lambda r: r[1]["scenario_version"].tolist() == [2, 2, 2])
    env.step(np.zeros(3, dtype=np.int64))


def test_the_pettingzoo_env_follows_the_file(tmp_path: pathlib.Path) -> None:
    path = tmp_path / "drill.tl"
    _write(path, 0.5, 0.0)
    env = touchline.parallel_env(path, 1, 0, watch=True, seed=0)
    _, infos = env.reset()
    assert infos["left_0"]["scenario_version"] == 1
    _write(path, -0.3, 0.1)
    _, infos = _until(env.reset, lambda r: r[1]["left_0"]["scenario_version"] == 2)
    assert np.asarray(env.raw_observations()["left_0"]["ball"])[:2] == pytest.approx(
        [-0.3, 0.1], abs=1e-3
    )


def test_a_script_edit_is_picked_up_too(tmp_path: pathlib.Path) -> None:
    (tmp_path / "r.rhai").write_text("fn reward(s) { 0.25 }\n")
    path = tmp_path / "drill.tl"
    path.write_text(
        'scenario scripted {\n  extends academy_empty_goal_close\n  reward script "r.rhai"\n}\n'
    )
    env = touchline.make(path, watch=True, seed=0)
    env.reset()
    assert env.step(0)[1] == pytest.approx(0.25)
    (tmp_path / "r.rhai").write_text("fn reward(s) { 0.5 }\n")
    _until(env.reset, lambda r: r[1]["scenario_version"] == 2)
    assert env.step(0)[1] == pytest.approx(0.5)


def test_watching_needs_a_file_and_a_first_version_that_loads(tmp_path: pathlib.Path) -> None:
    with pytest.raises(touchline.ScenarioError, match="stdlib scenario"):
        touchline.make("academy_empty_goal_close", watch=True)
    broken = tmp_path / "broken.tl"
    broken.write_text("scenario broken {\n  extends acadmey\n}\n")
    with pytest.raises(touchline.ScenarioError) as error:
        touchline.make(broken, watch=True)
    assert error.value.code == "tl::E114"
    with pytest.raises(ValueError, match="watch must be True or False"):
        touchline.make(broken, watch="yes")  # type: ignore[arg-type]
