//! Every example scenario in `examples/scenarios/*.tl` compiles without warnings, builds an env
//! (with its scripts, if any) and plays: a few episodes of seeded random actions, each of which
//! ends (terminated or truncated) within its time limit. New files are picked up by themselves.

use std::path::{Path, PathBuf};

use touchline_engine::{Action, EnvConfig};

fn examples() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| Some(e.ok()?.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "tl"))
        .collect();
    files.sort();
    files
}

/// A tiny seeded generator (xorshift64*).
fn random_actions(seed: u64) -> impl FnMut(usize) -> usize {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    move |n| {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 33) as usize % n
    }
}

#[test]
fn every_example_scenario_compiles_and_plays() {
    let files = examples();
    // Issue 9 asked for ten examples of behaviours, event rewards and curricula.
    assert!(files.len() >= 10, "{} examples in examples/scenarios, ten wanted", files.len());
    for path in files {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let formatted = touchline_dsl::format_source(&text, &name).unwrap_or_else(|d| panic!("{name}:\n{d}"));
        assert_eq!(formatted, text, "{name}: not in `touchline fmt` layout");
        let compiled = touchline_dsl::compile_file(&path).unwrap_or_else(|d| panic!("{name}:\n{}", d.render_plain()));
        assert!(compiled.warnings.items.is_empty(), "{name}:\n{}", compiled.warnings.render_plain());
        assert!(!compiled.scenario.description.is_empty(), "{name}: give the scenario a `///` doc line");
        let dir = path.parent().unwrap_or(Path::new("."));
        let mut env = touchline_dsl::build_env(compiled.scenario, dir, EnvConfig::default(), 3)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let limit = env.scenario().game_duration + 1;
        let mut next = random_actions(5);
        let set = env.action_set();
        for episode in 0..3 {
            let mut steps = 0;
            loop {
                let actions: Vec<Action> = (0..env.num_controllers()).map(|_| set.actions()[next(set.len())]).collect();
                let out = env.step(&actions).unwrap_or_else(|e| panic!("{name} episode {episode}: {e}"));
                assert!(env.rewards().iter().all(|r| r.is_finite()), "{name}: reward {:?}", env.rewards());
                steps += 1;
                if out.terminated || out.truncated {
                    break;
                }
                assert!(steps <= limit, "{name} episode {episode}: no end after {steps} steps");
            }
            env.reset().unwrap();
        }
    }
}
