"""Self-play through PettingZoo: both teams learn, one shared PPO policy playing both sides.

    pip install ./python stable-baselines3 supersuit tensorboard
    python examples/python/self_play_pettingzoo.py --scenario 1_vs_1_easy --timesteps 1000000

The usual PettingZoo recipe, unchanged: `touchline.parallel_env` with one controlled player a side
(agents `left_0` and `right_0`), SuperSuit's `pettingzoo_env_to_vec_env_v1` turning each agent into
one entry of a vector env, `concat_vec_envs_v1` gathering several matches (copies made by pickling
the env) as an SB3 `VecEnv`, and SB3 PPO. Each agent observes the match in its own frame (a
right-team player sees itself attacking +x), so one set of weights learns to play both sides: that
is the self-play. The reward is scoring + checkpoints, from each agent's own side.

At the end the policy plays `--eval-episodes` matches against the built-in AI from the left, and
against itself (left vs right), and the goal difference per match is printed with its standard
error. Writes `model.zip` and TensorBoard logs under `--out`.

The same training runs on touchline's own vector env with both sides as batch entries:
`touchline.vector.make(scenario, num_envs=N, number_of_left_players_agent_controls=1,
number_of_right_players_agent_controls=1)` (see python/README.md, "Training").
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np
import supersuit
import touchline
from stable_baselines3 import PPO
from stable_baselines3.common.utils import set_random_seed


def self_play_vec_env(scenario: str, matches: int, seed: int):  # type: ignore[no-untyped-def]
    """`matches` copies of the two-agent match as one SB3 VecEnv of 2 × matches entries."""
    env = touchline.parallel_env(
        scenario,
        number_of_left_players_agent_controls=1,
        number_of_right_players_agent_controls=1,
        rewards="scoring,checkpoints",
        seed=seed,
    )
    vec = supersuit.pettingzoo_env_to_vec_env_v1(env)
    # num_cpus=0 steps the copies in this process; more moves them to worker processes.
    vec = supersuit.concat_vec_envs_v1(vec, matches, num_cpus=0, base_class="stable_baselines3")
    # The copies are pickled from one env, seed and all: reseed match i with seed + i so they differ.
    # (SuperSuit's SB3 wrapper lacks SB3 2.x's `seed()`, so PPO is not given the seed below.)
    vec.venv.reset(seed=seed)
    return vec


def goal_difference(
    model: PPO, scenario: str, episodes: int, seed: int, opponent: str
) -> tuple[float, float]:
    """Mean goal difference per match for the policy on the left, and its standard error.

    `opponent`: "builtin" (the scenario's own AI on the right) or "self" (the policy on the right).
    """
    differences = []
    for episode in range(episodes):
        if opponent == "self":
            env = touchline.parallel_env(
                scenario,
                number_of_left_players_agent_controls=1,
                number_of_right_players_agent_controls=1,
                seed=seed + episode,
            )
        else:
            env = touchline.parallel_env(
                scenario,
                number_of_left_players_agent_controls=1,
                number_of_right_players_agent_controls=0,
                seed=seed + episode,
            )
        observations, infos = env.reset(seed=seed + episode)
        while env.agents:
            actions = {
                agent: int(model.predict(observations[agent], deterministic=True)[0])
                for agent in env.agents
            }
            observations, _, _, _, infos = env.step(actions)
        left, right = infos["left_0"]["score"]
        differences.append(left - right)
    values = np.asarray(differences, dtype=np.float64)
    se = values.std(ddof=1) / np.sqrt(len(values)) if len(values) > 1 else float("nan")
    return float(values.mean()), float(se)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenario", default="1_vs_1_easy")
    parser.add_argument("--timesteps", type=int, default=1_000_000, help="agent steps, both sides")
    parser.add_argument("--matches", type=int, default=4)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--n-steps", type=int, default=256)
    parser.add_argument("--eval-episodes", type=int, default=20)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    out = args.out or Path("runs") / f"self_play_{args.scenario}_{args.seed}"
    out.mkdir(parents=True, exist_ok=True)

    set_random_seed(args.seed)
    env = self_play_vec_env(args.scenario, args.matches, args.seed)
    model = PPO(
        "MlpPolicy",
        env,
        n_steps=args.n_steps,
        batch_size=max(args.n_steps * env.num_envs // 4, 1),
        n_epochs=4,
        gamma=0.993,
        ent_coef=0.01,
        tensorboard_log=str(out / "tb"),
        device="cpu",
        verbose=1,
    )
    started = time.perf_counter()
    model.learn(total_timesteps=args.timesteps)
    seconds = time.perf_counter() - started
    model.save(out / "model")
    env.close()
    print(
        f"trained {model.num_timesteps} agent steps in {seconds:.1f} s; model: {out / 'model.zip'}"
    )
    for opponent in ("builtin", "self"):
        mean, se = goal_difference(
            model, args.scenario, args.eval_episodes, args.seed + 10_000, opponent
        )
        print(
            f"goal difference per match vs {opponent}: {mean:+.2f} ± {se:.2f} (n={args.eval_episodes})"
        )


if __name__ == "__main__":
    main()
