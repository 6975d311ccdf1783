"""Issue 17: input that used to crash the interpreter raises instead, and saved states are checked.

- deep nesting (item 1) and a label past column 65,535 (item 2) raise ScenarioError with the
  rendered diagnostic, where they used to kill the interpreter (SIGSEGV) or raise RuntimeError;
- a scenario that compiles but cannot give the left agent a player in odd episodes (item 3) is
  refused when made, not at the second reset;
- the frame stacks are inside the state's checksum (item 11);
- `start from` takes what `get_state()` returns (item 12).
"""

from __future__ import annotations

import json
import pathlib

import numpy as np
import pytest
import touchline


def _scenario(tmp_path: pathlib.Path, name: str, text: str) -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


@pytest.mark.parametrize(
    "body",
    [
        "end when " + "(" * 1000 + "steps >= 5" + ")" * 1000,
        "ball at " + "(" * 5000 + "(0.5, 0)" + ")" * 5000,
        "end when " + "not " * 10_000 + "steps >= 5",
    ],
    ids=["parentheses", "position", "not"],
)
def test_deep_nesting_raises(tmp_path: pathlib.Path, body: str) -> None:
    text = "scenario deep {\n  extends academy_empty_goal_close\n  " + body + "\n}\n"
    with pytest.raises(touchline.ScenarioError, match="nested too deeply") as caught:
        touchline.make(_scenario(tmp_path, "deep.tl", text))
    assert caught.value.code == "tl::E148"


def test_a_label_past_column_65535_raises_the_diagnostic(tmp_path: pathlib.Path) -> None:
    text = (
        "scenario s { extends academy_empty_goal_close " + " " * 100_000 + " game_duraton 400 }\n"
    )
    with pytest.raises(touchline.ScenarioError, match="game_duraton") as caught:
        touchline.make(_scenario(tmp_path, "long.tl", text))
    assert caught.value.code == "tl::E101"
    assert len(str(caught.value)) < 2_000


def test_a_one_line_json_over_64_kib_raises_the_diagnostic(tmp_path: pathlib.Path) -> None:
    text = json.dumps({"description": "d" * 70_000, "game_duration": "long"})
    with pytest.raises(touchline.ScenarioError) as caught:
        touchline.make(_scenario(tmp_path, "long.json", text))
    assert caught.value.code == "tl::E003"


def test_a_swap_onto_a_team_nobody_controls_is_refused_when_made(tmp_path: pathlib.Path) -> None:
    text = "scenario lone {\n  extends 5_vs_5\n  team right { GK at (-1, 0) not controllable }\n}\n"
    path = _scenario(tmp_path, "lone.tl", text)
    with pytest.raises(ValueError, match="swap"):
        touchline.make(path)


def test_the_frame_stacks_are_inside_the_checksum() -> None:
    env = touchline.make("academy_corner", representation="simple115v2", stacked=True, seed=0)
    env.reset(seed=0)
    for _ in range(5):
        env.step(5)
    state = env.unwrapped.get_state()
    # The last bytes are the frame stacks: any flip there is caught.
    for at in (len(state) - 1, len(state) - 100, len(state) - 1000):
        flipped = bytearray(state)
        flipped[at] ^= 0x40
        with pytest.raises(ValueError, match="checksum"):
            env.unwrapped.set_state(bytes(flipped))
    env.unwrapped.set_state(state)


def test_start_from_takes_what_get_state_returns(tmp_path: pathlib.Path) -> None:
    env = touchline.make("11_vs_11_stochastic", representation="simple115v2", stacked=True, seed=5)
    env.reset(seed=5)
    for _ in range(60):
        env.step(0)
    (tmp_path / "moment.state").write_bytes(env.unwrapped.get_state())
    text = 'scenario moment {\n  extends 11_vs_11_stochastic\n  game_duration 50\n  start from "moment.state"\n}\n'
    drill = touchline.make(_scenario(tmp_path, "moment.tl", text), representation="simple115v2")
    obs, _ = drill.reset(seed=1)
    assert np.all(np.isfinite(obs))
    drill.step(0)
