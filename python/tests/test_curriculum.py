"""A scenario with a curriculum, written as text: the env moves through its lessons at reset and
reports the lesson in `info`."""

from __future__ import annotations

import touchline

LESSONS = """/// Close to the empty goal, then from the halfway line.
scenario quick_lessons {
  extends academy_empty_goal_close
  curriculum {
    lesson close
    lesson halfway extends academy_empty_goal
    advance when success_rate >= 0 over 2 episodes
  }
}
"""


def test_a_curriculum_advances_and_info_names_the_lesson(tmp_path) -> None:
    path = tmp_path / "lessons.tl"
    path.write_text(LESSONS)
    env = touchline.make(str(path))
    _, info = env.reset(seed=0)
    assert (info["lesson"], info["lesson_name"]) == (0, "close")
    seen = []
    for _ in range(3):
        terminated = truncated = False
        while not (terminated or truncated):
            _, _, terminated, truncated, info = env.step(0)
        seen.append((info["lesson"], info["lesson_name"]))
        _, reset_info = env.reset()
    # Two finished episodes meet `success_rate >= 0 over 2 episodes`: the third reset moves on.
    assert seen == [(0, "close"), (0, "close"), (1, "halfway")]
    assert (reset_info["lesson"], reset_info["lesson_name"]) == (1, "halfway")
    assert env.unwrapped._core.lesson == (1, "halfway")


def test_without_a_curriculum_the_lesson_is_zero() -> None:
    env = touchline.make("academy_empty_goal_close")
    _, info = env.reset(seed=0)
    assert info["lesson"] == 0 and "lesson_name" not in info
    _, _, _, _, info = env.step(0)
    assert info["lesson"] == 0 and "lesson_name" not in info
