"""A single-file PPO in the style of CleanRL's `ppo.py`, on touchline's Rust vector env (torch).

    pip install ./python torch tensorboard
    python examples/python/ppo_vector.py --scenario academy_empty_goal_close --total-timesteps 1000000

Everything a reader needs is in this file: the policy (a 2×64 tanh MLP actor and critic, as CleanRL's),
rollouts from `touchline.vector.make` (all matches stepped in one call into Rust, Gymnasium's
`RecordEpisodeStatistics` around it), GAE and the clipped PPO update. Logs go to
`runs/<run name>/` for TensorBoard (`charts/episodic_return`, `charts/goal_rate`, `charts/SPS`, the
losses). The run ends by printing env steps per second and the share of the time spent inside the env.

The vector env runs with `autoreset_mode="SameStep"`, the semantics CleanRL's loop is written for: the
observation after a done flag is already the next episode's first. As in CleanRL, a truncated
episode (the drill's time limit) is treated as ended.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import gymnasium
import numpy as np
import torch
import torch.nn as nn
import touchline.vector
from torch.distributions.categorical import Categorical
from torch.utils.tensorboard import SummaryWriter


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenario", default="academy_empty_goal_close")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--total-timesteps", type=int, default=1_000_000)
    parser.add_argument("--num-envs", type=int, default=16, help="matches stepped together")
    parser.add_argument("--num-threads", type=int, default=1, help="Rust threads stepping them")
    parser.add_argument("--num-steps", type=int, default=128, help="rollout steps per env")
    parser.add_argument("--learning-rate", type=float, default=2.5e-4)
    parser.add_argument("--gamma", type=float, default=0.993)
    parser.add_argument("--gae-lambda", type=float, default=0.95)
    parser.add_argument("--num-minibatches", type=int, default=4)
    parser.add_argument("--update-epochs", type=int, default=4)
    parser.add_argument("--clip-coef", type=float, default=0.2)
    parser.add_argument("--ent-coef", type=float, default=0.01)
    parser.add_argument("--vf-coef", type=float, default=0.5)
    parser.add_argument("--max-grad-norm", type=float, default=0.5)
    parser.add_argument("--out", type=Path, default=Path("runs"))
    return parser.parse_args()


def layer(in_features: int, out_features: int, std: float = np.sqrt(2)) -> nn.Linear:
    """An orthogonally initialised linear layer with zero bias (CleanRL's `layer_init`)."""
    linear = nn.Linear(in_features, out_features)
    nn.init.orthogonal_(linear.weight, std)
    nn.init.constant_(linear.bias, 0.0)
    return linear


class Agent(nn.Module):
    def __init__(self, observation_size: int, action_count: int) -> None:
        super().__init__()
        self.critic = nn.Sequential(
            layer(observation_size, 64), nn.Tanh(), layer(64, 64), nn.Tanh(), layer(64, 1, std=1.0)
        )
        self.actor = nn.Sequential(
            layer(observation_size, 64),
            nn.Tanh(),
            layer(64, 64),
            nn.Tanh(),
            layer(64, action_count, std=0.01),
        )

    def value(self, x: torch.Tensor) -> torch.Tensor:
        return self.critic(x)

    def action_and_value(
        self, x: torch.Tensor, action: torch.Tensor | None = None
    ) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor, torch.Tensor]:
        distribution = Categorical(logits=self.actor(x))
        if action is None:
            action = distribution.sample()
        return action, distribution.log_prob(action), distribution.entropy(), self.critic(x)


