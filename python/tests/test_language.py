"""Scenarios written in the language (`.tl` files), loaded from Python as a user would."""

from __future__ import annotations

import numpy as np
import pytest
import touchline

DRILL = """/// A drill whose defender starts somewhere new at every reset.
scenario wide_defender {
  extends academy_empty_goal_close
  team right {
    GK at (-1, 0)
    CB at (uniform(-0.5, -0.2), uniform(-0.3, 0.3))
  }
  require distance(right[1], ball) >= 5 m
}
"""


def test_a_tl_file_plays_and_randomises_every_reset(tmp_path) -> None:
    path = tmp_path / "drill.tl"
    path.write_text(DRILL)
    env = touchline.make(str(path))
    starts = []
    for _ in range(4):
        env.reset()
        starts.append(tuple(np.round(env.unwrapped.raw_observations()[0]["right_team"][1], 6)))
        env.step(0)
    assert len(set(starts)) == 4, starts
    # The same seed gives the same placements.
    again = touchline.make(str(path))
    first, _ = again.reset(seed=11)
    env_first, _ = env.reset(seed=11)
    assert np.array_equal(first, env_first)


def test_a_broken_tl_file_raises_scenario_error_with_the_diagnostics(tmp_path) -> None:
    path = tmp_path / "broken.tl"
    path.write_text(
        "scenario broken {\n  extends academy\n  team left { GK at (-1, 0) CBB at (0.5, 0) }\n}\n"
    )
    with pytest.raises(touchline.ScenarioError) as caught:
        touchline.make(str(path))
    message = str(caught.value)
    assert caught.value.code == "tl::E102"
    assert "unknown role `CBB`" in message and "did you mean `CB`?" in message
    assert "broken.tl:3" in message, message
    # Every error is reported at once: the right team is missing too.
    assert "tl::E108" in message


def test_grf_test_scenarios_load_by_name() -> None:
    env = touchline.make("tests/penalty")
    env.reset()
    assert env.unwrapped.raw_observations()[0]["ball"][0] == pytest.approx(-0.72)
