"""`RecordReplay`: a wrapper that saves episodes as `.tlreplay` files, for Gymnasium and PettingZoo.

```python
import touchline
env = touchline.RecordReplay(touchline.make("academy_empty_goal_close"), "replays")
obs, info = env.reset(seed=0)
done = False
while not done:
    env.record_values({"value": 0.5})              # optional: numbers shown beside the step
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
    done = terminated or truncated
print(info["replay_path"])                         # replays/episode-0.tlreplay
```

Then `touchline view replays` shows the agent's episodes in the browser.
"""

from __future__ import annotations

import itertools
import os
import warnings
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import gymnasium
from pettingzoo import ParallelEnv  # type: ignore[import-untyped]
from pettingzoo.utils import BaseParallelWrapper  # type: ignore[import-untyped]

from .recording import ReplayRecording

__all__ = ["ParallelRecordReplay", "RecordReplay"]


class _Episodes:
    """Which episodes to record and where, shared by the Gymnasium and PettingZoo wrappers."""

    def __init__(
        self,
        base: Any,
        folder: str | os.PathLike[str],
        episode_trigger: Callable[[int], bool] | None,
        name_prefix: str,
    ) -> None:
        if not isinstance(base, ReplayRecording):
            raise ValueError(
                f"RecordReplay needs a touchline env (touchline.make or touchline.parallel_env), "
                f"got {type(base).__name__}"
            )
        if not name_prefix or os.sep in name_prefix or (os.altsep and os.altsep in name_prefix):
            raise ValueError(f"name_prefix must be a plain file name part, got {name_prefix!r}")
        self.base = base
        self.folder = Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)
        self.trigger = episode_trigger
        self.prefix = name_prefix
        self.episode = -1
        self.recording = False
        self.warned = False

    def reset(self) -> None:
        """After the base env's reset: starts recording the new episode if it is chosen."""
        self.episode += 1
        self.recording = self.trigger is None or bool(self.trigger(self.episode))
        if self.recording:
            self.base.start_recording()
        else:
            self.base.stop_recording()

    def claim(self) -> Path:
        """The file for this episode, `{prefix}-{episode}.tlreplay`, created empty to hold the
        name. A name already taken (another wrapper writing to this folder with the same prefix, in
        this process or another, or an earlier run's file) is kept, and `_1`, `_2`, ... is added
        instead, with one warning: two recorders never overwrite each other's episodes."""
        stem = f"{self.prefix}-{self.episode}"
        for k in itertools.count():
            path = self.folder / (f"{stem}.tlreplay" if k == 0 else f"{stem}_{k}.tlreplay")
            try:
                os.close(os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
            except FileExistsError:
                continue
            if k and not self.warned:
                self.warned = True
                warnings.warn(
                    f"RecordReplay: {self.folder / (stem + '.tlreplay')} already exists, so this "
                    f"recorder writes {path.name} (and adds _1, _2, ... whenever a name is taken); "
                    "give each env its own folder or name_prefix to keep the names plain",
                    stacklevel=4,
                )
            return path
        raise AssertionError("unreachable")

    def end(self) -> Path | None:
        """At the episode's end: saves it if it was recorded; returns the file."""
        if not self.recording:
            return None
        self.recording = False
        path = self.claim()
        try:
            self.base.save_replay(path)
        except BaseException:
            # Nothing half-written is left: the claimed name goes with the failed save.
            path.unlink(missing_ok=True)
            raise
        return path

    def close(self) -> None:
        """Saves an episode cut short, if it has steps."""
        if self.recording and self.base.recorded_steps > 0:
            self.end()


class RecordReplay(gymnasium.Wrapper[Any, Any, Any, Any]):
    """Saves the episodes of a touchline env as `.tlreplay` files, as `touchline run --record` does.

    Args:
        env: a touchline Gymnasium env (`touchline.make`, `gymnasium.make("touchline/...")`, any
            wrappers around them), or a touchline PettingZoo env (`touchline.parallel_env`): then
            a `ParallelRecordReplay` is returned.
        folder: where the files go (made if missing): `{folder}/{name_prefix}-{episode}.tlreplay`,
            `episode` counting the episodes started through this wrapper from 0. An existing file
            is never overwritten: the name gets `_1`, `_2`, ... instead, with one warning.
        episode_trigger: which episodes to record (`lambda e: e % 100 == 0`); None records all.
        name_prefix: the files' name before `-{episode}`.

    At the end of a recorded episode the file is written and `info["replay_path"]` names it
    (in every agent's info for PettingZoo). An episode cut short by `reset()` or `close()` is
    saved as it stands (if it has steps).
    `record_values` attaches numbers (a value estimate, action probabilities) to the next step.

    Raises:
        ValueError: `env` is not a touchline env, or `name_prefix` holds a path separator.
    """

    def __new__(cls, env: Any, *args: Any, **kwargs: Any) -> Any:
        if isinstance(env, ParallelEnv):
            return ParallelRecordReplay(env, *args, **kwargs)
        return super().__new__(cls)

    def __init__(
        self,
        env: gymnasium.Env[Any, Any],
        folder: str | os.PathLike[str],
        episode_trigger: Callable[[int], bool] | None = None,
        name_prefix: str = "episode",
    ) -> None:
        episodes = _Episodes(getattr(env, "unwrapped", env), folder, episode_trigger, name_prefix)
        super().__init__(env)
        self._episodes = episodes

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[Any, dict[str, Any]]:
        """Resets the env and starts recording the new episode if `episode_trigger` chooses it."""
        self._episodes.close()
        result = self.env.reset(seed=seed, options=options)
        self._episodes.reset()
        return result

    def step(self, action: Any) -> tuple[Any, Any, bool, bool, dict[str, Any]]:
        """Steps the env; at a recorded episode's end writes its file (`info["replay_path"]`)."""
        observation, reward, terminated, truncated, info = self.env.step(action)
        if terminated or truncated:
            path = self._episodes.end()
            if path is not None:
                info["replay_path"] = str(path)
        return observation, reward, terminated, truncated, info

    def record_values(self, values: Mapping[str, float]) -> None:
        """Attaches named numbers to the next step (see `FootballEnv.record_values`); does
        nothing in an episode that is not recorded."""
        if self._episodes.recording:
            self._episodes.base.record_values(values)

    def close(self) -> None:
        """Saves an episode cut short, then closes the env."""
        self._episodes.close()
        super().close()


class ParallelRecordReplay(BaseParallelWrapper):  # type: ignore[misc]
    """`RecordReplay` for a touchline PettingZoo `ParallelEnv` (same arguments)."""

    def __init__(
        self,
        env: Any,
        folder: str | os.PathLike[str],
        episode_trigger: Callable[[int], bool] | None = None,
        name_prefix: str = "episode",
    ) -> None:
        episodes = _Episodes(getattr(env, "unwrapped", env), folder, episode_trigger, name_prefix)
        super().__init__(env)
        self._episodes = episodes

    def reset(
        self, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, Any], dict[str, dict[str, Any]]]:
        """Resets the env and starts recording the new episode if `episode_trigger` chooses it."""
        self._episodes.close()
        result = self.env.reset(seed=seed, options=options)
        self._episodes.reset()
        return result  # type: ignore[no-any-return]

    def step(self, actions: dict[str, Any]) -> tuple[Any, Any, Any, Any, dict[str, dict[str, Any]]]:
        """Steps the env; at a recorded episode's end writes its file (`replay_path` in every
        agent's info)."""
        observations, rewards, terminations, truncations, infos = self.env.step(actions)
        ended = all(terminations.values()) or all(truncations.values())
        if ended:
            path = self._episodes.end()
            if path is not None:
                for info in infos.values():
                    info["replay_path"] = str(path)
        return observations, rewards, terminations, truncations, infos

    def record_values(self, values: Mapping[str, float]) -> None:
        """Attaches named numbers to the next step; does nothing in an episode not recorded."""
        if self._episodes.recording:
            self._episodes.base.record_values(values)

    def close(self) -> None:
        """Saves an episode cut short, then closes the env."""
        self._episodes.close()
        super().close()
