//! Speed of `Env::step` when one team plays native behaviours instead of the built-in AI
//! (issue 9: a scenario whose opponents all use native behaviours steps at least as fast as the
//! same scenario under the built-in AI).
//!
//! Both cases play 11_vs_11_easy_stochastic with the left team under the built-in AI
//! (`builtin_ai`, v2 set); in `right_native_behaviours` every right player has a behaviour
//! (keeper and four players `hold_position`, three `press`, three `mark` a left player), in
//! `right_builtin_ai` none. The games differ (the behaviours play otherwise), so the bench also
//! prints each case's mean over 30,000 steps with its in-play ticks and goals, to show that the
//! comparison is between games of the same length.
//!
//! Run: `cargo bench -p touchline-engine --bench behaviours`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use touchline_engine::scenario::{Behaviour, Stage, Target};
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};

fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON")
}

/// The scenario with every right player on a native behaviour.
fn with_behaviours(mut s: Scenario) -> Scenario {
    let left = s.left_team.len();
    for (i, p) in s.right_team.iter_mut().enumerate() {
        let behaviour = match i % 3 {
            _ if i == 0 => Behaviour::HoldPosition,
            0 => Behaviour::Press,
            1 => Behaviour::Mark(Target::Left(left - i)),
            _ => Behaviour::HoldPosition,
        };
        p.behaviour = vec![Stage { behaviour, until: None }];
    }
    s
}

fn steps(c: &mut Criterion) {
    let v2 = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let base = scenario("11_vs_11_easy_stochastic");
    // Whole episodes first: both play as many in-play ticks, so the per-step figures compare.
    for (id, s) in [("right_builtin_ai", base.clone()), ("right_native_behaviours", with_behaviours(base.clone()))] {
        let mut env = Env::with_config(s, v2, 0).expect("env");
        let (mut ticks, mut goals, mut steps) = (0u64, 0u32, 0u32);
        for _ in 0..30_000 {
            let out = env.step(&[Action::BuiltinAi]).expect("step");
            steps += 1;
            if out.terminated || out.truncated {
                ticks += env.game().in_play_ticks();
                goals += env.game().score().iter().sum::<u32>();
                env.reset().unwrap();
            }
        }
        println!("play/{id}: {steps} steps, {ticks} in-play ticks in finished episodes, {goals} goals");
    }
    let mut group = c.benchmark_group("behaviours");
    group.throughput(Throughput::Elements(1));
    for (id, s) in [("right_builtin_ai", base.clone()), ("right_native_behaviours", with_behaviours(base))] {
        let mut env = Env::with_config(s, v2, 0).expect("env");
        group.bench_function(id, |b| {
            b.iter(|| {
                let out = env.step(&[Action::BuiltinAi]).expect("step");
                if out.terminated || out.truncated {
                    env.reset().unwrap();
                }
                black_box(env.observations());
            })
        });
    }
    group.finish();
}

criterion_group!(benches, steps);
criterion_main!(benches);
