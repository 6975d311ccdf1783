"""Type stubs for the compiled extension `touchline._touchline` (Rust, pyo3).

Checked against the built module by `python -m mypy.stubtest touchline._touchline`.
"""

import os
from typing import Any, final

import numpy as np
import numpy.typing as npt
from typing_extensions import Self

from touchline.options import EnvOptions

__all__ = [
    "Env",
    "Replay",
    "ReplayError",
    "ScenarioError",
    "TouchlineError",
    "VectorEnv",
    "__version__",
    "scenario_json",
    "scenario_names",
]

__version__: str

class TouchlineError(Exception):
    """Base class of every error raised by touchline."""

class ScenarioError(TouchlineError):
    """A scenario could not be loaded; the message is the rendered diagnostic."""

    code: str
    """The stable code: ``tl::E105``, ``tl::S002``, ``tl::S005`` for a script hook that failed, ..."""

class ReplayError(TouchlineError):
    """A replay file that cannot be read (damaged, another format version) or that does not re-simulate."""

def scenario_names() -> list[str]:
    """Names of the stdlib scenarios, sorted."""

def scenario_json(scenario: str) -> str:
    """The compiled JSON of a scenario given as a stdlib name, or the path of a `.tl` scenario
    (compiled here) or of a compiled `.json` one.

    Raises:
        ScenarioError: unknown name, unreadable file or invalid scenario.
    """

