//! The observation encoders (docs/grf-compatibility.md#representations) on observations produced by a real `Env`.

mod common;

use touchline_engine::obs::{FrameStack, SMM_CHANNELS, SMM_HEIGHT, SMM_WIDTH, encode_simple115v2, encode_smm};
use touchline_engine::{Action, Env, EnvConfig, RawObservation};

fn v2(obs: &RawObservation) -> [f32; 115] {
    let mut out = [0.0; 115];
    encode_simple115v2(obs, &mut out);
    out
}

#[test]
fn simple115v2_of_an_academy_drill_carries_the_raw_observation() {
    let env = common::env("academy_empty_goal_close", 0);
    let obs = &env.observations()[0];
    let out = v2(obs);
    assert_eq!(out[88..91], obs.ball);
    assert_eq!(out[91..94], obs.ball_direction);
    let n = obs.left_team.len();
    assert!(n < 11, "the drill has a short left team");
    for (i, p) in obs.left_team.iter().enumerate() {
        assert_eq!(out[2 * i..2 * i + 2], *p);
    }
    assert!(out[2 * n..22].iter().all(|&v| v == -1.0));
    for (i, p) in obs.right_team.iter().enumerate() {
        assert_eq!(out[44 + 2 * i..44 + 2 * i + 2], *p);
    }
    assert_eq!(out[97..108].iter().sum::<f32>(), 1.0);
    assert_eq!(out[97 + obs.active as usize], 1.0);
    assert_eq!(out[108 + obs.game_mode as usize], 1.0);

    let mut smm = vec![0; SMM_WIDTH * SMM_HEIGHT * SMM_CHANNELS];
    encode_smm(obs, SMM_WIDTH, SMM_HEIGHT, &mut smm);
    let count = |c: usize| smm.chunks_exact(SMM_CHANNELS).filter(|px| px[c] == 255).count();
    assert_eq!(count(2), 1);
    assert_eq!(count(3), 1);
    assert!((1..=n).contains(&count(0)));
}

#[test]
fn a_right_team_controller_sees_its_own_team_in_the_left_block() {
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("11_vs_11_stochastic"), config, 3).unwrap();
    for step in 0..30 {
        if step > 0 {
            env.step(&[Action::Right, Action::Right]).unwrap();
        }
        let [left, right] = env.observations() else { panic!("two controllers") };
        let (l, r) = (v2(left), v2(right));
        // The right controller's "left" block is its own team: the left controller's "right"
        // block turned by 180°.
        for i in 0..22 {
            assert_eq!(r[i], right.left_team[i / 2][i % 2]);
            assert!((r[i] + l[44 + i]).abs() < 1e-6, "step {step} position {i}");
            assert!((r[22 + i] + l[66 + i]).abs() < 1e-6, "step {step} direction {i}");
            assert!((l[i] + r[44 + i]).abs() < 1e-6, "step {step} position {i}");
        }
        // Ball mirrored in x, y; ownership one-hot swapped left ↔ right.
        assert!((r[88] + l[88]).abs() < 1e-6 && (r[89] + l[89]).abs() < 1e-6);
        assert_eq!(r[90], l[90]);
        assert_eq!([r[94], r[95], r[96]], [l[94], l[96], l[95]]);
        assert_eq!(r[97 + right.active as usize], 1.0);
        assert_eq!(r[108..], l[108..]);
    }
}

#[test]
fn stacked_simple115v2_over_an_episode() {
    let mut env = common::env("academy_empty_goal_close", 1);
    let mut frame = [0.0; 115];
    encode_simple115v2(&env.observations()[0], &mut frame);
    let first = frame;
    let mut stack = FrameStack::new(115, 115, 4);
    stack.reset(&frame);
    let mut history = vec![first; 3];
    for _ in 0..5 {
        env.step(&[Action::Right]).unwrap();
        encode_simple115v2(&env.observations()[0], &mut frame);
        stack.push(&frame);
        history.push(frame);
        // [t-3, t-2, t-1, t], the reset frame standing in for the missing past.
        let mut out = vec![0.0; 460];
        stack.write_stacked(&mut out);
        let expected: Vec<f32> = history[history.len() - 4..].iter().flatten().copied().collect();
        assert_eq!(out, expected);
    }
}
