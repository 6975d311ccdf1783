//! Speed of `Env::step` (criterion). Issue 3 asks for ≥ 10,000 steps/s on 11_vs_11_easy_stochastic
//! with the built-in AI on all 22 players and ≥ 200,000 steps/s on academy_empty_goal_close, on
//! one core. Also prints the resident memory per Env.
//!
//! Run: `cargo bench -p touchline-engine --bench step`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};

fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON")
}

/// Steps `env` with `next_action`, resetting at the end of each episode.
fn bench_steps(c: &mut Criterion, id: &str, mut env: Env, mut next_action: impl FnMut() -> Action) {
    let mut group = c.benchmark_group("step");
    group.throughput(Throughput::Elements(1));
    group.bench_function(id, |b| {
        b.iter(|| {
            let out = env.step(&[next_action()]).expect("step");
            if out.terminated || out.truncated {
                env.reset().unwrap();
            }
            black_box(env.observations());
        })
    });
    group.finish();
}

fn steps(c: &mut Criterion) {
    let v2 = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let full = Env::with_config(scenario("11_vs_11_easy_stochastic"), v2, 0).expect("env");
    bench_steps(c, "11_vs_11_easy_stochastic/builtin_ai_22_players", full, || Action::BuiltinAi);
    // The scenario of the side-by-side timing against GRF (README.md, Speed): medium opposition.
    let medium = Env::with_config(scenario("11_vs_11_stochastic"), v2, 0).expect("env");
    bench_steps(c, "11_vs_11_stochastic/builtin_ai_22_players", medium, || Action::BuiltinAi);

    let academy = Env::new(scenario("academy_empty_goal_close"), 0).expect("env");
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let set = ActionSet::Default;
    bench_steps(c, "academy_empty_goal_close/random_agent", academy, move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        set.actions()[(state % set.len() as u64) as usize]
    });
}

/// Resident set size in bytes (Linux); 0 elsewhere.
fn resident_bytes() -> usize {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().nth(1)?.parse::<usize>().ok())
        .map_or(0, |pages| pages * 4096)
}

fn memory(_: &mut Criterion) {
    for name in ["11_vs_11_easy_stochastic", "academy_empty_goal_close"] {
        let s = scenario(name);
        let before = resident_bytes();
        let envs: Vec<Env> = (0..2000).map(|seed| Env::new(s.clone(), seed).expect("env")).collect();
        let after = resident_bytes();
        println!(
            "memory/{name}: {:.1} KiB resident per Env ({} envs)",
            (after - before) as f64 / 1024.0 / envs.len() as f64,
            envs.len()
        );
        black_box(envs);
    }
}

fn snapshots(c: &mut Criterion) {
    let v2 = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario("11_vs_11_easy_stochastic"), v2, 0).expect("env");
    for _ in 0..500 {
        env.step(&[Action::BuiltinAi]).expect("step");
    }
    let snapshot = env.snapshot();
    println!("snapshot/11_vs_11: {} bytes serialised", snapshot.to_bytes().len());
    let mut group = c.benchmark_group("snapshot");
    group.bench_function("11_vs_11/snapshot", |b| b.iter(|| black_box(env.snapshot())));
    group.bench_function("11_vs_11/restore", |b| b.iter(|| env.restore(black_box(&snapshot)).expect("restore")));
    group.bench_function("11_vs_11/to_bytes", |b| b.iter(|| black_box(snapshot.to_bytes())));
    let bytes = snapshot.to_bytes();
    group.bench_function("11_vs_11/from_bytes", |b| {
        b.iter(|| black_box(touchline_engine::Snapshot::from_bytes(black_box(&bytes)).expect("bytes")))
    });
    group.finish();
}

criterion_group!(benches, steps, memory, snapshots);
criterion_main!(benches);
