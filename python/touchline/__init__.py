"""touchline: a fast football (soccer) reinforcement-learning environment with GRF's conventions.

```python
import touchline
env = touchline.make("academy_empty_goal_close", representation="simple115v2")
obs, info = env.reset(seed=0)
obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
```

* `touchline.make(...)`: a `gymnasium.Env`; `gymnasium.make("touchline/<scenario>-v0")` works too.
* `touchline.parallel_env(...)`: a PettingZoo `ParallelEnv` for several players, self-play included.
* `touchline.vector.make(scenario, num_envs=N)`: N matches stepped in Rust threads.
* `touchline.compat.gfootball.create_environment(...)`: GRF's function, for existing GRF code.
* `touchline.EnvOptions(...)`: the envs' shared keyword arguments as one checked value
  (`touchline.make(scenario, options=...)`).
* `touchline.RecordReplay(env, folder)`: saves episodes as `.tlreplay` files for `touchline view`;
  `touchline.Replay(path)` reads one back and re-simulates it.
* Errors: `touchline.TouchlineError`, and its subclass `touchline.ScenarioError` for a scenario
  that cannot be loaded; bad arguments raise `ValueError`, stepping after the end `RuntimeError`.
"""

from __future__ import annotations

from . import vector
from ._touchline import Replay, ReplayError, ScenarioError, TouchlineError, scenario_names
from ._touchline import __version__ as __version__
from .gymnasium_env import FootballEnv
from .make import make, parallel_env
from .options import EnvOptions
from .record_replay import ParallelRecordReplay, RecordReplay
from .registration import register_stdlib as _register_stdlib

__all__ = [
    "EnvOptions",
    "FootballEnv",
    "ParallelRecordReplay",
    "RecordReplay",
    "Replay",
    "ReplayError",
    "ScenarioError",
    "TouchlineError",
    "__version__",
    "make",
    "parallel_env",
    "scenario_names",
    "vector",
]

_register_stdlib()
