//! A failing `reset` hook (issue 17, item 7): `Env::reset` returns the error, the failed episode
//! cannot be stepped (it says why), and the next reset moves on to the following episode; before,
//! `reset` said nothing, the next `step` failed, and every later reset replayed the failing
//! episode (2,970 failures in a row).

use std::path::PathBuf;

use touchline_dsl::script::ScriptOptions;
use touchline_dsl::{build_env_with, load};
use touchline_engine::scenario::{EndCondition, RewardKind, RewardTerm};
use touchline_engine::{Action, EngineError, Env, EnvConfig};

const SCRIPT: &str = "fn reset(s) { if s.episode == 3 { throw \"no episode 3\" } }\nfn reward(s) { 0.0 }\n";

fn env() -> Env {
    let dir: PathBuf = std::env::temp_dir().join(format!("touchline-reset-hook-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("r.rhai"), SCRIPT).unwrap();
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![RewardTerm { reward: RewardKind::Script { path: "r.rhai".into() }, weight: 1.0 }];
    // Two-step episodes.
    scenario.end_when = vec![EndCondition::Steps(2)];
    build_env_with(scenario, &dir, EnvConfig::default(), 0, ScriptOptions::default()).unwrap()
}

fn play_out(env: &mut Env) {
    while !env.is_done() {
        env.step(&[Action::Idle]).unwrap();
    }
}

#[test]
fn reset_returns_the_hook_error_and_the_env_moves_on() {
    let mut env = env();
    let mut failures = Vec::new();
    for _ in 0..50 {
        play_out(&mut env);
        match env.reset() {
            Ok(()) => {}
            Err(EngineError::Script { message, .. }) => {
                assert!(message.contains("tl::S005") && message.contains("reset"), "{message}");
                assert!(message.contains("no episode 3"), "{message}");
                failures.push(env.info().episode);
                // The failed episode cannot be played, and says why, every time.
                for _ in 0..3 {
                    let Err(EngineError::Script { message: again, .. }) = env.step(&[Action::Idle]) else {
                        panic!("a step of the failed episode must fail with the reset's error")
                    };
                    assert_eq!(again, message);
                }
                assert!(env.is_done());
                // The next reset starts episode 4, and it plays.
                env.reset().unwrap();
                assert_eq!(env.info().episode, 4);
            }
            Err(e) => panic!("{e}"),
        }
    }
    assert_eq!(failures, [3], "episode 3 fails once, and only episode 3");
}
