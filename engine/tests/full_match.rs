//! Issue 3, must show: 100 full 11_vs_11_easy_stochastic matches with the built-in AI on both sides
//! all end at step 3001, with no panic, at least one goal in most matches, and no player or ball
//! ever at NaN or far off the pitch.

mod common;

use touchline_engine::Action;

/// Far off the pitch: beyond the rim players and ball are clamped to (60 m × 40 m half sizes).
const LIMIT_X: f32 = 60.0 + 1e-3;
const LIMIT_Y: f32 = 40.0 + 1e-3;

#[test]
fn a_hundred_easy_matches_play_out_sanely() {
    let matches = 100;
    let mut with_goals = 0;
    let mut goals = [0u32; 2];
    for seed in 0..matches {
        let mut env = common::builtin_env("11_vs_11_easy_stochastic", seed);
        let mut steps = 0;
        loop {
            let out = env.step(&[Action::BuiltinAi]).unwrap();
            steps += 1;
            let game = env.game();
            for p in game.players() {
                assert!(p.position.is_finite() && p.velocity.is_finite(), "seed {seed} step {steps}: {p:?}");
                assert!(p.position.x.abs() <= LIMIT_X && p.position.y.abs() <= LIMIT_Y, "seed {seed}: {p:?}");
            }
            let b = game.ball();
            assert!(b.position.is_finite() && b.velocity.is_finite(), "seed {seed} step {steps}: {b:?}");
            assert!(
                b.position.x.abs() <= LIMIT_X && b.position.y.abs() <= LIMIT_Y && b.position.z < 60.0,
                "seed {seed}: {b:?}"
            );
            if out.terminated || out.truncated {
                assert!(out.truncated && !out.terminated, "seed {seed}: a full match only ends at the time limit");
                break;
            }
        }
        assert_eq!(steps, 3001, "seed {seed}");
        assert_eq!(env.info().steps_left, 0);
        let s = env.info().score;
        goals[0] += s[0];
        goals[1] += s[1];
        if s[0] + s[1] > 0 {
            with_goals += 1;
        }
    }
    eprintln!("{with_goals}/{matches} matches with goals; goals left {} right {}", goals[0], goals[1]);
    assert!(with_goals * 2 > matches, "only {with_goals} of {matches} matches had a goal");
}
