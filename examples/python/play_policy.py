"""Serve a saved policy as your opponent in `touchline play` (issue 19).

    touchline play 1_vs_1_easy --opponent-port 8001        # then open http://127.0.0.1:8000/
    python examples/python/play_policy.py --port 8001 --model runs/ppo/model.zip

touchline sends, after every step, one JSON line with the opponent player's `simple115v2`
observation (in that player's own frame, as `touchline.make` gives it: a policy trained on the left
plays on the right) and a turn number; this script answers `{"turn": T, "action": A}` with an index
into GRF's 19 actions. The match does not wait: an answer that misses the next step (100 ms) leaves
the player idle for it. The protocol is in docs/play-protocol.md.

`--model` is a Stable-Baselines3 `.zip` (`PPO.load`, as examples/python/train_sb3_ppo.py saves);
without it the player takes random actions. Needs only the standard library and, with `--model`,
stable-baselines3.
"""

from __future__ import annotations

import argparse
import json
import random
import socket
import sys


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--port", type=int, default=8001, help="touchline play's --opponent-port")
    parser.add_argument("--model", help="a saved SB3 policy (.zip); random actions without one")
    parser.add_argument("--stochastic", action="store_true", help="sample the policy's actions")
    args = parser.parse_args()

    model = None
    if args.model:
        from stable_baselines3 import PPO

        model = PPO.load(args.model, device="cpu")

    def act(observation: list[float]) -> int:
        if model is None:
            return random.randrange(19)
        import numpy as np

        action, _ = model.predict(
            np.asarray(observation, dtype=np.float32), deterministic=not args.stochastic
        )
        return int(action)

    try:
        connection = socket.create_connection(("127.0.0.1", args.port))
    except OSError as e:
        sys.exit(f"error: cannot connect to touchline play on port {args.port}: {e}")
    connection.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    with connection, connection.makefile("r") as lines:
        print(f"playing on port {args.port}; Ctrl-C to stop")
        for line in lines:
            message = json.loads(line)
            if "error" in message:
                sys.exit(f"error: {message['error']}")
            if message["done"]:
                print(f"episode {message['episode']} ended at step {message['step']}")
                continue
            answer = {"turn": message["turn"], "action": act(message["observation"])}
            connection.sendall((json.dumps(answer) + "\n").encode())


if __name__ == "__main__":
    main()
