//! Snapshots (issue 10): for every stdlib scenario, snapshot at a random step, play 200 random
//! steps, restore, replay the same actions: identical observations, rewards and flags, bit for
//! bit; the same through the byte form; bad bytes and another scenario are clear errors.

mod common;

use touchline_engine::{Action, EngineError, Env, Snapshot, StepOutcome};

/// Plays `actions`, resetting at episode ends; returns what a learner would see.
fn play(env: &mut Env, actions: &[Action]) -> Vec<(Vec<touchline_engine::RawObservation>, Vec<f32>, StepOutcome)> {
    actions
        .iter()
        .map(|&a| {
            let out = env.step(&vec![a; env.num_controllers()]).unwrap();
            let seen = (env.observations().to_vec(), env.rewards().to_vec(), out);
            if out.terminated || out.truncated {
                env.reset().unwrap();
            }
            seen
        })
        .collect()
}

#[test]
fn restoring_replays_every_stdlib_scenario_bit_for_bit() {
    for (k, name) in common::names().into_iter().enumerate() {
        let mut env = common::env(&name, k as u64);
        let mut policy = common::RandomPolicy::new(k as u64 + 1);
        let warmup: Vec<Action> = (0..policy.index(300)).map(|_| policy.action(env.action_set())).collect();
        play(&mut env, &warmup);
        let snapshot = env.snapshot();
        let bytes = snapshot.to_bytes();
        let actions: Vec<Action> = (0..200).map(|_| policy.action(env.action_set())).collect();
        let first = play(&mut env, &actions);
        env.restore(&snapshot).unwrap();
        assert_eq!(play(&mut env, &actions), first, "{name}: restored in memory");
        // Through bytes, into a fresh env of the same scenario.
        let mut other = common::env(&name, 999);
        other.restore(&Snapshot::from_bytes(&bytes).unwrap()).unwrap();
        assert_eq!(play(&mut other, &actions), first, "{name}: restored from bytes");
    }
}

#[test]
fn a_full_match_snapshot_is_small() {
    let mut env = common::builtin_env("11_vs_11_stochastic", 0);
    for _ in 0..500 {
        env.step(&[Action::BuiltinAi]).unwrap();
    }
    let bytes = env.snapshot().to_bytes();
    assert!(bytes.len() < 16 * 1024, "{} bytes", bytes.len());
}

#[test]
fn bad_bytes_are_clear_errors_never_panics() {
    let env = common::env("academy_corner", 0);
    let bytes = env.snapshot().to_bytes();
    for cut in [0, 5, 23, 24, bytes.len() / 2, bytes.len() - 1] {
        assert!(
            matches!(Snapshot::from_bytes(&bytes[..cut]), Err(EngineError::InvalidSnapshot { .. })),
            "cut at {cut}"
        );
    }
    for at in [0, 7, 30, bytes.len() / 2, bytes.len() - 1] {
        let mut corrupted = bytes.clone();
        corrupted[at] ^= 0x5a;
        assert!(matches!(Snapshot::from_bytes(&corrupted), Err(EngineError::InvalidSnapshot { .. })), "flip at {at}");
    }
    let mut newer = bytes.clone();
    newer[6] = 99;
    let err = Snapshot::from_bytes(&newer).unwrap_err();
    assert!(err.to_string().contains("format version 99"), "{err}");
}

#[test]
fn a_snapshot_only_restores_into_its_own_scenario() {
    let snapshot = common::env("academy_corner", 0).snapshot();
    let mut other = common::env("academy_empty_goal", 0);
    let before = other.observations().to_vec();
    let err = other.restore(&snapshot).unwrap_err();
    assert!(matches!(err, EngineError::SnapshotScenario { .. }), "{err}");
    assert_eq!(other.observations(), &before[..], "a refused restore changes nothing");
}

/// Issue 17, item 11: the extra bytes (the Python env's frame stacks) are inside the checksum.
#[test]
fn extra_bytes_are_under_the_checksum() {
    let env = common::env("academy_corner", 0);
    let extra: Vec<u8> = (0..200u8).collect();
    let bytes = env.snapshot().to_bytes_with(&extra);
    let (_, back) = Snapshot::from_bytes_with(&bytes).unwrap();
    assert_eq!(back, extra);
    Snapshot::from_bytes(&bytes).expect("the plain reader skips the extra bytes");
    for at in [bytes.len() - 1, bytes.len() - 50, bytes.len() - 199] {
        let mut flipped = bytes.clone();
        flipped[at] ^= 0x01;
        assert!(
            matches!(Snapshot::from_bytes_with(&flipped), Err(EngineError::InvalidSnapshot { .. })),
            "flip at {at}"
        );
    }
}

/// Issue 17, item 11: a saved state with a consistent checksum but a ball that is not a number
/// is refused, where it used to give NaN observations.
#[test]
fn a_state_that_is_not_finite_is_refused() {
    let mut env = common::env("academy_corner", 0);
    env.step(&[Action::Idle]).unwrap();
    let good = env.snapshot();
    env.game_mut().place_ball(glam::Vec3::new(f32::NAN, 0.0, 0.1), glam::Vec3::ZERO, None);
    let bad = env.snapshot();
    let mut fresh = common::env("academy_corner", 1);
    let before = fresh.observations().to_vec();
    let err = fresh.restore(&Snapshot::from_bytes(&bad.to_bytes()).unwrap()).unwrap_err();
    assert!(matches!(err, EngineError::InvalidSnapshot { .. }) && err.to_string().contains("ball"), "{err}");
    assert_eq!(fresh.observations(), &before[..], "a refused restore changes nothing");
    fresh.restore(&good).unwrap();
}
