//! Plays 20,000 steps of a full match (11_vs_11_easy_stochastic, or the stdlib scenario named by
//! the first argument) with the built-in AI on all 22 players, or, with `random` as the second
//! argument, a random agent on the controlled player as the step bench's Academy case does: a
//! fixed workload for profilers and instruction counts (`perf stat`, `perf record`, `valgrind
//! --tool=callgrind`), which a loaded machine does not disturb as it does wall-clock benchmarks.
//! Prints the match state hash chained every 100 steps: an optimisation that must leave play bit
//! for bit as it was shows the same hash before and after.
//!
//! `cargo run --release -p touchline-engine --example profile_full -- academy_empty_goal_close random`
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "11_vs_11_easy_stochastic".into());
    let random = std::env::args().nth(2).is_some_and(|a| a == "random");
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let s: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    let set = if random { ActionSet::Default } else { ActionSet::V2 };
    let config = EnvConfig { action_set: set, ..EnvConfig::default() };
    let mut env = Env::with_config(s, config, 0).expect("env");
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut hash: u64 = 0;
    for step in 0..20000 {
        let action = if random {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            set.actions()[(state % set.len() as u64) as usize]
        } else {
            Action::BuiltinAi
        };
        let out = env.step(&[action]).expect("step");
        std::hint::black_box(env.observations());
        if step % 100 == 99 {
            hash = hash.rotate_left(7) ^ env.game().state_hash();
        }
        if out.terminated || out.truncated {
            env.reset().expect("reset");
        }
    }
    println!("trajectory hash {hash:#018x}");
}
