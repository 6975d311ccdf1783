//! Half-time at `second_half` (docs/grf-compatibility.md#half-time; GRF's `tests/second_half` and
//! test_second_half): with a 10-step game and the second half at step 5, the controlled player stays near the
//! centre for the first five steps, then (GRF's counting: engine step 5 is env step 6) the teams exchange
//! formations for the other team's kickoff, and the episode ends after 11 steps.

use touchline_engine::{Action, Env, PlayerEntry, Role, Scenario};

fn lazy(role: Role, x: f32, y: f32) -> PlayerEntry {
    PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) }
}

#[test]
fn formations_are_exchanged_at_the_second_half_kickoff() {
    let scenario = Scenario {
        name: "second_half".into(),
        game_duration: 10,
        second_half: 5,
        left_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, 0.0, 0.02)],
        right_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, -0.5, 0.0)],
        ..Scenario::default()
    };
    let mut env = Env::new(scenario, 0).unwrap();
    for step in 1..=11 {
        let out = env.step(&[Action::Idle]).unwrap();
        let o = &env.observations()[0];
        let x = o.left_team[o.active as usize][0];
        let expected = if step <= 5 { 0.0 } else { -0.5 };
        assert!((x - expected).abs() < 0.1, "step {step}: active x {x}, expected about {expected}");
        assert_eq!(out.truncated, step == 11, "step {step}");
    }
}
