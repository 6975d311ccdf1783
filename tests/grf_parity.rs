//! Parity with GRF's observed numbers (docs/grf-compatibility.md#scenario-semantics, #scenario-players,
//! #coordinates): every stdlib scenario, loaded through the dsl as a user would, starts with players and ball
//! where GRF's first observation has them, and with GRF's steps_left.

use touchline_engine::{Env, EnvConfig};

/// GRF places a formation entry at (55·x, 84.96·y) m and observes x/54.4, y/83.6.
const OBS_X: f32 = 55.0 / 54.4;
const OBS_Y: f32 = 2.36 * 36.0 / 83.6;

#[test]
fn every_stdlib_scenario_starts_where_grf_does() {
    for name in touchline_dsl::stdlib::names() {
        let scenario = touchline_dsl::load(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        let config = EnvConfig { left_agents: 1, ..EnvConfig::default() };
        let env = Env::with_config(scenario.clone(), config, 0).unwrap_or_else(|e| panic!("{name}: {e}"));
        let obs = &env.observations()[0];
        assert_eq!(obs.steps_left, scenario.game_duration + 1, "{name}");
        assert_eq!(obs.left_team.len(), scenario.left_team.len(), "{name}");
        assert_eq!(obs.right_team.len(), scenario.right_team.len(), "{name}");
        for (entry, seen) in scenario.left_team.iter().zip(&obs.left_team) {
            assert!(
                (seen[0] - OBS_X * entry.x).abs() < 1e-4 && (seen[1] - OBS_Y * entry.y).abs() < 1e-4,
                "{name}: {entry:?} seen at {seen:?}"
            );
        }
        for (entry, seen) in scenario.right_team.iter().zip(&obs.right_team) {
            assert!(
                (seen[0] + OBS_X * entry.x).abs() < 1e-4 && (seen[1] + OBS_Y * entry.y).abs() < 1e-4,
                "{name}: {entry:?} seen at {seen:?}"
            );
        }
        let [bx, by] = scenario.ball_position;
        assert!(
            (obs.ball[0] - bx).abs() < 1e-5 && (obs.ball[1] - by).abs() < 1e-5 && (obs.ball[2] - 0.11).abs() < 1e-6,
            "{name}"
        );
        for (entry, role) in scenario.left_team.iter().zip(&obs.left_team_roles) {
            assert_eq!(entry.role as u8, *role, "{name}");
        }
    }
}

#[test]
fn grf_table_spot_checks() {
    // docs/grf-compatibility.md#scenario-players, academy_corner: left LB (1, 0.42) is observed at (1.0110,
    // 0.4268), right RB (-1, -0.1) at (1.0110, 0.1016).
    let env = Env::new(touchline_dsl::load("academy_corner").unwrap(), 0).unwrap();
    let obs = &env.observations()[0];
    assert!((obs.left_team[1][0] - 1.0110).abs() < 1e-4 && (obs.left_team[1][1] - 0.4268).abs() < 1e-4);
    assert!((obs.right_team[4][0] - 1.0110).abs() < 1e-4 && (obs.right_team[4][1] - 0.1016).abs() < 1e-4);
}

#[test]
fn full_matches_swap_formations_on_odd_episodes() {
    // Set A (the kickoff formation, two players 1.7 m from the centre spot) goes left in the first
    // episode and right in the second (docs/grf-compatibility.md#scenario-semantics).
    let mut env = Env::new(touchline_dsl::load("11_vs_11_stochastic").unwrap(), 0).unwrap();
    let nearest =
        |team: &[[f32; 2]]| team.iter().map(|p| (p[0] * 54.4).hypot(p[1] * 83.6)).fold(f32::INFINITY, f32::min);
    let obs = &env.observations()[0];
    assert!(nearest(&obs.left_team) < nearest(&obs.right_team));
    env.step(&[touchline_engine::Action::Idle]).unwrap();
    env.reset().unwrap();
    let obs = &env.observations()[0];
    assert!(nearest(&obs.left_team) > nearest(&obs.right_team));
}