def main() -> None:
    args = parse_args()
    batch_size = args.num_envs * args.num_steps
    minibatch_size = batch_size // args.num_minibatches
    iterations = max(args.total_timesteps // batch_size, 1)
    run_name = f"ppo_vector_{args.scenario}_{args.seed}_{int(time.time())}"
    writer = SummaryWriter(str(args.out / run_name))
    writer.add_text("hyperparameters", "\n".join(f"{k}: {v}" for k, v in vars(args).items()))

    np.random.seed(args.seed)
    torch.manual_seed(args.seed)
    envs = gymnasium.wrappers.vector.RecordEpisodeStatistics(
        touchline.vector.make(
            args.scenario,
            num_envs=args.num_envs,
            num_threads=args.num_threads,
            seed=args.seed,
            autoreset_mode="SameStep",
        )
    )
    assert envs.single_observation_space.shape is not None
    assert isinstance(envs.single_action_space, gymnasium.spaces.Discrete)
    observation_size = envs.single_observation_space.shape[0]
    agent = Agent(observation_size, int(envs.single_action_space.n))
    optimizer = torch.optim.Adam(agent.parameters(), lr=args.learning_rate, eps=1e-5)

    observations = torch.zeros((args.num_steps, args.num_envs, observation_size))
    actions = torch.zeros((args.num_steps, args.num_envs), dtype=torch.long)
    log_probs = torch.zeros((args.num_steps, args.num_envs))
    rewards = torch.zeros((args.num_steps, args.num_envs))
    dones = torch.zeros((args.num_steps, args.num_envs))
    values = torch.zeros((args.num_steps, args.num_envs))

    global_step = 0
    env_seconds = 0.0
    started = time.perf_counter()
    next_obs_array, _ = envs.reset(seed=args.seed)
    next_obs = torch.from_numpy(next_obs_array)
    next_done = torch.zeros(args.num_envs)
    episodes = 0
    for iteration in range(1, iterations + 1):
        # Linear learning-rate annealing, as CleanRL's default.
        optimizer.param_groups[0]["lr"] = args.learning_rate * (
            1.0 - (iteration - 1.0) / iterations
        )
        for step in range(args.num_steps):
            global_step += args.num_envs
            observations[step] = next_obs
            dones[step] = next_done
            with torch.no_grad():
                action, log_prob, _, value = agent.action_and_value(next_obs)
            values[step] = value.flatten()
            actions[step] = action
            log_probs[step] = log_prob
            clock = time.perf_counter()
            next_obs_array, reward, terminated, truncated, infos = envs.step(action.numpy())
            env_seconds += time.perf_counter() - clock
            rewards[step] = torch.from_numpy(reward)
            next_obs = torch.from_numpy(next_obs_array)
            next_done = torch.from_numpy((terminated | truncated).astype(np.float32))
            if "episode" in infos:
                ended = infos["_episode"]
                episodes += int(ended.sum())
                returns = infos["episode"]["r"][ended]
                # With the scoring reward an episode's return is its goal difference.
                writer.add_scalar("charts/episodic_return", returns.mean(), global_step)
                writer.add_scalar("charts/goal_rate", (returns > 0).mean(), global_step)
                writer.add_scalar(
                    "charts/episodic_length", infos["episode"]["l"][ended].mean(), global_step
                )

        # Generalised advantage estimation, bootstrapped from the value of the next observation.
        with torch.no_grad():
            next_value = agent.value(next_obs).reshape(1, -1)
            advantages = torch.zeros_like(rewards)
            last = torch.zeros(args.num_envs)
            for t in reversed(range(args.num_steps)):
                if t == args.num_steps - 1:
                    non_terminal, following = 1.0 - next_done, next_value
                else:
                    non_terminal, following = 1.0 - dones[t + 1], values[t + 1]
                delta = rewards[t] + args.gamma * following * non_terminal - values[t]
                last = delta + args.gamma * args.gae_lambda * non_terminal * last
                advantages[t] = last
            returns = advantages + values

        b_obs = observations.reshape(-1, observation_size)
        b_log_probs, b_actions = log_probs.reshape(-1), actions.reshape(-1)
        b_advantages, b_returns = advantages.reshape(-1), returns.reshape(-1)
        order = np.arange(batch_size)
        for _ in range(args.update_epochs):
            np.random.shuffle(order)
            for start in range(0, batch_size, minibatch_size):
                mb = order[start : start + minibatch_size]
                _, new_log_prob, entropy, new_value = agent.action_and_value(
                    b_obs[mb], b_actions[mb]
                )
                ratio = (new_log_prob - b_log_probs[mb]).exp()
                mb_advantages = b_advantages[mb]
                mb_advantages = (mb_advantages - mb_advantages.mean()) / (
                    mb_advantages.std() + 1e-8
                )
                policy_loss = torch.max(
                    -mb_advantages * ratio,
                    -mb_advantages * ratio.clamp(1 - args.clip_coef, 1 + args.clip_coef),
                ).mean()
                value_loss = 0.5 * ((new_value.flatten() - b_returns[mb]) ** 2).mean()
                loss = policy_loss - args.ent_coef * entropy.mean() + args.vf_coef * value_loss
                optimizer.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(agent.parameters(), args.max_grad_norm)
                optimizer.step()

        seconds = time.perf_counter() - started
        writer.add_scalar("losses/policy_loss", policy_loss.item(), global_step)
        writer.add_scalar("losses/value_loss", value_loss.item(), global_step)
        writer.add_scalar("losses/entropy", entropy.mean().item(), global_step)
        writer.add_scalar("charts/SPS", global_step / seconds, global_step)

    seconds = time.perf_counter() - started
    print(
        f"{global_step} steps, {episodes} episodes in {seconds:.1f} s: "
        f"{global_step / seconds:.0f} env steps/s, {100 * env_seconds / seconds:.0f} % in the env; "
        f"logs: {args.out / run_name}"
    )
    envs.close()
    writer.close()


if __name__ == "__main__":
    main()
