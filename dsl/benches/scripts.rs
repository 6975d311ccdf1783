//! Cost of script rewards per env step on academy_empty_goal_close: a step with no script, then
//! the same step with each example script (examples/rewards/) as a reward term. The difference is
//! the script's overhead. Run: `cargo bench -p touchline-dsl --bench scripts`.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use touchline_engine::scenario::{EndCondition, RewardKind, RewardTerm};
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};

fn scenario() -> Scenario {
    let mut s = touchline_dsl::load("academy_empty_goal_close").unwrap();
    // Long episodes, so that resets do not dominate.
    s.end_episode_on_score = false;
    s.end_episode_on_out_of_play = false;
    s
}

fn bench_env(c: &mut Criterion, name: &str, mut env: Env) {
    let set = ActionSet::Default.actions();
    let mut rng = Pcg64::seed_from_u64(1);
    let actions: Vec<[Action; 1]> = (0..4096).map(|_| [set[rng.random_range(0..set.len())]]).collect();
    let mut i = 0;
    c.bench_function(name, |b| {
        b.iter(|| {
            if env.is_done() {
                env.reset().unwrap();
            }
            i = (i + 1) % actions.len();
            black_box(env.step(&actions[i]).unwrap());
        });
    });
}

fn steps(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/rewards");
    bench_env(c, "step/no_script", Env::with_config(scenario(), EnvConfig::default(), 0).unwrap());
    for script in ["possession", "pass_completion", "distance_to_goal", "checkpoints"] {
        let mut s = scenario();
        s.rewards = vec![
            RewardTerm::scoring(),
            RewardTerm { reward: RewardKind::Script { path: format!("{script}.rhai") }, weight: 1.0 },
        ];
        let env = touchline_dsl::build_env(s, &dir, EnvConfig::default(), 0).unwrap();
        bench_env(c, &format!("step/{script}"), env);
    }
    let mut s = scenario();
    s.end_when = vec![EndCondition::Script { path: "ends/ball_in_our_half.rhai".into() }];
    let env = touchline_dsl::build_env(s, &dir, EnvConfig::default(), 0).unwrap();
    bench_env(c, "step/end_ball_in_our_half", env);
}

criterion_group!(benches, steps);
criterion_main!(benches);
