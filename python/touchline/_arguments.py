"""Checks and conversions of the arguments shared by touchline's Python environments.

Everything here turns a user's argument into the form `touchline._touchline` expects, or raises a
`ValueError` whose message says what was wrong and what is accepted. The Rust side checks its
arguments too; checking here as well gives Python-shaped messages (and the GRF wording where GRF
users expect it).
"""

from __future__ import annotations

import os
import secrets
import warnings
from typing import TYPE_CHECKING, Any

import numpy as np
from gymnasium import spaces

from ._touchline import Env as _CoreEnv

if TYPE_CHECKING:
    from .options import EnvOptions

#: Representations whose observations are arrays (Gymnasium and PettingZoo envs accept these);
#: "pixels" and "pixels_gray" are frames drawn on the CPU (docs/grf-compatibility.md#pixels).
ARRAY_REPRESENTATIONS = ("simple115v2", "simple115", "extracted", "pixels", "pixels_gray")
#: Every representation the extension can encode; "raw" is a list of dicts
#: (docs/grf-compatibility.md#raw-observation).
REPRESENTATIONS = ("raw", *ARRAY_REPRESENTATIONS)
#: Render modes of the Gymnasium and PettingZoo envs: `render()` returns an RGB array.
RENDER_MODES = ("rgb_array",)
#: Action sets (docs/grf-compatibility.md#action-sets): "default" has 19 actions, "v2" adds
#: builtin_ai (20).
ACTION_SETS = ("default", "v2")
#: Reward terms (docs/grf-compatibility.md#rewards); "scoring" is always on.
REWARD_TERMS = ("scoring", "checkpoints")
#: Seeds are unsigned 64-bit integers on the Rust side.
SEED_LIMIT = 2**64


def scenario_argument(scenario: str | os.PathLike[str]) -> str:
    """A stdlib scenario name or the path of a `.tl` or compiled `.json` scenario, as a string."""
    if isinstance(scenario, os.PathLike):
        scenario = os.fspath(scenario)
    if not isinstance(scenario, str):
        raise TypeError(
            f"scenario must be a stdlib scenario name or a path, got {type(scenario).__name__}"
        )
    if not scenario:
        raise ValueError(
            "scenario must not be empty: give a stdlib name such as 'academy_empty_goal'"
        )
    return scenario


def representation_argument(representation: str, *, allow_raw: bool) -> str:
    """Checks `representation`; "raw" only where the caller can return lists of dicts."""
    if representation == "raw" and not allow_raw:
        raise ValueError(
            "representation='raw' returns a list of dicts, which has no Gymnasium space; use "
            "touchline.compat.gfootball.create_environment(..., representation='raw') or the "
            "low-level touchline._touchline.Env(scenario, touchline.EnvOptions(representation='raw')), or call "
            "env.raw_observations() next to an array representation"
        )
    accepted = REPRESENTATIONS if allow_raw else ARRAY_REPRESENTATIONS
    if representation not in accepted:
        raise ValueError(
            f"unknown representation {representation!r}; use one of {', '.join(map(repr, accepted))}"
        )
    return representation


def rewards_argument(rewards: str) -> str:
    """GRF's comma-separated reward list (docs/grf-compatibility.md#rewards), normalised for the
    extension.

    "scoring" must be present (GRF asserts it); "checkpoints" adds GRF's checkpoint reward.
    """
    if not isinstance(rewards, str):
        raise ValueError(f"rewards must be a comma-separated string, got {type(rewards).__name__}")
    terms = [term.strip() for term in rewards.split(",") if term.strip()]
    unknown = [term for term in terms if term not in REWARD_TERMS]
    if unknown:
        raise ValueError(
            f"unknown reward term {unknown[0]!r} in rewards={rewards!r}; the terms are "
            "'scoring' and 'checkpoints', e.g. rewards='scoring,checkpoints'"
        )
    if "scoring" not in terms:
        raise ValueError(
            f"rewards={rewards!r} must contain 'scoring' (as in GRF), e.g. 'scoring,checkpoints'"
        )
    return "scoring,checkpoints" if "checkpoints" in terms else "scoring"


def action_set_argument(action_set: str) -> str:
    """Checks the action set name (docs/grf-compatibility.md#action-sets)."""
    if action_set == "full":
        raise ValueError(
            "action_set='full' (33 actions, GRF's play_game set) is not supported; "
            "use 'default' (19 actions) or 'v2' (20, adds builtin_ai)"
        )
    if action_set not in ACTION_SETS:
        raise ValueError(
            f"unknown action_set {action_set!r}; use 'default' (19 actions) or 'v2' (20, adds builtin_ai)"
        )
    return action_set


def seed_argument(seed: int | None) -> int:
    """A seed for the extension: `seed` itself, or a random one when it is None."""
    if seed is None:
        return secrets.randbits(63)
    return checked_seed(seed)


def checked_seed(seed: Any) -> int:
    """`seed` as a Python int in [0, 2**64), or ValueError."""
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)):
        raise ValueError(f"seed must be a non-negative integer or None, got {seed!r}")
    value = int(seed)
    if not 0 <= value < SEED_LIMIT:
        raise ValueError(f"seed must be in [0, 2**64), got {value}")
    return value


