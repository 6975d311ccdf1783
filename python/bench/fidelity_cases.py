"""Episodes run as GRF's fidelity cases are run: policies, GRF's end-of-episode classification and
the per-match statistics of a full match. Shared by `fidelity.py` (the harness) and
`python/tests/test_fidelity.py` (the CI behaviours), which both put this folder on `sys.path`.

Every episode goes through `touchline.compat.gfootball.create_environment(env_name=S,
representation='raw', rewards='scoring')`, exactly as GRF's figures were measured with gfootball:
one env per case, n episodes in a row, each started with `env.reset()`.

The end of an episode is classified on its last step in the order of GRF's `football_env_core.step`:
`goal` (the scoring reward is not 0), `out_of_play` (game_mode != 0 while the previous step's was 0;
the previous one starts at -1), `possession` (ball_owned_team != -1, the last known owner != -1, and
they differ; the last known owner starts at -1 and is updated only on owned steps), `time_limit`
(steps_left == 0), else `other`.
"""

from __future__ import annotations

import argparse
import copy
import math
import statistics
import zlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any, Protocol

from touchline.compat.gfootball import FootballEnv, create_environment

# GRF's default action set (docs/grf-compatibility.md#actions): the indices the probes press.
IDLE = 0
RIGHT = 5
LONG_PASS = 9
HIGH_PASS = 10
SHORT_PASS = 11
SHOT = 12
SLIDING = 16
#: action_set 'v2' adds it: the controlled player is handed to the built-in AI.
BUILTIN_AI = 19

#: GRF's game_mode values (raw observation).
NORMAL, KICK_OFF, GOAL_KICK, FREE_KICK, CORNER, THROW_IN, PENALTY = range(7)
RESTARTS = {
    GOAL_KICK: "goal_kicks",
    FREE_KICK: "free_kicks",
    CORNER: "corners",
    THROW_IN: "throw_ins",
    PENALTY: "penalties",
}
ENDS = ("goal", "out_of_play", "possession", "time_limit")
#: Metres per unit of raw y for team width against real football: the pitch's 0.84 units of
#: width scaled to a real pitch's 68 m.
METRES_PER_Y = 68.0 / 0.84
#: Metres per unit of raw x and y as GRF's engine converts them (it divides its world by 54.4 m
#: and 83.6 m; docs/grf-compatibility.md): the profiles' distances and paces, the same in both
#: engines. A unit of y is longer than one of x.
METRES_X = 54.4
METRES_Y = 83.6
#: Role index of a goalkeeper in `left_team_roles` / `right_team_roles`.
GOALKEEPER_ROLE = 0
#: Metres per second per unit of raw ball movement per step (55 m per unit of x, 0.1 s a step):
#: the kick figures' scale, the same in both engines.
SPEED_PER_UNIT_STEP = 550.0
#: A kick: the ball's horizontal speed jumps by more than KICK_JUMP (m/s) in a step, to above
#: KICK_SPEED (m/s); a dribble's touches stay below.
KICK_JUMP = 4.0
KICK_SPEED = 8.0
#: Steps after the first kick at which `Episode.ball_x_after_kick` is read.
AFTER_KICK = 25

Observation = dict[str, Any]


