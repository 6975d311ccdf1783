"""`DumpWriter`: GRF's trace dumps and videos (`write_full_episode_dumps`, `write_goal_dumps`,
`write_video`, `dump_frequency`, `logdir`), written as touchline replays.

| GRF | touchline |
|---|---|
| `episode_done_<time>.dump` (whole episode) | `episode_done_<time>.tlreplay` |
| `score_<time>.dump` / `lost_score_<time>.dump` (100 steps before a goal, 1 after) | `score_<time>.tlreplay` / `lost_score_<time>.tlreplay` (the same steps) |
| `<dump>.avi` (with `write_video`) | `<dump>.gif`: the replay drawn on the CPU, 10 frames per second |

`<time>` is `YYYYmmdd-HHMMSSffffff`, as GRF's. A replay opens in `touchline view`, draws into MP4 with
`touchline replay FILE -o video.mp4`, and re-simulates with `touchline.Replay(FILE).simulate()`.
GRF's wall-clock throttles (one full-episode dump per 10 s, one goal dump per 600 s) are not
copied: touchline writes every dump asked for.
"""

from __future__ import annotations

import datetime
from pathlib import Path
from typing import Any

from .._touchline import Env as _CoreEnv
from .._touchline import Replay

#: GRF's goal dumps keep this many steps before the goal (`PAST_STEPS_TRACE_SIZE`), and 1 after.
GOAL_DUMP_STEPS_BEFORE = 100
#: Size of the GIF videos (GRF's downscaled XVID videos are 800 × 450).
VIDEO_SIZE = (800, 450)


class DumpWriter:
    """Records the episodes GRF's dump settings choose and writes their dumps as replays."""

    def __init__(
        self,
        core: _CoreEnv,
        logdir: str,
        full_episodes: bool,
        goals: bool,
        video: bool,
        dump_frequency: int,
    ) -> None:
        self._core = core
        self._dir = Path(logdir)
        self._full = full_episodes
        self._goals = goals
        self._video = video
        # GRF wraps in PeriodicDumpWriter only when dump_frequency > 1; 0 and 1 dump every episode.
        self._frequency = max(1, dump_frequency)
        self._episode = -1
        self._on = False
        self._score = [0, 0]
        self._pending_goal: tuple[int, str] | None = None
        # The agent's team: goals it scores are `score` dumps, goals it concedes `lost_score`.
        self._own = 1 if list(core.controller_sides)[:1] == ["right"] else 0

    @property
    def active(self) -> bool:
        """Whether any dump is asked for."""
        return self._full or self._goals

    def reset(self) -> None:
        """After a reset: records this episode if `dump_frequency` chooses it."""
        self._episode += 1
        self._on = self.active and self._episode % self._frequency == 0
        self._score = [0, 0]
        self._pending_goal = None
        if self._on:
            self._dir.mkdir(parents=True, exist_ok=True)
            self._core.start_recording()
        else:
            self._core.stop_recording()

    def step(self, info: dict[str, Any], done: bool) -> list[dict[str, Any]]:
        """After a step: writes the dumps it completes; returns their descriptors
        (`{"name", "replay", "video"}`, `video` None without `write_video`)."""
        if not self._on:
            return []
        written = []
        steps = self._core.recorded_steps
        if self._pending_goal is not None and steps >= self._pending_goal[0] + 1:
            written.append(self._goal_dump(steps))
        score = [int(goals) for goals in info["score"]]
        if self._goals and score != self._score:
            scored = score[self._own] > self._score[self._own]
            self._pending_goal = (steps, "score" if scored else "lost_score")
        self._score = score
        if done:
            if self._pending_goal is not None:
                written.append(self._goal_dump(steps))
            if self._full:
                path = self._path("episode_done")
                self._core.save_replay(str(path))
                written.append(self._descriptor("episode_done", path))
            self._on = False
        return written

    def _goal_dump(self, steps: int) -> dict[str, Any]:
        assert self._pending_goal is not None
        goal, name = self._pending_goal
        self._pending_goal = None
        path = self._path(name)
        first = max(0, goal - GOAL_DUMP_STEPS_BEFORE)
        self._core.save_replay_clip(str(path), first, min(goal + 1, steps))
        return self._descriptor(name, path)

    def _path(self, name: str) -> Path:
        stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S%f")
        path = self._dir / f"{name}_{stamp}.tlreplay"
        n = 1
        while path.exists():
            path = self._dir / f"{name}_{stamp}-{n}.tlreplay"
            n += 1
        return path

    def _descriptor(self, name: str, path: Path) -> dict[str, Any]:
        video = None
        if self._video:
            video = path.with_suffix(".gif")
            width, height = VIDEO_SIZE
            Replay(path).write_video(video, width=width, height=height)
        return {"name": name, "replay": str(path), "video": None if video is None else str(video)}
