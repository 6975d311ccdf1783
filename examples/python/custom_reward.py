"""Train on a scenario of your own: a `.tl` file whose reward adds a rhai script to GRF's scoring.

    pip install ./python stable-baselines3 tensorboard
    python examples/python/custom_reward.py --timesteps 300000

`examples/scenarios/run_to_score_shaped.tl` extends GRF's academy_run_to_score and adds
`reward script "../rewards/distance_to_goal.rhai" weight 0.5`: while the team has the ball, each step
pays how much closer the ball came to the opponents' goal. The script runs sandboxed inside the env
(a bad script is a `touchline.ScenarioError` at load, a runtime error counts in
`info["script_errors"]`), and each reward term is reported apart in the info: `score_reward`
(GRF's scoring), `script_reward` (the script's, weighted). `touchline.make` takes the `.tl` path as
it takes a stdlib name; edit the script and a new env picks the change up.

At the end the policy plays `--eval-episodes` episodes and the script prints the goal rate (from
`score_reward` alone, so it compares with an agent trained on scoring only) beside the shaped return.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np
import touchline
from stable_baselines3 import PPO
from stable_baselines3.common.env_util import make_vec_env

SCENARIO = Path(__file__).resolve().parents[1] / "scenarios" / "run_to_score_shaped.tl"


def evaluate(model: PPO, scenario: Path, episodes: int, seed: int) -> tuple[float, float]:
    """(goal rate, mean shaped return) of the deterministic policy over `episodes` episodes."""
    env = touchline.make(scenario)
    goals, returns = 0, []
    for episode in range(episodes):
        observation, _ = env.reset(seed=seed + episode)
        done, total = False, 0.0
        while not done:
            action, _ = model.predict(observation, deterministic=True)
            observation, reward, terminated, truncated, info = env.step(int(action))
            total += float(reward)
            goals += info["score_reward"] > 0
            done = terminated or truncated
        returns.append(total)
    return goals / episodes, float(np.mean(returns))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--scenario", type=Path, default=SCENARIO, help="a .tl or compiled .json file"
    )
    parser.add_argument("--timesteps", type=int, default=300_000)
    parser.add_argument("--envs", type=int, default=8)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--eval-episodes", type=int, default=50)
    parser.add_argument("--out", type=Path, default=Path("runs") / "custom_reward")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    scenario = args.scenario.resolve()
    env = make_vec_env(lambda: touchline.make(scenario), n_envs=args.envs, seed=args.seed)
    model = PPO(
        "MlpPolicy",
        env,
        n_steps=256,
        batch_size=256,
        gamma=0.993,
        ent_coef=0.01,
        tensorboard_log=str(args.out / "tb"),
        seed=args.seed,
        device="cpu",
        verbose=1,
    )
    started = time.perf_counter()
    model.learn(total_timesteps=args.timesteps)
    print(f"trained {model.num_timesteps} steps in {time.perf_counter() - started:.1f} s")
    model.save(args.out / "model")
    env.close()
    goal_rate, shaped = evaluate(model, scenario, args.eval_episodes, args.seed + 10_000)
    print(
        f"{scenario.name}: goal rate {goal_rate:.2f}, mean shaped return {shaped:.3f} "
        f"over {args.eval_episodes} episodes; model: {args.out / 'model.zip'}"
    )


if __name__ == "__main__":
    main()
