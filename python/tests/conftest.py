"""Shared fixtures of touchline's Python tests.

Run from the repository root (`python3 -m pytest python/tests`), so that the source folder
`python/touchline/` cannot shadow the installed package (which holds the compiled extension).
pytest.ini at the root makes every warning an error.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest


@pytest.fixture
def play_until_done() -> Callable[..., tuple[int, bool, bool, dict[str, Any]]]:
    """Steps a Gymnasium env with seeded random actions until the episode ends (or `limit` steps).

    Returns (steps taken, terminated, truncated, last info).
    """

    def play(
        env: Any, seed: int = 0, limit: int = 10_000
    ) -> tuple[int, bool, bool, dict[str, Any]]:
        env.action_space.seed(seed)
        terminated = truncated = False
        info: dict[str, Any] = {}
        steps = 0
        while not (terminated or truncated) and steps < limit:
            _, _, terminated, truncated, info = env.step(env.action_space.sample())
            steps += 1
        return steps, terminated, truncated, info

    return play
