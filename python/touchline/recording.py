"""`ReplayRecording`: the replay methods that `FootballEnv` and `FootballParallelEnv` share."""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from ._touchline import Env as _CoreEnv


class ReplayRecording:
    """Records episodes into `.tlreplay` files, the form `touchline run --record` writes.

    `touchline view FILE` shows a saved replay in the browser (with each step's actions, rewards
    and the numbers given to `record_values`), `touchline replay FILE -o video.mp4` draws it, and
    `touchline.Replay(FILE).simulate()` re-simulates it. A scenario's rhai scripts travel inside
    the file, so it re-simulates without them. `touchline.RecordReplay` does all of this at every
    episode's end; these methods are the manual way.

    Recording is off until `start_recording()`; while it is off, `step` does no recording work.
    """

    _core: _CoreEnv

    def start_recording(self) -> None:
        """Starts recording at the current state: from the episode's start right after `reset`,
        mid-episode from a snapshot of the state. Recording then restarts at every `reset` (and
        `set_state`) until `stop_recording()`."""
        self._core.start_recording()

    def stop_recording(self) -> None:
        """Stops recording and drops the episode recorded so far."""
        self._core.stop_recording()

    @property
    def recording(self) -> bool:
        """Whether recording is on."""
        return self._core.recording

    @property
    def recorded_steps(self) -> int:
        """Steps recorded in the current episode (0 when recording is off)."""
        return self._core.recorded_steps

    def record_values(self, values: Mapping[str, float | Sequence[float] | np.ndarray]) -> None:
        """Attaches named numbers to the next step played (for instance `{"value": v}`, the
        policy's value estimate of the observation it acts on): the viewer shows them beside that
        step. A 1-D sequence or array is stored as one number per element: named
        `name[<action>]` when it has one element per action (action probabilities:
        `{"probs": probs}` gives `probs[idle]`, `probs[left]`, ...), else `name[0]`, `name[1]`, ....
        Steps without a value under a name hold NaN.

        Raises:
            RuntimeError: recording is off.
            ValueError: a name that is empty or (expanded) longer than 64 characters, a value that
                is not a real number or a 1-D sequence of them, or an infinite value.
        """
        checked: dict[str, float] = {}
        for name, value in values.items():
            if not isinstance(name, str):
                raise ValueError(f"value names must be strings, got {name!r}")
            if isinstance(value, (str, bytes)):
                raise ValueError(f"value {name!r} must be a real number, got {value!r}")
            if isinstance(value, (Sequence, np.ndarray)):
                array = np.asarray(value)
                if array.ndim != 1 or not np.issubdtype(array.dtype, np.number):
                    raise ValueError(
                        f"value {name!r} must be a real number or a 1-D sequence of them, "
                        f"got shape {array.shape} of {array.dtype}"
                    )
                actions = self._core.action_names
                labels = (
                    actions if len(array) == len(actions) else [str(i) for i in range(len(array))]
                )
                for label, element in zip(labels, array):
                    checked[f"{name}[{label}]"] = _real(f"{name}[{label}]", element)
            else:
                checked[name] = _real(name, value)
        self._core.record_values(list(checked.items()))

    def save_replay(self, path: str | os.PathLike[str]) -> None:
        """Writes the episode recorded so far (whole once it has ended) to `path`, a `.tlreplay`
        file; the file is written whole or not at all.

        Raises:
            RuntimeError: recording is off (nothing was recorded).
            OSError: the file cannot be written.
        """
        self._core.save_replay(os.fspath(path))

    def state_hash(self) -> int:
        """A 32-bit hash of the exact match state, the one replays store after every step
        (`touchline.Replay.frame_hashes`)."""
        return self._core.state_hash()


def _real(name: str, value: Any) -> float:
    """`value` as a float, or a ValueError naming it."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"value {name!r} must be a real number, got {value!r}") from None
    if math.isinf(number):
        raise ValueError(f"value {name!r} is infinite")
    return number
