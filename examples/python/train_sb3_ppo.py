"""Stable-Baselines3 PPO on a touchline Academy drill, with TensorBoard logs, evaluation and a saved model.

    pip install ./python stable-baselines3 tensorboard
    python examples/python/train_sb3_ppo.py --scenario academy_empty_goal_close --timesteps 1000000

Writes under `--out` (default `runs/ppo_<scenario>_<seed>`):
- `tb/`: TensorBoard logs (`tensorboard --logdir runs`): SB3's `rollout/ep_rew_mean`, losses, fps.
- `eval/evaluations.npz`: SB3's `EvalCallback` record, every `--eval-every` steps `--eval-episodes`
  deterministic episodes on a separately seeded env (`timesteps`, `results` returns, `ep_lengths`).
- `learning_curve.csv`: the same, one row per evaluation: steps, mean return (= goal rate with the
  scoring reward), its standard error, mean episode length, wall-clock seconds.
- `model.zip`: the final policy (`PPO.load`), `best_model.zip`: the best evaluated one.
- `run.txt`: the scenario, the command line and the closing summary (steps per second, env share).

The env is the plain registered Gymnasium id (`touchline/<scenario>-v0`) through SB3's own
`make_vec_env`, no wrapper: the observation is simple115v2 (115 float32), the action one of GRF's 19,
the reward GRF's scoring reward (+1 for a goal for, -1 against). The run ends by printing env steps
per second and the share of the time spent inside the env: about 5 % on 2 cores, the rest is PPO's
torch work. That is why there is no SB3 `VecEnv` over touchline's Rust vector env: measured, one
(tried on this script) was no faster than `make_vec_env`'s Python loop over 8 envs.

Hyperparameters follow the PPO settings of the GRF paper's Academy experiments (Kurach et al. 2020,
"Google Research Football: A Novel Reinforcement Learning Environment", appendix): learning rate
3.43e-4, 512-step rollouts per env, 8 minibatches, 2 epochs, clip 0.08, discount 0.993, GAE 0.95,
entropy 0.003, gradient-norm clip 0.64; 8 envs here instead of 16 (a 2-core machine).
"""

from __future__ import annotations

import argparse
import csv
import shlex
import sys
import time
from pathlib import Path

import numpy as np
import touchline  # noqa: F401  (registers the touchline/<scenario>-v0 ids)
from stable_baselines3 import PPO
from stable_baselines3.common.callbacks import BaseCallback, EvalCallback
from stable_baselines3.common.env_util import make_vec_env
from stable_baselines3.common.vec_env import VecEnv, VecEnvWrapper


def make_env(scenario: str, n_envs: int, seed: int) -> VecEnv:
    """`n_envs` envs of the drill, straight from the registered id: no wrapper but SB3's `Monitor`."""
    return make_vec_env(f"touchline/{scenario}-v0", n_envs=n_envs, seed=seed)


class EnvClock(VecEnvWrapper):
    """Adds up the seconds spent inside the env's `reset` and `step`, to report the env's share."""

    def __init__(self, venv: VecEnv) -> None:
        super().__init__(venv)
        self.seconds = 0.0

    def reset(self) -> np.ndarray:
        started = time.perf_counter()
        observations: np.ndarray = self.venv.reset()
        self.seconds += time.perf_counter() - started
        return observations

    def step_wait(self):  # type: ignore[no-untyped-def]
        started = time.perf_counter()
        result = self.venv.step_wait()
        self.seconds += time.perf_counter() - started
        return result


class LearningCurve(BaseCallback):
    """Appends each new evaluation of an `EvalCallback` to a CSV, with the wall-clock time."""

    def __init__(self, evaluation: EvalCallback, path: Path) -> None:
        super().__init__()
        self.evaluation = evaluation
        self.path = path
        self.started = time.perf_counter()
        self.written = 0
        with path.open("w", newline="") as f:
            csv.writer(f).writerow(["steps", "mean_return", "se_return", "mean_length", "seconds"])

    def _on_step(self) -> bool:
        results = self.evaluation.evaluations_results
        if len(results) > self.written:
            returns = np.asarray(results[-1], dtype=np.float64)
            se = returns.std(ddof=1) / np.sqrt(len(returns)) if len(returns) > 1 else 0.0
            row = [
                self.evaluation.evaluations_timesteps[-1],
                f"{returns.mean():.4f}",
                f"{se:.4f}",
                f"{np.mean(self.evaluation.evaluations_length[-1]):.1f}",
                f"{time.perf_counter() - self.started:.1f}",
            ]
            with self.path.open("a", newline="") as f:
                csv.writer(f).writerow(row)
            self.written = len(results)
        return True


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenario", default="academy_empty_goal_close")
    parser.add_argument("--timesteps", type=int, default=1_000_000)
    parser.add_argument("--envs", type=int, default=8)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--n-steps", type=int, default=512, help="rollout steps per env")
    parser.add_argument(
        "--eval-every", type=int, default=50_000, help="env steps between evaluations"
    )
    parser.add_argument("--eval-episodes", type=int, default=50)
    parser.add_argument("--out", type=Path, default=None)
    parser.add_argument(
        "--device", default="cpu", help="torch device (an MLP trains fastest on cpu)"
    )
    args = parser.parse_args()
    out = args.out or Path("runs") / f"ppo_{args.scenario}_{args.seed}"
    out.mkdir(parents=True, exist_ok=True)

    env = EnvClock(make_env(args.scenario, args.envs, args.seed))
    # Evaluation plays its own seeds, never the training envs'.
    eval_env = make_env(args.scenario, 1, args.seed + 10_000)
    evaluation = EvalCallback(
        eval_env,
        n_eval_episodes=args.eval_episodes,
        eval_freq=max(args.eval_every // args.envs, 1),
        log_path=str(out / "eval"),
        best_model_save_path=str(out),
        deterministic=True,
        verbose=0,
    )
    model = PPO(
        "MlpPolicy",
        env,
        learning_rate=3.43e-4,
        n_steps=args.n_steps,
        batch_size=max(args.n_steps * args.envs // 8, 1),
        n_epochs=2,
        gamma=0.993,
        gae_lambda=0.95,
        clip_range=0.08,
        ent_coef=0.003,
        max_grad_norm=0.64,
        tensorboard_log=str(out / "tb"),
        seed=args.seed,
        device=args.device,
        verbose=1,
    )
    started = time.perf_counter()
    model.learn(
        total_timesteps=args.timesteps,
        callback=[evaluation, LearningCurve(evaluation, out / "learning_curve.csv")],
    )
    seconds = time.perf_counter() - started
    model.save(out / "model")
    # The env's share counts touchline and its SB3 adapter; evaluation episodes are outside it.
    summary = (
        f"trained {model.num_timesteps} steps in {seconds:.1f} s "
        f"({model.num_timesteps / seconds:.0f} env steps/s; {env.seconds:.1f} s "
        f"= {100 * env.seconds / seconds:.0f} % in the env); model: {out / 'model.zip'}"
    )
    print(summary)
    command = shlex.join([Path(sys.executable).name, *sys.argv])
    (out / "run.txt").write_text(
        f"scenario: {args.scenario}\ncommand: {command}\nsummary: {summary}\n"
    )
    env.close()
    eval_env.close()


if __name__ == "__main__":
    main()
