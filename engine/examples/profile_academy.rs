//! Plays 20,000 random-agent steps of academy_empty_goal_close: a fixed workload for profilers
//! (`valgrind --tool=callgrind`, `perf record`).
use touchline_engine::{Action, ActionSet, Env, Scenario};
fn main() {
    let path = format!("{}/../stdlib-scenarios/academy_empty_goal_close.json", env!("CARGO_MANIFEST_DIR"));
    let s: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    let mut env = Env::new(s, 0).expect("env");
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let set = ActionSet::Default;
    for _ in 0..20000 {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let a: Action = set.actions()[(state % set.len() as u64) as usize];
        let out = env.step(&[a]).expect("step");
        if out.terminated || out.truncated {
            env.reset().expect("reset");
        }
    }
}