def metres(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Distance (m) between two points given in raw observation units (GRF's world scale)."""
    return math.hypot((a[0] - b[0]) * METRES_X, (a[1] - b[1]) * METRES_Y)


def case_seed(base_seed: int, case_id: str) -> int:
    """A stable seed for one case: the same case gets the same episodes on every run."""
    return zlib.crc32(f"{base_seed}:{case_id}".encode())


#: Engine seeds a random-agent case's episodes are split over, even and odd alternately: GRF's
#: seed parity sets the order in which its engine processes the two teams, and left to itself GRF
#: draws a new seed every episode (`seed_spread.py`). A policy that plays the same actions every
#: episode (idle, builtin_ai) gets one seed per episode: with one engine seed GRF plays such an
#: episode the same way every time, so only new seeds give new episodes.
ENGINE_SEEDS = 8


def engine_seeds(policy: str, n: int) -> int:
    """How many engine seeds a case's n episodes are split over (`ENGINE_SEEDS`)."""
    return ENGINE_SEEDS if policy == "random" else n


def engine_seed(base_seed: int, case_id: str, k: int) -> int:
    """The k-th engine seed of a case: stable, and even or odd as k is."""
    return (case_seed(base_seed + k, case_id) & ~1) | (k & 1)


def split(n: int, seeds: int) -> list[int]:
    """n episodes over `seeds` seeds, as evenly as possible (the first get one more)."""
    return [n // seeds + (k < n % seeds) for k in range(seeds)]


def make_env(scenario: str, seed: int, builtin_ai: bool = False) -> FootballEnv:
    """One env of a case, seeded (GRF picks a random engine seed; a fixed one makes runs repeat)."""
    options: dict[str, Any] = {"game_engine_random_seed": seed}
    if builtin_ai:
        options["action_set"] = "v2"
    return create_environment(
        env_name=scenario, representation="raw", rewards="scoring", other_config_options=options
    )


class Policy(Protocol):
    """Chooses the action of our one controlled player; `start` is called at every reset."""

    def start(self) -> None: ...

    def act(self, step: int, obs: Observation) -> int: ...


class Constant:
    """The same action every step: `idle` (0), `builtin_ai` (19), or a button held down."""

    def __init__(self, action: int) -> None:
        self.action = action

    def start(self) -> None:
        pass

    def act(self, step: int, obs: Observation) -> int:
        return self.action


class RandomActions:
    """GRF's random agent: `sample()` of ONE seeded copy of the env's action space for the whole
    case (GRF's `env.action_space` is a new object at every read, so the measurement kept one)."""

    def __init__(self, env: FootballEnv, seed: int) -> None:
        self.space = copy.deepcopy(env.action_space)
        self.space.seed(seed)

    def start(self) -> None:
        pass

    def act(self, step: int, obs: Observation) -> int:
        return int(self.space.sample())


class Scripted:
    """The actions of `first` on steps 1, 2, …, then `then` every step (idle by default)."""

    def __init__(self, first: list[int], then: int = IDLE) -> None:
        self.first = list(first)
        self.then = then

    def start(self) -> None:
        pass

    def act(self, step: int, obs: Observation) -> int:
        return self.first[step - 1] if step <= len(self.first) else self.then


class OnceOwned:
    """Idle until our controlled player owns the ball, then `action` for `times` steps, then idle
    again."""

    def __init__(self, action: int, times: int = 1) -> None:
        self.action = action
        self.times = times
        self.pressed = 0

    def start(self) -> None:
        self.pressed = 0

    def act(self, step: int, obs: Observation) -> int:
        if self.pressed < self.times and (self.pressed > 0 or owns_ball(obs)):
            self.pressed += 1
            return self.action
        return IDLE


def owns_ball(obs: Observation) -> bool:
    """Our controlled player has the ball."""
    return bool(obs["ball_owned_team"] == 0 and obs["ball_owned_player"] == obs["active"])


def match_arguments(description: str, seed: int) -> argparse.Namespace:
    """The command line of the match-profiling tools: a scenario, `--steps` (3,000) and `--seed`."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("scenario")
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=seed)
    return parser.parse_args()


def policy_arguments(description: str) -> argparse.Namespace:
    """The command line of the tools that trace a policy's full matches: `--scenario`
    (11_vs_11_stochastic), `--policy` (idle), `--matches` (10), `--seed` (the first match's, 100)
    and `--steps` (at most 3,001 a match)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--scenario", default="11_vs_11_stochastic")
    parser.add_argument("--policy", default="idle", help="idle, random or builtin_ai")
    parser.add_argument("--matches", type=int, default=10)
    parser.add_argument("--seed", type=int, default=100, help="the first match's seed")
    parser.add_argument("--steps", type=int, default=3001, help="steps per match at most")
    return parser.parse_args()


def policy_match(scenario: str, policy: str, seed: int, steps: int) -> list[Observation]:
    """One match of `policy` (a reference policy's name) in an env seeded `seed`: the reset's
    observation, then one after each step, at most `steps` steps or to the episode's end."""
    env = make_env(scenario, seed, builtin_ai=policy == "builtin_ai")
    agent = make_policy(policy, env, seed)
    agent.start()
    first = env.reset()
    history = [first[0] if isinstance(first, list) else first]
    try:
        for step in range(steps):
            stepped, _, done, _ = env.step(agent.act(step, history[-1]))
            history.append(stepped[0] if isinstance(stepped, list) else stepped)
            if done:
                break
    finally:
        env.close()
    return history


def make_policy(name: str, env: FootballEnv, seed: int) -> Policy:
    """The reference's policies by name: random, idle, builtin_ai."""
    if name == "random":
        return RandomActions(env, seed)
    if name == "idle":
        return Constant(IDLE)
    if name == "builtin_ai":
        return Constant(BUILTIN_AI)
    raise ValueError(f"unknown policy {name!r}")


def builtin_match(scenario: str, steps: int, seed: int) -> Iterator[Observation]:
    """The observation after each step of one run of at most `steps` steps with the built-in AI on
    every player, up to the episode's end (the match-profiling tools' loop)."""
    env = make_env(scenario, seed, builtin_ai=True)
    policy = make_policy("builtin_ai", env, seed)
    policy.start()
    first = env.reset()
    obs = first[0] if isinstance(first, list) else first
    try:
        for step in range(steps):
            stepped, _, done, _ = env.step(policy.act(step, obs))
            obs = stepped[0] if isinstance(stepped, list) else stepped
            yield obs
            if done:
                return
    finally:
        env.close()


class EndTracker:
    """GRF's end-of-episode state: the previous step's game_mode and the last known ball owner."""

    def __init__(self) -> None:
        self.previous_mode = -1
        self.last_owner = -1

    def classify(self, obs: Observation, reward: float) -> str:
        """How the episode would end on this step (GRF's order); call once per step, in order."""
        mode = int(obs["game_mode"])
        owner = int(obs["ball_owned_team"])
        if reward != 0:
            end = "goal"
        elif mode != NORMAL and self.previous_mode == NORMAL:
            end = "out_of_play"
        elif owner != -1 and self.last_owner != -1 and owner != self.last_owner:
            end = "possession"
        elif int(obs["steps_left"]) == 0:
            end = "time_limit"
        else:
            end = "other"
        self.previous_mode = mode
        if owner != -1:
            self.last_owner = owner
        return end


@dataclass
class MatchStats:
    """What a full match is made of, counted from raw observations (both teams, per match).

    A restart is an entry into its game_mode; a completed pass is ball ownership moving between
    two players of one team in normal play, a turnover ownership moving to the other team in
    normal play; possession is our share of the steps on which a team owns the ball; width is the
    median, over normal-play owned steps, of the y-span of the outfield players of the team in
    possession. The flow of play: the share of normal-play steps on which nobody owns the ball,
    and the median length (steps) of a spell of one player owning it and of a spell of nobody
    owning it, counted in normal play (a restart ends a spell).
    """

    restarts: dict[str, int] = field(default_factory=lambda: dict.fromkeys(RESTARTS.values(), 0))
    yellow_cards: int = 0
    passes: int = 0
    turnovers: int = 0
    owned_steps: list[int] = field(default_factory=lambda: [0, 0])
    widths: list[float] = field(default_factory=list)
    normal_steps: int = 0
    loose_steps: int = 0
    owned_spells: list[int] = field(default_factory=list)
    loose_spells: list[int] = field(default_factory=list)
    _spell: tuple[tuple[int, int] | None, int] = (None, 0)
    _mode: int = -1
    _cards: int = 0
    _owner: tuple[int, int] | None = None

    def start(self, obs: Observation) -> None:
        self._mode = int(obs["game_mode"])
        self._cards = _card_count(obs)

    def update(self, obs: Observation) -> None:
        mode = int(obs["game_mode"])
        if mode != self._mode and mode in RESTARTS:
            self.restarts[RESTARTS[mode]] += 1
        self._mode = mode
        cards = _card_count(obs)
        self.yellow_cards += max(0, cards - self._cards)
        self._cards = cards
        team = int(obs["ball_owned_team"])
        self._follow_spell(mode, None if team == -1 else (team, int(obs["ball_owned_player"])))
        if team == -1:
            return
        self.owned_steps[team] += 1
        owner = (team, int(obs["ball_owned_player"]))
        if mode == NORMAL and self._owner is not None and owner != self._owner:
            if owner[0] == self._owner[0]:
                self.passes += 1
            else:
                self.turnovers += 1
        self._owner = owner
        if mode == NORMAL:
            self.widths.append(_outfield_span(obs, "left_team" if team == 0 else "right_team"))

    def _follow_spell(self, mode: int, owner: tuple[int, int] | None) -> None:
        """Extends the current spell (one owner, or nobody) or closes it and starts the next."""
        current, length = self._spell
        if mode != NORMAL:
            self._close_spell()
            return
        self.normal_steps += 1
        self.loose_steps += owner is None
        if length and owner == current:
            self._spell = (current, length + 1)
        else:
            self._close_spell()
            self._spell = (owner, 1)

    def _close_spell(self) -> None:
        current, length = self._spell
        if length:
            (self.loose_spells if current is None else self.owned_spells).append(length)
        self._spell = (None, 0)

    def summary(self) -> dict[str, float]:
        self._close_spell()
        owned = sum(self.owned_steps)
        return {
            **{name: float(count) for name, count in self.restarts.items()},
            "yellow_cards": float(self.yellow_cards),
            "passes": float(self.passes),
            "turnovers": float(self.turnovers),
            "possession": self.owned_steps[0] / owned if owned else float("nan"),
            "width_m": statistics.median(self.widths) if self.widths else float("nan"),
            "loose_share": self.loose_steps / self.normal_steps
            if self.normal_steps
            else float("nan"),
            "owned_spell": statistics.median(self.owned_spells)
            if self.owned_spells
            else float("nan"),
            "loose_spell": statistics.median(self.loose_spells)
            if self.loose_spells
            else float("nan"),
        }


def _card_count(obs: Observation) -> int:
    return int(obs["left_team_yellow_card"].sum() + obs["right_team_yellow_card"].sum())


def _outfield_span(obs: Observation, team: str) -> float:
    """Metres between the two outermost (in y) active outfield players of `team`."""
    ys = [
        float(position[1])
        for position, role, active in zip(
            obs[team], obs[f"{team}_roles"], obs[f"{team}_active"], strict=True
        )
        if int(role) != GOALKEEPER_ROLE and active
    ]
    return (max(ys) - min(ys)) * METRES_PER_Y if ys else 0.0


@dataclass
class Episode:
    """One episode's outcome."""

    steps: int
    end: str
    goals_for: int
    goals_against: int
    max_ball_x: float
    first_goal_step: int | None
    stats: dict[str, float] | None = None
    #: The first kick: the step the ball's horizontal speed first jumps by more than
    #: KICK_JUMP m/s to above KICK_SPEED m/s, that speed, and the ball's x AFTER_KICK steps later
    #: (None when the episode ends first).
    first_kick_step: int | None = None
    first_kick_speed: float | None = None
    ball_x_after_kick: float | None = None
    #: Share of the steps on which our goalkeeper (player 0) was the controlled player.
    keeper_active_share: float = 0.0


def run_episode(
    env: FootballEnv,
    policy: Policy,
    with_stats: bool = False,
    on_step: Callable[[int, Observation], None] | None = None,
) -> Episode:
    """Plays one episode from `env.reset()` to `done`; `on_step(step, obs)` sees each
    observation, the reset one as step 0."""
    obs = env.reset()[0]
    policy.start()
    tracker = EndTracker()
    stats = MatchStats() if with_stats else None
    if stats is not None:
        stats.start(obs)
    if on_step is not None:
        on_step(0, obs)
    goals_for = goals_against = steps = keeper_steps = 0
    first_goal: int | None = None
    kick_step: int | None = None
    kick_speed: float | None = None
    x_after_kick: float | None = None
    speed = 0.0
    max_x = float(obs["ball"][0])
    end = "other"
    done = False
    while not done:
        steps += 1
        observations, reward, done, _ = env.step(policy.act(steps, obs))
        obs = observations[0]
        end = tracker.classify(obs, reward)
        keeper_steps += int(obs["active"]) == 0
        move = obs["ball_direction"]
        previous, speed = speed, math.hypot(float(move[0]), float(move[1])) * SPEED_PER_UNIT_STEP
        if kick_step is None and speed > KICK_SPEED and speed > previous + KICK_JUMP:
            kick_step, kick_speed = steps, speed
        if kick_step is not None and steps == kick_step + AFTER_KICK:
            x_after_kick = float(obs["ball"][0])
        if reward > 0:
            goals_for += 1
            first_goal = first_goal or steps
        elif reward < 0:
            goals_against += 1
        max_x = max(max_x, float(obs["ball"][0]))
        if stats is not None:
            stats.update(obs)
        if on_step is not None:
            on_step(steps, obs)
    return Episode(
        steps=steps,
        end=end,
        goals_for=goals_for,
        goals_against=goals_against,
        max_ball_x=max_x,
        first_goal_step=first_goal,
        stats=stats.summary() if stats is not None else None,
        first_kick_step=kick_step,
        first_kick_speed=kick_speed,
        ball_x_after_kick=x_after_kick,
        keeper_active_share=keeper_steps / steps,
    )


def run_episodes(
    scenario: str,
    policy: str | Callable[[FootballEnv], Policy],
    n: int,
    seed: int,
    with_stats: bool = False,
) -> list[Episode]:
    """n episodes in a row of one env; `policy` is a reference name or a factory given the env."""
    builtin = policy == "builtin_ai"
    env = make_env(scenario, seed, builtin_ai=builtin)
    chosen = make_policy(policy, env, seed) if isinstance(policy, str) else policy(env)
    return [run_episode(env, chosen, with_stats=with_stats) for _ in range(n)]


def run_over_seeds(
    scenario: str, policy: str, n: int, base_seed: int, case_id: str
) -> list[list[Episode]]:
    """n episodes of a reference case split evenly over its engine seeds (`engine_seeds`,
    `engine_seed`), one env each: the samples, one list of episodes per seed."""
    seeds = engine_seeds(policy, n)
    return [
        run_episodes(scenario, policy, count, engine_seed(base_seed, case_id, k))
        for k, count in enumerate(split(n, seeds))
        if count
    ]
