"""Issue 17, item 7: a script whose `reset` hook fails makes `reset()` raise, with the diagnostic.

Before, `reset()` said nothing, the next `step()` raised, and every later `reset()` replayed the
failing episode: 2,970 failures in a row. Now the failed episode raises from `reset()` once, its
steps raise the same error, and the next `reset()` plays the following episode.
"""

from __future__ import annotations

import pathlib

import numpy as np
import pytest
import touchline

SCRIPT = 'fn reset(s) { if s.episode == 3 { throw "no episode 3" } }\nfn reward(s) { 0.0 }\n'
SCENARIO = (
    "scenario failing_reset {\n"
    "  extends academy_empty_goal_close\n"
    '  reward script "r.rhai"\n'
    "  end when steps >= 2\n"
    "}\n"
)


def _make(tmp_path: pathlib.Path):
    (tmp_path / "r.rhai").write_text(SCRIPT)
    path = tmp_path / "failing_reset.tl"
    path.write_text(SCENARIO)
    return touchline.make(str(path))


def _play_out(env) -> None:
    done = False
    while not done:
        _, _, terminated, truncated, _ = env.step(0)
        done = terminated or truncated


def test_a_failing_reset_hook_raises_from_reset_once_and_the_env_moves_on(
    tmp_path: pathlib.Path,
) -> None:
    env = _make(tmp_path)
    env.reset(seed=0)
    failures = []
    for _ in range(30):
        _play_out(env)
        try:
            env.reset()
        except touchline.ScenarioError as error:
            message = str(error)
            assert "tl::S005" in message and "no episode 3" in message, message
            assert error.code == "tl::S005", error.code
            failures.append(message)
            # The failed episode is not played: each step raises the same diagnostic.
            with pytest.raises(touchline.ScenarioError, match="no episode 3"):
                env.step(0)
            # The next reset plays the following episode: its first step works.
            env.reset()
            env.step(0)
    assert len(failures) == 1, failures


def test_a_vector_env_raises_and_resets_the_failed_match_again(tmp_path: pathlib.Path) -> None:
    (tmp_path / "r.rhai").write_text(SCRIPT)
    path = tmp_path / "failing_reset.tl"
    path.write_text(SCENARIO)
    envs = touchline.vector.make(str(path), num_envs=2, seed=0)
    envs.reset(seed=0)
    raised = 0
    for _ in range(40):
        try:
            envs.step(np.zeros(2, dtype=np.int64))
        except touchline.ScenarioError as error:
            assert "no episode 3" in str(error) and error.code == "tl::S005"
            raised += 1
    # Each match fails once, at its episode 3 (the autoreset of its third episode's end).
    assert 1 <= raised <= 2, raised


FIRST = 'fn reset(s) { throw "never" }\nfn reward(s) { 0.0 }\n'


@pytest.mark.parametrize(
    "make",
    [
        lambda path: touchline.make(path).reset(seed=0),
        lambda path: touchline.vector.make(path, num_envs=2, seed=0).reset(seed=0),
        lambda path: touchline.parallel_env(path).reset(seed=0),
    ],
    ids=["make", "vector", "parallel_env"],
)
def test_a_reset_hook_failing_at_the_first_reset_carries_its_code(
    tmp_path: pathlib.Path, make
) -> None:
    """Issue 18: the first reset's error is a `ScenarioError` with `.code`, as a compile error is."""
    (tmp_path / "r.rhai").write_text(FIRST)
    path = tmp_path / "failing_reset.tl"
    path.write_text(SCENARIO)
    with pytest.raises(touchline.ScenarioError, match="never") as caught:
        make(str(path))
    assert caught.value.code == "tl::S005", caught.value.code
    assert "tl::S005" in str(caught.value)
