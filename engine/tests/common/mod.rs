//! Shared fixtures: the stdlib scenarios' compiled JSON, read from the repository.
#![allow(dead_code, unreachable_pub)]

use touchline_engine::{Action, Env, EnvConfig, Scenario};

/// A stdlib scenario by name (from `stdlib-scenarios/<name>.json`).
pub fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// An env on a stdlib scenario with the default configuration.
pub fn env(name: &str, seed: u64) -> Env {
    Env::new(scenario(name), seed).unwrap()
}

/// An env where the agents' players are driven by the built-in AI (`builtin_ai`, v2 set).
pub fn builtin_env(name: &str, seed: u64) -> Env {
    let config = EnvConfig { action_set: touchline_engine::ActionSet::V2, ..EnvConfig::default() };
    Env::with_config(scenario(name), config, seed).unwrap()
}

/// Steps with `policy(step)` until the episode ends; returns (steps, summed reward of controller 0).
pub fn play(env: &mut Env, mut policy: impl FnMut(u32, &Env) -> Action) -> (u32, f32) {
    let mut total = 0.0;
    let mut k = 0;
    loop {
        let actions = vec![policy(k, env); env.num_controllers()];
        let out = env.step(&actions).unwrap();
        total += env.rewards().first().copied().unwrap_or(0.0);
        k += 1;
        if out.terminated || out.truncated {
            return (k, total);
        }
    }
}
