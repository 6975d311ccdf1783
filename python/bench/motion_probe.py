"""How a player starts, stops and turns: his velocity step by step under held directions.

For comparing touchline's player kinematics with GRF's, side by side. Two agents control the
left team: the keeper stands on the ball in his goal (so nobody is sent for a loose ball) and the
outfield player runs a fixed sequence of actions; the right team's two players are lazy. The
script prints the outfield player's velocity (m/s, from his displacement per step) at each step.
`--carry` gives the ball to the outfield player instead. `--theta` sets both teams' difficulty.

Sequences (GRF's default action set: 1 left, 3 top, 5 right, 13 sprint, 14 release direction):
  * `start-stop`: 5 idle, sprint, right ×30, release direction ×15;
  * `reverse`: 5 idle, sprint, right ×25, left ×25;
  * `square`: 5 idle, sprint, right ×25, top ×20;
  * `jog-reverse`: 5 idle, right ×20, left ×20.

Measured with GRF 2.10.2 and touchline at 285ec2a on 2026-11-27: the table is in
docs/grf-compatibility.md#player-motion.

In GRF the scenario must be one of its scenario modules: `--grf` writes `tl_motion_probe.py` into
the installed `gfootball/scenarios` folder first (run it with GRF's Python; `README.md` beside
this file says how to build GRF). In touchline the same scenario is written as a `.tl` file.

Usage (from the repository root):
    PYTHONPATH=python/bench python3 python/bench/motion_probe.py reverse
    PYTHONPATH=python/bench ~/grf-venv/bin/python python/bench/motion_probe.py reverse --grf
"""

from __future__ import annotations

import argparse
import math
import tempfile
from pathlib import Path
from typing import Any

#: Metres per observation unit along and across the pitch (GRF's raw coordinates), the values of
#: kick_profile.py: not imported from it, since it imports touchline, which GRF's Python lacks.
METRES_X = 54.4
METRES_Y = 83.6
#: Steps of 0.1 s.
STEP_SECONDS = 0.1

SEQUENCES = {
    "start-stop": [0] * 5 + [13] + [5] * 30 + [14] * 15,
    "reverse": [0] * 5 + [13] + [5] * 25 + [1] * 25,
    "square": [0] * 5 + [13] + [5] * 25 + [3] * 20,
    "jog-reverse": [0] * 5 + [5] * 20 + [1] * 20,
}

#: The outfield player's start (observation units); the keeper's, and the ball's unless carried.
RUNNER = (-0.6, 0.3)
KEEPER = (-0.95, 0.0)

GRF_SCENARIO = """from . import *


def build_scenario(builder):
  builder.config().game_duration = 400
  builder.config().deterministic = False
  builder.config().offsides = False
  builder.config().end_episode_on_score = False
  builder.config().end_episode_on_out_of_play = False
  builder.config().end_episode_on_possession_change = False
  builder.config().left_team_difficulty = {theta}
  builder.config().right_team_difficulty = {theta}
  builder.SetBallPosition({ball_x}, {ball_y})
  builder.SetTeam(Team.e_Left)
  builder.AddPlayer({keeper_x}, {keeper_y}, e_PlayerRole_GK)
  builder.AddPlayer({runner_x}, {runner_y}, e_PlayerRole_CB)
  builder.SetTeam(Team.e_Right)
  builder.AddPlayer(1.0, 0.0, e_PlayerRole_GK, lazy=True)
  builder.AddPlayer(0.9, -0.35, e_PlayerRole_CB, lazy=True)
"""

TL_SCENARIO = """scenario tl_motion_probe {{
  game_duration 400
  left_team_difficulty {theta}
  right_team_difficulty {theta}
  offsides false
  ball at ({ball_x}, {ball_y})
  team left {{
    GK at ({keeper_x}, {keeper_y})
    CB at ({runner_x}, {runner_y})
  }}
  team right {{
    GK at (1, 0) lazy
    CB at (0.9, -0.35) lazy
  }}
}}
"""


def scenario_text(template: str, theta: float, carry: bool) -> str:
    """The probe's scenario in GRF's or touchline's form."""
    ball = (RUNNER[0] + 0.01, RUNNER[1]) if carry else KEEPER
    return template.format(
        theta=theta,
        ball_x=ball[0],
        ball_y=ball[1],
        keeper_x=KEEPER[0],
        keeper_y=KEEPER[1],
        runner_x=RUNNER[0],
        runner_y=RUNNER[1],
    )


def make_env(grf: bool, theta: float, carry: bool, folder: Path) -> Any:
    """The env with two left agents, through gfootball or touchline's compat layer."""
    if grf:
        import gfootball.scenarios  # type: ignore[import-not-found]
        from gfootball.env import create_environment  # type: ignore[import-not-found]

        module = Path(gfootball.scenarios.__file__).parent / "tl_motion_probe.py"
        module.write_text(scenario_text(GRF_SCENARIO, theta, carry))
        env_name = "tl_motion_probe"
    else:
        from touchline.compat.gfootball import create_environment

        path = folder / "tl_motion_probe.tl"
        path.write_text(scenario_text(TL_SCENARIO, theta, carry))
        env_name = str(path)
    return create_environment(
        env_name=env_name,
        representation="raw",
        number_of_left_players_agent_controls=2,
        other_config_options={"action_set": "default"},
    )


def velocities(env: Any, actions: list[int]) -> list[tuple[float, float]]:
    """The outfield player's velocity (m/s, x and y) over each step of `actions`."""
    obs = env.reset()
    before = obs[1]["left_team"][1]
    out = []
    for action in actions:
        obs, _, done, _ = env.step([0, action])
        now = obs[1]["left_team"][1]
        out.append(
            (
                (now[0] - before[0]) * METRES_X / STEP_SECONDS,
                (now[1] - before[1]) * METRES_Y / STEP_SECONDS,
            )
        )
        before = now
        if done:
            break
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sequence", choices=sorted(SEQUENCES))
    parser.add_argument("--grf", action="store_true", help="run gfootball instead of touchline")
    parser.add_argument("--carry", action="store_true", help="the outfield player has the ball")
    parser.add_argument("--theta", type=float, default=1.0, help="both teams' difficulty")
    args = parser.parse_args()
    actions = SEQUENCES[args.sequence]
    with tempfile.TemporaryDirectory() as folder:
        env = make_env(args.grf, args.theta, args.carry, Path(folder))
        rows = velocities(env, actions)
    for step, (action, (vx, vy)) in enumerate(zip(actions, rows)):
        print(
            f"{step:3d} action {action:2d}  vx {vx:6.2f}  vy {vy:6.2f}  speed {math.hypot(vx, vy):5.2f}"
        )


if __name__ == "__main__":
    main()
