//! Plays 20,000 steps of a full match (11_vs_11_easy_stochastic, or the stdlib scenario named by
//! the first argument) with the built-in AI on all 22 players: a fixed
//! workload for profilers and instruction counts (`perf stat -e instructions:u`, `valgrind
//! --tool=callgrind`), which a loaded machine does not disturb as it does wall-clock benchmarks.
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "11_vs_11_easy_stochastic".into());
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let s: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(s, config, 0).expect("env");
    for _ in 0..20000 {
        let out = env.step(&[Action::BuiltinAi]).expect("step");
        if out.terminated || out.truncated {
            env.reset().expect("reset");
        }
    }
}
