"""RLlib PPO on touchline, on this machine or a Ray cluster, single-agent or both teams in self-play.

    pip install ./python "ray[rllib]" torch
    python examples/python/rllib_ppo.py --scenario academy_empty_goal_close --iterations 50
    python examples/python/rllib_ppo.py --scenario 1_vs_1_easy --multi-agent --iterations 50

The config is `touchline.rllib.ppo_config`: env names registered with Ray, so every env runner finds
the env wherever it runs (touchline must be installed there). On a cluster the same command runs
with `--address auto` on any of its machines:

    ray start --head --port 6379                 # on the head machine
    ray start --address HEAD_IP:6379             # on each other machine
    python examples/python/rllib_ppo.py --address auto --num-env-runners 16 --iterations 500

Each iteration prints the env steps sampled so far and the mean episode return; the final policy
is saved as an RLlib checkpoint under `--out` (`Algorithm.from_checkpoint`).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import ray
from touchline.rllib import ppo_config


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenario", default="academy_empty_goal_close")
    parser.add_argument("--multi-agent", action="store_true", help="one agent a side")
    parser.add_argument(
        "--no-self-play", action="store_true", help="with --multi-agent: a policy per side"
    )
    parser.add_argument("--iterations", type=int, default=50)
    parser.add_argument("--num-env-runners", type=int, default=2)
    parser.add_argument("--batch", type=int, default=4000, help="env steps per iteration")
    parser.add_argument("--minibatch", type=int, default=500)
    parser.add_argument("--epochs", type=int, default=4)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--address", default=None, help="a Ray cluster ('auto'); none: local Ray")
    parser.add_argument("--num-cpus", type=int, default=None, help="CPUs of the local Ray")
    parser.add_argument("--out", type=Path, default=Path("runs") / "rllib_ppo")
    args = parser.parse_args()

    if args.address:
        ray.init(address=args.address)
    else:
        ray.init(num_cpus=args.num_cpus, include_dashboard=False)
    config = ppo_config(
        args.scenario,
        multi_agent=args.multi_agent,
        self_play=not args.no_self_play,
        num_env_runners=args.num_env_runners,
        env_config={"seed": args.seed},
    ).training(
        train_batch_size_per_learner=args.batch,
        minibatch_size=args.minibatch,
        num_epochs=args.epochs,
    )
    algorithm = config.build_algo()
    started = time.perf_counter()
    for iteration in range(1, args.iterations + 1):
        result = algorithm.train()
        runners = result["env_runners"]
        print(
            f"iteration {iteration}: {int(runners['num_env_steps_sampled_lifetime'])} env steps, "
            f"mean episode return {runners.get('episode_return_mean', float('nan')):.3f}, "
            f"{time.perf_counter() - started:.0f} s",
            flush=True,
        )
    args.out.mkdir(parents=True, exist_ok=True)
    checkpoint = algorithm.save(str(args.out.resolve()))
    print(f"checkpoint: {checkpoint.checkpoint.path}")
    algorithm.stop()
    ray.shutdown()


if __name__ == "__main__":
    main()