@final
class Env:
    """One match: the Rust `Env` plus an observation encoder.

    Observations always have a leading controller axis `M` (left controllers first); rewards
    are float32 `(M,)`.

    Args:
        scenario: stdlib name, or the path of a `.tl` scenario or a compiled `.json` one.
        options: a `touchline.EnvOptions` (any object with its attributes): representation
            ("raw" allowed here), rewards, stacked, the players the agents control on each side,
            channel_dimensions, action_set and watch. With `watch`, the scenario file, its
            imports and scripts are followed: a change that loads is played from the next reset
            (`scenario_version` counts them); one that does not is reported by
            `watch_messages` and the last good version stays.
        seed: seed of the first episode, in [0, 2**64).

    Raises:
        ScenarioError: the scenario cannot be loaded, or `watch` names a stdlib scenario.
        ValueError: bad options (unknown representation, too many agents, ...).
        TypeError: `options` lacks one of `EnvOptions`'s attributes, or one has the wrong type.
    """

    def __new__(cls, scenario: str, options: EnvOptions, *, seed: int = 0) -> Self: ...
    @property
    def num_controllers(self) -> int: ...
    @property
    def action_count(self) -> int: ...
    @property
    def observation_shape(self) -> tuple[int, ...]:
        """Shape of one controller's observation ((115,), (72, 96, 4), ... ; () for raw)."""
    @property
    def observation_dtype(self) -> str:
        """ "float32", "uint8" or "raw"."""
    @property
    def controller_sides(self) -> list[str]:
        """ "left" or "right" for each controller."""
    @property
    def scenario_name(self) -> str: ...
    @property
    def lesson(self) -> tuple[int, str] | None:
        """The curriculum lesson played, (0-based index, name); None without a curriculum."""
    @property
    def game_duration(self) -> int: ...
    @property
    def scenario_version(self) -> int:
        """The scenario version played: 0 without `watch`; with it 1 for the file as first
        loaded, then the count of changes that loaded, taken up at a reset."""
    def watch_messages(self) -> list[str]:
        """What the watcher reported since the last call (rendered diagnostics of changes that
        do not load, versions the env refused), oldest first; empty without `watch`."""
    def reset(self, seed: int | None = None) -> Any:
        """Starts an episode; returns the observation (array (M, *shape) or, for raw, a list of dicts)."""
    def step(
        self, actions: npt.ArrayLike
    ) -> tuple[Any, npt.NDArray[np.float32], bool, bool, dict[str, Any]]:
        """One step with one action index per controller.

        Returns:
            (observation, rewards (M,) float32, terminated, truncated, info) where info has
            score [left, right], steps_left, game_mode, score_reward, checkpoint_reward, event_reward
            (the scenario's `reward on …` terms, summed over controllers), script_reward,
            script_errors, steps, episode, lesson (0-based curriculum lesson, 0 without one),
            scenario_version,
            lesson_name (with a curriculum), and script_log (lines scripts printed) when not empty.

        Raises:
            ValueError: wrong number of actions or an index outside the action set.
            RuntimeError: stepping after the episode ended (call reset).
        """
    def raw_observations(self) -> list[dict[str, Any]]:
        """The raw observation of each controller (GRF's dict of numpy arrays,
        docs/grf-compatibility.md#raw-observation)."""
    def render(self, width: int = 1280, height: int = 720) -> npt.NDArray[np.uint8]:
        """The match drawn from above on the CPU: a (height, width, 3) uint8 RGB image with the
        scoreboard, every agent-driven player ringed in yellow.

        Raises:
            ValueError: a side of 0 or above 8192 pixels.
        """
    def get_state(self) -> bytes:
        """The whole state of the episode: an engine snapshot with the stacked frames inside its checksum."""
    def set_state(self, state: bytes) -> None:
        """Restores `get_state` bytes of an env built with the same arguments.

        Raises:
            ValueError: corrupted or truncated bytes, another scenario, representation or
                format version.
        """
    def __getnewargs_ex__(self) -> tuple[tuple[str], dict[str, Any]]:
        """Pickling: the constructor's arguments (with `__getstate__`, the episode's state)."""
    def __getstate__(self) -> bytes: ...
    def __setstate__(self, state: bytes) -> None: ...
    @property
    def action_names(self) -> list[str]:
        """GRF names of the action set's actions, in index order ("idle", "left", ...)."""
    def start_recording(self) -> None:
        """Starts recording the episode at the current state (from its start right after a reset,
        mid-episode from a snapshot); recording restarts at every reset until `stop_recording`."""
    def stop_recording(self) -> None:
        """Stops recording and drops what was recorded."""
    @property
    def recording(self) -> bool:
        """Whether recording is on."""
    @property
    def recorded_steps(self) -> int:
        """Steps recorded in the current episode (0 when recording is off)."""
    def record_values(self, values: list[tuple[str, float]]) -> None:
        """Attaches named numbers to the next step played, in order (new names become new series
        in that order).

        Raises:
            RuntimeError: recording is off.
            ValueError: a name that is empty or longer than 64 characters.
        """
    def save_replay(self, path: str) -> None:
        """Writes the episode recorded so far as a `.tlreplay` file, whole or not at all.

        Raises:
            RuntimeError: recording is off.
            OSError: the file cannot be written.
        """
    def save_replay_clip(self, path: str, first: int, last: int) -> None:
        """Writes frames `first..=last` of the episode recorded so far (frame 0 the recording's
        start) as a replay starting at `first`, whole or not at all.

        Raises:
            RuntimeError: recording is off.
            ValueError: a span outside the frames recorded.
            OSError: the file cannot be written.
        """
    def state_hash(self) -> int:
        """A 32-bit hash of the exact match state (the one replays store after every step)."""