def controls_argument(left: int, right: int) -> tuple[int, int]:
    """Numbers of controlled players per side: non-negative integers, at least one in total."""
    for name, value in (
        ("number_of_left_players_agent_controls", left),
        ("number_of_right_players_agent_controls", right),
    ):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
            raise ValueError(f"{name} must be a non-negative integer, got {value!r}")
    if left + right == 0:
        raise ValueError("the agent must control at least one player (left + right controls >= 1)")
    return int(left), int(right)


def channel_dimensions_argument(channel_dimensions: Any) -> tuple[int, int]:
    """(width, height) of SMM observations, positive integers."""
    try:
        width, height = channel_dimensions
        width, height = int(width), int(height)
    except (TypeError, ValueError):
        raise ValueError(
            f"channel_dimensions must be (width, height), got {channel_dimensions!r}"
        ) from None
    if width <= 0 or height <= 0:
        raise ValueError(f"channel_dimensions must be positive, got {channel_dimensions!r}")
    return width, height


def render_mode_argument(render_mode: str | None) -> None:
    """Checks `render_mode`: None or "rgb_array" (frames drawn on the CPU, no display needed)."""
    if render_mode is not None and render_mode not in RENDER_MODES:
        raise ValueError(
            f"render_mode={render_mode!r} is not available; use None or 'rgb_array' "
            "(touchline draws on the CPU: no window, no display)"
        )


def core_env(scenario: str | os.PathLike[str], options: EnvOptions, seed: int | None) -> _CoreEnv:
    """The extension's `Env` for `scenario`, made with `options` (checked when they were made;
    whether "raw" is allowed is the caller's check) and `seed` (None: a random one)."""
    return _CoreEnv(scenario_argument(scenario), options, seed=seed_argument(seed))


def watch_argument(watch: Any) -> bool:
    """Checks `watch`: True or False (the extension refuses True for a stdlib name: no file)."""
    if not isinstance(watch, (bool, np.bool_)):
        raise ValueError(f"watch must be True or False, got {watch!r}")
    return bool(watch)


def show_watch_messages(core: Any) -> None:
    """Turns each message of a watched scenario's watcher (a change that does not load, a version
    the env refused) into one `UserWarning`; the env goes on with the last good version."""
    for message in core.watch_messages():
        warnings.warn(message, UserWarning, stacklevel=3)


def observation_box(shape: tuple[int, ...], dtype: str) -> spaces.Box:
    """The Box of one observation: float32 (-inf, inf) or uint8 [0, 255]
    (docs/grf-compatibility.md#simple115, #smm)."""
    if dtype == "float32":
        return spaces.Box(-np.inf, np.inf, shape, np.float32)
    if dtype == "uint8":
        return spaces.Box(0, 255, shape, np.uint8)
    raise ValueError(f"observations of dtype {dtype!r} have no Box space")


def single_action(action: Any, action_count: int) -> int:
    """Checks the action of a single controlled player and returns it as a Python int.

    Accepts a Python or numpy integer, or an integer array of shape () or (1,).
    """
    if type(action) is int:  # the common case, kept fast
        if 0 <= action < action_count:
            return action
        raise ValueError(_range_message(action, action_count))
    if isinstance(action, np.integer) and not isinstance(action, np.bool_):
        value = int(action)
        if 0 <= value < action_count:
            return value
        raise ValueError(_range_message(value, action_count))
    out = np.zeros(1, dtype=np.int64)
    write_actions(action, out, action_count)
    return int(out[0])


def write_actions(action: Any, out: np.ndarray, action_count: int) -> None:
    """Checks `action` and writes it into `out` (int64, one entry per controlled player).

    Accepts a Python or numpy integer when one player is controlled, otherwise anything that
    converts to an integer array of shape `out.shape`. Raises ValueError with the reason.
    """
    count = out.shape[0]
    if type(action) is int and count == 1:  # the common case, kept fast
        if 0 <= action < action_count:
            out[0] = action
            return
        raise ValueError(_range_message(action, action_count))
    # GRF's own habit, a list of Python ints (`env.step([19])`): checked and written without
    # building a numpy array, which cost more than the engine's step for one player.
    if type(action) is list or type(action) is tuple:
        if count == 1 and len(action) == 1:
            first = action[0]
            if type(first) is int and 0 <= first < action_count:
                out[0] = first
                return
        elif len(action) == count and all(type(a) is int and 0 <= a < action_count for a in action):
            out[:] = action
            return
    if isinstance(action, (bool, np.bool_)):
        raise ValueError(f"an action must be an integer index, got the bool {action!r}")
    if isinstance(action, (int, np.integer)):
        if count != 1:
            raise ValueError(
                f"expected {count} actions (one per controlled player), got the single integer {action!r}"
            )
        if 0 <= action < action_count:
            out[0] = action
            return
        raise ValueError(_range_message(int(action), action_count))
    array = np.asarray(action)
    if array.dtype.kind not in "iu":
        raise ValueError(
            f"actions must be integer indices, got {type(action).__name__} of dtype {array.dtype}"
        )
    if array.shape != out.shape and not (count == 1 and array.shape == ()):
        raise ValueError(
            f"expected actions of shape {out.shape} (one per controlled player), got shape {array.shape}"
        )
    array = array.reshape(out.shape)
    bad = (array < 0) | (array >= action_count)
    if bad.any():
        index = int(np.argmax(bad))
        raise ValueError(
            _range_message(int(array[index]), action_count)
            + (f" (controlled player {index})" if count > 1 else "")
        )
    out[:] = array


def _range_message(action: int, action_count: int) -> str:
    return f"action {action} is outside the action set: indices run from 0 to {action_count - 1}"