@final
class Replay:
    """A `.tlreplay` file read by the Rust reader: header, checksum and consistency checked.

    Raises (constructor):
        OSError: the file cannot be read.
        ReplayError: not a replay, truncated, corrupted, another format version, inconsistent.
    """

    def __new__(cls, path: str | os.PathLike[str]) -> Self: ...
    @property
    def scenario_name(self) -> str:
        """The scenario's name."""
    @property
    def steps(self) -> int:
        """Steps recorded."""
    @property
    def controllers(self) -> int:
        """Actions per step (controlled players)."""
    @property
    def first_step(self) -> int:
        """Steps the episode had played before the recording started."""
    @property
    def script_paths(self) -> list[str]:
        """Paths (as the scenario names them) of the scripts the replay carries."""
    @property
    def frame_hashes(self) -> list[int]:
        """The state hash stored with each frame: `steps + 1` of them, frame 0 the start."""
    @property
    def scores(self) -> list[list[int]]:
        """Score `[left, right]` of each frame."""
    @property
    def actions(self) -> list[list[str]]:
        """GRF names of each step's actions, one list of `controllers` names per step."""
    @property
    def values(self) -> dict[str, npt.NDArray[np.float32]]:
        """The recorder's per-step values: name -> float32 (steps,), NaN where none was given."""
    def write_video(
        self,
        path: str | os.PathLike[str],
        *,
        width: int = 640,
        height: int = 360,
        every: int = 1,
        fps: int = 10,
    ) -> int:
        """Draws the replay (its stored frames) into `path`: `NAME.gif`, `NAME.mp4` (needs
        `ffmpeg` on the PATH) or a folder of PNG frames; `every`th step, `fps` frames per second.
        Returns the number of frames written.

        Raises:
            OSError: a bad size, rate or extension, a file that cannot be written, no ffmpeg for MP4.
        """
    def simulate(self) -> list[int]:
        """Re-simulates the episode (scripts compiled from the text the replay carries) and
        returns the state hash of every frame.

        Raises:
            ReplayError: a frame differs from the stored one (another engine version).
            ScenarioError: the carried scripts do not compile.
        """

@final
class VectorEnv:
    """`num_envs` independent matches stepped in Rust threads with the GIL released.

    Same arguments as `Env` (an array representation only), plus `num_envs` (≥ 1),
    `num_threads` (0 = one per core) and `autoreset_mode` (Gymnasium's `AutoresetMode` value:
    "SameStep", "NextStep" or "Disabled"); seeds are `seed + i` for env i.
    """

    def __new__(
        cls,
        scenario: str,
        num_envs: int,
        options: EnvOptions,
        *,
        num_threads: int = 0,
        seed: int = 0,
        autoreset_mode: str = "SameStep",
    ) -> Self: ...
    def watch_messages(self) -> list[str]:
        """As `Env.watch_messages`, for every match (each message once)."""
    @property
    def num_envs(self) -> int: ...
    @property
    def controller_sides(self) -> list[str]: ...
    @property
    def num_controllers(self) -> int: ...
    @property
    def action_count(self) -> int: ...
    @property
    def observation_shape(self) -> tuple[int, ...]: ...
    @property
    def observation_dtype(self) -> str: ...
    def get_states(self) -> list[bytes]:
        """Every match's whole state, in match order (for pickling)."""
    def ended(self) -> list[bool]:
        """Which matches ended on their last step and wait for their reset (NextStep, Disabled)."""
    def set_states(self, states: list[bytes], ended: list[bool] | None = None) -> None:
        """Restores `get_states` (and `ended`) of a vector env built with the same arguments.

        Raises:
            ValueError: another number of states or flags, or bytes `Env.set_state` refuses.
        """
    def infos(self, current: npt.NDArray[np.float64], finals: npt.NDArray[np.float64]) -> None:
        """Writes each match's info row (13 float64 columns), now and at its last episode's end."""
    def reset(
        self,
        observations: npt.NDArray[Any],
        seed: int | None = None,
        mask: list[bool] | None = None,
    ) -> None:
        """Resets every env (or those `mask` marks), writing their observations into
        `observations` (num_envs, M, *shape).

        Raises:
            ValueError: a wrong shape or dtype, or a mask of another length.
        """
    def step(
        self,
        actions: npt.NDArray[np.int64],
        observations: npt.NDArray[Any],
        rewards: npt.NDArray[np.float32],
        terminated: npt.NDArray[np.bool_],
        truncated: npt.NDArray[np.bool_],
        final_observations: npt.NDArray[Any] | None = None,
    ) -> None:
        """Steps every env with `actions` (num_envs, M) and writes the results into the given
        preallocated arrays without copies: observations (num_envs, M, *shape), rewards
        (num_envs, M), terminated and truncated (num_envs,). In SameStep, envs that end are reset
        at once and their new first observation is written, their last observation going to
        `final_observations` (same shape as `observations`) when given; in NextStep they are
        reset on the following step instead of being stepped.

        Raises:
            ValueError: a wrong shape or dtype, an action outside the action set, or (Disabled)
                an env that ended and was not reset.
        """
